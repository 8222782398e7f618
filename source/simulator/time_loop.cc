/**
 * The explicit run (SPEC 5): the initial state, the time loop of
 * central-difference steps with the postprocessors after each, the
 * checkpoint cadence, and the end of the run.
 */
#include <deal.II/base/mpi.h>
#include <deal.II/base/timer.h>
#include <deal.II/base/utilities.h>

#include <wheelrail/base/stop_signal.h>
#include <wheelrail/geometry/interface.h>
#include <wheelrail/mesh/geometry.h>
#include <wheelrail/postprocess/patch_series.h>
#include <wheelrail/postprocess/series_hdf5.h>
#include <wheelrail/simulator/format.h>
#include <wheelrail/simulator/simulator.h>
#include <wheelrail/verification/checks.h>

#include <chrono>
#include <cmath>

namespace WheelRail
{
  using Report::fmt;

  namespace
  {
    using Clock = std::chrono::steady_clock;

    /**
     * The timing of the steps after the warm-up (Output/Timing warm-up
     * steps): the solver's and the contact's part timers restart when the
     * warm-up ends; the wall time of each timed step and the time spent
     * in the postprocessing are kept for report_timing().
     */
    class StepClock
    {
    public:
      StepClock(const unsigned long warmup)
        : warmup(warmup)
        , timed_start(Clock::now())
      {}

      /** Before step @p n: at the end of the warm-up, restart the timers. */
      void
      start_step(const unsigned long n, ExplicitSolver &solver, PenaltyContact *contact)
      {
        if (n == warmup)
          {
            solver.reset_times();
            if (contact)
              contact->reset_times();
            output_seconds = 0;
            timed_start    = Clock::now();
          }
        step_start = Clock::now();
      }
      /** The step is done, the postprocessing begins. */
      void
      step_done(const unsigned long n)
      {
        output_start = Clock::now();
        if (n >= warmup)
          step_seconds.push_back(std::chrono::duration<double>(output_start - step_start).count());
      }
      /** The postprocessing of the step is done. */
      void
      output_done()
      {
        output_seconds += std::chrono::duration<double>(Clock::now() - output_start).count();
      }
      /** Seconds since the end of the warm-up. */
      double
      timed_seconds() const
      {
        return std::chrono::duration<double>(Clock::now() - timed_start).count();
      }

      const unsigned long warmup;
      double              output_seconds = 0;
      std::vector<double> step_seconds; ///< of the timed steps, for their spread

    private:
      Clock::time_point timed_start, step_start, output_start;
    };
  } // namespace



  void
  Simulator::setup_postprocessors()
  {
    const auto add = [&](auto pointer) {
      auto *raw = pointer.get();
      postprocessors.emplace_back(std::move(pointer));
      return raw;
    };
    auto balance   = std::make_unique<EnergyBalance>();
    energy_balance = balance.get();
    // In the order of execution after a step: the records of every step
    // first (a divergence writes them with this step), then the divergence
    // check, then what takes the energies of a statistics step.
    probes        = add(std::make_unique<Probes>(*access));
    contact_patch = add(std::make_unique<ContactPatch>(*access));
    add(std::make_unique<PatchSeries>(*access));
    // those Output/Postprocessors selects, before the statistics that
    // take their columns
    std::vector<Postprocessor *> selected;
    for (const auto &[name, factory] : parameters.output.postprocessors)
      selected.push_back(add(factory(*access)));
    // a profile case's results per patch: columns after the selected ones
    // (no state: checkpointed last, writing nothing)
    std::vector<Postprocessor *> with_columns = selected;
    if (contact && parameters.geometry_model->reports_patches())
      with_columns.push_back(patch_statistics = add(std::make_unique<PatchStatistics>(*access)));
    divergence =
      add(std::make_unique<DivergenceCheck>(*access, *energy_balance, [this] { write_records(); }));
    add(std::move(balance));
    statistics =
      add(std::make_unique<Statistics>(*access,
                                       *energy_balance,
                                       std::vector<const Postprocessor *>(with_columns.begin(),
                                                                          with_columns.end())));
    samples = add(std::make_unique<SampleRecorder>(*access));
    vtu     = add(std::make_unique<VtuOutput>(*access));
    // the order of the checkpoint format (a checkpoint of an earlier run
    // resumes only in this order), then the selected ones in their order
    checkpointed = {statistics, vtu, probes, contact_patch, energy_balance, samples, divergence};
    checkpointed.insert(checkpointed.end(), with_columns.begin(), with_columns.end());
  }



