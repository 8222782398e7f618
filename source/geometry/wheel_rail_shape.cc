/**
 * @file geometry/wheel_rail_shape.cc
 * The rail top and the wheel tread of the geometry "wheel and rail" as
 * profile curves in the mesh's frame, and the entries of Geometry/Profiles.
 */

#include <deal.II/base/exceptions.h>

#include <wheelrail/geometry/wheel_rail_shape.h>
#include <wheelrail/simulator/format.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iomanip>
#include <limits>
#include <sstream>
#include <utility>

namespace WheelRail
{
  namespace Geometry
  {
    namespace
    {
      using Report::fmt;

      /** Points of a profile file may lie at most this many Minimum cell
       *  sizes apart inside the modelled window. */
      constexpr double max_spacing_in_cells = 4;

      /**
       * A curve moved in its plane: z(y) = base.z(y + dy) + dz, over the
       * base's range moved by -dy; a point outside the range (where
       * rounding puts the vertices of a side face) takes the value at the
       * nearer end.
       */
      class ShiftedProfile : public ProfileCurve
      {
      public:
        ShiftedProfile(std::shared_ptr<const ProfileCurve> base, const double dy, const double dz)
          : base(std::move(base))
          , dy(dy)
          , dz(dz)
        {}

        double
        z(const double y) const override
        {
          return base->z(inside(y + dy)) + dz;
        }

        double
        slope(const double y) const override
        {
          return base->slope(inside(y + dy));
        }

        double
        curvature_z(const double y) const override
        {
          return base->curvature_z(inside(y + dy));
        }

        double
        y_min() const override
        {
          return base->y_min() - dy;
        }

        double
        y_max() const override
        {
          return base->y_max() - dy;
        }

        std::string
        description() const override
        {
          return base->description();
        }

      private:
        std::shared_ptr<const ProfileCurve> base;
        double                              dy, dz;

        double
        inside(const double y) const
        {
          return std::min(std::max(y, base->y_min()), base->y_max());
        }
      };



      /** @p name read relative to @p directory unless absolute; empty stays
       *  empty. */
      std::string
      resolve(const std::string &name, const std::string &directory)
      {
        if (name.empty())
          return name;
        const std::filesystem::path path(name);
        if (path.is_absolute() || directory.empty())
          return name;
        return (std::filesystem::path(directory) / path).lexically_normal().string();
      }
    } // namespace



