/**
 * @file geometry/wheel_and_rail.cc
 * The geometry "wheel and rail" (SPEC 1 and 10): the wheel, revolved about
 * the axle with a bore, on the rail head, extruded along x, refined towards
 * the solution zone, the further contact points and the rolling path. The
 * shapes are the paper's (a cylinder on the circular crown of
 * Geometry/Rail/Profile radius) or profiles read from files
 * (Geometry/Profiles, geometry/wheel_rail_shape.h). The coarse mesh, the
 * charts and the refinement are in source/mesh/.
 */

#include <deal.II/grid/manifold_lib.h>
#include <deal.II/grid/tria.h>

#include <wheelrail/geometry/interface.h>
#include <wheelrail/geometry/wheel_rail_shape.h>
#include <wheelrail/mesh/coarse_mesh.h>
#include <wheelrail/mesh/geometry.h>
#include <wheelrail/mesh/rail_chart.h>
#include <wheelrail/mesh/refinement.h>
#include <wheelrail/mesh/wheel_chart.h>
#include <wheelrail/simulator/format.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <utility>
#include <vector>

namespace WheelRail
{
  namespace Geometry
  {
    namespace
    {
      using Report::fmt;

      /** Relative tolerance of the classification of boundary faces. */
      constexpr double eps = 1e-6;

      /** The wheel and the rail head. */
      class WheelAndRail : public GeometryModel
      {
      public:
        WheelAndRail(const GeometryParameters &parameters, const ProfileParameters &profiles)
          : GeometryModel(parameters)
          , profiles(profiles)
          , shape(parameters, profiles)
        {}

        std::vector<Body>
        bodies() const override
        {
          return {{MaterialIds::wheel, "wheel"}, {MaterialIds::rail, "rail"}};
        }

        std::vector<Box>
        bounding_boxes() const override;

        double
        exact_volume(const types::material_id material) const override;

        CoarseCellEstimate
        coarse_cell_estimate() const override;

        void
        create_coarse_mesh(std::vector<Point<dim>>    &vertices,
                           std::vector<CellData<dim>> &cells) const override
        {
          internal::build_wheel_and_rail(p, shape, vertices, cells);
        }

        void
        set_boundary_ids(Triangulation<dim> &coarse) const override;

        void
        set_manifold_ids(Triangulation<dim> &coarse) const override;

        void
        attach_manifolds(parallel::distributed::Triangulation<dim> &triangulation) const override;

        void
        refine(parallel::distributed::Triangulation<dim> &triangulation) const override
        {
          internal::refine_wheel_and_rail(p, shape, triangulation);
        }

        std::optional<ZoneCells>
        zone_cells(const types::material_id                         material,
                   const parallel::distributed::Triangulation<dim> &triangulation) const override
        {
          return internal::zone_cells(p, shape, material, triangulation);
        }

        bool
        has_contact() const override
        {
          return true;
        }

        bool
        has_wheel() const override
        {
          return true;
        }

        Point<dim>
        wheel_centre() const override
        {
          return shape.wheel_centre();
        }

        double
        rolling_radius() const override
        {
          return shape.rolling_radius();
        }

        ContactRadii
        contact_radii() const override
        {
          const RigidContact &c = shape.contacts().front();
          return {c.rolling_radius, c.radius_across};
        }

        std::vector<RigidContact>
        rigid_contacts() const override
        {
          return shape.contacts();
        }

        bool
        has_profile_files() const override
        {
          return profiles.from_files();
        }

        std::pair<double, double>
        zone_span() const override
        {
          return shape.zone_span(p.zone_half_width);
        }

        std::string
        description() const override
        {
          return profiles.from_files() ? shape.description() : std::string();
        }

      private:
        const ProfileParameters profiles;
        const WheelRailShape    shape;

        /** Volume of a body with profiles from files, by quadrature [m^3]. */
        double
        profile_volume(const types::material_id material) const;

        /** Coarse cells of the wheel and of the rail head, as
         *  build_wheel_and_rail() divides them without alignment. */
        std::pair<double, double>
        coarse_cells() const;

        /** The boundary id of a wheel face with centre @p c. */
        types::boundary_id
        wheel_boundary_id(const Point<dim> &c) const;

        /** The boundary id of a rail face @p face, classified by its
         *  vertices in chart space: a curved face's centre lies below the
         *  arc. */
        types::boundary_id
        rail_boundary_id(const internal::RailChart               &chart,
                         const Triangulation<dim>::face_iterator &face) const;
      };



