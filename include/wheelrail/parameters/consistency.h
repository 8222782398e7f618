/**
 * @file parameters/consistency.h
 * Checks of the parameters against each other before anything is built:
 * the loads (applied force, prescribed velocity, gravity) over the run,
 * and the wheel-rail geometry against the rolling path.
 */
#ifndef wheelrail_parameters_consistency_h
#define wheelrail_parameters_consistency_h

#include <wheelrail/parameters/parameters.h>

#include <string>

namespace WheelRail
{
  namespace Consistency
  {
    /**
     * The size of the bodies from the parameters: the longest side of
     * their common bounding box and their total exact volume.
     */
    struct BodySize
    {
      double extent; ///< [m]
      double volume; ///< [m^3]
      /** The mean cross-section across the longest side [m^2]. */
      double
      cross_section() const
      {
        return volume / extent;
      }
    };

    BodySize
    body_size(const Parameters &p);

    /** The largest value of a vector expression over a run. */
    struct Peak
    {
      double       magnitude = 0; ///< largest |f| (infinite if not finite) [unit of f]
      double       t         = 0; ///< where it is reached [s]
      unsigned int component = 0; ///< the largest (or first non-finite) component
      double       value     = 0; ///< its value there
    };

    /**
     * The largest |f(x, t)| of the vector expression @p expression
     * (variables x,y,z,t; @p entry names it in messages) at 101 times
     * evenly over [0, @p t_end], at the corners and the centre of the
     * bodies' bounding box with @p over_the_bodies (a field such as the
     * prescribed velocity), else at x = 0 (the applied total force, which
     * the solver evaluates there); the first non-finite value if there is
     * one.
     */
    Peak
    peak_over_run(const Parameters  &p,
                  const std::string &expression,
                  const std::string &constants,
                  const std::string &entry,
                  const double       t_end,
                  const bool         over_the_bodies);

    /**
     * Refuse an applied force, a prescribed velocity, an initial velocity
     * or a gravity that is not finite during the run (on the bodies) or
     * absurd by itself: a load whose weight or force alone strains the
     * bodies by more than 100, a prescribed velocity faster than the
     * dilatational wave speed, an initial velocity more than 100 times it.
     */
    void
    check_loads(const Parameters &p);

    /**
     * Refuse a wheel-rail geometry whose parts do not fit: a solution
     * zone mostly (more than half) off the rail, the contact patch with as
     * much rail again beyond it leaving the rail over the run, and a
     * Static solve/Axle load that the run replaces by the wheelset's
     * weight.
     */
    void
    check_wheel_and_rail(const Parameters &p);

    /** The largest |lateral creepage| (Wheelset/Lateral creepage, or the
     *  Yaw angle's -psi) of the small-angle kinematics [-]. */
    constexpr double max_lateral_creepage = 0.02;

    /**
     * Refuse Wheelset/Lateral creepage and Yaw angle given together (each
     * sets the axle's lateral velocity), and a lateral creepage eta - psi
     * outside [-0.02, 0.02] (kinematics_checks.cc).
     */
    void
    check_wheelset_kinematics(const Parameters &p);
  } // namespace Consistency
} // namespace WheelRail

#endif
