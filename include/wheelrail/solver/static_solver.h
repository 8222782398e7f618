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
   * The Newton tangent K + sum_p k_p g_p g_p^T: the stiffness matrix K of the
   * bodies (constant: the one-point element's small-strain stiffness in the
   * reference configuration) and the rank-one penalty tangent of each active
   * contact pair, g_p being the pair's gap functional (slave minus the
   * interpolated master point, along the normal). The contact part is applied
   * outside the matrix, so K and its AMG preconditioner are built once for
   * the whole static solve; CG deals with the contact directions the
   * preconditioner does not see.
   */
  class StaticTangent
  {
  public:
    StaticTangent(const TrilinosWrappers::SparseMatrix &K, MPI_Comm comm);

    /** The gap functionals of @p pairs on the free DoFs: hanging DoFs are
     *  expanded into their masters, fixed DoFs dropped; each rank keeps the
     *  entries on its owned DoFs. */
    void
    set_contact_pairs(const std::vector<ContactPair>  &pairs,
                      const AffineConstraints<double> &constraints,
                      const IndexSet                  &owned);

    void
    vmult(TrilinosWrappers::MPI::Vector &dst, const TrilinosWrappers::MPI::Vector &src) const;

  private:
    const TrilinosWrappers::SparseMatrix &K;
    MPI_Comm                              comm;
    std::vector<double>                   stiffness; ///< k_p [N/m]
    std::vector<unsigned int>             offsets;   ///< pair p: entries [offsets[p], offsets[p+1])
    std::vector<unsigned int>             local_index; ///< owned DoF, local numbering
    std::vector<double>                   coefficient; ///< d g_p / d u_dof
    mutable std::vector<double>           gaps;
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
    /** Newton at a fixed bore displacement; returns the contact force. */
    double
    solve_at(const double delta, StaticResult &result, std::ostream &log);

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
