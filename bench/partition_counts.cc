// What the explicit step exchanges on N ranks, computed on one rank from the
// partition that p4est would make: the active cells in p4est's order (the
// trees in p4est's order, each cell's children in z-order) split into N
// contiguous blocks of equal size (Problem/Partition = cells) or of equal
// work (= work, the weights of mesh/partition_weights.h: the first cell
// whose work starts at or after r W / N begins rank r's block), a node
// owned by the lowest rank among
// its cells, and a rank's ghost nodes the nodes of its cells and of the
// cells that share a vertex with them (deal.II's locally relevant set; the
// hanging nodes' masters that the solver adds are left out) that it does not
// own. Per rank count: owned nodes, ghost nodes per owned node and the ranks
// a rank exchanges with (each way, three times a step: the ghosts of u and v
// and the forces), smallest and largest over the ranks. p4est moves block
// boundaries so that the 8 children of a parent stay on one rank; the counts
// here do not, and differ from a run's by that (the note compares them with
// the runs on 2, 4 and 8 ranks). Also per rank count: the largest rank's
// work over the mean (the weights of mesh/partition_weights.h, whichever
// partition) and the smallest and largest cell count.
//
// usage: partition_counts CASE.prm [N ...]   (default N: 2 4 8 16 32 64)

#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>

#include <deal.II/distributed/tria.h>

#include <wheelrail/geometry/interface.h>
#include <wheelrail/mesh/partition_weights.h>
#include <wheelrail/parameters/parameters.h>

#include <algorithm>
#include <array>
#include <cstdio>
#include <cstdlib>
#include <vector>

using namespace dealii;
constexpr unsigned int dim = 3;

namespace
{
  // a short sorted set of ranks
  void
  insert(std::vector<unsigned int> &set, const unsigned int r)
  {
    const auto it = std::lower_bound(set.begin(), set.end(), r);
    if (it == set.end() || *it != r)
      set.insert(it, r);
  }

