/**
 * @file mesh/refinement.cc
 * The local refinement of the wheel and rail: the target size of each
 * cell from its distance to the solution zone and the rolling path in
 * chart coordinates, the cycles of refinement, and the cells in the zone.
 */

#include <deal.II/base/mpi.h>

#include <deal.II/grid/grid_tools.h>
#include <deal.II/grid/manifold.h>
#include <deal.II/grid/manifold_lib.h>
#include <deal.II/grid/tria.h>

#include <wheelrail/mesh/cell_estimate.h>
#include <wheelrail/mesh/geometry.h>
#include <wheelrail/mesh/refinement.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace WheelRail
{
  namespace Geometry
  {
    using namespace internal;

    namespace
    {
      /** Longest edge of a cell (the size the refinement targets). */
      template <typename CellIterator>
      double
      longest_edge(const CellIterator &cell)
      {
        double h = 0;
        for (unsigned int l = 0; l < GeometryInfo<dim>::lines_per_cell; ++l)
          h = std::max(h, cell->line(l)->vertex(0).distance(cell->line(l)->vertex(1)));
        return h;
      }



      /**
       * The refinement's chart coordinates of a point: (x, y, depth below
       * the rail top) on the rail, (arc length s from the lowest tread
       * point, positive towards +x, y, depth below the tread) on the wheel.
       * On the wheel, s is taken on the branch nearest to the angle
       * @p theta_ref, so that the points of one cell do not straddle the
       * cut of atan2 at the top of the wheel.
       */
      std::array<double, 3>
      chart_coordinates(const WheelRailShape    &shape,
                        const types::material_id material,
                        const Point<dim>        &x,
                        const double             theta_ref)
      {
        if (material == MaterialIds::rail)
          return {{x[0], x[1], shape.rail_top(x[1]) - x[2]}};
        const Point<dim> centre = shape.wheel_centre();
        const double     dx     = x[0] - centre[0];
        const double     dz     = x[2] - centre[2];
        const double theta = theta_ref + std::remainder(std::atan2(dx, -dz) - theta_ref, 2 * M_PI);
        return {{shape.rolling_radius() * theta,
                 x[1],
                 shape.wheel_radius(x[1]) - std::sqrt(dx * dx + dz * dz)}};
      }



      /**
       * Target size of a cell (SPEC 1 local refinement): h_min + Grading d,
       * d the distance of the cell's centre from the solution zone in chart
       * coordinates (the rolling path likewise with its own size), capped
       * by the coarse size (wheel: growing inwards with the depth). With
       * @p whole_zone, a cell whose chart bounding box overlaps the zone
       * (path) gets the zone's (path's) size whatever the grading: with the
       * centre's distance alone, a cell that reaches into the zone from
       * outside keeps h > h_min once Grading exceeds about 0.5 (at 2.5 the
       * wheel's coarse cells were not refined at all). For wheel and rail
       * cells only (the caller below returns the bar's "no refinement").
       */
      double
      target_size(const GeometryParameters    &p,
                  const WheelRailShape        &shape,
                  const types::material_id     material,
                  const std::array<double, 3> &centre,
                  const ChartBox              &cell_box,
                  const double                 coarse,
                  const bool                   whole_zone)
      {
        const double          g = p.grading;
        const RefinementBoxes b = refinement_boxes(p, shape, material);
        double                h = (material == MaterialIds::rail) ? coarse : coarse + g * centre[2];
        if (b.has_zone)
          for (const ChartBox &zone : b.zones())
            h =
              std::min(h,
                       whole_zone && cell_box.overlaps(zone) ? p.h_min :
                                                               p.h_min + g * zone.distance(centre));
        if (b.has_path)
          {
            const double hp = std::max(p.path_cell_size, p.h_min);
            h               = std::min(
              h, whole_zone && cell_box.overlaps(b.path) ? hp : hp + g * b.path.distance(centre));
          }
        return h;
      }



      /**
       * A cell's centre in chart coordinates and the bounding box of its
       * centre and vertices there.
       */
      template <typename CellIterator>
      std::pair<std::array<double, 3>, ChartBox>
      cell_in_chart(const WheelRailShape &shape, const CellIterator &cell)
      {
        const Point<dim> c         = cell->center();
        const Point<dim> axle      = shape.wheel_centre();
        const double     theta_ref = std::atan2(c[0] - axle[0], -(c[2] - axle[2]));
        const auto       centre    = chart_coordinates(shape, cell->material_id(), c, theta_ref);
        ChartBox         box{centre, centre};
        for (const unsigned int v : cell->vertex_indices())
          {
            const auto q =
              chart_coordinates(shape, cell->material_id(), cell->vertex(v), theta_ref);
            for (unsigned int d = 0; d < 3; ++d)
              {
                box.lo[d] = std::min(box.lo[d], q[d]);
                box.hi[d] = std::max(box.hi[d], q[d]);
              }
          }
        return {centre, box};
      }



      /** target_size() of a cell, from its centre and vertices. */
      template <typename CellIterator>
      double
      target_size(const GeometryParameters &p,
                  const WheelRailShape     &shape,
                  const CellIterator       &cell,
                  const double              coarse,
                  const bool                whole_zone)
      {
        const types::material_id material = cell->material_id();
        if (material != MaterialIds::rail && material != MaterialIds::wheel)
          return std::numeric_limits<double>::max(); // the bar is not refined
        const auto [centre, box] = cell_in_chart(shape, cell);
        return target_size(p, shape, material, centre, box, coarse, whole_zone);
      }
    } // namespace



    namespace internal
    {
      /** Coarse cell size that halves exactly onto h_min. */
      double
      effective_coarse_size(const GeometryParameters &p)
      {
        const double levels = std::round(std::log2(p.coarse_cell_size / p.h_min));
        return p.h_min * std::pow(2., std::max(0., levels));
      }



      RefinementBoxes
      refinement_boxes(const GeometryParameters &p,
                       const WheelRailShape     &shape,
                       const types::material_id  material)
      {
        RefinementBoxes b;
        const double    w = p.zone_half_width;
        if (material == MaterialIds::rail)
          {
            b.has_zone = p.zone_length > 0;
            b.zone = {{{-0.5 * p.zone_length, -w, 0}}, {{0.5 * p.zone_length, w, p.zone_depth}}};
            b.has_path = p.path_cell_size > 0;
            b.path     = {{{p.rail_start_x, -w, 0}}, {{p.rail_end_x, w, p.zone_depth}}};
          }
        else if (material == MaterialIds::wheel)
          {
            // the arc that meets the zone when the wheel rolls from Centre x
            // to O, and the arc that meets the rail: from just before the
            // initial contact point to the rail's end
            const double sO = -p.wheel_centre_x;
            b.has_zone      = p.zone_length > 0 && p.refine_wheel;
            b.zone          = {{{sO - 0.5 * p.zone_length, -w, 0}},
                               {{sO + 0.5 * p.zone_length, w, p.zone_depth}}};
            b.has_path      = p.path_cell_size > 0;
            b.path          = {{{-w, -w, 0}}, {{p.rail_end_x - p.wheel_centre_x, w, p.zone_depth}}};
          }
        // a further contact point (two-point contact): the zone's box
        // moved across to it
        for (std::size_t i = 1; i < shape.contacts().size(); ++i)
          {
            ChartBox     zone = b.zone;
            const double y    = shape.contacts()[i].y;
            zone.lo[1] += y;
            zone.hi[1] += y;
            b.further_zones.push_back(zone);
          }
        return b;
      }



      void
      refine_wheel_and_rail(const GeometryParameters                  &p,
                            const WheelRailShape                      &shape,
                            parallel::distributed::Triangulation<dim> &triangulation)
      {
        // Two passes: the grading from the cells' centres first (the meshes
        // of Grading <= 0.5 end here, cell for cell and in the same order as
        // before the second pass existed), then the same with the cells that
        // reach into the zone or the path at their size; with a steeper
        // grading the first pass leaves such cells coarser.
        const double   coarse_size = effective_coarse_size(p);
        const MPI_Comm comm        = triangulation.get_communicator();
        const double   memory      = physical_memory(comm);
        for (const bool whole_zone : {false, true})
          for (unsigned int cycle = 0;; ++cycle)
            {
              AssertThrow(cycle < 20,
                          ExcMessage("The local refinement of the wheel and rail did not "
                                     "reach its target sizes in 20 cycles: Geometry/Mesh/"
                                     "Minimum cell size is too small for Coarse cell size "
                                     "(at most 2^20 times smaller)."));
              // Final cell count, estimated before each cycle: a flagged cell
              // of longest edge l and target size h becomes 8^k cells, k =
              // ceil(log2(l / h)) (h at its centre); the others stay.
              unsigned int n_flagged = 0;
              double       estimate  = 0;
              for (const auto &cell : triangulation.active_cell_iterators())
                if (cell->is_locally_owned())
                  {
                    const double l = longest_edge(cell);
                    const double h = target_size(p, shape, cell, coarse_size, whole_zone);
                    if (l > (1 + 1e-6) * h)
                      {
                        cell->set_refine_flag();
                        ++n_flagged;
                        estimate += std::pow(8., std::ceil(std::log2(l / ((1 + 1e-6) * h))));
                      }
                    else
                      estimate += 1;
                  }
              if (Utilities::MPI::sum(n_flagged, comm) == 0)
                break;
              estimate = Utilities::MPI::sum(estimate, comm);
              internal::check_cell_estimate(p, estimate, cycle, comm, memory);
              triangulation.execute_coarsening_and_refinement();
            }
      }
    } // namespace internal



    ZoneCells
    internal::zone_cells(const GeometryParameters                        &p,
                         const WheelRailShape                            &shape,
                         const types::material_id                         material,
                         const parallel::distributed::Triangulation<dim> &triangulation)
    {
      ZoneCells             z;
      const RefinementBoxes b = refinement_boxes(p, shape, material);
      if (b.has_zone)
        for (const auto &cell : triangulation.active_cell_iterators())
          if (cell->is_locally_owned() && cell->material_id() == material)
            {
              const ChartBox box = cell_in_chart(shape, cell).second;
              if (box.overlaps(b.zone))
                {
                  ++z.n_cells;
                  z.max_longest_edge = std::max(z.max_longest_edge, longest_edge(cell));
                }
            }
      const MPI_Comm comm = triangulation.get_communicator();
      z.n_cells           = Utilities::MPI::sum(z.n_cells, comm);
      z.max_longest_edge  = Utilities::MPI::max(z.max_longest_edge, comm);
      return z;
    }
  } // namespace Geometry
} // namespace WheelRail