      std::vector<Box>
      WheelAndRail::bounding_boxes() const
      {
        std::vector<Box> boxes;
        double           top = 0; // the crown's top is O
        if (profiles.from_files())
          for (unsigned int i = 0; i <= 1000; ++i)
            top = std::max(top,
                           shape.rail_top(shape.rail_y_lo +
                                          i * (shape.rail_y_hi - shape.rail_y_lo) / 1000));
        boxes.push_back({Point<3>(p.rail_start_x, shape.rail_y_lo, -p.rail_head_height),
                         Point<3>(p.rail_end_x, shape.rail_y_hi, top)});
        const double zc = shape.wheel_centre()[2], R = shape.largest_wheel_radius();
        boxes.push_back({Point<3>(p.wheel_centre_x - R, shape.wheel_y_lo, zc - R),
                         Point<3>(p.wheel_centre_x + R, shape.wheel_y_hi, zc + R)});
        return boxes;
      }



      double
      WheelAndRail::exact_volume(const types::material_id material) const
      {
        if (profiles.from_files())
          return profile_volume(material);
        if (material == MaterialIds::wheel)
          return M_PI * (p.wheel_radius * p.wheel_radius - p.bore_radius * p.bore_radius) *
                 p.tread_width;
        const double a   = 0.5 * p.rail_head_width;
        const double rho = p.rail_profile_radius;
        // integral over y of (z_top(y) + H), z_top = sqrt(rho^2-y^2)-rho
        const double area = a * std::sqrt(rho * rho - a * a) + rho * rho * std::asin(a / rho) -
                            2 * a * rho + 2 * a * p.rail_head_height;
        return area * (p.rail_end_x - p.rail_start_x);
      }



      double
      WheelAndRail::profile_volume(const types::material_id material) const
      {
        // 3-point Gauss-Legendre on 4000 intervals: the profiles are cubic
        // splines with knots at least 1e-2 mm apart, integrated to ~1e-12
        const bool   wheel = material == MaterialIds::wheel;
        const double lo    = wheel ? shape.wheel_y_lo : shape.rail_y_lo;
        const double hi    = wheel ? shape.wheel_y_hi : shape.rail_y_hi;
        const auto   f     = [&](const double y) {
          if (wheel)
            {
              const double r = shape.wheel_radius(y);
              return M_PI * (r * r - p.bore_radius * p.bore_radius);
            }
          return (shape.rail_top(y) + p.rail_head_height) * (p.rail_end_x - p.rail_start_x);
        };
        const unsigned int n = 4000;
        const double       d = (hi - lo) / n, g = std::sqrt(0.6);
        double             sum = 0;
        for (unsigned int i = 0; i < n; ++i)
          {
            const double m = lo + (i + 0.5) * d;
            sum += (5 * f(m - 0.5 * d * g) + 8 * f(m) + 5 * f(m + 0.5 * d * g)) / 18 * d;
          }
        return sum;
      }



      std::pair<double, double>
      WheelAndRail::coarse_cells() const
      {
        const double coarse  = internal::effective_coarse_size(p);
        const double R       = shape.rolling_radius();
        double       n_theta = p.wheel_circumferential_cells;
        if (n_theta == 0)
          n_theta = 4 * std::ceil(2 * M_PI * R / (4 * 4 * coarse));
        n_theta              = std::max(n_theta, 8.);
        const double d_theta = 2 * M_PI / n_theta;
        const double n_radial =
          std::max(1., std::round(std::log(p.bore_radius / R) / std::log(1 - d_theta)));
        const double n_y =
          std::max(1., std::ceil((shape.wheel_y_hi - shape.wheel_y_lo) / (4 * coarse) - 1e-9));
        const double rail = std::ceil((p.rail_end_x - p.rail_start_x) / coarse - 1e-9) *
                            std::ceil((shape.rail_y_hi - shape.rail_y_lo) / coarse - 1e-9) *
                            std::ceil(p.rail_head_height / coarse - 1e-9);
        return {n_theta * n_y * n_radial, rail};
      }