    void
    ProfileParameters::declare_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Geometry");
      prm.enter_subsection("Profiles");
      prm.declare_entry("Wheel profile file",
                        "",
                        Patterns::Anything(),
                        "Wheel profile, two columns y z in mm (text or CSV; # and % "
                        "start comments): y lateral from the taping line towards the "
                        "flange, z up from the nominal rolling circle (the flange has "
                        "z < 0); the wheel is the profile revolved about the axle, its "
                        "radius Geometry/Wheel/Radius - z. A relative name is read from the "
                        "directory of the parameter file that sets it (as an include). "
                        "Empty: a cylindrical tread of Geometry/Wheel/Radius. Shipped: "
                        "mesh/profiles/ (mesh/profiles/README.md).");
      prm.declare_entry("Rail profile file",
                        "",
                        Patterns::Anything(),
                        "Rail head profile, two columns y z in mm: y lateral from the "
                        "rail's centre line towards the gauge side, z up from the top of "
                        "the upright head, inclined by Rail inclination. A relative name is "
                        "read from the directory of the parameter file that sets it. "
                        "Empty: the circular crown of Geometry/Rail/Profile radius.");
      prm.declare_entry("Wheel profile flip y",
                        "false",
                        Patterns::Bool(),
                        "Whether the wheel file's y runs the other way (towards the field "
                        "side): the file is mirrored y -> -y before anything else.");
      prm.declare_entry("Wheel profile z down",
                        "false",
                        Patterns::Bool(),
                        "Whether the wheel file's z points down (into the rail), as in "
                        "CONTACT's profile files: z -> -z on reading.");
      prm.declare_entry("Wheel profile taping line",
                        "0",
                        Patterns::Double(-0.2, 0.2),
                        "The taping line's y in the wheel file, as written [m], range "
                        "[-0.2, 0.2] (e.g. 0.07 for a file whose y = 0 is the flange back "
                        "of a wheel with the taping line 70 mm from it): the profile is "
                        "moved so that the taping line is its y = 0.");
      prm.declare_entry("Rail profile flip y",
                        "false",
                        Patterns::Bool(),
                        "Whether the rail file's y runs towards the field side: mirrored "
                        "y -> -y on reading. The file's (0, 0) must be the top of the head "
                        "on its centre line (the point the inclination turns it about).");
      prm.declare_entry("Rail profile z down",
                        "false",
                        Patterns::Bool(),
                        "Whether the rail file's z points down: z -> -z on reading.");
      prm.declare_entry("Wheel window centre",
                        "0",
                        Patterns::Double(-0.2, 0.2),
                        "Middle of the modelled tread, which is Geometry/Wheel/Tread width "
                        "wide, from the taping line towards the flange [m], range "
                        "[-0.2, 0.2].");
      prm.declare_entry("Rail window centre",
                        "0",
                        Patterns::Double(-0.2, 0.2),
                        "Middle of the modelled head, which is Geometry/Rail/Head width "
                        "wide, from the head's centre line towards the gauge side (before "
                        "the inclination) [m], range [-0.2, 0.2].");
      prm.declare_entry("Rail inclination",
                        "0",
                        Patterns::Double(0, 1000),
                        "The rail is inclined 1:N towards the track centre (its head "
                        "turned about the top of its centre line, the gauge side down): "
                        "N [-], 0 for an upright rail, else in [5, 1000] (1:40 and 1:20 "
                        "are usual).");
      prm.declare_entry("Lateral shift",
                        "0",
                        Patterns::Double(-0.03, 0.03),
                        "Wheelset lateral shift y_w [m], range [-0.03, 0.03]: positive "
                        "brings this wheel's flange towards the rail's gauge face (the "
                        "wheel profile moves by -y_w in the rail profile's frame) before "
                        "the rigid contact search.");
      prm.declare_entry("Taping line position",
                        "0",
                        Patterns::Double(-0.1, 0.1),
                        "Lateral coordinate, in the rail profile's frame, of the wheel "
                        "profile's y = 0 (the taping line) at zero lateral shift [m], range "
                        "[-0.1, 0.1]. A standard track (gauge 1435 mm, flange back spacing "
                        "1360 mm) puts the taping line of S1002 3.035 mm from the centre "
                        "line of 60E1 inclined 1:40 (scripts/profile_contact.py).");
      prm.declare_entry("Smoothing tolerance",
                        "1e-6",
                        Patterns::Double(0, 1e-4),
                        "RMS deviation of the cubic smoothing spline of each profile from "
                        "its points [m], range [0, 1e-4]; 0 interpolates the points.");
      prm.declare_entry("Second contact tolerance",
                        "1e-4",
                        Patterns::Double(0, 0.005),
                        "A second local minimum of the vertical distance of the profiles "
                        "at most this far apart before loading is a second contact point, "
                        "meshed like the first (two-point contact) [m], range [0, 0.005].");
      prm.leave_subsection();
      prm.leave_subsection();
    }



    void
    ProfileParameters::parse_parameters(ParameterHandler &prm, const GeometryParameters &geometry)
    {
      prm.enter_subsection("Geometry");
      prm.enter_subsection("Profiles");
      wheel_file               = prm.get("Wheel profile file");
      rail_file                = prm.get("Rail profile file");
      wheel_flip_y             = prm.get_bool("Wheel profile flip y");
      wheel_z_down             = prm.get_bool("Wheel profile z down");
      wheel_taping_line        = prm.get_double("Wheel profile taping line");
      rail_flip_y              = prm.get_bool("Rail profile flip y");
      rail_z_down              = prm.get_bool("Rail profile z down");
      wheel_window_centre      = prm.get_double("Wheel window centre");
      rail_window_centre       = prm.get_double("Rail window centre");
      rail_inclination         = prm.get_double("Rail inclination");
      lateral_shift            = prm.get_double("Lateral shift");
      taping_line_position     = prm.get_double("Taping line position");
      smoothing_tolerance      = prm.get_double("Smoothing tolerance");
      second_contact_tolerance = prm.get_double("Second contact tolerance");
      prm.leave_subsection();
      prm.leave_subsection();
      const auto directory = [&](const std::string &entry) {
        return geometry.file_directory ? geometry.file_directory("Geometry/Profiles", entry) :
                                         std::string();
      };
      wheel_path = resolve(wheel_file, directory("Wheel profile file"));
      rail_path  = resolve(rail_file, directory("Rail profile file"));
      AssertThrow(rail_inclination == 0 || rail_inclination >= 5,
                  ExcMessage("Geometry/Profiles/Rail inclination = " + fmt(rail_inclination) +
                             " would incline the rail 1:" + fmt(rail_inclination) +
                             ": give N of 1:N in [5, 1000] (40 and 20 are usual), or 0 for an "
                             "upright rail."));
    }



