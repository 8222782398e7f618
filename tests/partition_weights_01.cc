// Unit test of the partition by work (mesh/partition_weights.h) on a bar of
// 8 x 2 x 2 cells whose first two cells are refined, and one child of the
// first once more (2:1 kept):
//  - the cells' kinds: the unrefined coarse cells and the children of a
//    parent whose 8 children are active are family cells, the 7 siblings
//    of the refined child are not;
//  - the faces with hanging nodes, against an independent count: a face is
//    one where the cell across it (found by the point just outside the
//    face's centre) is larger;
//  - the contact faces (here the bar's end, Geometry/Bar x = L): their
//    areas sum to the end's area;
//  - the partition: the work per rank with equal cells and with equal work
//    (Mesh::partition_by_work()); by work, no rank holds more than the mean
//    by more than a family's work (p4est keeps the 8 children of a parent
//    on one rank).
#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>

#include <wheelrail/geometry/interface.h>
#include <wheelrail/mesh/geometry.h>
#include <wheelrail/mesh/partition_weights.h>
#include <wheelrail/parameters/parameters.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <iterator>

using namespace WheelRail;

namespace
{
  // the work and cells of each rank, printed by rank 0
  void
  print_ranks(const char                                      *name,
              const parallel::distributed::Triangulation<dim> &triangulation,
              const std::vector<types::boundary_id>           &contact,
              const double                                     largest_cell)
  {
    const MPI_Comm       comm  = triangulation.get_communicator();
    const Mesh::RankWork w     = Mesh::rank_work(triangulation, contact);
    const auto           work  = Utilities::MPI::all_gather(comm, w.work);
    const auto           cells = Utilities::MPI::all_gather(comm, w.cells);
    double               total = 0, largest = 0;
    for (const double x : work)
      total += x, largest = std::max(largest, x);
    const double mean = total / work.size();
    if (Utilities::MPI::this_mpi_process(comm) == 0)
      {
        std::printf("partition by %s:", name);
        for (unsigned int r = 0; r < work.size(); ++r)
          std::printf(" rank %u %.0f cells, work %.0f;", r, cells[r], work[r]);
        std::printf(" largest / mean %.4f; within a family's work of the mean: %s\n",
                    largest / mean,
                    largest - mean <= 8 * largest_cell ? "yes" : "no");
      }
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const MPI_Comm                   comm = MPI_COMM_WORLD;
  if (Utilities::MPI::this_mpi_process(comm) == 0)
    {
      std::ofstream prm_file("partition_weights_01_case.prm");
      prm_file << "subsection Problem\n  set Geometry = bar\n  set Test mode = true\nend\n"
                  "subsection Geometry\n  subsection Bar\n    set Length = 0.08\n"
                  "    set Width = 0.02\n    set Height = 0.02\n    set Cells = 8, 2, 2\n"
                  "    set Distortion = 0\n  end\nend\n";
    }
  MPI_Barrier(comm);
  ParameterHandler prm;
  Parameters       parameters;
  Parameters::declare_parameters(prm);
  parameters.parse(prm, "partition_weights_01_case.prm");

  parallel::distributed::Triangulation<dim> triangulation(comm);
  Geometry::build(*parameters.geometry_model, triangulation);
  for (const auto &cell : triangulation.active_cell_iterators())
    if (cell->is_locally_owned() && cell->center()[0] < 0.02)
      cell->set_refine_flag();
  triangulation.execute_coarsening_and_refinement();
  for (const auto &cell : triangulation.active_cell_iterators())
    if (cell->is_locally_owned() &&
        cell->center().distance(Point<dim>(0.0025, -0.0075, -0.0075)) < 1e-9)
      cell->set_refine_flag();
  triangulation.execute_coarsening_and_refinement();

  const std::vector<types::boundary_id> contact = {Geometry::BoundaryIds::bar_end};

  // the kinds, the faces and the independent count, over the owned cells
  double n_coarse = 0, n_family = 0, n_other = 0, hanging = 0, hanging_geometric = 0;
  double contact_faces = 0, contact_area = 0, largest_cell = 0;
  for (const auto &cell : triangulation.active_cell_iterators())
    if (cell->is_locally_owned())
      {
        const Mesh::CellWorkParts parts = Mesh::cell_work_parts(cell, contact);
        largest_cell                    = std::max<double>(largest_cell, parts.work());
        if (cell->level() == 0)
          n_coarse += parts.in_family;
        else if (parts.in_family)
          ++n_family;
        else
          ++n_other;
        hanging += parts.hanging_faces;
        contact_faces += parts.contact_faces;
        for (const unsigned int f : cell->face_indices())
          {
            if (cell->face(f)->at_boundary())
              {
                if (cell->face(f)->boundary_id() == Geometry::BoundaryIds::bar_end)
                  contact_area += cell->face(f)->measure();
                continue;
              }
            const Point<dim> c       = cell->face(f)->center();
            const Point<dim> outside = c + 0.01 * (c - cell->center());
            for (const auto &other : triangulation.active_cell_iterators())
              if (!other->is_artificial() && other->point_inside(outside))
                {
                  hanging_geometric += other->diameter() > 1.5 * cell->diameter();
                  break;
                }
          }
      }
  const auto sum = [&](const double x) { return Utilities::MPI::sum(x, comm); };
  largest_cell   = Utilities::MPI::max(largest_cell, comm);
  if (Utilities::MPI::this_mpi_process(comm) == 0)
    std::printf("%u active cells\n", triangulation.n_global_active_cells());
  const double n[7] = {sum(n_coarse),
                       sum(n_family),
                       sum(n_other),
                       sum(hanging),
                       sum(hanging_geometric),
                       sum(contact_faces),
                       sum(contact_area)};
  if (Utilities::MPI::this_mpi_process(comm) == 0)
    {
      std::printf("family cells: %.0f coarse, %.0f children; other cells: %.0f\n",
                  n[0],
                  n[1],
                  n[2]);
      std::printf("faces with hanging nodes: %.0f (counted from the cells across them: %.0f)\n",
                  n[3],
                  n[4]);
      std::printf("contact faces: %.0f, area %.4g of the end's %.4g m^2\n",
                  n[5],
                  n[6],
                  0.02 * 0.02);
    }

  // partition by cells (repartition() without weights), then by work
  triangulation.repartition();
  print_ranks("cells", triangulation, contact, largest_cell);
  Mesh::partition_by_work(triangulation, contact);
  print_ranks("work", triangulation, contact, largest_cell);
  return 0;
}
