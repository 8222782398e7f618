/**
 * @file geometry/profile_checks.cc
 * SplineProfile::build(): the placement of a profile's points (z_down, mirror,
 * rotation, shift), what is refused (too few points, duplicates, a polyline
 * crossing itself, a window the points do not cover or in which they are not
 * single-valued in y, points too far apart) and the fit of the spline.
 */
#include <wheelrail/geometry/profile.h>
#include <wheelrail/geometry/smoothing_spline.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace WheelRail
{
  namespace Geometry
  {
    namespace
    {
      using internal::mm;
      using internal::ProfilePoint;
      using Points = std::vector<ProfilePoint>;

      /** The least number of points in the window. */
      constexpr unsigned int min_points = 10;

      /**
       * Knots beyond each end of a window where the points go on: the error
       * of the natural end conditions (s'' = 0) falls by a factor 0.27 a knot
       * (to 2e-6 of itself in 10), so that it stays mostly outside the window.
       */
      constexpr std::size_t extra_knots = 10;

      /** Where the points come from, for the messages. */
      struct Context
      {
        const std::string        &source;
        const ProfileReadOptions &options;

        [[noreturn]] void
        fail(const unsigned int line, const std::string &what) const
        {
          internal::throw_profile_error(source, line, what, options.parameter);
        }
      };

      /** z_down, mirror, rotation about (0, 0), shift: in this order. */
      void
      transform(Points &points, const ProfileReadOptions &o)
      {
        const double c = std::cos(o.rotation), s = std::sin(o.rotation);
        for (auto &p : points)
          {
            const double y = o.mirror ? -p.y : p.y, z = o.z_down ? -p.z : p.z;
            p.y = c * y - s * z + o.shift_y;
            p.z = s * y + c * z + o.shift_z;
          }
      }

      /** (b - a) x (c - a), the orientation of the triangle a b c: exactly 0
       *  for a point repeated or collinear in exact arithmetic of the
       *  differences (this file is compiled without fused multiply-adds,
       *  CMakeLists.txt: a fused a*b - c*d is not 0 for a*b == c*d). */
      double
      orientation(const ProfilePoint &a, const ProfilePoint &b, const ProfilePoint &c)
      {
        return (b.y - a.y) * (c.z - a.z) - (b.z - a.z) * (c.y - a.y);
      }

      /** Whether c, collinear with a b, lies on the segment a b. */
      bool
      on_segment(const ProfilePoint &a, const ProfilePoint &b, const ProfilePoint &c)
      {
        return std::min(a.y, b.y) <= c.y && c.y <= std::max(a.y, b.y) &&
               std::min(a.z, b.z) <= c.z && c.z <= std::max(a.z, b.z);
      }

      /** Whether the segments p q and r s have a point in common. */
      bool
      segments_meet(const ProfilePoint &p,
                    const ProfilePoint &q,
                    const ProfilePoint &r,
                    const ProfilePoint &s)
      {
        const double o1 = orientation(p, q, r), o2 = orientation(p, q, s),
                     o3 = orientation(r, s, p), o4 = orientation(r, s, q);
        if (((o1 > 0 && o2 < 0) || (o1 < 0 && o2 > 0)) &&
            ((o3 > 0 && o4 < 0) || (o3 < 0 && o4 > 0)))
          return true;
        return (o1 == 0 && on_segment(p, q, r)) || (o2 == 0 && on_segment(p, q, s)) ||
               (o3 == 0 && on_segment(r, s, p)) || (o4 == 0 && on_segment(r, s, q));
      }

      /** Refuses consecutive points closer than 1 nm. */
      void
      check_duplicates(const Points &points, const Context &c)
      {
        for (std::size_t i = 1; i < points.size(); ++i)
          if (std::hypot(points[i].y - points[i - 1].y, points[i].z - points[i - 1].z) < 1e-9)
            c.fail(points[i].line,
                   "the point (" + mm(points[i].y) + ", " + mm(points[i].z) +
                     ") repeats the point of line " + std::to_string(points[i - 1].line) +
                     ": remove one of them");
      }

      /**
       * Refuses a polyline that crosses or touches itself: two segments that are
       * not neighbours meet, or two neighbours fold back onto each other.
       */
      void
      check_self_intersection(const Points &p, const Context &c)
      {
        const std::size_t n = p.size();
        // folds first: a fold also touches the segment before, and which of
        // the two were named first would depend on the last bit of the
        // orientation
        for (std::size_t i = 0; i + 2 < n; ++i)
          if (orientation(p[i], p[i + 1], p[i + 2]) == 0 &&
              (p[i + 1].y - p[i].y) * (p[i + 2].y - p[i + 1].y) +
                  (p[i + 1].z - p[i].z) * (p[i + 2].z - p[i + 1].z) <
                0)
            c.fail(p[i + 2].line,
                   "the profile folds back onto itself along the segment of lines " +
                     std::to_string(p[i].line) + "-" + std::to_string(p[i + 1].line));
        for (std::size_t i = 0; i + 1 < n; ++i)
          {
            const double y0 = std::min(p[i].y, p[i + 1].y), y1 = std::max(p[i].y, p[i + 1].y);
            for (std::size_t j = i + 2; j + 1 < n; ++j)
              if (std::max(p[j].y, p[j + 1].y) >= y0 && std::min(p[j].y, p[j + 1].y) <= y1 &&
                  segments_meet(p[i], p[i + 1], p[j], p[j + 1]))
                c.fail(p[i].line,
                       "the profile crosses itself: the segment of lines " +
                         std::to_string(p[i].line) + "-" + std::to_string(p[i + 1].line) +
                         " meets the segment of lines " + std::to_string(p[j].line) + "-" +
                         std::to_string(p[j + 1].line));
          }
      }

      /** The window [m] of the options, as text for the messages. */
      std::string
      window_text(const double lower, const double upper)
      {
        if (!std::isfinite(lower) && !std::isfinite(upper))
          return "the whole file (no window)";
        return "the window [" + (std::isfinite(lower) ? mm(lower) : std::string("-inf")) + ", " +
               (std::isfinite(upper) ? mm(upper) : std::string("inf")) + "]";
      }

      /** The first and last index of the points inside [lower, upper]. */
      std::pair<std::size_t, std::size_t>
      window_indices(const Points &p, const double lower, const double upper, const Context &c)
      {
        std::size_t first = p.size(), last = 0;
        for (std::size_t i = 0; i < p.size(); ++i)
          if (p[i].y >= lower && p[i].y <= upper)
            {
              first = std::min(first, i);
              last  = i;
            }
        if (first == p.size())
          c.fail(
            0,
            "no point lies in " + window_text(lower, upper) + " (the points' y runs from " +
              mm(std::min_element(p.begin(), p.end(), [](auto &a, auto &b) { return a.y < b.y; })
                   ->y) +
              " to " +
              mm(std::max_element(p.begin(), p.end(), [](auto &a, auto &b) { return a.y < b.y; })
                   ->y) +
              ")");
        return {first, last};
      }

      /** Refuses y not strictly increasing from point i0 to point i1. */
      void
      check_single_valued(const Points      &p,
                          const std::size_t  i0,
                          const std::size_t  i1,
                          const std::string &window,
                          const Context     &c)
      {
        for (std::size_t i = i0 + 1; i <= i1; ++i)
          if (!(p[i].y > p[i - 1].y))
            c.fail(p[i].line,
                   "the profile turns back in y (y = " + mm(p[i].y) + " after " + mm(p[i - 1].y) +
                     " on line " + std::to_string(p[i - 1].line) +
                     "): it must be single-valued in y in " + window +
                     "; narrow the window or correct the file");
      }

      /**
       * Orients the points to increasing y in the window and returns the range
       * of the knots: the window's points and up to extra_knots beyond each end
       * of the window (at least one where the end is not a point).
       */
      std::pair<std::size_t, std::size_t>
      knot_range(Points &p, const double lower, const double upper, const Context &c)
      {
        const std::string window = window_text(lower, upper);
        auto [first, last]       = window_indices(p, lower, upper, c);
        if (p[last].y < p[first].y)
          {
            std::reverse(p.begin(), p.end());
            const std::size_t n = p.size() - 1, old_first = first;
            first = n - last;
            last  = n - old_first;
          }
        check_single_valued(p, first, last, window, c);
        if (last - first + 1 < min_points)
          c.fail(0,
                 std::to_string(last - first + 1) + " points in " + window + ": at least " +
                   std::to_string(min_points) + " are needed");
        std::size_t begin = first, end = last;
        if (std::isfinite(lower) && p[first].y > lower && first == 0)
          c.fail(p[first].line,
                 "the points start at y = " + mm(p[first].y) + ", inside " + window +
                   ": the file does not cover the window");
        if (std::isfinite(upper) && p[last].y < upper && last + 1 == p.size())
          c.fail(p[last].line,
                 "the points end at y = " + mm(p[last].y) + ", inside " + window +
                   ": the file does not cover the window");
        // the window's ends must be covered by a point of the same monotonic run
        if (std::isfinite(lower) && p[first].y > lower)
          check_single_valued(p, first - 1, first, window, c);
        if (std::isfinite(upper) && p[last].y < upper)
          check_single_valued(p, last, last + 1, window, c);
        // up to extra_knots more where y goes on increasing: the natural end
        // conditions' error decays by 0.27 a knot, outside the window
        while (begin > 0 && first - begin < extra_knots && p[begin - 1].y < p[begin].y)
          --begin;
        while (end + 1 < p.size() && end - last < extra_knots && p[end + 1].y > p[end].y)
          ++end;
        return {begin, end};
      }

      /**
       * Refuses consecutive knots farther apart than options.max_spacing where
       * their interval overlaps the window [lower, upper] [m].
       */
      void
      check_spacing(const Points     &p,
                    const std::size_t begin,
                    const std::size_t end,
                    const double      lower,
                    const double      upper,
                    const Context    &c)
      {
        const double limit = c.options.max_spacing;
        if (!(limit > 0))
          return;
        for (std::size_t i = begin + 1; i <= end; ++i)
          {
            const double distance = std::hypot(p[i].y - p[i - 1].y, p[i].z - p[i - 1].z);
            if (distance > limit && p[i].y > lower && p[i - 1].y < upper)
              c.fail(p[i].line,
                     "the points of lines " + std::to_string(p[i - 1].line) + "-" +
                       std::to_string(p[i].line) + " are " + mm(distance) +
                       " apart, more than the largest spacing " + mm(limit) +
                       ": the profile is too coarse for the requested cell size");
          }
      }

      /** Refuses options out of their ranges. */
      void
      check_options(const ProfileReadOptions &o, const Context &c)
      {
        if (!(o.smoothing_tolerance >= 0 && std::isfinite(o.smoothing_tolerance)))
          c.fail(0, "the smoothing tolerance must be finite and >= 0");
        if (!(o.max_spacing >= 0 && std::isfinite(o.max_spacing)))
          c.fail(0, "the largest spacing must be finite and >= 0");
        if (!std::isfinite(o.rotation) || !std::isfinite(o.shift_y) || !std::isfinite(o.shift_z))
          c.fail(0, "the rotation and the shifts must be finite");
        if (std::isfinite(o.y_from) && std::isfinite(o.y_to) && !(o.y_from < o.y_to))
          c.fail(0, window_text(o.y_from, o.y_to) + " is empty: y_from must be below y_to");
        if (std::isinf(o.y_from) || std::isinf(o.y_to))
          c.fail(0, "the window's ends must be finite, or NaN for the whole file");
      }
    } // namespace



    std::shared_ptr<SplineProfile>
    SplineProfile::build(std::vector<internal::ProfilePoint> points,
                         const ProfileReadOptions           &options,
                         const std::string                  &source)
    {
      const Context c{source, options};
      check_options(options, c);
      if (points.size() < min_points)
        c.fail(0,
               "has " + std::to_string(points.size()) + " points: at least " +
                 std::to_string(min_points) + " are needed");
      transform(points, options);
      check_duplicates(points, c);
      check_self_intersection(points, c);

      const double inf        = std::numeric_limits<double>::infinity();
      const double lower      = std::isnan(options.y_from) ? -inf : options.y_from;
      const double upper      = std::isnan(options.y_to) ? inf : options.y_to;
      const auto [begin, end] = knot_range(points, lower, upper, c);
      check_spacing(points, begin, end, lower, upper, c);

      std::vector<double> y, z;
      for (std::size_t i = begin; i <= end; ++i)
        {
          y.push_back(points[i].y);
          z.push_back(points[i].z);
        }
      const SplineFit fit = fit_smoothing_spline_to_tolerance(y, z, options.smoothing_tolerance);

      std::shared_ptr<SplineProfile> profile(new SplineProfile());
      profile->knots              = std::move(y);
      profile->values             = fit.values;
      profile->second_derivatives = fit.second_derivatives;
      profile->lower              = std::isfinite(lower) ? lower : profile->knots.front();
      profile->upper              = std::isfinite(upper) ? upper : profile->knots.back();
      profile->max_dev            = fit.max_deviation;
      profile->rms_dev            = fit.rms_deviation;
      profile->alpha              = fit.alpha;
      profile->source             = source;
      return profile;
    }
  } // namespace Geometry
} // namespace WheelRail