    WheelRailShape::WheelRailShape(const GeometryParameters &geometry,
                                   const ProfileParameters  &profiles)
      : p(geometry)
      , radius_at_O(geometry.wheel_radius)
    {
      if (profiles.from_files())
        build_from_files(profiles);
      else
        {
          // the paper's pair, analytic, centred on O
          const double w = 0.5 * p.rail_head_width;
          rail           = std::make_shared<CircularProfile>(p.rail_profile_radius, 0., 0., -w, w);
          rail_y_lo      = -w;
          rail_y_hi      = w;
          wheel_y_lo     = -0.5 * p.tread_width;
          wheel_y_hi     = 0.5 * p.tread_width;
          points         = {{0., 0., 0., 0., p.wheel_radius, p.rail_profile_radius}};
        }
    }



    ProfileReadOptions
    WheelRailShape::read_options(const ProfileParameters &profiles,
                                 const std::string       &body,
                                 const double             centre,
                                 const double             width) const
    {
      const bool         wheel = body == "Wheel";
      ProfileReadOptions options;
      options.parameter           = "Geometry/Profiles/" + body + " profile file";
      options.name                = wheel ? profiles.wheel_file : profiles.rail_file;
      options.smoothing_tolerance = profiles.smoothing_tolerance;
      options.mirror              = wheel ? profiles.wheel_flip_y : profiles.rail_flip_y;
      options.z_down              = wheel ? profiles.wheel_z_down : profiles.rail_z_down;
      options.y_from              = centre - 0.5 * width;
      options.y_to                = centre + 0.5 * width;
      options.max_spacing         = max_spacing_in_cells * p.h_min;
      return options;
    }



