/**
 * @file solver/wheelset_creepages.h
 * Kalker's creepages of the rigid wheelset at its main contact point
 * (SPEC 10), from the axle's velocity and angular velocity and the contact
 * angle of the rigid contact.
 */
#ifndef wheelrail_solver_wheelset_creepages_h
#define wheelrail_solver_wheelset_creepages_h

#include <wheelrail/parameters/parameters.h>
#include <wheelrail/solver/wheelset.h>

namespace WheelRail
{
  /**
   * The creepages of SPEC 10 in the contact frame (x, s, n) of the main
   * contact point: n = (0, sin delta, cos delta) the rail's outward normal
   * at the contact angle delta (delta = -atan z_r'(y) > 0 leaning towards
   * +y, the flange), x the rolling direction, s = n x x = (0, cos delta,
   * -sin delta); V = v_x of the axle. The wheel's rigid velocity relative
   * to the (resting) rail at the contact point x_c is
   * v = v_a + omega e_y x (x_c - x_a); the rotation about the axle adds
   * only -omega r e_x for x_c - x_a in the y-z plane, so
   *  - xi  = (v_x - omega r) / V  (r the rolling radius, as Wheelset::creepage()),
   *  - eta = v . s / V = (v_y cos delta - v_z sin delta) / V, which is the
   *    input eta - psi where delta = 0 and the axle does not bounce,
   *  - phi = Omega . n / V = omega sin(delta) / V [1/m], with Omega = omega
   *    e_y (no yaw rate, omega = V / r > 0 rolling towards +x): about
   *    sin(delta) / r; 0 for the cylinder on the crown (delta = 0), and
   *    positive on a coned tread, where the rail falls towards the flange
   *    (delta > 0).
   */
  struct Creepages
  {
    double longitudinal = 0; ///< xi [-]
    double lateral      = 0; ///< eta [-]
    double spin         = 0; ///< phi [1/m]
  };

  /** The creepages of @p wheelset at the contact angle @p contact_angle
   *  [rad] (all 0 before rolling starts). */
  Creepages
  kinematic_creepages(const Wheelset &wheelset, const double contact_angle);

  /** Whether the statistics report the lateral and spin creepages: where
   *  Wheelset/Lateral creepage or Yaw angle is given (@p parameters) or the
   *  shapes come from profile files (@p profile_contact). Without them the
   *  columns are those of before. */
  inline bool
  reports_kinematic_creepages(const WheelsetParameters &parameters, const bool profile_contact)
  {
    return parameters.lateral_creepage != 0 || parameters.yaw_angle != 0 || profile_contact;
  }
} // namespace WheelRail

#endif
