/**
 * @file static_solver.h
 * Implicit static equilibrium with penalty contact (SPEC 5.2): the same
 * discretisation as the explicit run (one-point element, stiffness
 * hourglass control, the same penalty), Newton iterations on the contact
 * set, linear systems by CG with algebraic multigrid (Trilinos ML).
 */
#ifndef wheelrail_static_solver_h
#define wheelrail_static_solver_h

#include <wheelrail/contact.h>
#include <wheelrail/explicit_solver.h>
#include <wheelrail/parameters.h>

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
   * equals the target load. The contact is frictionless here. The solution
   * is left in the ExplicitSolver's displacement, ready for an explicit run.
   */
  class StaticContactSolver
  {
  public:
    StaticContactSolver(const Parameters &parameters,
                        ExplicitSolver &  solver,
                        PenaltyContact &  contact,
                        MPI_Comm          comm);

    StaticResult
    solve(const double target_load, std::ostream &log);

  private:
    /** Newton at a fixed bore displacement; returns the contact force. */
    double
    solve_at(const double delta, StaticResult &result, std::ostream &log);

    const Parameters &parameters;
    ExplicitSolver &  solver;
    PenaltyContact &  contact;
    MPI_Comm          mpi_communicator;
    AffineConstraints<double> constraints; ///< hanging + homogeneous Dirichlet
    IndexSet                  bore_dofs;   ///< locally owned bore DoFs
    VectorType                u;           ///< current iterate
  };
} // namespace WheelRail

#endif
