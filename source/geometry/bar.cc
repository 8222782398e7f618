/**
 * @file geometry/bar.cc
 * The geometry "bar": a straight prismatic bar along x, [0, Length] x
 * [-Width/2, Width/2] x [-Height/2, Height/2] (Geometry/Bar), in
 * Cells hexahedra whose interior vertices may be displaced by Distortion;
 * for the verification of the elastic operator. No contact.
 */

#include <wheelrail/geometry/interface.h>
#include <wheelrail/mesh/cell_estimate.h>
#include <wheelrail/mesh/coarse_mesh.h>
#include <wheelrail/mesh/geometry.h>
#include <wheelrail/simulator/format.h>

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
      /** The bar. */
      class Bar : public GeometryModel
      {
      public:
        using GeometryModel::GeometryModel;

        std::vector<Body>
        bodies() const override
        {
          return {{MaterialIds::bar, "bar"}};
        }

        std::vector<Box>
        bounding_boxes() const override
        {
          return {{Point<3>(0, -0.5 * p.bar_width, -0.5 * p.bar_height),
                   Point<3>(p.bar_length, 0.5 * p.bar_width, 0.5 * p.bar_height)}};
        }

        double
        exact_volume(const types::material_id) const override
        {
          return p.bar_length * p.bar_width * p.bar_height;
        }

        CoarseCellEstimate
        coarse_cell_estimate() const override
        {
          const double n = internal::product(p.bar_cells);
          return {n,
                  "Geometry/Bar/Cells = " + internal::cell_list(p.bar_cells) + " make a bar of " +
                    Report::fmt(n, 3) + " cells",
                  "reduce Geometry/Bar/Cells."};
        }

        void
        create_coarse_mesh(std::vector<Point<dim>>    &vertices,
                           std::vector<CellData<dim>> &cells) const override;

        void
        set_boundary_ids(Triangulation<dim> &coarse) const override;

        bool
        has_contact() const override
        {
          return false;
        }

        /** The bar about its centre. */
        std::pair<types::material_id, Point<dim>>
        rotating_body() const override
        {
          return {MaterialIds::bar, Point<dim>(0.5 * p.bar_length, 0, 0)};
        }
      };



      void
      Bar::create_coarse_mesh(std::vector<Point<dim>>    &vertices,
                              std::vector<CellData<dim>> &cells) const
      {
        const unsigned int nx = p.bar_cells[0], ny = p.bar_cells[1], nz = p.bar_cells[2];
        const double       hx = p.bar_length / nx, hy = p.bar_width / ny, hz = p.bar_height / nz;
        internal::add_block(
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
      Bar::set_boundary_ids(Triangulation<dim> &coarse) const
      {
        const double eps = 1e-6;
        for (const auto &cell : coarse.active_cell_iterators())
          for (const unsigned int f : cell->face_indices())
            if (cell->face(f)->at_boundary())
              {
                const Point<dim> c = cell->face(f)->center();
                if (std::abs(c[0]) < eps * p.bar_length)
                  cell->face(f)->set_boundary_id(BoundaryIds::bar_start);
                else if (std::abs(c[0] - p.bar_length) < eps * p.bar_length)
                  cell->face(f)->set_boundary_id(BoundaryIds::bar_end);
                else
                  cell->face(f)->set_boundary_id(BoundaryIds::bar_side);
              }
      }
    } // namespace



    namespace GeometryModels
    {
      std::unique_ptr<GeometryModel>
      bar(const GeometryParameters &parameters, ParameterHandler &)
      {
        return std::make_unique<Bar>(parameters);
      }
    } // namespace GeometryModels
  }   // namespace Geometry
} // namespace WheelRail