      CoarseCellEstimate
      WheelAndRail::coarse_cell_estimate() const
      {
        const auto [wheel, rail] = coarse_cells();
        const double n           = wheel + rail;
        return {n,
                "Geometry/Mesh/Coarse cell size = " + fmt(p.coarse_cell_size) +
                  " m would divide the wheel and rail into about " + fmt(n, 2) +
                  " coarse cells (wheel " + fmt(wheel, 2) + ", rail " + fmt(rail, 2) +
                  ") before any refinement",
                "increase Geometry/Mesh/Coarse cell size (the local refinement "
                "reaches Minimum cell size where it is needed)."};
      }



      types::boundary_id
      WheelAndRail::wheel_boundary_id(const Point<dim> &c) const
      {
        const Point<dim> centre = shape.wheel_centre();
        const double     r      = std::hypot(c[0] - centre[0], c[2] - centre[2]);
        const double     width  = shape.wheel_y_hi - shape.wheel_y_lo;
        if (std::abs(c[1] - shape.wheel_y_lo) < eps * width ||
            std::abs(c[1] - shape.wheel_y_hi) < eps * width)
          return BoundaryIds::wheel_side;
        else if (r > 0.5 * (shape.rolling_radius() + p.bore_radius))
          return BoundaryIds::wheel_tread;
        else
          return BoundaryIds::wheel_bore;
      }



      types::boundary_id
      WheelAndRail::rail_boundary_id(const internal::RailChart               &chart,
                                     const Triangulation<dim>::face_iterator &face) const
      {
        const double H     = p.rail_head_height;
        const double width = shape.rail_y_hi - shape.rail_y_lo;
        bool         top = true, bottom = true, side = true;
        for (unsigned int v = 0; v < 4; ++v)
          {
            const Point<dim> q = chart.pull_back(face->vertex(v));
            top                = top && std::abs(q[2]) < eps * H;
            bottom             = bottom && std::abs(q[2] + H) < eps * H;
            side               = side && (std::abs(q[1] - shape.rail_y_lo) < eps * width ||
                            std::abs(q[1] - shape.rail_y_hi) < eps * width);
          }
        return top    ? BoundaryIds::rail_top :
               bottom ? BoundaryIds::rail_bottom :
               side   ? BoundaryIds::rail_side :
                        BoundaryIds::rail_end;
      }



      void
      WheelAndRail::set_boundary_ids(Triangulation<dim> &coarse) const
      {
        const internal::RailChart chart(p.rail_head_height, shape.rail_curve());
        for (const auto &cell : coarse.active_cell_iterators())
          for (const unsigned int f : cell->face_indices())
            if (cell->face(f)->at_boundary())
              cell->face(f)->set_boundary_id(cell->material_id() == MaterialIds::wheel ?
                                               wheel_boundary_id(cell->face(f)->center()) :
                                               rail_boundary_id(chart, cell->face(f)));
      }



      void
      WheelAndRail::set_manifold_ids(Triangulation<dim> &coarse) const
      {
        for (const auto &cell : coarse.active_cell_iterators())
          if (cell->material_id() == MaterialIds::wheel)
            cell->set_all_manifold_ids(ManifoldIds::wheel);
          else if (cell->material_id() == MaterialIds::rail)
            cell->set_all_manifold_ids(ManifoldIds::rail);
      }



      void
      WheelAndRail::attach_manifolds(parallel::distributed::Triangulation<dim> &triangulation) const
      {
        if (shape.cylindrical_wheel())
          triangulation.set_manifold(ManifoldIds::wheel,
                                     CylindricalManifold<dim>(Tensor<1, dim>({0., 1., 0.}),
                                                              shape.wheel_centre()));
        else
          triangulation.set_manifold(ManifoldIds::wheel,
                                     internal::RevolvedProfileChart(shape.wheel_centre(),
                                                                    shape.rolling_radius(),
                                                                    p.bore_radius,
                                                                    shape.wheel_curve()));
        triangulation.set_manifold(ManifoldIds::rail,
                                   internal::RailChart(p.rail_head_height, shape.rail_curve()));
      }
    } // namespace



    namespace GeometryModels
    {
      std::unique_ptr<GeometryModel>
      wheel_and_rail(const GeometryParameters &parameters, ParameterHandler &prm)
      {
        ProfileParameters profiles;
        profiles.parse_parameters(prm, parameters);
        return std::make_unique<WheelAndRail>(parameters, profiles);
      }



      void
      wheel_and_rail_declarations(ParameterHandler &prm)
      {
        ProfileParameters::declare_parameters(prm);
      }
    } // namespace GeometryModels
  }   // namespace Geometry
} // namespace WheelRail