  void
  collect(const typename Triangulation<dim>::cell_iterator &cell,
          const std::vector<types::boundary_id>            &contact_boundaries,
          std::vector<std::array<unsigned int, 8>>         &vertices,
          std::vector<double>                              &work)
  {
    if (cell->is_active())
      {
        std::array<unsigned int, 8> v;
        for (unsigned int k = 0; k < 8; ++k)
          v[k] = cell->vertex_index(k);
        vertices.push_back(v);
        work.push_back(WheelRail::Mesh::cell_work_parts(cell, contact_boundaries).work());
      }
    else
      for (unsigned int c = 0; c < cell->n_children(); ++c)
        collect(cell->child(c), contact_boundaries, vertices, work);
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  if (argc < 2)
    {
      std::fprintf(stderr, "usage: partition_counts CASE.prm [N ...]\n");
      return 2;
    }
  std::vector<unsigned int> counts;
  for (int i = 2; i < argc; ++i)
    counts.push_back(std::atoi(argv[i]));
  if (counts.empty())
    counts = {2, 4, 8, 16, 32, 64};
  try
    {
      ParameterHandler      prm;
      WheelRail::Parameters parameters;
      WheelRail::Parameters::declare_parameters(prm);
      parameters.parse(prm, argv[1]);
      parallel::distributed::Triangulation<dim> triangulation(MPI_COMM_SELF);
      WheelRail::Geometry::build(*parameters.geometry_model, triangulation);

      // the active cells in p4est's order, by their vertices
      const auto contact_boundaries =
        WheelRail::Mesh::contact_boundaries(parameters.contact,
                                            parameters.geometry_model->has_contact());
      const bool by_work = parameters.problem.partition == WheelRail::PartitionBy::work;
      std::vector<std::array<unsigned int, 8>> cells;
      std::vector<double>                      work;
      for (const auto coarse : triangulation.get_p4est_tree_to_coarse_cell_permutation())
        collect(typename Triangulation<dim>::cell_iterator(&triangulation, 0, coarse),
                contact_boundaries,
                cells,
                work);
      double total_work = 0;
      for (const double w : work)
        total_work += w;
      const std::size_t n_cells    = cells.size();
      const std::size_t n_vertices = triangulation.n_vertices();
      std::printf("%zu cells, %zu vertices in use\n",
                  n_cells,
                  std::size_t(std::count(triangulation.get_used_vertices().begin(),
                                         triangulation.get_used_vertices().end(),
                                         true)));
      std::printf("partition by %s\n", by_work ? "work" : "cells");
      std::printf("ranks,cells_per_rank,owned_nodes_min,owned_nodes_max,ghosts_per_owned_min,"
                  "ghosts_per_owned_max,ghosts_per_owned_all,neighbours_min,neighbours_max,"
                  "work_max_over_mean,cells_min,cells_max\n");
      for (const unsigned int N : counts)
        {
          std::vector<unsigned int> part(n_cells);
          if (by_work)
            {
              double before = 0;
              for (std::size_t k = 0; k < n_cells; ++k)
                {
                  part[k] = std::min<unsigned int>(N - 1, before * N / total_work + 1e-9);
                  before += work[k];
                }
            }
          else
            for (unsigned int r = 0; r < N; ++r)
              for (std::size_t k = n_cells * r / N; k < n_cells * (r + 1) / N; ++k)
                part[k] = r;
          std::vector<double> rank_work(N, 0), rank_cells(N, 0);
          for (std::size_t k = 0; k < n_cells; ++k)
            {
              rank_work[part[k]] += work[k];
              rank_cells[part[k]] += 1;
            }
          // per vertex: the ranks of its cells (owner: the lowest)
          std::vector<std::vector<unsigned int>> vertex_parts(n_vertices);
          for (std::size_t k = 0; k < n_cells; ++k)
            for (const unsigned int v : cells[k])
              insert(vertex_parts[v], part[k]);
          // per vertex: the ranks that hold it as relevant (a rank of a
          // cell that shares a vertex with a cell of the vertex)
          std::vector<std::vector<unsigned int>> relevant(n_vertices);
          for (std::size_t k = 0; k < n_cells; ++k)
            {
              std::vector<unsigned int> ranks;
              for (const unsigned int v : cells[k])
                for (const unsigned int r : vertex_parts[v])
                  insert(ranks, r);
              for (const unsigned int v : cells[k])
                for (const unsigned int r : ranks)
                  insert(relevant[v], r);
            }
          std::vector<double>                    owned(N, 0), ghosts(N, 0);
          std::vector<std::vector<unsigned int>> neighbours(N);
          for (std::size_t v = 0; v < n_vertices; ++v)
            {
              if (vertex_parts[v].empty())
                continue;
              const unsigned int owner = vertex_parts[v].front();
              ++owned[owner];
              for (const unsigned int r : relevant[v])
                if (r != owner)
                  {
                    ++ghosts[r];
                    insert(neighbours[r], owner);
                    insert(neighbours[owner], r);
                  }
            }
          double       ratio_min = 1e300, ratio_max = 0, owned_min = 1e300, owned_max = 0;
          unsigned int peers_min = N, peers_max = 0;
          double       all_owned = 0, all_ghosts = 0;
          for (unsigned int r = 0; r < N; ++r)
            {
              ratio_min = std::min(ratio_min, ghosts[r] / owned[r]);
              ratio_max = std::max(ratio_max, ghosts[r] / owned[r]);
              owned_min = std::min(owned_min, owned[r]);
              owned_max = std::max(owned_max, owned[r]);
              peers_min = std::min<unsigned int>(peers_min, neighbours[r].size());
              peers_max = std::max<unsigned int>(peers_max, neighbours[r].size());
              all_owned += owned[r];
              all_ghosts += ghosts[r];
            }
          std::printf("%u,%.0f,%.0f,%.0f,%.4f,%.4f,%.4f,%u,%u,%.4f,%.0f,%.0f\n",
                      N,
                      double(n_cells) / N,
                      owned_min,
                      owned_max,
                      ratio_min,
                      ratio_max,
                      all_ghosts / all_owned,
                      peers_min,
                      peers_max,
                      *std::max_element(rank_work.begin(), rank_work.end()) * N / total_work,
                      *std::min_element(rank_cells.begin(), rank_cells.end()),
                      *std::max_element(rank_cells.begin(), rank_cells.end()));
        }
    }
  catch (const std::exception &e)
    {
      std::fprintf(stderr, "Error: %s\n", e.what());
      return 1;
    }
  return 0;
}
