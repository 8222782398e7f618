/**
 * @file geometry/profile.cc
 * The analytic profiles, the evaluation of the spline profile and the
 * messages of the profile reader.
 */
#include <wheelrail/geometry/profile.h>

#include <algorithm>
#include <cstdio>
#include <stdexcept>

namespace WheelRail
{
  namespace Geometry
  {
    namespace internal
    {
      void
      throw_profile_error(const std::string &source,
                          const unsigned int line,
                          const std::string &what,
                          const std::string &parameter)
      {
        std::string message = source;
        if (line > 0)
          message += ":" + std::to_string(line);
        message += ": " + what;
        if (!parameter.empty())
          message += " (the file given by " + parameter + ")";
        throw std::runtime_error(message);
      }



      std::string
      mm(const double length)
      {
        char text[64];
        std::snprintf(text, sizeof(text), "%.4f mm", length * 1e3);
        return text;
      }
    } // namespace internal



    void
    ProfileCurve::check_range(const double y) const
    {
      if (!(y >= y_min() && y <= y_max()))
        throw std::out_of_range("profile evaluated at y = " + internal::mm(y) + " outside [" +
                                internal::mm(y_min()) + ", " + internal::mm(y_max()) +
                                "]: " + description());
    }



    FlatProfile::FlatProfile(const double y_min, const double y_max)
      : lower(y_min)
      , upper(y_max)
    {
      if (!(y_min < y_max))
        throw std::invalid_argument("FlatProfile: needs y_min < y_max");
    }

    double
    FlatProfile::z(const double y) const
    {
      check_range(y);
      return 0;
    }

    double
    FlatProfile::slope(const double y) const
    {
      check_range(y);
      return 0;
    }

    double
    FlatProfile::curvature_z(const double y) const
    {
      check_range(y);
      return 0;
    }

    double
    FlatProfile::y_min() const
    {
      return lower;
    }

    double
    FlatProfile::y_max() const
    {
      return upper;
    }

    std::string
    FlatProfile::description() const
    {
      return "flat, y from " + internal::mm(lower) + " to " + internal::mm(upper);
    }



    CircularProfile::CircularProfile(const double radius,
                                     const double y_c,
                                     const double z_top,
                                     const double y_min,
                                     const double y_max)
      : radius(radius)
      , y_c(y_c)
      , z_top(z_top)
      , lower(y_min)
      , upper(y_max)
    {
      if (!(radius > 0 && y_min < y_max && y_min > y_c - radius && y_max < y_c + radius))
        throw std::invalid_argument("CircularProfile: needs radius > 0 and "
                                    "y_c - radius < y_min < y_max < y_c + radius");
    }

    double
    CircularProfile::slope(const double y) const
    {
      check_range(y);
      const double u = y - y_c;
      return -u / std::sqrt(radius * radius - u * u);
    }

    double
    CircularProfile::curvature_z(const double y) const
    {
      check_range(y);
      const double u = y - y_c, w = radius * radius - u * u;
      return -radius * radius / (w * std::sqrt(w));
    }

    double
    CircularProfile::y_min() const
    {
      return lower;
    }

    double
    CircularProfile::y_max() const
    {
      return upper;
    }

    std::string
    CircularProfile::description() const
    {
      return "circular arc of radius " + internal::mm(radius) +
             ", top at y = " + internal::mm(y_c) + ", z = " + internal::mm(z_top) + ", y from " +
             internal::mm(lower) + " to " + internal::mm(upper);
    }



    std::shared_ptr<SplineProfile>
    SplineProfile::from_points(std::vector<std::array<double, 2>> points_m,
                               const ProfileReadOptions          &options,
                               std::string                        source)
    {
      std::vector<internal::ProfilePoint> points;
      points.reserve(points_m.size());
      for (const auto &p : points_m)
        points.push_back({p[0], p[1], static_cast<unsigned int>(points.size() + 1)});
      return build(std::move(points), options, source);
    }



    unsigned int
    SplineProfile::interval(const double y) const
    {
      check_range(y);
      // the last knot y_i <= y, at most the second last knot
      const auto it = std::upper_bound(knots.begin() + 1, knots.end() - 1, y);
      return static_cast<unsigned int>(it - knots.begin()) - 1;
    }

    // On [y_i, y_i+1], t = y - y_i, h = y_i+1 - y_i, the cubic
    // s = a + b t + c t^2 + d t^3 with a = s_i, c = s''_i / 2,
    // d = (s''_i+1 - s''_i) / (6 h), b = (s_i+1 - s_i) / h - h (2 s''_i + s''_i+1) / 6.

    double
    SplineProfile::z(const double y) const
    {
      const unsigned int i = interval(y);
      const double       h = knots[i + 1] - knots[i], t = y - knots[i];
      const double       g0 = second_derivatives[i], g1 = second_derivatives[i + 1];
      const double       b = (values[i + 1] - values[i]) / h - h * (2 * g0 + g1) / 6;
      return values[i] + t * (b + t * (g0 / 2 + t * (g1 - g0) / (6 * h)));
    }

    double
    SplineProfile::slope(const double y) const
    {
      const unsigned int i = interval(y);
      const double       h = knots[i + 1] - knots[i], t = y - knots[i];
      const double       g0 = second_derivatives[i], g1 = second_derivatives[i + 1];
      const double       b = (values[i + 1] - values[i]) / h - h * (2 * g0 + g1) / 6;
      return b + t * (g0 + t * (g1 - g0) / (2 * h));
    }

    double
    SplineProfile::curvature_z(const double y) const
    {
      const unsigned int i = interval(y);
      const double       h = knots[i + 1] - knots[i], t = y - knots[i];
      return second_derivatives[i] + t * (second_derivatives[i + 1] - second_derivatives[i]) / h;
    }

    double
    SplineProfile::y_min() const
    {
      return lower;
    }

    double
    SplineProfile::y_max() const
    {
      return upper;
    }

    std::string
    SplineProfile::description() const
    {
      return "spline through " + std::to_string(knots.size()) + " points of " + source +
             ", y from " + internal::mm(lower) + " to " + internal::mm(upper) +
             (alpha > 0 ? ", smoothed to an RMS deviation of " + internal::mm(rms_dev) : "");
    }

    double
    SplineProfile::max_deviation() const
    {
      return max_dev;
    }

    double
    SplineProfile::rms_deviation() const
    {
      return rms_dev;
    }

    double
    SplineProfile::smoothing_parameter() const
    {
      return alpha;
    }

    unsigned int
    SplineProfile::n_knots() const
    {
      return static_cast<unsigned int>(knots.size());
    }
  } // namespace Geometry
} // namespace WheelRail