  void
  Simulator::run_explicit()
  {
    const bool resume = parameters.output.resume;
    // a resumed run has set up the postprocessors and read the checkpoint
    // in run(), before it wrote anything; otherwise the probes first: a
    // probe point outside the mesh stops the run before the static start
    if (!resume)
      {
        setup_postprocessors();
        if (wheelset)
          {
            start_wheelset();
            solver->set_rolling_velocity(wheelset->axle_velocity(),
                                         parameters.geometry_model->wheel_centre(),
                                         wheelset->angular_velocity());
          }
        else
          apply_initial_conditions();
      }
    // a signal during the static start or the initial conditions stops
    // the run before its first step
    StopSignal::stop_if_received(mpi_communicator,
                                 "before the time loop",
                                 resume ? "the checkpoint in " + checkpoint_directory +
                                            " is unchanged; resume again with --resume" :
                                          "no checkpoint was written; run the case again");
    const double        dt = solver->time_step();
    const unsigned long n_steps =
      static_cast<unsigned long>(std::ceil(parameters.solver.end_time / dt - 1e-9));
    const OutputParameters &op = parameters.output;
    for (const Probe &probe : probes->nodes())
      pcout << (&probe == &probes->nodes().front() ? "Probe node" : "Wheel probe node (passes O)")
            << " at (" << fmt(probe.location[0] * 1e3) << ", " << fmt(probe.location[1] * 1e3)
            << ", " << fmt(probe.location[2] * 1e3) << ") mm" << std::endl;

    Timer timer(mpi_communicator, true);
    if (!resume)
      {
        if (!parameters.problem.test_mode)
          vtu->write();
        probes->record();
      }
    const unsigned long first_step = solver->step_number();
    divergence->record_initial_velocities();
    last_checkpoint = Clock::now();
    StepClock clock(std::min<unsigned long>(first_step + op.timing_warmup_steps, n_steps));

    for (unsigned long n = first_step; n < n_steps; ++n)
      {
        clock.start_step(n, *solver, contact.get());
        const bool report_step = (n % op.report_interval == 0);
        const bool stats_step  = (n % op.statistics_interval == 0) || report_step;
        Energies   e;
        if (contact)
          contact->evaluate_every_slave(n + 1 == n_steps); // the gaps of contact_nodes.csv
        solver->step(stats_step ? &e : nullptr);
        clock.step_done(n);
        postprocess({n, n_steps, stats_step ? &e : nullptr, report_step},
                    stats_step ? timer.wall_time() : 0.);
        clock.output_done();
        if (checkpoint_if_due(n, n_steps))
          return;
      }
    finish_explicit(n_steps,
                    clock.timed_seconds(),
                    clock.output_seconds,
                    n_steps - clock.warmup,
                    clock.step_seconds,
                    timer);
  }



  void
  Simulator::postprocess(const StepInfo &step, const double wall_seconds)
  {
    for (const auto &postprocessor : postprocessors)
      postprocessor->execute(step);
    if (step.report_step)
      report(*step.energies, wall_seconds);
  }



  void
  Simulator::write_records() const
  {
    for (const auto &postprocessor : postprocessors)
      postprocessor->write_files();
    write_series_hdf5(*access, *statistics, *probes);
    if (contact)
      write_contact_nodes(*access, "contact_nodes.csv");
  }



