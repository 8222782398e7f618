/**
 * @file nodal_damping.h
 * SPEC 2's stiffness damping evaluated from one nodal field (Time
 * integration/Damping form = nodal field): the element forces are the
 * undamped internal forces at w = u + beta_n v, with beta_n per node the
 * smallest beta_e of the node's cells. To first order in beta,
 * f_int(u + beta v) - f_int(u) = beta K(u) v, the viscous stress
 * beta_e C : dE/dt of the strain-rate form on a cell whose nodes share its
 * beta_e (tests/nodal_damping_01.cc), plus the same damping of the
 * hourglass springs; the force loop reads w alone instead of u and v.
 *
 * The damping forces are not formed apart from the elastic ones, so their
 * dissipation is sampled: at the statistics steps the power
 * v . (f_int(w) - f_int(u)) (a second, undamped force pass at u, which the
 * strain energies need anyway) is integrated over time by the trapezoidal
 * rule between the samples.
 *
 * The explicit step forms w in its update pass (NodalUpdate::apply() with w)
 * for the owned DoFs, the distribution of the hanging DoFs for those, and
 * fix_up() where else the step changes u or v after that pass: the
 * prescribed DoFs and the ghost entries.
 */
#ifndef wheelrail_solver_nodal_damping_h
#define wheelrail_solver_nodal_damping_h

#include <wheelrail/solver/elastic_operator.h>

namespace WheelRail
{
  class NodalDamping
  {
  public:
    /** beta_n of @p op (ElasticOperator::smallest_cell_beta()); clears
     *  the dissipation. Collective. */
    void
    setup(const ElasticOperator &op);

    /** w = u + beta_n v on every locally relevant entry of @p u and @p v
     *  (ghosted, hanging DoFs distributed); @p w is on the same
     *  partitioner. */
    void
    damped_displacement(const VectorType &u, const VectorType &v, VectorType &w) const;

    /** beta_n per DoF [s] (owned and ghost entries). */
    const VectorType &
    beta_per_dof() const
    {
      return beta;
    }

    /**
     * The entries that fix_up() forms: the ghost entries of @p u's
     * partitioner and the owned DoFs @p overwritten (prescribed). The
     * hanging DoFs get theirs where they are set
     * (ElasticOperator::distribute() with beta_n and w).
     */
    void
    prepare_fix_up(const VectorType &u, const std::vector<unsigned int> &overwritten);

    /** w = u + beta_n v on the entries of prepare_fix_up() only. */
    void
    fix_up(const VectorType &u, const VectorType &v, VectorType &w) const;

    /**
     * This rank's damping power v . (f_w - f_u) [W]: @p f_w and @p f_u are
     * this rank's element forces at w and u before they are compressed
     * (owned and ghost entries hold the contributions of this rank's cells
     * only), so that summed over the ranks every cell counts once; @p v is
     * ghosted and distributed.
     */
    static double
    power(const VectorType &v, const VectorType &f_w, const VectorType &f_u);

    /** Take this rank's damping power @p p at time @p t: the dissipation
     *  grows by the trapezoidal rule from the last sample. */
    void
    sample(const double t, const double p);

    /** This rank's damping dissipation up to the last sample [J]. */
    double
    dissipation() const
    {
      return dissipated;
    }

    /** The sampled state, for the checkpoint (the Archive of
     *  Checkpoint::Writer and Reader). */
    template <class Archive>
    void
    serialize(Archive &ar)
    {
      ar.pod(have_sample);
      ar.pod(last_time);
      ar.pod(last_power);
      ar.pod(dissipated);
    }

  private:
    VectorType                beta; ///< beta_n per DoF [s], ghosted
    std::vector<unsigned int> fix_up_dofs; ///< owned local indices, sorted
    unsigned int              ghost_begin = 0, ghost_end = 0; ///< the ghost entries
    bool       have_sample = false;
    double     last_time   = 0;
    double     last_power  = 0;
    double     dissipated  = 0;
  };
} // namespace WheelRail

#endif
