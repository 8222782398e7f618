/**
 * @file mesh/partition_weights.h
 * The partition of the cells between the ranks by the work of the
 * explicit step (Problem/Partition = work): each cell weighs what a step
 * costs for it, from its kind and its surroundings alone, so that the
 * partition is the same in every run and no result depends on timing.
 *
 * A cell's work, in hundredths of the element loop's time for a cell of a
 * family batch (the 8 active children of one parent: 27 nodes gathered and
 * scattered for 8 cells):
 *   - 100 for a cell whose 7 siblings are active too (a family) and for
 *     a coarse cell (level 0: the batches take the cells of a structured
 *     coarse mesh in blocks of 2 x 2 x 2 as a family's), 134 for any other
 *     cell (gathered and scattered by its own 8 nodes);
 *   - 100 for each face whose neighbour is coarser: such faces hold 0.8
 *     hanging nodes each on the paper meshes (a hanging node is shared by
 *     the fine faces around it), and a hanging node costs condense() and
 *     distribute() about 1.25 cells' element work;
 *   - 25 for each face on a contact boundary (Contact/Slave boundary,
 *     Master boundary): about one contact node, owned by the cell's rank,
 *     whose motion the approach bound and the candidates' gather read
 *     every step.
 * The figures are the paper mesh's (bench_paper_single and the paper
 * case on 2 ranks, doc/notes/performance_balance.md); they are fixed
 * constants, not measured at run time.
 */
#ifndef wheelrail_mesh_partition_weights_h
#define wheelrail_mesh_partition_weights_h

#include <deal.II/distributed/tria.h>

#include <wheelrail/parameters/parameters.h>

#include <vector>

namespace WheelRail
{
  namespace Mesh
  {
    /** The constants of the cell work (see the file's description). */
    struct CellWorkModel
    {
      static constexpr unsigned int family_cell  = 100;
      static constexpr unsigned int other_cell   = 134;
      static constexpr unsigned int hanging_face = 100;
      static constexpr unsigned int contact_face = 25;
    };

    /** What a cell holds of the step's work. */
    struct CellWorkParts
    {
      bool         in_family     = false;
      unsigned int hanging_faces = 0;
      unsigned int contact_faces = 0;

      unsigned int
      work() const
      {
        return (in_family ? CellWorkModel::family_cell : CellWorkModel::other_cell) +
               CellWorkModel::hanging_face * hanging_faces +
               CellWorkModel::contact_face * contact_faces;
      }
    };

    /** The parts of the active cell @p cell; @p contact_boundaries are the
     *  boundary ids of the contact surfaces (none without contact). */
    CellWorkParts
    cell_work_parts(const Triangulation<dim>::cell_iterator &cell,
                    const std::vector<types::boundary_id>   &contact_boundaries);

    /** The boundary ids whose nodes the contact visits every step: the
     *  slave and master boundaries where contact is on, none otherwise. */
    std::vector<types::boundary_id>
    contact_boundaries(const ContactParameters &contact, const bool geometry_has_contact);

    /** Repartition @p triangulation so that every rank holds about the
     *  same work (cell_work_parts()); p4est keeps its order of the cells
     *  and each family on one rank. Collective. */
    void
    partition_by_work(parallel::distributed::Triangulation<dim> &triangulation,
                      const std::vector<types::boundary_id>     &contact_boundaries);

    /** This rank's sums of the cells' work parts. */
    struct RankWork
    {
      double cells         = 0;
      double other_cells   = 0;
      double hanging_faces = 0;
      double contact_faces = 0;
      double work          = 0;
    };

    /** The sums over this rank's locally owned cells. */
    RankWork
    rank_work(const parallel::distributed::Triangulation<dim> &triangulation,
              const std::vector<types::boundary_id>           &contact_boundaries);
  } // namespace Mesh
} // namespace WheelRail

#endif
