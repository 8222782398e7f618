#include <deal.II/base/mpi.h>
#include <deal.II/base/utilities.h>

#include <wheelrail/simulator/format.h>
#include <wheelrail/simulator/simulator.h>
#include <wheelrail/solver/element_data.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <iomanip>
#include <sstream>
#include <utility>
#include <vector>

namespace WheelRail
{
  using Report::fmt;

  namespace
  {
    /** Smallest and largest value of entry @p k over the rows of @p by_rank. */
    std::pair<double, double>
    extremes(const std::vector<std::vector<double>> &by_rank, const unsigned int k)
    {
      std::pair<double, double> range{by_rank[0][k], by_rank[0][k]};
      for (const std::vector<double> &row : by_rank)
        range = {std::min(range.first, row[k]), std::max(range.second, row[k])};
      return range;
    }

    /**
     * The timed parts of the steps (entries 0-5 of each row of @p by_rank,
     * one row per rank), of the contact (entries 6-11, printed where
     * @p with_contact) and two parts of the update (entries 12-13): each
     * rank's own on up to eight ranks, else each part's largest and
     * smallest time over the ranks. @p by_rank is empty except on rank 0,
     * which prints.
     */
    void
    print_split(const ConditionalOStream               &out,
                const std::vector<std::vector<double>> &by_rank,
                const bool                              with_contact)
    {
      if (by_rank.empty())
        return;
      const char *const names[3][6] = {
        {"elements", "contact", "update", "communication", "energies", "output"},
        {"search", "wait", "positions", "slaves", "exchange", "forces"},
        {"constraints", "rigid body"}};
      const char *const  titles[3] = {"  split", "  contact split", "  update split"};
      const unsigned int sizes[3]  = {6, 6, 2};
      const unsigned int n_ranks   = by_rank.size();
      for (const unsigned int block : {0u, 1u, 2u})
        {
          if (block == 1 && !with_contact)
            continue;
          out << titles[block];
          if (n_ranks > 8)
            {
              out << ", largest / smallest time over the ranks (s):";
              for (unsigned int i = 0; i < sizes[block]; ++i)
                {
                  const auto [least, most] = extremes(by_rank, 6 * block + i);
                  out << " " << names[block][i] << " " << fmt(most, 3) << " / " << fmt(least, 3);
                }
              out << std::endl;
              continue;
            }
          out << (n_ranks > 1 ? " by rank (s):\n" : " (s):");
          for (unsigned int r = 0; r < n_ranks; ++r)
            {
              if (n_ranks > 1)
                out << "    rank " << r << ":";
              for (unsigned int i = 0; i < sizes[block]; ++i)
                out << " " << names[block][i] << " "
                    << fmt(by_rank[r][6 * block + i], block == 0 ? 4 : 3);
              out << std::endl;
            }
        }
    }
  } // namespace



  void
  Simulator::report(const Energies &e, const double wall_seconds) const
  {
    if (access->robust_output_only())
      return;
    pcout << "step " << std::setw(8) << e.step << "  t = " << std::setw(10) << fmt(e.time * 1e3)
          << " ms  E_kin " << fmt(e.kinetic) << " J  E_int " << fmt(e.internal) << " J  E_hg "
          << fmt(e.hourglass, 3) << " J  D " << fmt(e.damping, 3) << " J  W_ext "
          << fmt(e.external_work) << " J";
    if (contact)
      pcout << "  contact " << contact->summary().n_contact << " nodes, F = ("
            << fmt(contact->summary().force[0] * 1e-3, 4) << ", "
            << fmt(contact->summary().force[1] * 1e-3, 4) << ", "
            << fmt(contact->summary().force[2] * 1e-3, 4) << ") kN  E_c " << fmt(e.contact, 3)
            << " J  D_f " << fmt(e.friction, 3) << " J";
    pcout << "  balance error " << fmt(energy_balance->max_balance_error(), 2);
    if (!parameters.problem.test_mode)
      {
        // progress of a long run: steps per second and the time to finish
        const double rate  = e.step / std::max(wall_seconds, 1e-9);
        const double total = std::ceil(parameters.solver.end_time / solver->time_step() - 1e-9);
        pcout << "  [" << fmt(wall_seconds, 3) << " s, " << fmt(rate, 3) << " steps/s";
        if (e.step > 0)
          pcout << ", " << fmt(100. * e.step / total, 3) << " %, ETA "
                << fmt((total - e.step) / rate, 3) << " s";
        pcout << "]";
      }
    pcout << std::endl;
  }



  std::vector<std::vector<double>>
  Simulator::gather_part_times(const double output_seconds) const
  {
    const StepTimes    &t = solver->step_times();
    const ContactTimes  no_contact;
    const ContactTimes &c = contact ? contact->times() : no_contact;
    return Utilities::MPI::gather(mpi_communicator,
                                  std::vector<double>{t.elements,
                                                      t.contact,
                                                      t.update,
                                                      t.communication,
                                                      t.energies,
                                                      output_seconds,
                                                      c.search,
                                                      c.wait,
                                                      c.positions,
                                                      c.slaves,
                                                      c.exchange,
                                                      c.forces,
                                                      t.constraints,
                                                      t.rigid_body},
                                  0);
  }



