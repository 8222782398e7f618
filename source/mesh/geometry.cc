/**
 * @file mesh/geometry.cc
 * Geometry::build(): the coarse mesh of the chosen geometry, its boundary,
 * material and manifold ids, and the local refinement; and the exact
 * volumes of the bodies.
 */

#include <deal.II/base/mpi.h>

#include <deal.II/grid/grid_tools.h>
#include <deal.II/grid/manifold.h>
#include <deal.II/grid/manifold_lib.h>
#include <deal.II/grid/tria.h>

#include <wheelrail/mesh/coarse_mesh.h>
#include <wheelrail/mesh/geometry.h>
#include <wheelrail/mesh/rail_chart.h>
#include <wheelrail/mesh/refinement.h>

#include <cmath>
#include <string>
#include <vector>

namespace WheelRail
{
  namespace Geometry
  {
    using namespace internal;


    Point<dim>
    wheel_centre(const GeometryParameters &p)
    {
      return Point<dim>(p.wheel_centre_x, 0., p.wheel_centre_z());
    }



    namespace internal
    {
      void
      set_boundary_ids(const GeometryParameters &p, Triangulation<dim> &tria)
      {
        const Point<dim> centre = wheel_centre(p);
        const RailChart  chart(p.rail_head_height, p.rail_profile_radius);
        for (const auto &cell : tria.active_cell_iterators())
          for (const unsigned int f : cell->face_indices())
            if (cell->face(f)->at_boundary())
              {
                const Point<dim>   c   = cell->face(f)->center();
                const double       eps = 1e-6;
                types::boundary_id id;
                switch (cell->material_id())
                  {
                    case MaterialIds::wheel:
                      {
                        const double r = std::hypot(c[0] - centre[0], c[2] - centre[2]);
                        if (std::abs(std::abs(c[1]) - 0.5 * p.tread_width) < eps * p.tread_width)
                          id = BoundaryIds::wheel_side;
                        else if (r > 0.5 * (p.wheel_radius + p.bore_radius))
                          id = BoundaryIds::wheel_tread;
                        else
                          id = BoundaryIds::wheel_bore;
                        break;
                      }
                    case MaterialIds::rail:
                      {
                        // classify by the face's vertices in chart space: a
                        // curved face's centre lies below the arc
                        const double H   = p.rail_head_height;
                        bool         top = true, bottom = true, side = true;
                        for (unsigned int v = 0; v < 4; ++v)
                          {
                            const Point<dim> q = chart.pull_back(cell->face(f)->vertex(v));
                            top                = top && std::abs(q[2]) < eps * H;
                            bottom             = bottom && std::abs(q[2] + H) < eps * H;
                            side = side && std::abs(std::abs(q[1]) - 0.5 * p.rail_head_width) <
                                             eps * p.rail_head_width;
                          }
                        id = top    ? BoundaryIds::rail_top :
                             bottom ? BoundaryIds::rail_bottom :
                             side   ? BoundaryIds::rail_side :
                                      BoundaryIds::rail_end;
                        break;
                      }
                    case MaterialIds::block:
                    case MaterialIds::plate:
                      {
                        const bool   block    = cell->material_id() == MaterialIds::block;
                        const double z_bottom = block ? p.block_gap : -p.plate_size[2];
                        const double z_top    = block ? p.block_gap + p.block_size[2] : 0.;
                        const double h        = block ? p.block_size[2] : p.plate_size[2];
                        if (std::abs(c[2] - z_bottom) < eps * h)
                          id = block ? BoundaryIds::block_bottom : BoundaryIds::plate_bottom;
                        else if (std::abs(c[2] - z_top) < eps * h)
                          id = block ? BoundaryIds::block_top : BoundaryIds::plate_top;
                        else
                          id = block ? BoundaryIds::block_side : BoundaryIds::plate_side;
                        break;
                      }
                    default:
                      {
                        if (std::abs(c[0]) < eps * p.bar_length)
                          id = BoundaryIds::bar_start;
                        else if (std::abs(c[0] - p.bar_length) < eps * p.bar_length)
                          id = BoundaryIds::bar_end;
                        else
                          id = BoundaryIds::bar_side;
                      }
                  }
                cell->face(f)->set_boundary_id(id);
              }
      }
    } // namespace internal



