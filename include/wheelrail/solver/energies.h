/**
 * @file energies.h
 * The energies of the whole model at one instant, as the explicit step
 * collects them (ExplicitSolver::step()).
 */
#ifndef wheelrail_solver_energies_h
#define wheelrail_solver_energies_h

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
} // namespace WheelRail

#endif
