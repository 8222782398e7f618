/**
 * @file explicit_solver.h
 * Central-difference time integration (SPEC 2) of the elastic operator
 * (elastic_operator.h) with penalty contact, prescribed and loaded
 * boundaries and the rigid axle of the wheelset.
 */
#ifndef wheelrail_solver_explicit_solver_h
#define wheelrail_solver_explicit_solver_h

#include <deal.II/base/function.h>

#include <wheelrail/base/checkpoint.h>
#include <wheelrail/contact/penalty_contact.h>
#include <wheelrail/parameters/parameters.h>
#include <wheelrail/solver/boundary_conditions.h>
#include <wheelrail/solver/elastic_operator.h>
#include <wheelrail/solver/nodal_update.h>
#include <wheelrail/solver/wheelset.h>

#include <functional>
#include <memory>

namespace WheelRail
{
  /** Energies of the whole model at one instant [J]. */
  struct Energies
  {
    double        time      = 0; ///< t_n, the instant of these values [s]
    unsigned long step      = 0; ///< n
    double        kinetic   = 0; ///< with the mid-step velocity v_n
    double        internal  = 0; ///< St. Venant-Kirchhoff strain energy
    double        hourglass = 0; ///< energy stored in the hourglass springs
    /** Hourglass-mode energy with the reference coefficient QM = 0.1,
     *  also when the control is off: shows spurious modes. */
    double hourglass_reference = 0;
    double damping             = 0; ///< dissipated by damping, accumulated
    double contact             = 0; ///< stored in the penalty springs
    double friction            = 0; ///< dissipated by friction, accumulated
    double external_work       = 0; ///< gravity, applied forces, prescribed boundaries

    /** KE + IE + HG + D + contact + friction - W_ext. */
    double
    total() const
    {
      return kinetic + internal + hourglass + damping + contact + friction - external_work;
    }
  };

  /** Wall seconds of this rank spent in the parts of the explicit steps. */
  struct StepTimes
  {
    double        elements      = 0; ///< element kernel: gather, forces, scatter
    double        contact       = 0; ///< search, projection, friction, contact forces
    double        update        = 0; ///< central-difference update, constraints, axle
    double        communication = 0; ///< ghost exchange and force compression
    double        energies      = 0; ///< energies at statistics steps
    unsigned long steps         = 0; ///< steps timed
  };

  /**
   * The explicit elastodynamics core: the elastic operator it derives from
   * (DoFs, constraints, element data, lumped mass) plus the state of the
   * time integration, u (at t_n) and v (at t_{n-1/2}), advanced by step().
   */
  class ExplicitSolver : public ElasticOperator
  {
  public:
    ExplicitSolver(const Parameters                          &parameters,
                   parallel::distributed::Triangulation<dim> &triangulation);

    /** Distribute DoFs, build constraints, element data, mass and loads. */
    void
    setup();

    void
    set_time_step(const double dt);
    double
    time_step() const
    {
      return dt;
    }

    /** Set u everywhere (on cells of @p material, or all if invalid id). */
    void
    set_displacement(const std::function<Tensor<1, dim>(const Point<dim> &)> &u_of_X,
                     const types::material_id material = numbers::invalid_material_id);
    /** Set the initial velocity v_0 (the first step is a half step). */
    void
    set_velocity(
      const std::function<Tensor<1, dim>(const Point<dim> &, const types::material_id)> &v_of_X);

    /** Let @p contact add its forces in every step (nullptr: none). */
    void
    attach_contact(PenaltyContact *contact)
    {
      this->contact = contact;
    }
    /** Let the bore nodes move with @p wheelset (Wheel bore = rigid axle):
     *  passes it the bore nodes' mass and inertia. */
    void
    attach_wheelset(Wheelset *wheelset);
    /** Set the owned entries of u from a vector with the same layout (e.g.
     *  a static solution); hanging DoFs follow their masters. */
    void
    set_displacement(const VectorType &displacement);
    /** f_int(u) - f_contact(u) (frictionless) - f_ext, condensed and compressed. */
    void
    compute_residual(VectorType &residual);
    /** The same at the displacement @p w (ghosted, hanging DoFs
     *  distributed) instead of u; u is not touched. */
    void
    compute_residual(const VectorType &w, VectorType &residual);
    /** Momentum (from v at t_{n-1/2}) of the cells of @p material [kg m/s]. */
    Tensor<1, dim>
    momentum(const types::material_id material) const;
    /** Mean displacement of the nodes of @p material [m]. */
    Tensor<1, dim>
    mean_displacement(const types::material_id material) const;

    /**
     * Add the centrifugal load m omega^2 (x - c) of a wheel spinning at
     * @p omega about the axle through @p centre to the external force, for
     * a static solve of the steadily rolling wheel (it expands by about
     * 30 um at the tread at 140 km/h; without the load the rolling run
     * starts with that expansion as a radial vibration that presses the
     * wheel into the rail).
     */
    void
    add_centrifugal_load(const Point<dim> &centre, const double omega);
    /** The external force as it was before add_centrifugal_load(), to the
     *  bit (not the load subtracted again, which rounds). */
    void
    remove_centrifugal_load();

