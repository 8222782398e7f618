/**
 * @file mesh/wheel_chart.h
 * The manifold of a wheel with a profiled tread: a profile revolved about
 * the axle (used by the coarse mesh and the refinement).
 */
#ifndef wheelrail_mesh_wheel_chart_h
#define wheelrail_mesh_wheel_chart_h

#include <deal.II/base/point.h>

#include <deal.II/grid/manifold.h>

#include <wheelrail/geometry/profile.h>
#include <wheelrail/parameters/parameters.h>

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
       * The wheel as a chart: (theta, y, rho'), theta the angle about the
       * axle from the lowest point towards +x, y along the axle and rho'
       * the radius of the wheel built as a cylinder of radius r_O (the
       * rolling radius at O) with a bore of radius r_b. The chart's
       * push-forward scales the radius between bore and tread,
       * rho = r_b + (rho' - r_b) (r(y) - r_b) / (r_O - r_b), so that the
       * cylinder's tread rho' = r_O becomes the revolved profile
       * r(y) = r_O - z_w(y) exactly, at every refinement, and the bore stays
       * a cylinder. Periodic in theta.
       */
      class RevolvedProfileChart : public ChartManifold<dim>
      {
      public:
        RevolvedProfileChart(const Point<dim>                   &centre,
                             const double                        rolling_radius,
                             const double                        bore_radius,
                             std::shared_ptr<const ProfileCurve> profile)
          : ChartManifold<dim>(Tensor<1, dim>({2 * M_PI, 0., 0.}))
          , centre(centre)
          , r_O(rolling_radius)
          , r_b(bore_radius)
          , profile(std::move(profile))
        {}

        /** The radius of the tread at @p y. */
        double
        tread_radius(const double y) const
        {
          return r_O - profile->z(y);
        }

        Point<dim>
        pull_back(const Point<dim> &p) const override
        {
          const double dx = p[0] - centre[0], dz = p[2] - centre[2];
          const double rho = std::sqrt(dx * dx + dz * dz);
          const double rho_c =
            r_b + (rho - r_b) * (r_O - r_b) / (tread_radius(clamped(p[1])) - r_b);
          return Point<dim>(std::atan2(dx, -dz), p[1], rho_c);
        }

        Point<dim>
        push_forward(const Point<dim> &q) const override
        {
          const double rho = r_b + (q[2] - r_b) * (tread_radius(clamped(q[1])) - r_b) / (r_O - r_b);
          return Point<dim>(centre[0] + rho * std::sin(q[0]),
                            q[1],
                            centre[2] - rho * std::cos(q[0]));
        }

        std::unique_ptr<Manifold<dim>>
        clone() const override
        {
          return std::make_unique<RevolvedProfileChart>(centre, r_O, r_b, profile);
        }

      private:
        const Point<dim>                          centre;
        const double                              r_O;
        const double                              r_b;
        const std::shared_ptr<const ProfileCurve> profile;

        /** @p y within the profile's range (a side face's points lie on
         *  its ends up to rounding). */
        double
        clamped(const double y) const
        {
          return std::min(std::max(y, profile->y_min()), profile->y_max());
        }
      };
    } // namespace internal
  }   // namespace Geometry
} // namespace WheelRail

#endif
