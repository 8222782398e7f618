/**
 * @file nodal_update.h
 * The central-difference update of the explicit step from per-node mass
 * data: v += h m^-1 (m g - f), u += dt v, f = 0.
 */
#ifndef wheelrail_solver_nodal_update_h
#define wheelrail_solver_nodal_update_h

#include <deal.II/base/tensor.h>

#include <vector>

namespace WheelRail
{
  using namespace dealii;

  /**
   * The update of every owned DoF, v_i += h w_i (g_i - f_i), u_i += dt v_i,
   * f_i = 0, streams u, v, f and the inverse mass w and the load g per DoF.
   * Where the three components of every node share one mass and one inverse
   * mass and the load is gravity, g_i = m_i gravity_c, the two per-DoF
   * streams shrink to two per node: the update moves 53 instead of 64 bytes
   * per DoF. The results are the same to the bit: g_i is formed and rounded
   * as the stored load was (mass times gravity, one product), and the other
   * operations are those of the per-DoF loop.
   *
   * A prescribed DoF may carry its node's inverse mass here instead of 0:
   * its u and v are overwritten after the update (ExplicitSolver).
   */
  class NodalUpdate
  {
  public:
    /**
     * Take the per-node form if the owned DoFs (x, y, z of one node in a
     * row, @p component[i] = i mod 3) allow it: per node, one mass, one
     * inverse mass on the DoFs not in @p overwritten, and a load equal to
     * mass times gravity. Returns whether it did; otherwise apply() must not
     * be called (the per-DoF loop applies).
     */
    bool
    prepare(const double            *mass,
            const double            *inverse_mass,
            const double            *load,
            const unsigned char     *component,
            const std::vector<bool> &overwritten,
            const unsigned int       n_dofs,
            const Tensor<1, 3>      &gravity);

    /** Whether prepare() took the per-node form. */
    bool
    active() const
    {
      return is_active;
    }

    /**
     * v += h w (g - f), u += dt v, f = 0 over the owned DoFs. With @p W,
     * in the same pass also the damped field W = u + beta_n v of the nodal
     * damping from the new u and v, as NodalDamping::damped_displacement()
     * forms it (the same operations: the same bits); set_damping() must
     * have taken beta_n. The DoFs that the step changes after the update
     * need theirs formed again (ExplicitSolver::exchange_ghosts()).
     */
    void
    apply(const double h,
          const double dt,
          double      *U,
          double      *V,
          double      *F,
          double      *W = nullptr) const;

    /**
     * Take the nodal damping's beta_n (NodalDamping) per node for apply()
     * with W, if the three components of every owned node share it (they
     * do: beta_n is a node's). Returns whether it did. Call after
     * prepare().
     */
    bool
    set_damping(const double *beta, const unsigned int n_dofs);

    /** Whether set_damping() took beta_n. */
    bool
    forms_damped_field() const
    {
      return !node_beta.empty();
    }

    /** The same update from per-DoF inverse mass @p W and load @p G. */
    static void
    apply_per_dof(const double       h,
                  const double       dt,
                  const double      *W,
                  const double      *G,
                  const unsigned int n_dofs,
                  double            *U,
                  double            *V,
                  double            *F);

  private:
    bool                is_active = false;
    unsigned int        n_nodes   = 0;
    double              gravity[3]{};
    std::vector<double> node_mass;
    std::vector<double> node_inverse_mass;
    std::vector<double> node_beta; ///< empty unless set_damping() took it

    template <bool damped>
    void
    update(const double h, const double dt, double *U, double *V, double *F, double *W) const;
  };
} // namespace WheelRail

#endif
