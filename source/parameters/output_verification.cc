/**
 * @file parameters/output_verification.cc
 * The subsections Output (screen reports, statistics, VTU snapshots,
 * probes) and Verification (checks against analytic solutions).
 */

#include <deal.II/base/exceptions.h>
#include <deal.II/base/utilities.h>

#include <wheelrail/base/checkpoint.h>
#include <wheelrail/parameters/entry_flags.h>
#include <wheelrail/parameters/parameters.h>
#include <wheelrail/parameters/vector_entry.h>
#include <wheelrail/postprocess/registry.h>

#include <cmath>
#include <string>

namespace WheelRail
{
  using ParameterEntries::get_vector;
  using ParameterEntries::vector_pattern;



  void
  OutputParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Output");
    const EntryFlags flags("Output");
    prm.declare_entry("Report interval",
                      "1000",
                      Patterns::Integer(1, 1000000000),
                      "Steps between screen reports of time and energies "
                      "[-], range [1, 1e9].");
    flags.mark("Report interval", EntryFlag::resumable);
    prm.declare_entry("Statistics interval",
                      "100",
                      Patterns::Integer(1, 1000000000),
                      "Steps between rows of the statistics file [-], range "
                      "[1, 1e9].");
    flags.mark("Statistics interval", EntryFlag::resumable);
    prm.declare_entry("VTU interval",
                      "0",
                      Patterns::Integer(0, 1000000000),
                      "Steps between VTU/PVTU snapshots [-], range [0, 1e9]; "
                      "0 = first and last step only.");
    flags.mark("VTU interval", EntryFlag::resumable);
    prm.declare_entry("VTU compression",
                      "fast",
                      Patterns::Selection("fast|best|none"),
                      "zlib level of the VTU snapshots: 'fast' (about 3 s "
                      "less per snapshot of the paper mesh than 'best', "
                      "files about 30 % larger), 'best', or 'none'.");
    flags.mark("VTU compression", EntryFlag::resumable);
    prm.declare_entry("Patch averaging window",
                      "0",
                      Patterns::Double(0, 1e-3),
                      "Length [s] of the time window, centred on each contact-patch "
                      "snapshot instant, over which the patch fields are averaged "
                      "into patch_NAME_mean.csv (pressure, shear, s_n, adhesion and "
                      "slip fractions), range [0, 1e-3]; 0 = no means. The paper's "
                      "sampling interval is 5.7e-6 s.");
    flags.mark("Patch averaging window", EntryFlag::static_start_free);
    prm.declare_entry("Patch series interval",
                      "0",
                      Patterns::Integer(0, 1000000000),
                      "Every this many steps the contact fields on the rail-top "
                      "surface of the solution zone are appended to "
                      "patch_series.h5, which patch_series.xdmf lists for "
                      "ParaView (a movie of the patch), range [0, 1e9]; 0 = none. "
                      "The paper's 175 kHz sampling is every 219 steps of 2.6e-8 s.");
    flags.mark("Patch series interval", EntryFlag::static_start_free);
    prm.declare_entry("Patch series tread",
                      "true",
                      Patterns::Bool(),
                      "Whether the patch series also holds the wheel tread's faces "
                      "over the solution zone, each frame with its own mesh at the "
                      "current positions (patch_series_tread.xdmf) [-]: about 125 kB "
                      "per frame on the paper mesh, against 18 kB for the rail top.");
    flags.mark("Patch series tread", EntryFlag::static_start_free);
    prm.declare_entry("Probe point",
                      "0, 0, 0",
                      vector_pattern(),
                      "A velocity history is recorded at the node nearest "
                      "to this point [m] (file probe.csv).");
    flags.mark("Probe point", EntryFlag::static_start_free);
    prm.declare_entry("Probe component",
                      "0",
                      Patterns::Integer(0, 2),
                      "Component (0 = x, 1 = y, 2 = z) used by the "
                      "verification checks on the probe [-].");
    flags.mark("Probe component", EntryFlag::static_start_free);
    prm.declare_entry("Divergence limit",
                      "0.5",
                      Patterns::Double(1e-12, 1e6),
                      "The run stops with a diagnosis when the relative energy "
                      "balance error exceeds this [-], range [1e-12, 1e6] "
                      "(an exploding energy; NaN or infinite energies always "
                      "stop it). Checked at statistics steps.");
    flags.mark("Divergence limit", EntryFlag::resumable);
    prm.declare_entry("Checkpoint minutes",
                      "0",
                      Patterns::Double(0, 1e6),
                      "Wall-clock minutes between checkpoints [min], range "
                      "[0, 1e6]; 0 = none.");
    flags.mark("Checkpoint minutes", EntryFlag::resumable);
    prm.declare_entry("Stop after step",
                      "0",
                      Patterns::Integer(0, 2000000000),
                      "Stop the explicit run after this step with a "
                      "checkpoint [-], range [0, 2e9]; 0 = run to the end "
                      "(for splitting a run, and the restart test).");
    flags.mark("Stop after step", EntryFlag::resumable);
    prm.declare_entry("Resume",
                      "false",
                      Patterns::Bool(),
                      "Continue from the checkpoint in the output directory "
                      "(the same as the command line flag --resume); see "
                      "Checkpoint interval for what may change.");
    flags.mark("Resume", EntryFlag::resumable);
    prm.declare_entry("Timing warm-up steps",
                      "0",
                      Patterns::Integer(0, 1000000000),
                      "Steps before the timers of the explicit run start [-], "
                      "range [0, 1e9]: the time split (elements, contact, "
                      "update, communication, output) and ns per "
                      "element-step printed at the end and written to "
                      "timing.csv count only the steps after them (a "
                      "benchmark leaves out the first, cold steps).");
    flags.mark("Timing warm-up steps", EntryFlag::resumable);
    Postprocessors::declare_parameters(prm);
    prm.leave_subsection();
  }



  void
  OutputParameters::declare_checkpoint_interval(ParameterHandler &prm)
  {
    // its documentation lists the resumable entries: declared after all
    // others are marked
    prm.enter_subsection("Output");
    const EntryFlags flags("Output");
    flags.mark("Checkpoint interval", EntryFlag::resumable);
    std::string resumable;
    for (const std::string &entry : EntryFlags::marked(EntryFlag::resumable))
      resumable += (resumable.empty() ? "" : ", ") + entry;
    prm.declare_entry("Checkpoint interval",
                      "0",
                      Patterns::Integer(0, 1000000000),
                      "Steps between checkpoints of an explicit run [-], range "
                      "[0, 1e9]; 0 = none. A checkpoint (OUTDIR/checkpoint/, "
                      "one file per rank) holds all vectors, the contact and "
                      "friction state, axle and suspension, statistics and "
                      "probes; 'wheelrail CASE.prm --resume' continues from "
                      "it with the same rank count. Each rank file records "
                      "every parameter and a CRC-32 checksum: a resumed run "
                      "stops on a damaged file, and on any changed entry but "
                      "these (which it lists): " +
                        resumable + ".");
    prm.leave_subsection();
  }



  void
  OutputParameters::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Output");
    report_interval       = prm.get_integer("Report interval");
    statistics_interval   = prm.get_integer("Statistics interval");
    vtu_interval          = prm.get_integer("VTU interval");
    vtu_compression       = vtu_compression_names.parse(prm.get("VTU compression"));
    patch_window          = prm.get_double("Patch averaging window");
    patch_series_interval = prm.get_integer("Patch series interval");
    patch_series_tread    = prm.get_bool("Patch series tread");
    probe_point           = Point<3>(get_vector(prm, "Probe point"));
    probe_component       = prm.get_integer("Probe component");
    timing_warmup_steps   = prm.get_integer("Timing warm-up steps");
    divergence_limit      = prm.get_double("Divergence limit");
    checkpoint_interval   = prm.get_integer("Checkpoint interval");
    checkpoint_minutes    = prm.get_double("Checkpoint minutes");
    stop_after_step       = prm.get_integer("Stop after step");
    resume                = prm.get_bool("Resume");
    postprocessors        = Postprocessors::parse_parameters(prm);
    prm.leave_subsection();
  }



  void
  VerificationParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Verification");
    const EntryFlags flags("Verification");
    prm.declare_entry(
      "Check",
      "none",
      Patterns::Selection(
        "none|wave arrival|longitudinal frequency|bending frequency|energy balance|"
        "inclined plane|tangential sliding|impact|static start|traction|free rolling|"
        "creep forces"),
      "Analytic comparison made at the end of an explicit run on the bar: "
      "'wave arrival': first time the probe velocity exceeds Wave threshold "
      "times the far-end steady value, against L/sqrt(E/rho); "
      "'longitudinal frequency': frequency of the probe displacement "
      "(zero crossings) against sqrt(E/rho)/(2L) (free-free) or /(4L) "
      "(clamped); 'bending frequency': against the Euler-Bernoulli "
      "cantilever 1.8751^2/(2 pi L^2) sqrt(EI/(rho A)); this check also "
      "compares the hourglass energy ratio with Hourglass limit; 'energy balance': "
      "the largest relative energy balance error of the run against Tolerance; "
      "'inclined plane' (block on plate, gravity tilted by theta in the x-z "
      "plane): sliding acceleration against g (sin theta - f(v) cos theta), or "
      "for tan theta < f the drift against the elastic slip of the friction "
      "springs; 'tangential sliding': the friction force saturates at f F_N and "
      "the friction dissipation equals the applied work minus the kinetic "
      "energy; 'impact': momentum conserved, contact released, no energy "
      "gained; 'static start' (rigid axle): F_N after the static solve against "
      "the static load, and its largest change in the first 100 explicit "
      "steps; 'traction' (rigid axle): the mean achieved traction coefficient "
      "F_L / F_N over the second half of the run against min(mu_n, f), f the "
      "Coulomb coefficient or f_D of the exponential law; 'free rolling' (rigid "
      "axle, no torque): the mean F_N over the second half against the static "
      "load, and the mean F_L / F_N and the mean longitudinal creepage of the "
      "trailing part near zero; 'creep forces' (rigid axle, the paper's pair: "
      "Hertz b/a = 0.752, nu = 0.3): the mean F_lateral / F_N over the second "
      "half against Kalker's linear theory -G c^2 C22 eta / F_N (Wheelset/Lateral "
      "creepage or Yaw angle), and the mean F_L / F_N against -G c^2 C11 xi / F_N "
      "where an Initial creepage xi is held for the whole run; c^2 = a b from "
      "Hertz at the mean F_N, C11 = 4.623, C22 = 4.175.");
    flags.mark("Check", EntryFlag::static_start_free);
    prm.declare_entry("Displacement gradient",
                      "1e-3, 2e-4, -3e-4, 5e-4, -1e-3, 2e-4, 1e-4, 3e-4, 2e-3",
                      Patterns::List(Patterns::Double(-1, 1), 9, 9, ","),
                      "G of the patch test, row by row (G_xx, G_xy, ..., "
                      "G_zz) [-], each in [-1, 1].");
    prm.declare_entry("Rotation angle",
                      "30",
                      Patterns::Double(-360, 360),
                      "Angle of the rigid rotation [degrees], range "
                      "[-360, 360].");
    prm.declare_entry("Rotation axis",
                      "0, 1, 0",
                      vector_pattern(),
                      "Direction of the rotation axis (normalised; through "
                      "the wheel centre, or the bar centre) [-].");
    prm.declare_entry("Tolerance",
                      "0.02",
                      Patterns::Double(0, 1),
                      "Relative tolerance of the check [-], range [0, 1].");
    flags.mark("Tolerance", EntryFlag::resumable);
    prm.declare_entry("Wave threshold",
                      "0.5",
                      Patterns::Double(0.01, 0.99),
                      "Fraction of the far-end steady velocity that marks "
                      "the arrival of the front [-], range [0.01, 0.99].");
    flags.mark("Wave threshold", EntryFlag::resumable);
    prm.declare_entry("Hourglass limit",
                      "0.1",
                      Patterns::Double(0, 10),
                      "Largest accepted ratio of hourglass-mode energy to "
                      "internal energy [-], range [0, 10].");
    flags.mark("Hourglass limit", EntryFlag::resumable);
    prm.declare_entry("Round-off sensitive",
                      "false",
                      Patterns::Bool(),
                      "The run is chaotic: round-off differences (another "
                      "compiler, summation order, number of ranks) grow to "
                      "percent-level differences of instantaneous values, "
                      "as in rolling with velocity-weakening friction. In "
                      "test mode only what is robust is printed: no step "
                      "rows, patch lines or end summary; the checks' values "
                      "with two digits and their verdict.");
    prm.declare_entry("Expected verdict",
                      "yes",
                      Patterns::Selection("yes|no"),
                      "In test mode, what the checks of the run must say: 'yes' "
                      "(every check passes; a 'no' ends the run with an error "
                      "and a non-zero exit status, so that a test's reference "
                      "cannot store a failed check) or 'no' (a test that "
                      "shows a check failing: at least one must say 'no') [-].");
    prm.declare_entry("Clamped",
                      "false",
                      Patterns::Bool(),
                      "The bar is clamped at x = 0 (boundary id 21) in the "
                      "longitudinal frequency check.");
    prm.leave_subsection();
  }



  void
  VerificationParameters::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Verification");
    check        = prm.get("Check");
    const auto g = Utilities::string_to_double(
      Utilities::split_string_list(prm.get("Displacement gradient"), ','));
    for (unsigned int i = 0; i < 3; ++i)
      for (unsigned int j = 0; j < 3; ++j)
        displacement_gradient[i][j] = g[3 * i + j];
    rotation_angle = prm.get_double("Rotation angle") * M_PI / 180.;
    rotation_axis  = get_vector(prm, "Rotation axis");
    AssertThrow(rotation_axis.norm() > 0,
                ExcMessage("Verification/Rotation axis must not be zero."));
    rotation_axis /= rotation_axis.norm();
    tolerance           = prm.get_double("Tolerance");
    wave_threshold      = prm.get_double("Wave threshold");
    hourglass_limit     = prm.get_double("Hourglass limit");
    bar_clamped         = prm.get_bool("Clamped");
    round_off_sensitive = prm.get_bool("Round-off sensitive");
    expect_failure      = prm.get("Expected verdict") == "no";
    prm.leave_subsection();
  }
} // namespace WheelRail