  std::array<double, 3>
  Simulator::step_time_spread(std::vector<double> &step_seconds) const
  {
    // fastest, median and 95th percentile, each the largest over the
    // ranks, in ms; printed where any step was timed
    std::array<double, 3> spread = {{0, 0, 0}};
    if (!step_seconds.empty())
      {
        const auto at = [&](const double q) {
          const std::size_t k =
            std::min<std::size_t>(step_seconds.size() - 1, q * step_seconds.size());
          std::nth_element(step_seconds.begin(), step_seconds.begin() + k, step_seconds.end());
          return 1e3 * step_seconds[k];
        };
        const double local[3] = {at(0.), at(0.5), at(0.95)};
        Utilities::MPI::max(ArrayView<const double>(local, 3),
                            mpi_communicator,
                            ArrayView<double>(spread.data(), 3));
        pcout << "  step wall time (ms): fastest " << fmt(spread[0], 4) << ", median "
              << fmt(spread[1], 4) << ", 95th percentile " << fmt(spread[2], 4) << std::endl;
      }
    return spread;
  }



  void
  Simulator::report_timing(const double         wall_seconds,
                           const double         output_seconds,
                           const unsigned long  n_steps,
                           std::vector<double> &step_seconds) const
  {
    const double       cells   = triangulation.n_global_active_cells();
    const unsigned int n_ranks = Utilities::MPI::n_mpi_processes(mpi_communicator);
    // Each rank's parts: the run goes at the pace of the slowest rank in
    // each part, and a faster rank's lead shows up as waiting in the next
    // part that meets the other ranks (the contact's first reduction, or the
    // communication). timing.csv keeps each part's largest time over the ranks.
    const std::vector<std::vector<double>> by_rank = gather_part_times(output_seconds);
    const double                         wall = Utilities::MPI::max(wall_seconds, mpi_communicator);
    const Utilities::System::MemoryStats memory = [] {
      Utilities::System::MemoryStats m;
      Utilities::System::get_memory_stats(m);
      return m;
    }();
    const double       peak_mb = Utilities::MPI::max(memory.VmHWM / 1024., mpi_communicator);
    const unsigned int family_cells =
      Utilities::MPI::sum(solver->n_family_cells(), mpi_communicator);
    const double ns = n_steps > 0 ? wall / (cells * n_steps) * 1e9 : 0.;
    // the paper's full run: 0.22 m of rolling at 2.6e-8 s
    const double full_steps = 0.22 / parameters.wheelset.rolling_speed / 2.6e-8;
    const double full_hours = ns * 1e-9 * cells * full_steps / 3600.;

    pcout << "Timing of " << n_steps << " steps (after " << parameters.output.timing_warmup_steps
          << " warm-up steps) on " << n_ranks << " rank(s), " << fmt(cells, 8) << " cells, "
          << solver->get_dof_handler().n_dofs() << " DoFs:" << std::endl
          << "  wall " << fmt(wall, 4) << " s, " << fmt(ns, 4) << " ns per element-step (wall), "
          << fmt(ns * n_ranks, 4) << " ns per element-step per rank" << std::endl
          << "  cells in family batches (8 cells arranged as the children of one "
             "parent: 27 nodes gathered "
             "and scattered, not 64): "
          << family_cells << " (" << fmt(100. * family_cells / cells, 3) << " %)" << std::endl;
    const auto [blocks, batches]  = solver->n_single_blocks_and_batches();
    const unsigned int all_blocks = Utilities::MPI::sum(blocks, mpi_communicator);
    if (all_blocks > 0)
      pcout << "  single-precision element data: " << all_blocks << " distinct blocks for "
            << Utilities::MPI::sum(batches, mpi_communicator) << " batches ("
            << fmt(all_blocks * ElementKernel::SingleField::n_double * 8e-6, 3) << " MB)"
            << std::endl;
    print_split(pcout, by_rank, contact != nullptr);
    report_partition();
    // The wall time of single steps (this machine's noise: on a shared
    // host the same step's time varies by tens of per cent, and with
    // several ranks each step waits for the slowest): fastest, median and
    // 95th percentile, each the largest over the ranks, in ms
    const std::array<double, 3> spread = step_time_spread(step_seconds);
    pcout << "  peak memory per rank " << fmt(peak_mb, 5) << " MB" << std::endl
          << "  the paper's full run (" << fmt(full_steps, 6)
          << " steps of 2.6e-8 s) at this rate on " << fmt(cells, 8)
          << " cells: " << fmt(full_hours, 3) << " h" << std::endl;

    // timing.csv: rank 0 alone holds by_rank and writes files
    if (by_rank.empty())
      return;
    std::ostringstream csv;
    csv
      << "# wheelrail timing: wall seconds of the timed steps (slowest rank), ns per element-step "
         "(wall), each part of the split its largest time over the ranks, peak resident memory per "
         "rank (largest) in MB\n"
      << "ranks,cells,dofs,steps,wall_s,ns_per_element_step,elements_s,contact_s,update_s,"
         "communication_s,energies_s,output_s,peak_memory_mb,projected_full_run_h,"
         "fastest_step_ms,median_step_ms,p95_step_ms\n"
      << n_ranks << "," << cells << "," << solver->get_dof_handler().n_dofs() << "," << n_steps
      << "," << wall << "," << ns;
    for (unsigned int i = 0; i < 6; ++i)
      csv << "," << extremes(by_rank, i).second;
    csv << "," << peak_mb << "," << full_hours;
    for (unsigned int i = 0; i < 3; ++i)
      csv << "," << spread[i];
    csv << "\n";
    access->write_file("timing.csv", csv.str());
  }
} // namespace WheelRail
