/**
 * @file mesh/refinement.h
 * The local refinement of the wheel and rail towards the solution zone and
 * the rolling path, in the chart coordinates of each body (SPEC 1), and
 * the cells in the solution zone.
 */
#ifndef wheelrail_mesh_refinement_h
#define wheelrail_mesh_refinement_h

#include <deal.II/base/mpi.h>

#include <deal.II/distributed/tria.h>

#include <wheelrail/geometry/interface.h>
#include <wheelrail/geometry/wheel_rail_shape.h>
#include <wheelrail/parameters/parameters.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

namespace WheelRail
{
  namespace Geometry
  {
    namespace internal
    {
      /** Coarse cell size that halves exactly onto h_min. */
      double
      effective_coarse_size(const GeometryParameters &p);



      /** Distance of (a, b, c) to the box [a0,a1] x [b0,b1] x [c0,c1]. */
      inline double
      box_distance(const double a,
                   const double b,
                   const double c,
                   const double a0,
                   const double a1,
                   const double b0,
                   const double b1,
                   const double c0,
                   const double c1)
      {
        const double da = std::max({a0 - a, 0., a - a1});
        const double db = std::max({b0 - b, 0., b - b1});
        const double dc = std::max({c0 - c, 0., c - c1});
        return std::sqrt(da * da + db * db + dc * dc);
      }



      /**
       * A box [lo, hi] in chart coordinates: the zone, the rolling path,
       * or the bounding box of a cell's vertices.
       */
      struct ChartBox
      {
        std::array<double, 3> lo;
        std::array<double, 3> hi;

        /** Distance of the point @p c to the box (0 inside). */
        double
        distance(const std::array<double, 3> &c) const
        {
          return box_distance(c[0], c[1], c[2], lo[0], hi[0], lo[1], hi[1], lo[2], hi[2]);
        }

        /** Whether the two boxes share a volume (touching does not count). */
        bool
        overlaps(const ChartBox &other) const
        {
          const double eps = 1e-9; // [m]
          for (unsigned int d = 0; d < 3; ++d)
            if (other.hi[d] <= lo[d] + eps || other.lo[d] >= hi[d] - eps)
              return false;
          return true;
        }
      };



      /** The solution zone and the rolling path of one body, in chart space. */
      struct RefinementBoxes
      {
        bool     has_zone = false;
        ChartBox zone;
        /** The zone moved across to each further rigid contact point. */
        std::vector<ChartBox> further_zones;
        bool                  has_path = false;
        ChartBox              path;

        /** The zone and the further zones. */
        std::vector<ChartBox>
        zones() const
        {
          std::vector<ChartBox> all = {zone};
          all.insert(all.end(), further_zones.begin(), further_zones.end());
          return all;
        }
      };



      /** The solution zone and the rolling path of body @p material in chart
       *  space (none for the bar and the block on plate). */
      RefinementBoxes
      refinement_boxes(const GeometryParameters &p,
                       const WheelRailShape     &shape,
                       const types::material_id  material);



      /**
       * Refine the wheel and rail locally to the target sizes of
       * Geometry/Mesh (SPEC 1): cycles of refinement until no cell is larger
       * than its target, each checked first by check_cell_estimate().
       */
      void
      refine_wheel_and_rail(const GeometryParameters                  &p,
                            const WheelRailShape                      &shape,
                            parallel::distributed::Triangulation<dim> &triangulation);



      /** The cells of body @p material (wheel or rail) that reach into its
       *  solution zone, and the largest of them: a check that the whole
       *  zone is meshed at Minimum cell size whatever the grading.
       *  Collective over the triangulation's communicator. */
      ZoneCells
      zone_cells(const GeometryParameters                        &p,
                 const WheelRailShape                            &shape,
                 const types::material_id                         material,
                 const parallel::distributed::Triangulation<dim> &triangulation);
    } // namespace internal
  }   // namespace Geometry
} // namespace WheelRail

#endif
