/**
 * @file simulator/simulator.h
 * The run of one parameter file: mesh, solver, initial and boundary
 * conditions, time loop, reports, output files and verification checks.
 *
 * The class is split over several files in source/simulator/: setup.cc
 * (construction, output directory, setup summary, run()), static_runs.cc
 * (patch test and rigid rotation, static contact, the wheelset's start),
 * time_loop.cc (the explicit run), reports.cc (progress and timing) and
 * restart.cc (checkpoint and resume). The postprocessing lives in
 * postprocess/, the checks in verification/.
 */
#ifndef wheelrail_simulator_simulator_h
#define wheelrail_simulator_simulator_h

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/timer.h>

#include <deal.II/distributed/tria.h>

#include <wheelrail/base/checkpoint.h>
#include <wheelrail/contact/penalty_contact.h>
#include <wheelrail/parameters/parameters.h>
#include <wheelrail/postprocess/contact_patch.h>
#include <wheelrail/postprocess/energy_balance.h>
#include <wheelrail/postprocess/output_files.h>
#include <wheelrail/postprocess/patch_statistics.h>
#include <wheelrail/postprocess/postprocessor.h>
#include <wheelrail/postprocess/probes.h>
#include <wheelrail/postprocess/statistics.h>
#include <wheelrail/postprocess/vtu_output.h>
#include <wheelrail/simulator/divergence_check.h>
#include <wheelrail/solver/explicit_solver.h>
#include <wheelrail/solver/wheelset.h>
#include <wheelrail/solver/wheelset_coupling.h>
#include <wheelrail/verification/samples.h>

#include <array>
#include <chrono>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

namespace WheelRail
{
  struct StaticResult;

  /**
   * Runs one case. run() follows SPEC 5 as far as the explicit core goes:
   * build mesh and solver, print the setup summary, then either a static
   * verification (patch test, rigid rotation), the static contact, or the
   * explicit run.
   */
  class Simulator
  {
  public:
    Simulator(const Parameters &parameters, const ParameterHandler &prm, MPI_Comm comm);

    void
    run();

  private:
    // setup.cc
    /** Create the output directory and lock it (DirectoryLock); nothing
     *  is written there before the setup has succeeded. */
    void
    prepare_output_directory();
    void
    print_setup_summary();
    /** The contact's part of the setup summary. */
    void
    print_contact_summary();
    /** Time integration/Time step, checked against the stable one, or
     *  the stable step. */
    void
    choose_time_step();
    /** Refuse an explicit run of more than 1e8 steps or with a Time step
     *  under a thousandth of the stable one, unless Time integration/Allow
     *  long runs confirms it. */
    void
    check_run_length() const;
    /** Where the implicit solver's iterations go: the screen of rank 0,
     *  or nowhere in test mode and on the other ranks. */
    std::ostream &
    solver_log();

    // static_runs.cc
    /** Patch test or rigid rotation: one evaluation of the internal
     *  forces (Problem/Mode). */
    void
    run_static_check();
    /** The patch test: u = G X on every node. */
    void
    run_patch_test();
    /** The wheel pressed onto the rail by the axle load, against Hertz. */
    void
    run_static_contact();
    /** Static equilibrium at A and the start of rolling (SPEC 5.2, 5.3). */
    void
    start_wheelset();
    void
    apply_initial_conditions();

    // static_start_state.cc
    /** The static start from Wheelset/Static start state, if a run of the
     *  same static problem wrote it there: the solver's and the contact's
     *  state and @p result. False if there is none (or no directory is
     *  set); a state that does not fit this run stops it, naming why. */
    bool
    read_static_start(StaticResult &result);
    /** The static start just solved into Wheelset/Static start state
     *  (written beside it, then renamed: a reader sees all or nothing). */
    void
    write_static_start(const StaticResult &result);

    // time_loop.cc
    /** Create the postprocessors (the probes first: a probe point outside
     *  the mesh stops the run) in their order of execution. */
    void
    setup_postprocessors();
    /** The explicit run: initial state or checkpoint, the time loop, the
     *  final outputs and check. */
    void
    run_explicit();
    /** After step @p step.step: the postprocessors in order, then the
     *  progress report at a report step. */
    void
    postprocess(const StepInfo &step, const double wall_seconds);
    /** Write a checkpoint when one is due after step @p n; true if the
     *  run stops here (Output/Stop after step). */
    bool
    checkpoint_if_due(const unsigned long n, const unsigned long n_steps);
    /** The files written before a checkpoint and at a divergence. */
    void
    write_records() const;
    /** The last outputs, reports and the check of a finished run. */
    void
    finish_explicit(const unsigned long  n_steps,
                    const double         timed_seconds,
                    const double         output_seconds,
                    const unsigned long  n_timed_steps,
                    std::vector<double> &step_seconds,
                    Timer               &timer);

