/**
 * @file geometry/rigid_contact.h
 * A rigid contact point of the undeformed wheel and rail profiles in the
 * frame of the mesh (SPEC 10): where the patches of a profile case are
 * expected, and the frame each patch's results are given in.
 */
#ifndef wheelrail_geometry_rigid_contact_h
#define wheelrail_geometry_rigid_contact_h

namespace WheelRail
{
  namespace Geometry
  {
    /** A rigid contact point of the two undeformed profiles, in the mesh's
     *  frame. */
    struct RigidContact
    {
      double y;              ///< lateral position [m]
      double z;              ///< height of the rail top there [m]
      double separation;     ///< distance before any load [m] (0: the main point)
      /** Contact angle delta [rad], -atan of the rail top's slope dz/dy
       *  there: the rail's outer normal is (0, sin delta, cos delta),
       *  delta > 0 leaning towards +y, the gauge side (flange-root contact
       *  21 deg for S1002 on 60E1 1:40 at y_w = 6 mm). */
      double contact_angle;
      double rolling_radius; ///< the wheel's radius there [m]
      /** Radius of relative curvature across, 1 / (z_w'' - z_r'') [m]
       *  (infinite where the profiles are conformal). */
      double radius_across;
    };
  } // namespace Geometry
} // namespace WheelRail

#endif
