/**
 * @file geometry/profile_contact.cc
 * The rigid contact search of two profiles (profile_contact.h): the sampled
 * vertical distance, its local minima, their refinement and their geometry.
 */
#include <wheelrail/geometry/profile_contact.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace WheelRail
{
  namespace Geometry
  {
    namespace
    {
      /** Sampling step [m] of the distance function. */
      constexpr double sample_step = 1e-5;
      /** Accuracy [m] of a refined minimum. */
      constexpr double accuracy = 1e-9;

      /** The wheel and the rail, and d(y) = z_w(y) - z_r(y) [m] and d' [-]. */
      struct ProfilePair
      {
        const ProfileCurve &wheel, &rail;

        double
        d(const double y) const
        {
          return wheel.z(y) - rail.z(y);
        }

        double
        d_slope(const double y) const
        {
          return wheel.slope(y) - rail.slope(y);
        }
      };

      /**
       * The minimum of d in [a, b] [m]: bisection on d' where d' goes from
       * negative to positive (to 1e-12 m, below the required 1e-9 m), golden
       * section on d otherwise (to 1e-9 m).
       */
      double
      refine(const ProfilePair &pair, double a, double b)
      {
        if (pair.d_slope(a) < 0 && pair.d_slope(b) > 0)
          {
            while (b - a > 1e-12)
              {
                const double m                = 0.5 * (a + b);
                (pair.d_slope(m) < 0 ? a : b) = m;
              }
            return 0.5 * (a + b);
          }
        const double ratio = 0.5 * (std::sqrt(5.) - 1);
        double       c = b - ratio * (b - a), e = a + ratio * (b - a);
        double       dc = pair.d(c), de = pair.d(e);
        while (b - a > accuracy)
          if (dc < de)
            {
              b  = e;
              e  = c;
              de = dc;
              c  = b - ratio * (b - a);
              dc = pair.d(c);
            }
          else
            {
              a  = c;
              c  = e;
              dc = de;
              e  = a + ratio * (b - a);
              de = pair.d(e);
            }
        return 0.5 * (a + b);
      }

      /**
       * The separation t [m] along the rail's normal n = (-sin delta, cos delta)
       * from (y, z_r) to the wheel lifted by dz: Newton on
       * f(t) = z_w(y - t sin delta) + dz - z_r - t cos delta, from t = d cos delta
       * (returned as it is where the normal leaves the wheel's range).
       */
      double
      normal_separation(const ProfileCurve &wheel,
                        const double        y,
                        const double        z_rail,
                        const double        delta,
                        const double        lift,
                        const double        d)
      {
        const double s = std::sin(delta), c = std::cos(delta);
        double       t = d * c;
        for (unsigned int i = 0; i < 50; ++i)
          {
            const double y_w = y - t * s;
            if (y_w < wheel.y_min() || y_w > wheel.y_max())
              return d * c;
            const double f    = wheel.z(y_w) + lift - z_rail - t * c;
            const double step = f / (-s * wheel.slope(y_w) - c);
            t -= step;
            if (std::abs(step) < 1e-15)
              break;
          }
        return t;
      }

      /** The positions [m] of the local minima of d sampled on [lo, hi], refined. */
      std::vector<std::pair<double, bool>>
      local_minima(const ProfilePair &pair, const double lo, const double hi)
      {
        const unsigned int  n    = static_cast<unsigned int>(std::ceil((hi - lo) / sample_step));
        const double        step = (hi - lo) / n;
        std::vector<double> d(n + 1);
        auto y_of = [&](const unsigned int i) { return i == n ? hi : lo + i * step; };
        for (unsigned int i = 0; i <= n; ++i)
          d[i] = pair.d(y_of(i));
        std::vector<std::pair<double, bool>> minima;
        for (unsigned int i = 0; i <= n; ++i)
          {
            const double left  = i == 0 ? std::numeric_limits<double>::infinity() : d[i - 1];
            const double right = i == n ? std::numeric_limits<double>::infinity() : d[i + 1];
            if (!(d[i] <= left && d[i] < right))
              continue;
            if (i == 0 || i == n)
              minima.emplace_back(y_of(i), true);
            else
              {
                const double y = refine(pair, y_of(i - 1), y_of(i + 1));
                if (minima.empty() || std::abs(y - minima.back().first) > 1e-7)
                  minima.emplace_back(y, false);
              }
          }
        return minima;
      }
    } // namespace



    std::vector<ProfileContactPoint>
    rigid_contact(const ProfileCurve &wheel,
                  const ProfileCurve &rail,
                  const double        nominal_radius,
                  const double        separation_tolerance)
    {
      const double lo = std::max(wheel.y_min(), rail.y_min());
      const double hi = std::min(wheel.y_max(), rail.y_max());
      if (!(lo < hi))
        throw std::invalid_argument("rigid_contact: the wheel (" + wheel.description() +
                                    ") and the rail (" + rail.description() +
                                    ") have no lateral range in common");
      const ProfilePair pair{wheel, rail};
      const auto        minima = local_minima(pair, lo, hi);
      double            d_min  = std::numeric_limits<double>::infinity();
      for (const auto &m : minima)
        d_min = std::min(d_min, pair.d(m.first));

      std::vector<ProfileContactPoint> points;
      for (const auto &[y, at_end] : minima)
        {
          ProfileContactPoint p;
          p.y          = y;
          p.lift       = -d_min;
          p.separation = pair.d(y) - d_min;
          if (p.separation > separation_tolerance)
            continue;
          p.at_range_end      = at_end;
          p.z                 = rail.z(y);
          const double slope  = rail.slope(y);
          p.contact_angle     = std::atan(slope);
          p.rolling_radius    = nominal_radius - wheel.z(y);
          const double cos3_r = std::pow(1 + slope * slope, -1.5);
          const double w      = wheel.slope(y);
          p.rail_curvature    = rail.curvature_z(y) * cos3_r;
          p.wheel_curvature   = wheel.curvature_z(y) * std::pow(1 + w * w, -1.5);
          const double cos_d  = std::cos(p.contact_angle);
          p.A                 = cos_d / (2 * p.rolling_radius);
          p.B = 0.5 * (wheel.curvature_z(y) - rail.curvature_z(y)) * cos_d * cos_d * cos_d;
          p.normal_separation =
            normal_separation(wheel, y, p.z, p.contact_angle, p.lift, p.separation);
          points.push_back(p);
        }
      std::stable_sort(points.begin(), points.end(), [](const auto &a, const auto &b) {
        return a.separation < b.separation;
      });
      return points;
    }
  } // namespace Geometry
} // namespace WheelRail