  bool
  Simulator::checkpoint_if_due(const unsigned long n, const unsigned long n_steps)
  {
    // checkpoint every N steps, every M minutes (rank 0's clock decides),
    // at a requested stop, and after SIGTERM or SIGINT on any rank: one
    // collective of two ints (none on one rank) tells all ranks alike the
    // signal and rank 0's minutes: after every step with Checkpoint
    // minutes, else after every StopSignal::check_interval-th step
    const OutputParameters &op = parameters.output;
    const bool stop = op.stop_after_step > 0 && n + 1 == op.stop_after_step && n + 1 < n_steps;
    bool       due  = stop || (op.checkpoint_interval > 0 && (n + 1) % op.checkpoint_interval == 0);
    const bool minutes   = op.checkpoint_minutes > 0;
    const bool ask       = minutes || (n + 1) % StopSignal::check_interval == 0;
    int        agreed[2] = {ask ? StopSignal::received() : 0, 0};
    if (minutes && Utilities::MPI::this_mpi_process(mpi_communicator) == 0)
      agreed[1] = std::chrono::duration<double>(Clock::now() - last_checkpoint).count() / 60. >=
                  op.checkpoint_minutes;
    if (ask && Utilities::MPI::n_mpi_processes(mpi_communicator) > 1)
      MPI_Allreduce(MPI_IN_PLACE, agreed, 2, MPI_INT, MPI_MAX, mpi_communicator);
    const int signal = agreed[0];
    due              = due || agreed[1] || signal;
    if (due && n + 1 < n_steps)
      {
        for (const auto &postprocessor : postprocessors)
          postprocessor->write_files();
        write_series_hdf5(*access, *statistics, *probes);
        write_checkpoint();
        last_checkpoint = Clock::now();
      }
    if (stop)
      pcout << "Stopped after step " << n + 1
            << " (Output/Stop after step) at t = " << fmt(solver->time() * 1e3)
            << " ms; checkpoint in " << output_directory
            << "/checkpoint; continue with: wheelrail CASE.prm --resume" << std::endl;
    // a signal in the last step lets the run finish
    else if (signal && n + 1 < n_steps)
      throw StopSignal::Stopped(signal,
                                "stopped by " + StopSignal::name(signal) + " at step " +
                                  std::to_string(n + 1) + ", t = " + fmt(solver->time() * 1e3) +
                                  " ms; checkpoint written in " + output_directory +
                                  "/checkpoint, resume with: wheelrail CASE.prm --resume");
    return stop;
  }



  void
  Simulator::finish_explicit(const unsigned long  n_steps,
                             const double         timed_seconds,
                             const double         output_seconds,
                             const unsigned long  n_timed_steps,
                             std::vector<double> &step_seconds,
                             Timer               &timer)
  {
    const bool test = parameters.problem.test_mode;
    write_records();
    if (!test)
      vtu->write();
    timer.stop();

    pcout << "Explicit run finished: " << n_steps << " steps to t = " << fmt(solver->time() * 1e3)
          << " ms; largest energy balance error " << fmt(energy_balance->max_balance_error(), 2)
          << std::endl;
    if (!test)
      {
        const double cells = triangulation.n_global_active_cells();
        pcout << "  wall time " << fmt(timer.wall_time(), 4) << " s, "
              << fmt(timer.wall_time() / (cells * n_steps) * 1e9 *
                       Utilities::MPI::n_mpi_processes(mpi_communicator),
                     4)
              << " ns per element-step per rank ("
              << fmt(timer.wall_time() / (cells * n_steps) * 1e9, 4) << " ns wall)" << std::endl;
        report_timing(timed_seconds, output_seconds, n_timed_steps, step_seconds);
        if (contact)
          pcout << "  contact: " << contact->n_searches() << " candidate searches ("
                << contact->n_approach_searches() << " for the approach bound alone), "
                << fmt(contact->search_seconds() / std::max(1u, contact->n_searches()) * 1e3, 3)
                << " ms per search; at the last search " << contact->n_candidates().first
                << " candidate slaves, " << contact->n_candidates().second << " slave-face pairs"
                << std::endl;
        pcout << "  results in " << output_directory
              << "/ (solution.pvd, statistics, probe.csv, parameters.prm)" << std::endl;
      }
    contact_patch->print_summary();
    if (patch_statistics)
      patch_statistics->print_summary();
    Verification::run_final_check(*access, *probes, *energy_balance, *samples);
  }
} // namespace WheelRail
