/**
 * @file geometry/profile.h
 * Profiles: curves z(y) in the cross-section of a wheel or a rail (y lateral,
 * z up, both in m), analytic (flat, circular) or read from a file of points
 * and fitted by a cubic (smoothing) spline (SPEC 10).
 */
#ifndef wheelrail_geometry_profile_h
#define wheelrail_geometry_profile_h

#include <array>
#include <cmath>
#include <limits>
#include <memory>
#include <string>
#include <vector>

namespace WheelRail
{
  namespace Geometry
  {
    /**
     * A curve z(y) of the cross-section, single-valued over [y_min(), y_max()]
     * [m]. Evaluation outside that range throws std::out_of_range (the callers
     * stay inside).
     */
    class ProfileCurve
    {
    public:
      virtual ~ProfileCurve() = default;

      /** Height z [m] at the lateral coordinate y [m]. */
      virtual double
      z(const double y) const = 0;

      /** Slope dz/dy [-] at y [m]. */
      virtual double
      slope(const double y) const = 0;

      /** Second derivative d2z/dy2 [1/m] at y [m] (not the curvature of the arc). */
      virtual double
      curvature_z(const double y) const = 0;

      /** Smallest y [m] of the range. */
      virtual double
      y_min() const = 0;

      /** Largest y [m] of the range. */
      virtual double
      y_max() const = 0;

      /** One line saying what the curve is (for the screen and the messages). */
      virtual std::string
      description() const = 0;

    protected:
      /** Throws std::out_of_range unless y_min() <= y <= y_max(). */
      void
      check_range(const double y) const;
    };

    /** z = 0 over [y_min, y_max] [m]: the cylindrical wheel or a flat rail. */
    class FlatProfile : public ProfileCurve
    {
    public:
      /** The range [y_min, y_max] [m], y_min < y_max. */
      FlatProfile(const double y_min, const double y_max);

      double
      z(const double y) const override;
      double
      slope(const double y) const override;
      double
      curvature_z(const double y) const override;
      double
      y_min() const override;
      double
      y_max() const override;
      std::string
      description() const override;

    private:
      const double lower, upper;
    };

    /**
     * A circular arc of radius rho [m], convex upwards, with its top at
     * (y_c, z_top) [m]: z = z_top + (sqrt(rho^2 - (y - y_c)^2) - rho) over a
     * range inside (y_c - rho, y_c + rho). With y_c = z_top = 0, z() is the
     * expression of RailChart::top() (mesh/rail_chart.h) and is compiled inline
     * as it is, so that both give the same bits in the same translation unit.
     */
    class CircularProfile : public ProfileCurve
    {
    public:
      /** Radius rho [m] > 0, top (y_c, z_top) [m], range [y_min, y_max] [m]. */
      CircularProfile(const double radius,
                      const double y_c,
                      const double z_top,
                      const double y_min,
                      const double y_max);

      double
      z(const double y) const override
      {
        check_range(y);
        const double u = y - y_c;
        return z_top + (std::sqrt(radius * radius - u * u) - radius);
      }

      double
      slope(const double y) const override;
      double
      curvature_z(const double y) const override;
      double
      y_min() const override;
      double
      y_max() const override;
      std::string
      description() const override;

    private:
      const double radius, y_c, z_top, lower, upper;
    };

    /**
     * How a profile file is read and placed. The transformations apply in this
     * order to the file's points (mm -> m first): z_down, mirror, rotation,
     * shift. The window [y_from, y_to] is in the coordinates after all of them.
     */
    struct ProfileReadOptions
    {
      /** The parameter entry that named the file, for the messages. */
      std::string parameter;
      /** The file's name in the messages and the description, as the user
       *  gave it (the path read where empty). */
      std::string name;
      /** RMS deviation [m] of the smoothing spline from the points; 0: interpolation. */
      double smoothing_tolerance = 0;
      /** The window [m] that is modelled; NaN: unbounded on that side. */
      double y_from = std::numeric_limits<double>::quiet_NaN();
      /** See y_from. */
      double y_to = std::numeric_limits<double>::quiet_NaN();
      /** Largest distance [m] of consecutive points in the window; 0: no check. */
      double max_spacing = 0;
      /** The file's z is positive downwards (CONTACT's profiles): z -> -z. */
      bool z_down = false;
      /** y -> -y. */
      bool mirror = false;
      /**
       * Rotation [rad] about the file's (0, 0), counter-clockwise in the y-z
       * plane (y to the right, z up): y' = y cos - z sin, z' = y sin + z cos.
       */
      double rotation = 0;
      /** Shift [m] in y, applied last. */
      double shift_y = 0;
      /** Shift [m] in z, applied last. */
      double shift_z = 0;
    };

