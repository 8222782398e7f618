/**
 * @file simulator.h
 * The run of one parameter file: mesh, solver, initial and boundary
 * conditions, time loop, reports, output files and verification checks.
 */
#ifndef wheelrail_simulator_h
#define wheelrail_simulator_h

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/table_handler.h>

#include <deal.II/distributed/tria.h>

#include <wheelrail/contact.h>
#include <wheelrail/explicit_solver.h>
#include <wheelrail/output_files.h>
#include <wheelrail/parameters.h>

#include <memory>
#include <sstream>
#include <string>
#include <vector>

namespace WheelRail
{
  /**
   * Runs one case. run() follows SPEC 5 as far as the explicit core goes:
   * build mesh and solver, print the setup summary, then either a static
   * verification (patch test, rigid rotation) or the explicit run.
   */
  class Simulator
  {
  public:
    Simulator(const Parameters &parameters, const ParameterHandler &prm, MPI_Comm comm);

    void
    run();

  private:
    /** Create the output directory and lock it (DirectoryLock); nothing
     *  is written there before the setup has succeeded. */
    void
    prepare_output_directory();
    void
    print_setup_summary();
    void
    run_static_check();
    void
    run_static_contact();
    /** Per-node contact state of the slave surface as CSV (SPEC 6 columns). */
    void
    write_contact_nodes(const std::string &name) const;
    /** Record the sample of the contact checks at a statistics step. */
    void
    record_sample(const Energies &e);
    void
    run_explicit();
    void
    apply_initial_conditions();
    /** Static equilibrium at A and the start of rolling (SPEC 5.2, 5.3). */
    void
    start_wheelset();
    void
    setup_probe();
    void
    record_probe();
    void
    report(const Energies &e, const double wall_seconds);
    /** Test mode of a round-off sensitive (chaotic) run: print only what
     *  is robust (Verification/Round-off sensitive). */
    bool
    robust_output_only() const
    {
      return parameters.problem.test_mode && parameters.verification.round_off_sensitive;
    }
    /** Write the whole run state to OUTDIR/checkpoint/ (write, then
     *  rename: the previous checkpoint stays until the new one is
     *  complete). In simulator_checkpoint.cc, as the two below. */
    void
    write_checkpoint();
    /** Before the setup of a resumed run: every rank file is complete and
     *  its checksum matches, the rank count is the checkpoint's, and no
     *  parameter other than Checkpoint::resumable_entries() differs from
     *  the run that wrote it (those that do are listed). */
    void
    check_checkpoint();
    /** Read the state back (wheelrail CASE.prm --resume). */
    void
    read_checkpoint();
    /** OUTDIR/checkpoint, or checkpoint.old if a run died between the
     *  two renames of write_checkpoint(); set by check_checkpoint(). */
    std::string checkpoint_directory;

    /** Where and why a run diverged (all ranks call it): @p velocity_spread
     *  is the largest spread of a velocity component over the nodes at the
     *  start of the run [m/s], @p deepest_penetration the deepest contact
     *  penetration seen in the run [m]. */
    std::string
    divergence_message(const unsigned long n,
                       const Energies     &e,
                       const double        velocity_spread,
                       const double        deepest_penetration) const;
    /** Time split, ns per element-step, the spread of the step times
     *  (@p step_seconds: this rank's timed steps, reordered here), peak
     *  memory and the projected full paper run: on the screen and in
     *  timing.csv. */
    void
    report_timing(const double         wall_seconds,
                  const double         output_seconds,
                  const unsigned long  n_steps,
                  std::vector<double> &step_seconds) const;
    void
    add_statistics_row(const Energies &e);
    void
    write_statistics() const;
    void
    write_probe() const;
    void
    write_vtu();
    void
    final_checks();

    /** Where the implicit solver's iterations go: the screen of rank 0,
     *  or nowhere in test mode and on the other ranks. */
    std::ostream                    &
    solver_log();
    std::ostringstream silent_log;

    /** Write @p content to @p name in the output directory atomically
     *  (temporary file, then rename), from rank 0. */
    void
    write_file(const std::string &name, const std::string &content) const;

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
    std::string                               output_directory;
    /** Held by rank 0 from the start to the end of the run. */
    std::unique_ptr<DirectoryLock> lock;

    TableHandler                                statistics;
    std::vector<std::pair<double, std::string>> vtu_records;
    unsigned int                                vtu_counter = 0;

    /** A node whose displacement and velocity are recorded every step. */
    struct Probe
    {
      std::string         file;   ///< output file name
      Point<dim>          target; ///< the node nearest to it is recorded
      types::material_id  material = numbers::invalid_material_id; ///< search only this body
      unsigned int        owner    = 0;                            ///< rank owning the node
      unsigned int        dof      = 0; ///< local index of its x-DoF on the owner
      Point<dim>          location;     ///< reference position of the node
      std::vector<double> history;      ///< t, u_x,u_y,u_z, v_x,v_y,v_z per step
    };
    /** probes[0]: Output/Probe point; with a wheelset also the wheel-tread
     *  node that passes O. */
    std::vector<Probe> probes;

    /** Contact-patch snapshots at the instants of SPEC 5.5: when the patch
     *  centre passes x = -V dt_s, 0, +V dt_s (dt_s = 5.7 us). */
    void
                 write_patch_snapshots();
    double       previous_patch_centre = -std::numeric_limits<double>::max();
    unsigned int next_snapshot         = 0;
    /** Force-weighted mean x of the contact nodes (NaN without contact). */
    double
    patch_centre() const;
    /** Means over the contact nodes behind the patch centre. */
    struct TrailingSlip
    {
      double         magnitude = 0; ///< of the micro-slip s_n = |de| / dt [m/s]
      Tensor<1, dim> rate;          ///< of the relative velocity de / dt [m/s]
    };
    TrailingSlip
    trailing_micro_slip() const;

    Energies initial_energies;
    bool     have_initial_energies       = false;
    double   max_balance_error           = 0;
    double   hourglass_time_integral     = 0;
    double   hourglass_ref_time_integral = 0;
    double   internal_time_integral      = 0;
    double   max_hourglass_ratio_actual  = 0;

    /** Time series for the contact checks (block on plate). */
    struct Sample
    {
      double         t;
      Tensor<1, dim> block_momentum, plate_momentum, block_displacement, contact_force;
      Tensor<1, dim> relative_displacement; ///< block relative to the plate under it
      unsigned int   n_contact;
      double         kinetic, external_work, friction, total;
      double         tangential_stiffness; ///< sum of k_t over the contact pairs
      double         mean_cof;             ///< sum f |F_n| / sum |F_n| over the contact nodes
      double         trailing_slip;        ///< mean micro-slip behind the patch centre
      Tensor<1, dim> trailing_slip_rate;   ///< mean relative velocity vector there
    };
    std::vector<Sample> samples;
    unsigned long       friction_violations = 0;
    unsigned int        most_contact_nodes  = 0; ///< largest contact node count so far
  };
} // namespace WheelRail

#endif
