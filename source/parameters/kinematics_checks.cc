/**
 * @file parameters/kinematics_checks.cc
 * The wheelset kinematics beyond the longitudinal creepage (Wheelset/Lateral
 * creepage, Yaw angle) checked before anything is built.
 */

#include <deal.II/base/exceptions.h>

#include <wheelrail/parameters/consistency.h>
#include <wheelrail/simulator/format.h>

#include <cmath>
#include <string>

namespace WheelRail
{
  namespace Consistency
  {
    using Report::fmt;

    void
    check_wheelset_kinematics(const Parameters &p)
    {
      const WheelsetParameters &w     = p.wheelset;
      const double              eta   = w.axle_lateral_creepage();
      const bool                range = std::abs(eta) <= max_lateral_creepage;
      const std::string         limit =
        "[-" + fmt(max_lateral_creepage) + ", " + fmt(max_lateral_creepage) + "]";
      // both set the axle's lateral velocity: the sum would be a third value
      AssertThrow(w.lateral_creepage == 0 || w.yaw_angle == 0,
                  ExcMessage("Wheelset/Lateral creepage = " + fmt(w.lateral_creepage) +
                             " and Wheelset/Yaw angle = " + fmt(w.yaw_angle) +
                             " rad are both given: each sets the axle's lateral velocity (eta V, "
                             "and -psi V for the yaw), so together they would make the lateral "
                             "creepage eta - psi = " +
                             fmt(eta) +
                             (range ? "" :
                                      ", outside the range " + limit +
                                        " of the small-angle "
                                        "kinematics") +
                             ". Give one of them."));
      const std::string entry = w.lateral_creepage != 0 ?
                                  "Wheelset/Lateral creepage = " + fmt(w.lateral_creepage) :
                                  "Wheelset/Yaw angle = " + fmt(w.yaw_angle) + " rad";
      AssertThrow(range,
                  ExcMessage(entry + " makes the lateral creepage " + fmt(eta) +
                             ", outside the range " + limit +
                             " of the small-angle kinematics (the mesh is not turned for the "
                             "yaw; the patch drifts across the refined zone by eta V per unit "
                             "time)."));
    }
  } // namespace Consistency
} // namespace WheelRail
