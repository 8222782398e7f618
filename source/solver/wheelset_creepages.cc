/**
 * @file solver/wheelset_creepages.cc
 * Kalker's creepages of the rigid wheelset (wheelset_creepages.h).
 */

#include <wheelrail/solver/wheelset_creepages.h>

#include <cmath>

namespace WheelRail
{
  Creepages
  kinematic_creepages(const Wheelset &wheelset, const double contact_angle)
  {
    Creepages            c;
    const Tensor<1, dim> v = wheelset.axle_velocity();
    if (v[0] == 0)
      return c;
    const double V     = v[0];
    const double omega = wheelset.angular_velocity();
    c.longitudinal     = wheelset.creepage();
    c.lateral          = (v[1] * std::cos(contact_angle) - v[2] * std::sin(contact_angle)) / V;
    // 0 + ...: +0, not -0, on the crown (delta = 0)
    c.spin = 0. + omega * std::sin(contact_angle) / V;
    return c;
  }
} // namespace WheelRail
