/**
 * @file mesh/rail_chart.h
 * The manifold of the rail head: the box chart mapped onto the profile of
 * the rail top (used by the coarse mesh and the refinement).
 */
#ifndef wheelrail_mesh_rail_chart_h
#define wheelrail_mesh_rail_chart_h

#include <deal.II/base/point.h>

#include <deal.II/grid/manifold.h>

#include <wheelrail/geometry/profile.h>
#include <wheelrail/parameters/parameters.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <utility>

namespace WheelRail
{
  namespace Geometry
  {
    namespace internal
    {
      /**
       * The rail head as a chart: the box (x, y, zeta), zeta in [-H, 0],
       * is mapped to z = -H + (zeta + H)/H (z_top(y) + H), so that zeta = 0
       * is the top z_top(y) of the rail's profile (the circular crown
       * sqrt(rho^2 - y^2) - rho of the paper, or a profile read from a file)
       * and the bottom stays flat. Refinement thus stays on the true
       * profile.
       */
      class RailChart : public ChartManifold<dim>
      {
      public:
        RailChart(const double height, std::shared_ptr<const ProfileCurve> profile)
          : height(height)
          , profile(std::move(profile))
        {}

        /** The top at @p y (at the nearer end of the profile's range
         *  outside it, where rounding puts a side face's points). */
        double
        top(const double y) const
        {
          return profile->z(std::min(std::max(y, profile->y_min()), profile->y_max()));
        }

        Point<dim>
        pull_back(const Point<dim> &p) const override
        {
          return Point<dim>(p[0], p[1], -height + (p[2] + height) * height / (top(p[1]) + height));
        }

        Point<dim>
        push_forward(const Point<dim> &q) const override
        {
          return Point<dim>(q[0], q[1], -height + (q[2] + height) / height * (top(q[1]) + height));
        }

        std::unique_ptr<Manifold<dim>>
        clone() const override
        {
          return std::make_unique<RailChart>(height, profile);
        }

      private:
        const double                              height;
        const std::shared_ptr<const ProfileCurve> profile;
      };
    } // namespace internal
  }   // namespace Geometry
} // namespace WheelRail

#endif
