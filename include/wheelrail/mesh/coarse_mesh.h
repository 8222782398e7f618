/**
 * @file mesh/coarse_mesh.h
 * The coarse meshes of the geometries, before refinement: structured
 * blocks of hexahedra (the bar and the block on a plate are made of them
 * in source/geometry/) and the wheel and rail.
 */
#ifndef wheelrail_mesh_coarse_mesh_h
#define wheelrail_mesh_coarse_mesh_h

#include <deal.II/base/point.h>

#include <deal.II/grid/tria.h>

#include <wheelrail/geometry/wheel_rail_shape.h>
#include <wheelrail/parameters/parameters.h>

#include <vector>

namespace WheelRail
{
  namespace Geometry
  {
    namespace internal
    {
      /**
       * Append a structured block of nx x ny x nz hexahedra whose vertex
       * (i, j, k) lies at position(i, j, k). With @p periodic_i the index
       * i = nx is identified with i = 0 (the closed wheel).
       */
      template <typename PositionFunction>
      void
      add_block(const unsigned int          nx,
                const unsigned int          ny,
                const unsigned int          nz,
                const bool                  periodic_i,
                const types::material_id    material,
                const PositionFunction     &position,
                std::vector<Point<dim>>    &vertices,
                std::vector<CellData<dim>> &cells)
      {
        const unsigned int offset = vertices.size();
        const unsigned int vx     = periodic_i ? nx : nx + 1;
        for (unsigned int k = 0; k <= nz; ++k)
          for (unsigned int j = 0; j <= ny; ++j)
            for (unsigned int i = 0; i < vx; ++i)
              vertices.push_back(position(i, j, k));
        const auto index = [&](unsigned int i, unsigned int j, unsigned int k) {
          return offset + (i % vx) + vx * (j + (ny + 1) * k);
        };
        for (unsigned int k = 0; k < nz; ++k)
          for (unsigned int j = 0; j < ny; ++j)
            for (unsigned int i = 0; i < nx; ++i)
              {
                CellData<dim> cell;
                for (unsigned int v = 0; v < 8; ++v)
                  cell.vertices[v] = index(i + (v & 1), j + ((v >> 1) & 1), k + ((v >> 2) & 1));
                cell.material_id = material;
                cells.push_back(cell);
              }
      }



      /** The coarse mesh of the wheel and rail (SPEC 1), Align coarse cells
       *  with zone included (wheel_and_rail.cc). */
      void
      build_wheel_and_rail(const GeometryParameters   &p,
                           const WheelRailShape       &shape,
                           std::vector<Point<dim>>    &vertices,
                           std::vector<CellData<dim>> &cells);
    } // namespace internal
  }   // namespace Geometry
} // namespace WheelRail

#endif
