/**
 * @file simulator/partition_report.cc
 * How the run is split between the ranks, printed with the timing: what
 * each rank computes (cells, the cells of family batches, the contact's
 * slaves) and what it exchanges at every step (ghost nodes, the ranks it
 * exchanges them with, the collectives). The figures that decide how far
 * the explicit step scales with the number of ranks.
 */

#include <deal.II/base/mpi.h>

#include <wheelrail/geometry/interface.h>
#include <wheelrail/mesh/partition_weights.h>
#include <wheelrail/simulator/format.h>
#include <wheelrail/simulator/simulator.h>

#include <algorithm>
#include <set>

namespace WheelRail
{
  void
  Simulator::report_partition() const
  {
    using Report::fmt;
    const MPI_Comm     comm    = mpi_communicator;
    const unsigned int n_ranks = Utilities::MPI::n_mpi_processes(comm);
    const auto        &part    = *solver->partitioner();
    // the nodes a rank owns and its ghosts (3 DoFs each), the ranks it
    // receives ghosts from or sends its own to: one message each way for
    // each of the step's exchanges (the ghosts of u and v, the forces)
    const double owned = part.locally_owned_size() / dim, ghosts = part.n_ghost_indices() / dim;
    std::set<unsigned int> neighbours;
    for (const auto &target : part.ghost_targets())
      neighbours.insert(target.first);
    for (const auto &target : part.import_targets())
      neighbours.insert(target.first);
    const double cells  = triangulation.n_locally_owned_active_cells();
    const double family = solver->n_family_cells();
    const auto   range  = [&](const double x) {
      return std::make_pair(Utilities::MPI::min(x, comm), Utilities::MPI::max(x, comm));
    };
    // the hanging nodes (owned and ghost) that condense() and distribute()
    // visit every step
    const double hanging = solver->constrained_local_dofs().size() / dim;
    const auto   c = range(cells), fc = range(family), n = range(owned), hn = range(hanging);
    const auto   ratio = range(owned > 0 ? ghosts / owned : 0.);
    const auto   peers = range(neighbours.size());
    const double ghost_mean =
      Utilities::MPI::sum(ghosts, comm) / std::max(1., Utilities::MPI::sum(owned, comm));
    pcout << "  partition: cells per rank " << fmt(c.first, 7) << " to " << fmt(c.second, 7)
          << " (in family batches " << fmt(fc.first, 7) << " to " << fmt(fc.second, 7)
          << "), owned nodes " << fmt(n.first, 7) << " to " << fmt(n.second, 7)
          << ", hanging nodes " << fmt(hn.first, 7) << " to " << fmt(hn.second, 7) << std::endl
          << "    ghost nodes per owned node " << fmt(ratio.first, 3) << " to "
          << fmt(ratio.second, 3) << " (all ranks " << fmt(ghost_mean, 3) << "), neighbour ranks "
          << peers.first << " to " << peers.second
          << ": per step 3 exchanges with each (ghosts of u and v, forces)" << std::endl;
    // the work model of Problem/Partition = work, whichever partition ran
    const Mesh::RankWork w =
      Mesh::rank_work(triangulation,
                      Mesh::contact_boundaries(parameters.contact,
                                               parameters.geometry_model->has_contact()));
    const auto   wr   = range(w.work);
    const double mean = Utilities::MPI::sum(w.work, comm) / n_ranks;
    const auto oc = range(w.other_cells), hf = range(w.hanging_faces), cf = range(w.contact_faces);
    pcout << "    cell work per rank in family cells' element work (mesh/partition_weights.h; "
          << "Problem/Partition = " << partition_by_names(parameters.problem.partition)
          << "): " << fmt(wr.first / Mesh::CellWorkModel::family_cell, 7) << " to "
          << fmt(wr.second / Mesh::CellWorkModel::family_cell, 7) << ", largest / mean "
          << fmt(wr.second / mean, 4) << "; cells outside families " << fmt(oc.first, 6) << " to "
          << fmt(oc.second, 6) << ", faces with hanging nodes " << fmt(hf.first, 6) << " to "
          << fmt(hf.second, 6) << ", contact faces " << fmt(cf.first, 6) << " to "
          << fmt(cf.second, 6) << std::endl;
    if (contact && contact->times().evaluations > 0)
      {
        const ContactTimes &t = contact->times();
        const double        e = t.evaluations;
        pcout << "    contact per step: " << fmt(t.candidates / e, 6) << " candidate slaves, "
              << fmt(t.computed / e, 6) << " computed (" << fmt(100. * t.computed / t.candidates, 3)
              << " %), " << fmt(t.computed / e / n_ranks, 6) << " per rank";
        if (n_ranks > 1)
          pcout << "; " << 2 + 2 * contact->n_passes()
                << " collectives (approach bound, positions, per pass gaps and states)";
        pcout << std::endl;
      }
  }
} // namespace WheelRail
