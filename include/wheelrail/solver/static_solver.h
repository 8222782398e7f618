/**
 * @file static_solver.h
 * Implicit static equilibrium with penalty contact (SPEC 5.2): the same
 * discretisation as the explicit run (one-point element, stiffness
 * hourglass control, the same penalty), Newton iterations on the contact
 * set, linear systems by CG with algebraic multigrid (Trilinos ML) on the bodies' stiffness
 * and the contact tangent applied beside it.
 */
#ifndef wheelrail_solver_static_solver_h
#define wheelrail_solver_static_solver_h

#include <deal.II/lac/trilinos_precondition.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <wheelrail/contact/penalty_contact.h>
#include <wheelrail/parameters/parameters.h>
#include <wheelrail/solver/explicit_solver.h>
#include <wheelrail/solver/static_tangent.h>

#include <Epetra_MultiVector.h>

namespace WheelRail
{
  /** Outcome of a static contact solve. */
  struct StaticResult
  {
    double       axle_displacement = 0; ///< downward displacement of the bore [m]
    double       contact_force     = 0; ///< vertical force of the rail on the wheel [N]
    unsigned int load_iterations   = 0;
    unsigned int newton_iterations = 0; ///< in all load iterations
    unsigned int linear_iterations = 0; ///< CG iterations in all
  };

  /**
   * Presses the wheel onto the rail: the bore nodes are moved down rigidly
   * by delta (all other conditions as in the explicit run: fixed rail
   * bottom, rail ends fixed in x) and delta is found by secant iterations on
   * F^(2/3) (nearly linear for a Hertzian contact) so that the contact force
   * equals the target load; Newton at each new delta starts from the line
   * through the last two converged states where delta goes on in the same
   * direction. The contact is frictionless here. The residuals
   * are those of the ExplicitSolver at the iterate (its operator, external
   * force and contact); the solution is left in its displacement, ready for
   * an explicit run.
   */
  class StaticContactSolver
  {
  public:
    StaticContactSolver(const Parameters &parameters,
                        ExplicitSolver   &solver,
                        PenaltyContact   &contact,
                        MPI_Comm          comm);

    StaticResult
    solve(const double target_load, std::ostream &log);

  private:
    /** The hanging-node constraints and the homogeneous Dirichlet
     *  conditions of the fixed boundaries and the bore. */
    void
    make_constraints(const IndexSet &relevant);
    /** K, with the constraints condensed, once. */
    void
    assemble_stiffness(const IndexSet &relevant);
    /** The AMG of K with the near null space that Static solve/AMG null
     *  space selects, once. */
    void
    initialize_amg();

    /** Newton at a fixed bore displacement; returns the contact force. */
    double
    solve_at(const double delta, StaticResult &result, std::ostream &log);
    /** Move the bore down rigidly by @p delta. */
    void
    prescribe_bore(const double delta);
    /** The residual at the displacement @p v (its owned entries) into
     *  @p residual, and its norm over the free DoFs. Collective. */
    double
    residual_norm(const VectorType &v, VectorType &residual);
    /** Log Newton iteration @p it; whether it has converged (or stalled
     *  within 10 x the tolerance). */
    bool
    newton_converged(const unsigned int it,
                     const double       norm,
                     const double       previous_norm,
                     const double       load_scale,
                     std::ostream      &log) const;
    /** Throw when Static solve/Max Newton iterations are spent. */
    void
    check_newton_progress(const unsigned int it,
                          const double       norm,
                          const double       previous_norm,
                          const double       delta,
                          const double       load_scale) const;
    /** The relative tolerance of the linear solve (inexact Newton). */
    double
    linear_tolerance(const bool   first,
                     const double reduction,
                     const double norm,
                     const double load_scale) const;
    /** The Newton increment: CG with the AMG on the tangent at the active
     *  contact pairs, to the relative tolerance @p eta. */
    TrilinosWrappers::MPI::Vector
    newton_increment(const VectorType &residual, const double eta, StaticResult &result);
    /** u + alpha du with the step length alpha halved until the residual
     *  norm falls below @p norm (8 times at most); returns the new norm,
     *  leaves the residual in @p residual. */
    double
    line_search(const TrilinosWrappers::MPI::Vector &du,
                const double                         norm,
                VectorType                          &trial,
                VectorType                          &residual,
                std::ostream                        &log);
    /** Drop the whole wheel rigidly by the initial @p gap. */
    void
    drop_wheel(const double gap);
    /** u += s (u - u_before) where s > 0; u_before = the old u. */
    void
    extrapolate(const double s, VectorType &u_before);
    /** The errors of the load iterations: no contact found ... */
    ExcMessage
    no_contact_message(const double d1, const double gap, const unsigned int max_closing) const;
    /** ... or the load not reached. */
    ExcMessage
    load_message(const double       target,
                 const double       F0,
                 const double       F1,
                 const double       d1,
                 const double       gap,
                 const unsigned int max_load) const;

    /** The six rigid-body modes (translations, rotations about the
     *  coordinate axes) on the locally owned rows of @p matrix, for the
     *  AMG's near null space. */
    static Epetra_MultiVector
    rigid_body_modes(const DoFHandler<dim>                &dof_handler,
                     const TrilinosWrappers::SparseMatrix &matrix);

    const Parameters         &parameters;
    ExplicitSolver           &solver;
    PenaltyContact           &contact;
    MPI_Comm                  mpi_communicator;
    AffineConstraints<double> constraints; ///< hanging + homogeneous Dirichlet
    IndexSet                  bore_dofs;   ///< locally owned bore DoFs
    VectorType                u;           ///< current iterate
    VectorType state; ///< the displacement of a residual, ghosts and hanging DoFs set
    TrilinosWrappers::SparseMatrix    stiffness_matrix; ///< K, with the constraints condensed
    TrilinosWrappers::PreconditionAMG amg;              ///< of K, built once
    StaticTangent                     tangent;
  };
} // namespace WheelRail

#endif
