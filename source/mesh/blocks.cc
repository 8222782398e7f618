/**
 * @file mesh/blocks.cc
 * The coarse meshes of the simple test bodies: the bar and the block on a
 * plate.
 */

#include <wheelrail/mesh/coarse_mesh.h>
#include <wheelrail/mesh/geometry.h>

#include <cmath>
#include <vector>

namespace WheelRail
{
  namespace Geometry
  {
    using namespace internal;

    namespace internal
    {
      void
      build_bar(const GeometryParameters   &p,
                std::vector<Point<dim>>    &vertices,
                std::vector<CellData<dim>> &cells)
      {
        const unsigned int nx = p.bar_cells[0], ny = p.bar_cells[1], nz = p.bar_cells[2];
        const double       hx = p.bar_length / nx, hy = p.bar_width / ny, hz = p.bar_height / nz;
        add_block(
          nx,
          ny,
          nz,
          false,
          MaterialIds::bar,
          [&](unsigned int i, unsigned int j, unsigned int k) {
            Point<dim> x(i * hx, -0.5 * p.bar_width + j * hy, -0.5 * p.bar_height + k * hz);
            const bool interior = i > 0 && i < nx && j > 0 && j < ny && k > 0 && k < nz;
            if (interior && p.bar_distortion > 0)
              {
                // deterministic pseudo-random direction per vertex
                const double a = std::sin(12.9898 * i + 78.233 * j + 37.719 * k);
                const double b = std::sin(93.989 * i + 67.345 * j + 11.135 * k);
                const double c = std::sin(41.235 * i + 24.414 * j + 73.156 * k);
                x[0] += p.bar_distortion * hx * a;
                x[1] += p.bar_distortion * hy * b;
                x[2] += p.bar_distortion * hz * c;
              }
            return x;
          },
          vertices,
          cells);
      }



      void
      build_block_on_plate(const GeometryParameters   &p,
                           std::vector<Point<dim>>    &vertices,
                           std::vector<CellData<dim>> &cells)
      {
        const auto box = [&](const Point<dim>                &lower,
                             const Tensor<1, dim>            &size,
                             const std::vector<unsigned int> &n,
                             const types::material_id         material) {
          add_block(
            n[0],
            n[1],
            n[2],
            false,
            material,
            [&](unsigned int i, unsigned int j, unsigned int k) {
              return Point<dim>(lower[0] + i * size[0] / n[0],
                                lower[1] + j * size[1] / n[1],
                                lower[2] + k * size[2] / n[2]);
            },
            vertices,
            cells);
        };
        box(Point<dim>(0, -0.5 * p.plate_size[1], -p.plate_size[2]),
            p.plate_size,
            p.plate_cells,
            MaterialIds::plate);
        box(Point<dim>(p.block_x, -0.5 * p.block_size[1], p.block_gap),
            p.block_size,
            p.block_cells,
            MaterialIds::block);
      }
    } // namespace internal
  }   // namespace Geometry
} // namespace WheelRail
