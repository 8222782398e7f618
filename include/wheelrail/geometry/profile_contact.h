/**
 * @file geometry/profile_contact.h
 * The rigid contact search of a wheel and a rail profile in the cross-section
 * through the axle: the undeformed distance function, its contact points
 * (tread, flange root) and the local geometry that Hertz needs there.
 */
#ifndef wheelrail_geometry_profile_contact_h
#define wheelrail_geometry_profile_contact_h

#include <wheelrail/geometry/profile.h>

#include <vector>

namespace WheelRail
{
  namespace Geometry
  {
    /**
     * One local minimum of the vertical distance d(y) = z_w(y) + dz - z_r(y)
     * of the wheel placed by the lift dz on the rail. All lengths in m, angles
     * in rad, curvatures in 1/m.
     */
    struct ProfileContactPoint
    {
      /** Lateral position [m]. */
      double y = 0;
      /** Height of the rail surface z_r(y) [m]. */
      double z = 0;
      /** Vertical separation d(y) [m] before deformation (0 at the first point). */
      double separation = 0;
      /**
       * Separation [m] along the rail's normal at y: t with
       * z_w(y - t sin delta) + dz = z_r(y) + t cos delta; about d cos(delta).
       */
      double normal_separation = 0;
      /** Contact angle delta = atan(z_r'(y)) [rad], the sign of the slope. */
      double contact_angle = 0;
      /** The wheel's rolling radius r(y) = R0 - z_w(y) [m]. */
      double rolling_radius = 0;
      /** Curvature of the rail across, z_r'' / (1 + z_r'^2)^(3/2) [1/m] (crown < 0). */
      double rail_curvature = 0;
      /** Curvature of the wheel across, z_w'' / (1 + z_w'^2)^(3/2) [1/m]. */
      double wheel_curvature = 0;
      /**
       * Hertz's A [1/m], along x: half the wheel's normal curvature in the
       * rolling direction, cos(delta) / (2 r) (Meusnier; 1 / (2 r) at delta = 0).
       */
      double A = 0;
      /**
       * Hertz's B [1/m], across in the tangent plane: (z_w'' - z_r'')/2 cos^3
       * delta, half the difference of the two curvatures across where the
       * slopes are equal.
       */
      double B = 0;
      /** The lift [m] of the wheel from its given placement to first touch. */
      double lift = 0;
      /** Whether the minimum lies at an end of the two profiles' common range. */
      bool at_range_end = false;
    };

    /**
     * The contact points of the wheel curve z_w(y) (the wheel's surface in the
     * section through the axle, z up; rolling radius R0 - z_w) on the rail
     * curve z_r(y): over the common range, the wheel is lifted by dz so that
     * min d = 0, and every local minimum of d with d <= separation_tolerance
     * [m] is returned, sorted by d. d is sampled every 0.01 mm, each minimum
     * refined to 1e-9 m (bisection on d' = z_w' - z_r', golden section where d'
     * does not change sign). The vertical distance stands for the normal one:
     * near equal slopes (every minimum) they differ by the factor cos(delta)
     * to first order, which normal_separation gives exactly; on a steep flange
     * the vertical search still finds the points where the slopes are equal.
     * Where d is constant (flat on flat, a line contact) the one point returned
     * is the right end of the common range, marked at_range_end.
     */
    std::vector<ProfileContactPoint>
    rigid_contact(const ProfileCurve &wheel,
                  const ProfileCurve &rail,
                  const double        nominal_radius,
                  const double        separation_tolerance);
  } // namespace Geometry
} // namespace WheelRail

#endif
