/**
 * @file step_times.h
 * The wall seconds of the parts of the explicit steps (timing.csv and the
 * screen's timing table).
 */
#ifndef wheelrail_solver_step_times_h
#define wheelrail_solver_step_times_h

namespace WheelRail
{
  /** Wall seconds of this rank spent in the parts of the explicit steps,
   *  each summed by a ScopedTime around its part of ExplicitSolver::step(). */
  struct StepTimes
  {
    double        elements      = 0; ///< element kernel: gather, forces, scatter
    double        contact       = 0; ///< search, projection, friction, contact forces
    double        update        = 0; ///< central-difference update, constraints, rigid body
    double        communication = 0; ///< ghost exchange and force compression
    double        energies      = 0; ///< energies at statistics steps
    double        constraints   = 0; ///< within update: condense(), distribute(), w fix-up
    double        rigid_body    = 0; ///< within update: the rigid body's advance and sum
    unsigned long steps         = 0; ///< steps timed
  };
} // namespace WheelRail

#endif