    /**
     * Initial velocity of steady rolling superposed on the current (static)
     * displacement u: the deformation pattern stays with the axle while the
     * material moves through it. Wheel: v = V + w + H w, w = omega e_y x
     * (X - c); rail: v = -V H e_x (H = grad u, averaged at the nodes).
     * Without the convective terms H w and -V H e_x the start from the static
     * state is a jolt (the rail's deflection does not travel with the load).
     */
    void
    set_rolling_velocity(const Tensor<1, dim> &V, const Point<dim> &centre, const double omega);

    /** One central-difference step; energies at t_n if @p energies. */
    void
    step(Energies *energies = nullptr);

    /** Internal force f_int(u) without damping, condensed and compressed. */
    void
    compute_internal_force(VectorType &force);

    /** The state of the time integration (this rank's part), in the order
     *  of the checkpoint file, for Checkpoint::Writer and Reader. */
    template <class Archive>
    void
    serialize(Archive &ar);

    /** Times of the steps since the last reset_times(). */
    const StepTimes &
    step_times() const
    {
      return times;
    }
    void
    reset_times()
    {
      times = StepTimes();
    }

    /** Stress of every locally owned cell (in active cell index order). */
    std::vector<CellStress>
    cell_stresses() const
    {
      return stresses(u);
    }

    const VectorType &
    displacement() const
    {
      return u;
    }
    const VectorType &
    velocity() const
    {
      return v;
    }
    double
    time() const
    {
      return t;
    }
    unsigned long
    step_number() const
    {
      return n_steps;
    }
    /** Mean displacement of the wheel bore nodes (zero if none). */
    Tensor<1, dim>
    bore_displacement() const;

  private:
    /** f = f_int(u) + f_damp(v) - f_contact(u); returns the damping power.
     *  Contact is evaluated for a step (friction advanced) if @p advance.
     *  With @p f_is_zero the caller guarantees f = 0 already (owned and
     *  ghost entries), and the pass that would zero it is left out. With
     *  @p strain, this rank's strain energies at u from the same pass. */
    double
    assemble_forces(const VectorType &u,
                    const VectorType *v,
                    VectorType       &f,
                    const bool        with_contact,
                    const bool        advance,
                    const bool        f_is_zero = false,
                    StrainEnergies   *strain    = nullptr);
    /** Applied forces at t_n into f; returns their work over the first
     *  half of the step (velocity at t_{n-1/2}). */
    double
    apply_forces(const double h, Tensor<1, dim> &applied_total);
    /** The rigid axle: the FE forces on the bore nodes and their moment
     *  move the wheelset over the step. */
    void
    advance_wheelset(const double h);
    /** Wheelset/Run-up damping: adds alpha m (v - v_rigid) to f (the sign of
     *  internal forces) and returns its dissipated power on the local DoFs,
     *  alpha m |v - v_rigid|^2; its work on the rigid motion over the step
     *  (an external work) goes to @p work. */
    double
    add_runup_damping(const double h, double &work);
    /** Take the per-node update (NodalUpdate) where the DoFs allow it. */
    void
    prepare_nodal_update();
    /** Move the prescribed DoFs to t_{n+1}; adds their reactions' work to
     *  @p work and, with energies, their kinetic energy to @p ke. */
    void
    update_prescribed(const double h,
                      const bool   first,
                      const bool   with_energies,
                      double      &work,
                      double      &ke);
    /** Sum the energies at t_n over the ranks and add contact and axle. */
    void
    collect_energies(Energies    &energies,
                     const double ke,
                     const double gravity_work,
                     const double damping_power,
                     const double h,
                     const double work_step,
                     const bool   first) const;

    std::vector<unsigned int> bore_dofs;
    /** A locally owned node of the wheel: its reference x and z and its x
     *  DoF (add_runup_damping()). */
    struct RunupNode
    {
      double       x, z;
      unsigned int dof;
    };
    std::vector<RunupNode> runup_nodes;
    VectorType             inv_mass; ///< 0 on constrained and prescribed DoFs
    VectorType             f_ext;    ///< gravity, condensed
    VectorType             u0;       ///< displacement at the start
    /** f_ext while a static start adds the centrifugal load to it */
    VectorType f_ext_without_centrifugal;
    /** The update from per-node mass data where the DoFs allow it; prepared
     *  at the first step after the loads or masses change. */
    NodalUpdate nodal_update;
    bool        nodal_update_prepared = false;

    std::vector<PrescribedDof>     prescribed;
    std::unique_ptr<Function<dim>> prescribed_velocity;
    std::vector<AppliedForceDof>   applied;
    std::unique_ptr<Function<dim>> applied_force;
    PenaltyContact                *contact  = nullptr;
    Wheelset                      *wheelset = nullptr;

    VectorType u, v, f, v_old;
    /** f is zero (the update of the last step cleared it behind itself:
     *  the next step's assembly need not). */
    bool          f_cleared           = false;
    double        t                   = 0;
    double        dt                  = 0;
    unsigned long n_steps             = 0;
    double        damping_dissipation = 0;
    double        boundary_work       = 0;
    StepTimes     times;
  };
} // namespace WheelRail

#endif
