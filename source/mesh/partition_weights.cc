/**
 * @file mesh/partition_weights.cc
 * The cells' work and the partition by it (mesh/partition_weights.h).
 */

#include <deal.II/base/mpi.h>

#include <wheelrail/mesh/partition_weights.h>

#include <algorithm>

namespace WheelRail
{
  namespace Mesh
  {
    CellWorkParts
    cell_work_parts(const Triangulation<dim>::cell_iterator &cell,
                    const std::vector<types::boundary_id>   &contact_boundaries)
    {
      CellWorkParts parts;
      // the family rule of ElasticOperator::cells_in_batch_order() (its
      // check that the 8 children are locally owned holds here: p4est keeps
      // a family on one rank); a coarse cell: where the coarse mesh is
      // structured, the batches take its cells in blocks of 2 x 2 x 2 as a
      // family's
      parts.in_family = cell->level() == 0;
      if (cell->level() > 0)
        {
          const auto parent = cell->parent();
          parts.in_family   = parent->n_children() == 8;
          for (unsigned int i = 0; i < parent->n_children() && parts.in_family; ++i)
            parts.in_family = parent->child(i)->is_active();
        }
      for (const unsigned int f : cell->face_indices())
        if (cell->at_boundary(f))
          {
            const types::boundary_id id = cell->face(f)->boundary_id();
            if (std::find(contact_boundaries.begin(), contact_boundaries.end(), id) !=
                contact_boundaries.end())
              ++parts.contact_faces;
          }
        else if (cell->neighbor_is_coarser(f))
          ++parts.hanging_faces;
      return parts;
    }



    std::vector<types::boundary_id>
    contact_boundaries(const ContactParameters &contact, const bool geometry_has_contact)
    {
      if (!contact.enabled || !geometry_has_contact)
        return {};
      return {contact.slave_boundary, contact.master_boundary};
    }



    void
    partition_by_work(parallel::distributed::Triangulation<dim> &triangulation,
                      const std::vector<types::boundary_id>     &contact_boundaries)
    {
      if (Utilities::MPI::n_mpi_processes(triangulation.get_communicator()) == 1)
        return;
      // called by repartition() for each locally owned active cell (status
      // CELL_PERSIST: nothing is refined or coarsened here)
      const auto connection = triangulation.signals.weight.connect(
        [&](const Triangulation<dim>::cell_iterator &cell,
            const Triangulation<dim>::CellStatus) -> unsigned int {
          return cell_work_parts(cell, contact_boundaries).work();
        });
      triangulation.repartition();
      connection.disconnect();
    }



    RankWork
    rank_work(const parallel::distributed::Triangulation<dim> &triangulation,
              const std::vector<types::boundary_id>           &contact_boundaries)
    {
      RankWork sums;
      for (const auto &cell : triangulation.active_cell_iterators())
        if (cell->is_locally_owned())
          {
            const CellWorkParts parts = cell_work_parts(cell, contact_boundaries);
            sums.cells += 1;
            sums.other_cells += parts.in_family ? 0 : 1;
            sums.hanging_faces += parts.hanging_faces;
            sums.contact_faces += parts.contact_faces;
            sums.work += parts.work();
          }
      return sums;
    }
  } // namespace Mesh
} // namespace WheelRail
