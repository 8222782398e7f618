/**
 * @file geometry/wheel_rail_shape.h
 * The shapes of the wheel and the rail head of the geometry "wheel and
 * rail" (SPEC 1 and 10): the rail's top and the wheel's tread as profile
 * curves in the frame of the mesh, the rigid contact points of the two
 * profiles at the wheelset's lateral shift, and the entries of
 * Geometry/Profiles that select them.
 *
 * The frame of the mesh: O, the origin, is the main rigid contact point on
 * the undeformed rail top (the solution zone is centred on it), y lateral
 * (towards the wheel's flange and the rail's gauge side), z up. Without
 * profile files the wheel is a cylinder and the rail top the circular
 * crown of Geometry/Rail/Profile radius centred on O (the paper's pair),
 * built from the analytic curves as before; with files, the profiles
 * are read in their own frames (mm), the rail's turned by its
 * inclination, the wheel's moved by the taping line's position and the
 * lateral shift, the two searched for their rigid contact points, and
 * both moved so that the main contact point is O.
 */
#ifndef wheelrail_geometry_wheel_rail_shape_h
#define wheelrail_geometry_wheel_rail_shape_h

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/point.h>

#include <wheelrail/geometry/profile.h>
#include <wheelrail/geometry/profile_contact.h>
#include <wheelrail/geometry/rigid_contact.h>
#include <wheelrail/parameters/parameters.h>

#include <algorithm>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace WheelRail
{
  namespace Geometry
  {
    /** The entries of Geometry/Profiles (declared by the geometry "wheel
     *  and rail" through the registry's hook). */
    struct ProfileParameters
    {
      /** Profile files as given, and as read (relative to the directory of
       *  the parameter file that names them); empty: the analytic shape. */
      std::string wheel_file, rail_file;
      std::string wheel_path, rail_path;
      /** How the files are written: y mirrored, z down; the taping line's
       *  y in the wheel file [m]. */
      bool   wheel_flip_y, wheel_z_down, rail_flip_y, rail_z_down;
      double wheel_taping_line;
      /** Middle of the modelled tread (from the taping line, towards the
       *  flange) and head (from the centre line, towards the gauge side) [m]. */
      double wheel_window_centre;
      double rail_window_centre;
      /** Rail inclination 1:N as N [-]; 0: upright. */
      double rail_inclination;
      /** Wheelset lateral shift y_w, towards the flange positive [m]. */
      double lateral_shift;
      /** Lateral position of the wheel profile's y = 0 (taping line) in the
       *  rail profile's frame at y_w = 0 [m]. */
      double taping_line_position;
      /** RMS deviation of the smoothing splines from the points [m]. */
      double smoothing_tolerance;
      /** Separation below which a second local minimum of the distance of
       *  the profiles is a second contact point [m]. */
      double second_contact_tolerance;

      static void
      declare_parameters(ParameterHandler &prm);
      /** Read the entries; a relative file name is read from the directory
       *  of the parameter file that set it (@p geometry's file_directory). */
      void
      parse_parameters(ParameterHandler &prm, const GeometryParameters &geometry);
      /** Whether a profile file is given. */
      bool
      from_files() const
      {
        return !wheel_file.empty() || !rail_file.empty();
      }
    };



    /**
     * The rail top and the wheel tread in the frame of the mesh.
     */
    class WheelRailShape
    {
    public:
      /** The shape of @p geometry with the profiles of @p profiles (read
       *  and searched here; throws naming the entry on bad input). */
      WheelRailShape(const GeometryParameters &geometry, const ProfileParameters &profiles);

      /** Height of the undeformed rail top at @p y [m] (0 at O; outside
       *  the modelled head, the height at its nearer side). */
      double
      rail_top(const double y) const
      {
        return rail->z(std::min(std::max(y, rail->y_min()), rail->y_max()));
      }

      /** The rail top's curve. */
      const std::shared_ptr<const ProfileCurve> &
      rail_curve() const
      {
        return rail;
      }

      /** The wheel tread's curve z_w(y) (0 at O; null for the cylinder). */
      const std::shared_ptr<const ProfileCurve> &
      wheel_curve() const
      {
        return wheel;
      }

      /** Whether the wheel is a cylinder (no wheel profile file). */
      bool
      cylindrical_wheel() const
      {
        return !wheel;
      }

      /** Radius of the undeformed wheel at lateral position @p y [m]
       *  (outside the modelled tread, the radius at its nearer side). */
      double
      wheel_radius(const double y) const
      {
        return wheel ?
                 radius_at_O - wheel->z(std::min(std::max(y, wheel->y_min()), wheel->y_max())) :
                 radius_at_O;
      }

      /** The wheel's rolling radius at O [m] (Geometry/Wheel/Radius for
       *  the cylinder). */
      double
      rolling_radius() const
      {
        return radius_at_O;
      }

      /** The largest radius of the modelled tread [m]. */
      double
      largest_wheel_radius() const;

      /** The undeformed wheel centre: above O by the rolling radius and
       *  Initial gap. */
      Point<dim>
      wheel_centre() const;

      /** Lateral extent of the rail head and of the wheel in the mesh's
       *  frame [m]. */
      double rail_y_lo, rail_y_hi, wheel_y_lo, wheel_y_hi;

      /** The rigid contact points, the main one (O) first. */
      const std::vector<RigidContact> &
      contacts() const
      {
        return points;
      }

      /** The lateral span of the zones of half width @p w about every
       *  contact point: [min y - w, max y + w] [m]. */
      std::pair<double, double>
      zone_span(const double w) const
      {
        double lo = points.front().y - w, hi = points.front().y + w;
        for (const RigidContact &c : points)
          {
            lo = std::min(lo, c.y - w);
            hi = std::max(hi, c.y + w);
          }
        return {lo, hi};
      }

      /** What the profiles are, for the run's summary. */
      std::string
      description() const;

    private:
      GeometryParameters                  p;
      std::shared_ptr<const ProfileCurve> rail;
      std::shared_ptr<const ProfileCurve> wheel;
      double                              radius_at_O;
      std::vector<RigidContact>           points;
      std::string                         summary;

      /** How the file of @p body ("Wheel" or "Rail") is read: its entries,
       *  the window of @p width about @p centre (in the rail's frame). */
      ProfileReadOptions
      read_options(const ProfileParameters &profiles,
                   const std::string       &body,
                   const double             centre,
                   const double             width) const;

      /** Read the files, search the contact and move both curves to O. */
      void
      build_from_files(const ProfileParameters &profiles);
    };
  } // namespace Geometry
} // namespace WheelRail

#endif