    namespace internal
    {
      /** A profile point [m] and where it came from (file line, or point number). */
      struct ProfilePoint
      {
        double       y, z;
        unsigned int line;
      };

      /**
       * Throws std::runtime_error "SOURCE:LINE: WHAT (the file given by
       * PARAMETER)";
       * without ":LINE" where line is 0, without the parenthesis where
       * parameter is empty.
       */
      [[noreturn]] void
      throw_profile_error(const std::string &source,
                          const unsigned int line,
                          const std::string &what,
                          const std::string &parameter);

      /** y [m] as mm with 4 decimals, for the messages. */
      std::string
      mm(const double length);
    } // namespace internal

    /**
     * A cubic spline through (or, smoothing, near) the points of a profile
     * inside its window: natural end conditions (s'' = 0 at the first and the
     * last knot), knots at the window's points and at up to 10 points beyond
     * each end of the window where y goes on increasing (at least one where
     * the end is not a point), so that the spline covers [y_min(), y_max()] =
     * the window (the file's range where the window is unbounded) and the error
     * of the end conditions, which falls by 0.27 a knot, stays mostly outside. The smoothing spline
     * (Reinsch 1967) minimises sum (z_i - s(y_i))^2 + alpha int s''^2 dy, with alpha found by
     * bisection on log alpha so that the RMS deviation equals the tolerance.
     */
    class SplineProfile : public ProfileCurve
    {
    public:
      /**
       * Reads a file of points y z [mm] (profile_read.cc: the format and what
       * is refused); throws std::runtime_error naming the file, the line, what
       * is wrong and options.parameter.
       */
      static std::shared_ptr<SplineProfile>
      read(const std::string &filename, const ProfileReadOptions &options);

      /**
       * The same from points (y, z) [m] in the order of a file; `source` names
       * them in the messages, where the "line" is the point's number from 1.
       * The transformations of `options` are applied to the points.
       */
      static std::shared_ptr<SplineProfile>
      from_points(std::vector<std::array<double, 2>> points_m,
                  const ProfileReadOptions          &options,
                  std::string                        source);

      /**
       * Applies the transformations of `options` to the points [m] as in the
       * file, checks them (profile_checks.cc: count, duplicates,
       * self-intersection, window, single-valuedness, spacing) and fits the
       * spline; `source` names the points in the messages.
       */
      static std::shared_ptr<SplineProfile>
      build(std::vector<internal::ProfilePoint> points,
            const ProfileReadOptions           &options,
            const std::string                  &source);

      double
      z(const double y) const override;
      double
      slope(const double y) const override;
      double
      curvature_z(const double y) const override;
      double
      y_min() const override;
      double
      y_max() const override;
      std::string
      description() const override;

      /** Largest |z_i - s(y_i)| [m] over the knots (0 when interpolating). */
      double
      max_deviation() const;

      /** RMS of z_i - s(y_i) [m] over the knots (0 when interpolating). */
      double
      rms_deviation() const;

      /** The smoothing parameter alpha [m^3] (0: interpolation). */
      double
      smoothing_parameter() const;

      /** Number of knots. */
      unsigned int
      n_knots() const;

    private:
      SplineProfile() = default;

      /** Index i of the knot interval [y_i, y_{i+1}] holding y. */
      unsigned int
      interval(const double y) const;

      std::vector<double> knots, values, second_derivatives;
      double              lower = 0, upper = 0;
      double              max_dev = 0, rms_dev = 0, alpha = 0;
      std::string         source;
    };
  } // namespace Geometry
} // namespace WheelRail

#endif