    // reports.cc
    void
    report(const Energies &e, const double wall_seconds) const;
    /** Time split, ns per element-step, the spread of the step times
     *  (@p step_seconds: this rank's timed steps, reordered here), peak
     *  memory and the projected full paper run: on the screen and in
     *  timing.csv. */
    void
    report_timing(const double         wall_seconds,
                  const double         output_seconds,
                  const unsigned long  n_steps,
                  std::vector<double> &step_seconds) const;
    /** How the mesh is split between the ranks, printed with the timing:
     *  cells and family cells per rank, ghost nodes per owned node, the
     *  ranks each exchanges with, and the contact's share per rank
     *  (partition_report.cc). */
    void
    report_partition() const;
    /** Every rank's times of the parts of the steps and of the contact,
     *  on rank 0 (empty on the others). */
    std::vector<std::vector<double>>
    gather_part_times(const double output_seconds) const;
    /** The spread of the step times (this machine's noise: on a shared
     *  host the same step's time varies by tens of per cent, and with
     *  several ranks each step waits for the slowest), printed. */
    std::array<double, 3>
    step_time_spread(std::vector<double> &step_seconds) const;

    // restart.cc
    /** Write the whole run state to OUTDIR/checkpoint/ (write, then
     *  rename: the previous checkpoint stays until the new one is
     *  complete). */
    void
    write_checkpoint();
    /** Before the setup of a resumed run: every rank file is complete and
     *  its checksum matches, the rank count is the checkpoint's, and no
     *  parameter other than EntryFlags::entries(EntryFlag::resumable) differs from
     *  the run that wrote it (those that do are listed). */
    void
    check_checkpoint();
    /** Read the state back (wheelrail CASE.prm --resume): in run(), after
     *  the setup and before anything is written. */
    void
    read_checkpoint();
    /** The header of this rank's file of the run state now: rank count,
     *  mesh size, step, time, time step and the parameter record. */
    Checkpoint::Header
    state_header() const;
    /** The run state after the header, in the order of the checkpoint
     *  format: solver, contact, wheelset, postprocessors. */
    template <class Archive>
    void
    serialize(Archive &ar);

    const Parameters &parameters;
    /** The parameter file as parsed: for OUTDIR/parameters.prm (with the
     *  documentation) and for the checkpoints (ShortPRM). */
    const std::string                         parameter_file;
    const std::string                         parameter_record;
    MPI_Comm                                  mpi_communicator;
    ConditionalOStream                        pcout;
    parallel::distributed::Triangulation<dim> triangulation;
    std::unique_ptr<ExplicitSolver>           solver;
    std::unique_ptr<PenaltyContact>           contact;
    std::unique_ptr<Wheelset>                 wheelset;
    /** The wheelset coupled to the FE wheel, for the solver */
    std::unique_ptr<WheelsetCoupling> wheelset_coupling;
    std::string                       output_directory;
    /** Held by rank 0 from the start to the end of the run. */
    std::unique_ptr<DirectoryLock> lock;
    /** OUTDIR/checkpoint, or checkpoint.old if a run died between the
     *  two renames of write_checkpoint(); set by check_checkpoint(). */
    std::string checkpoint_directory;
    /** The resumable entries that differ from the checkpoint's run; set by
     *  check_checkpoint(), listed by read_checkpoint(). */
    std::vector<Checkpoint::Change> resumed_changes;
    std::ostringstream              silent_log;
    /** What the postprocessors and checks read of the run (after the
     *  setup). */
    std::unique_ptr<SimulatorAccess> access;

    /** The postprocessors of the explicit run, in the order in which the
     *  time loop executes them; the pointers below name those that the
     *  simulator also calls directly. */
    std::vector<std::unique_ptr<Postprocessor>> postprocessors;
    /** The same in the order of the checkpoint format. */
    std::vector<Postprocessor *> checkpointed;
    Probes                      *probes         = nullptr;
    ContactPatch                *contact_patch  = nullptr;
    DivergenceCheck             *divergence     = nullptr;
    EnergyBalance               *energy_balance = nullptr;
    Statistics                  *statistics     = nullptr;
    SampleRecorder              *samples        = nullptr;
    VtuOutput                   *vtu            = nullptr;
    /** The results per patch (a geometry that reports patches), or null. */
    PatchStatistics *patch_statistics = nullptr;
    /** When the last checkpoint was written (Output/Checkpoint minutes). */
    std::chrono::steady_clock::time_point last_checkpoint;
  };
} // namespace WheelRail

#endif