    void
    WheelRailShape::build_from_files(const ProfileParameters &profiles)
    {
      // both curves in the rail profile's frame
      const double angle =
        profiles.rail_inclination > 0 ? -std::atan(1. / profiles.rail_inclination) : 0.;
      ProfileReadOptions rail_options =
        read_options(profiles, "Rail", profiles.rail_window_centre, p.rail_head_width);
      rail_options.rotation = angle;
      std::shared_ptr<const ProfileCurve> rail_r;
      if (!profiles.rail_path.empty())
        rail_r = SplineProfile::read(profiles.rail_path, rail_options);
      else // the crown turned by the inclination about its top
        rail_r = std::make_shared<CircularProfile>(p.rail_profile_radius,
                                                   p.rail_profile_radius * std::sin(-angle),
                                                   p.rail_profile_radius * (1 - std::cos(angle)),
                                                   rail_options.y_from,
                                                   rail_options.y_to);

      // y_w > 0 brings this wheel's flange towards its rail's gauge face:
      // the wheel moves towards the rail's field side (-y)
      // the file's taping line (mirrored with the file) onto y = 0 first
      const double taping_line =
        profiles.wheel_flip_y ? -profiles.wheel_taping_line : profiles.wheel_taping_line;
      const double shift = profiles.taping_line_position - profiles.lateral_shift - taping_line;
      ProfileReadOptions wheel_options = read_options(
        profiles, "Wheel", shift + taping_line + profiles.wheel_window_centre, p.tread_width);
      wheel_options.shift_y = shift;
      std::shared_ptr<const ProfileCurve> wheel_r;
      if (!profiles.wheel_path.empty())
        wheel_r = SplineProfile::read(profiles.wheel_path, wheel_options);
      else
        wheel_r = std::make_shared<FlatProfile>(wheel_options.y_from, wheel_options.y_to);

      const bool overlap =
        std::max(wheel_r->y_min(), rail_r->y_min()) < std::min(wheel_r->y_max(), rail_r->y_max());
      const std::vector<ProfileContactPoint> found =
        overlap ?
          rigid_contact(*wheel_r, *rail_r, p.wheel_radius, profiles.second_contact_tolerance) :
          std::vector<ProfileContactPoint>();
      AssertThrow(!found.empty(),
                  ExcMessage(
                    "The wheel profile (Geometry/Profiles/Wheel profile file, window " +
                    fmt(1e3 * wheel_options.y_from) + " to " + fmt(1e3 * wheel_options.y_to) +
                    " mm in the rail's frame) and the rail profile (window " +
                    fmt(1e3 * rail_options.y_from) + " to " + fmt(1e3 * rail_options.y_to) +
                    " mm) do not overlap laterally, or touch only at a window's edge: "
                    "move Wheel window centre, Rail window centre or Taping line "
                    "position, or widen Tread width and Head width."));
      const double yc = found.front().y;
      const double zr = rail_r->z(yc), zw = wheel_r->z(yc);
      radius_at_O = p.wheel_radius - zw;
      rail        = std::make_shared<ShiftedProfile>(rail_r, yc, -zr);
      if (!profiles.wheel_path.empty())
        wheel = std::make_shared<ShiftedProfile>(wheel_r, yc, -zw);
      rail_y_lo  = rail_r->y_min() - yc;
      rail_y_hi  = rail_r->y_max() - yc;
      wheel_y_lo = wheel_r->y_min() - yc;
      wheel_y_hi = wheel_r->y_max() - yc;
      for (const ProfileContactPoint &c : found)
        {
          const double y      = c.y - yc;
          const double across = wheel_r->curvature_z(c.y) - rail_r->curvature_z(c.y);
          const double cos_d  = 1 / std::sqrt(1 + std::pow(rail_r->slope(c.y), 2));
          points.push_back({y,
                            rail->z(y),
                            c.separation,
                            std::atan(-rail_r->slope(c.y)),
                            wheel_radius(y),
                            across > 0 ? 1 / (across * std::pow(cos_d, 3)) :
                                         std::numeric_limits<double>::infinity()});
        }

      std::ostringstream s;
      s << "wheel " << (profiles.wheel_file.empty() ? "cylinder" : profiles.wheel_file) << ", rail "
        << (profiles.rail_file.empty() ? "circular crown" : profiles.rail_file);
      if (profiles.rail_inclination > 0)
        s << " inclined 1:" << fmt(profiles.rail_inclination);
      s << "; lateral shift " << fmt(1e3 * profiles.lateral_shift) << " mm";
      summary = s.str();
    }



    double
    WheelRailShape::largest_wheel_radius() const
    {
      if (!wheel)
        return radius_at_O;
      double r = 0;
      for (unsigned int i = 0; i <= 1000; ++i)
        r = std::max(r, wheel_radius(wheel_y_lo + i * (wheel_y_hi - wheel_y_lo) / 1000));
      return r;
    }



    Point<dim>
    WheelRailShape::wheel_centre() const
    {
      return Point<dim>(p.wheel_centre_x, 0., radius_at_O + p.initial_gap);
    }



    std::string
    WheelRailShape::description() const
    {
      std::ostringstream s;
      s << summary;
      // fixed decimals: the search's rounding (1e-12 m) stays out of print
      const auto fixed = [](const double value, const int digits) {
        const double       scale = std::pow(10., digits);
        std::ostringstream out;
        out << std::fixed << std::setprecision(digits)
            << std::round(value * scale) / scale + 0.; // no "-0.000"
        return out.str();
      };
      for (const RigidContact &c : points)
        s << "\n  contact point at y " << fixed(1e3 * c.y, 3) << " mm, separation "
          << fixed(1e3 * c.separation, 4) << " mm, contact angle "
          << fixed(c.contact_angle * 180 / M_PI, 3) << " deg, rolling radius "
          << fixed(1e3 * c.rolling_radius, 3) << " mm, radius across "
          << fixed(1e3 * c.radius_across, 1) << " mm";
      return s.str();
    }
  } // namespace Geometry
} // namespace WheelRail
