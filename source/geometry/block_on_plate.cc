/**
 * @file geometry/block_on_plate.cc
 * The geometry "block on plate": a block of Block size at (Block x, 0,
 * Block gap) above a plate of Plate size whose top is z = 0 (Geometry/Block
 * on plate), both boxes of hexahedra; for the verification of the contact
 * (the sliding block checks).
 */

#include <wheelrail/geometry/interface.h>
#include <wheelrail/mesh/cell_estimate.h>
#include <wheelrail/mesh/coarse_mesh.h>
#include <wheelrail/mesh/geometry.h>
#include <wheelrail/simulator/format.h>

#include <cmath>
#include <memory>
#include <vector>

namespace WheelRail
{
  namespace Geometry
  {
    namespace
    {
      /** The block on the plate. */
      class BlockOnPlate : public GeometryModel
      {
      public:
        using GeometryModel::GeometryModel;

        std::vector<Body>
        bodies() const override
        {
          return {{MaterialIds::block, "block"}, {MaterialIds::plate, "plate"}};
        }

        std::vector<Box>
        bounding_boxes() const override
        {
          return {{Point<3>(0, -0.5 * p.plate_size[1], -p.plate_size[2]),
                   Point<3>(p.plate_size[0], 0.5 * p.plate_size[1], 0)},
                  {Point<3>(p.block_x, -0.5 * p.block_size[1], p.block_gap),
                   Point<3>(p.block_x + p.block_size[0],
                            0.5 * p.block_size[1],
                            p.block_gap + p.block_size[2])}};
        }

        double
        exact_volume(const types::material_id material) const override
        {
          if (material == MaterialIds::block)
            return p.block_size[0] * p.block_size[1] * p.block_size[2];
          return p.plate_size[0] * p.plate_size[1] * p.plate_size[2];
        }

        CoarseCellEstimate
        coarse_cell_estimate() const override
        {
          const double n = internal::product(p.plate_cells) + internal::product(p.block_cells);
          return {n,
                  "Geometry/Block on plate/Plate cells = " + internal::cell_list(p.plate_cells) +
                    " and Block cells = " + internal::cell_list(p.block_cells) + " make " +
                    Report::fmt(n, 3) + " cells",
                  "reduce Geometry/Block on plate/Plate cells or Block cells."};
        }

        void
        create_coarse_mesh(std::vector<Point<dim>>    &vertices,
                           std::vector<CellData<dim>> &cells) const override;

        void
        set_boundary_ids(Triangulation<dim> &coarse) const override;

        bool
        has_contact() const override
        {
          return true;
        }

        bool
        is_block_on_plate() const override
        {
          return true;
        }
      };



      void
      BlockOnPlate::create_coarse_mesh(std::vector<Point<dim>>    &vertices,
                                       std::vector<CellData<dim>> &cells) const
      {
        const auto box = [&](const Point<dim>                &lower,
                             const Tensor<1, dim>            &size,
                             const std::vector<unsigned int> &n,
                             const types::material_id         material) {
          internal::add_block(
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



      void
      BlockOnPlate::set_boundary_ids(Triangulation<dim> &coarse) const
      {
        const double eps = 1e-6;
        for (const auto &cell : coarse.active_cell_iterators())
          for (const unsigned int f : cell->face_indices())
            if (cell->face(f)->at_boundary())
              {
                const Point<dim>   c        = cell->face(f)->center();
                const bool         block    = cell->material_id() == MaterialIds::block;
                const double       z_bottom = block ? p.block_gap : -p.plate_size[2];
                const double       z_top    = block ? p.block_gap + p.block_size[2] : 0.;
                const double       h        = block ? p.block_size[2] : p.plate_size[2];
                types::boundary_id id;
                if (std::abs(c[2] - z_bottom) < eps * h)
                  id = block ? BoundaryIds::block_bottom : BoundaryIds::plate_bottom;
                else if (std::abs(c[2] - z_top) < eps * h)
                  id = block ? BoundaryIds::block_top : BoundaryIds::plate_top;
                else
                  id = block ? BoundaryIds::block_side : BoundaryIds::plate_side;
                cell->face(f)->set_boundary_id(id);
              }
      }
    } // namespace



    namespace GeometryModels
    {
      std::unique_ptr<GeometryModel>
      block_on_plate(const GeometryParameters &parameters, ParameterHandler &)
      {
        return std::make_unique<BlockOnPlate>(parameters);
      }
    } // namespace GeometryModels
  }   // namespace Geometry
} // namespace WheelRail