    double
    exact_volume(const GeometryParameters &p, const types::material_id material)
    {
      switch (material)
        {
          case MaterialIds::wheel:
            return M_PI * (p.wheel_radius * p.wheel_radius - p.bore_radius * p.bore_radius) *
                   p.tread_width;
          case MaterialIds::rail:
            {
              const double a   = 0.5 * p.rail_head_width;
              const double rho = p.rail_profile_radius;
              // integral over y of (z_top(y) + H), z_top = sqrt(rho^2-y^2)-rho
              const double area = a * std::sqrt(rho * rho - a * a) +
                                  rho * rho * std::asin(a / rho) - 2 * a * rho +
                                  2 * a * p.rail_head_height;
              return area * (p.rail_end_x - p.rail_start_x);
            }
          case MaterialIds::block:
            return p.block_size[0] * p.block_size[1] * p.block_size[2];
          case MaterialIds::plate:
            return p.plate_size[0] * p.plate_size[1] * p.plate_size[2];
          default:
            return p.bar_length * p.bar_width * p.bar_height;
        }
    }



    namespace
    {
      /** Each geometry's bodies; the first geometry is the default. */
      struct GeometryBodies
      {
        const char       *geometry;
        std::vector<Body> bodies;
      };
      const std::vector<GeometryBodies> &
      geometry_bodies()
      {
        static const std::vector<GeometryBodies> table = {
          {"wheel and rail", {{MaterialIds::wheel, "wheel"}, {MaterialIds::rail, "rail"}}},
          {"bar", {{MaterialIds::bar, "bar"}}},
          {"block on plate", {{MaterialIds::block, "block"}, {MaterialIds::plate, "plate"}}}};
        return table;
      }
    } // namespace



    std::vector<Body>
    bodies(const std::string &geometry_type)
    {
      for (const GeometryBodies &g : geometry_bodies())
        if (geometry_type == g.geometry)
          return g.bodies;
      return geometry_bodies().front().bodies;
    }



    const char *
    body_name(const types::material_id material)
    {
      for (const GeometryBodies &g : geometry_bodies())
        for (const Body &body : g.bodies)
          if (body.material == material)
            return body.name;
      return "unknown body";
    }



    void
    build(const GeometryParameters                  &p,
          const std::string                         &geometry_type,
          parallel::distributed::Triangulation<dim> &triangulation)
    {
      internal::check_coarse_cell_estimate(p, geometry_type, triangulation.get_communicator());
      std::vector<Point<dim>>    vertices;
      std::vector<CellData<dim>> cells;
      if (geometry_type == "bar")
        build_bar(p, vertices, cells);
      else if (geometry_type == "block on plate")
        build_block_on_plate(p, vertices, cells);
      else
        build_wheel_and_rail(p, vertices, cells);

      // The two bodies are separate coarse meshes in one triangulation:
      // vertices are not merged, so wheel and rail never share a node.
      Triangulation<dim> coarse;
      coarse.create_triangulation(vertices, cells, SubCellData());
      for (const auto &cell : coarse.active_cell_iterators())
        AssertThrow(cell->measure() > 0, ExcMessage("Internal error: inverted coarse cell."));
      set_boundary_ids(p, coarse);
      for (const auto &cell : coarse.active_cell_iterators())
        if (cell->material_id() == MaterialIds::wheel)
          cell->set_all_manifold_ids(ManifoldIds::wheel);
        else if (cell->material_id() == MaterialIds::rail)
          cell->set_all_manifold_ids(ManifoldIds::rail);

      triangulation.copy_triangulation(coarse);
      triangulation.set_manifold(ManifoldIds::wheel,
                                 CylindricalManifold<dim>(Tensor<1, dim>({0., 1., 0.}),
                                                          wheel_centre(p)));
      triangulation.set_manifold(ManifoldIds::rail,
                                 RailChart(p.rail_head_height, p.rail_profile_radius));

      if (geometry_type == "wheel and rail")
        internal::refine_wheel_and_rail(p, triangulation);
    }
  } // namespace Geometry
} // namespace WheelRail
