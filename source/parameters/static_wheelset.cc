/**
 * @file parameters/static_wheelset.cc
 * The subsections Static solve (the implicit static contact solve, SPEC
 * 5.2) and Wheelset (axle, suspension, sprung mass, torque, SPEC 3).
 */

#include <deal.II/base/exceptions.h>
#include <deal.II/base/utilities.h>

#include <wheelrail/parameters/entry_flags.h>
#include <wheelrail/parameters/parameters.h>

#include <cmath>
#include <string>

namespace WheelRail
{
  void
  StaticParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Static solve");
    prm.declare_entry("Axle load",
                      "140300", // default_axle_load
                      Patterns::Double(0, 1e8),
                      "Vertical force F_N of the wheel on the rail sought by "
                      "the static contact solve [N], range [0, 1e8]; the paper: "
                      "(13.4 t + 0.9 t) g = 140.3 kN. Only the static contact solve "
                      "uses it: with Boundary conditions/Wheel bore = rigid axle the "
                      "wheel load is the weight of the Wheelset masses, and an Axle "
                      "load other than that weight is refused there.");
    prm.declare_entry("Load tolerance",
                      "1e-4",
                      Patterns::Double(1e-12, 0.1),
                      "Relative tolerance on the contact force [-], range "
                      "[1e-12, 0.1].");
    prm.declare_entry("Newton tolerance",
                      "1e-5",
                      Patterns::Double(1e-14, 1e-2),
                      "Newton stops when the residual norm falls below this "
                      "fraction of the load's norm [-], range [1e-14, 1e-2].");
    prm.declare_entry("Max Newton iterations",
                      "30",
                      Patterns::Integer(1, 1000),
                      "Largest number of Newton iterations per load step [-].");
    prm.declare_entry("Linear solver tolerance",
                      "1e-8",
                      Patterns::Double(1e-16, 1e-2),
                      "Relative tolerance of CG with AMG [-], range "
                      "[1e-16, 1e-2].");
    prm.declare_entry("Inexact Newton",
                      "true",
                      Patterns::Bool(),
                      "Solve each Newton step only as accurately as the next "
                      "iterate can use (Eisenstat-Walker): CG stops at the "
                      "larger of the relative residuals 0.5 x Newton "
                      "tolerance x load / Newton residual (at most 0.5) and "
                      "0.9 x (Newton residual / the one before)^2 (at most "
                      "1e-2, and 1e-2 at the first step of each axle "
                      "position), and not below Linear solver tolerance. "
                      "The converged state meets the same "
                      "Newton tolerance with fewer CG iterations and "
                      "possibly more Newton iterations; false: every step "
                      "to Linear solver tolerance.");
    prm.declare_entry("AMG near null space",
                      "rigid body modes",
                      Patterns::Selection("translations|rigid body modes"),
                      "Near null space of the AMG preconditioner of the static "
                      "solve: 'rigid body modes' (translations and rotations, "
                      "aggregation threshold 1e-4) or 'translations' (3 "
                      "constant modes, threshold 0.02): the translations "
                      "take about 2.5 x the CG iterations and 2 x the time "
                      "(paper mesh and the default case), for about 0.75 x "
                      "the peak memory on the paper mesh (1.34 instead of "
                      "1.79 GB per rank of 2).");
    prm.leave_subsection();
  }



  void
  StaticParameters::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Static solve");
    axle_load             = prm.get_double("Axle load");
    load_tolerance        = prm.get_double("Load tolerance");
    newton_tolerance      = prm.get_double("Newton tolerance");
    max_newton_iterations = prm.get_integer("Max Newton iterations");
    linear_tolerance      = prm.get_double("Linear solver tolerance");
    inexact_newton        = prm.get_bool("Inexact Newton");
    amg_null_space        = amg_null_space_names.parse(prm.get("AMG near null space"));
    prm.leave_subsection();
  }



  void
  WheelsetParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Wheelset");
    const EntryFlags flags("Wheelset");
    prm.declare_entry("Unsprung mass",
                      "900",
                      Patterns::Double(1, 1e6),
                      "Mass of wheel and axle [kg], range [1, 1e6]; the rigid axle "
                      "gets this minus the FE wheel's mass. The paper: 900 kg.");
    prm.declare_entry("Sprung mass",
                      "13400",
                      Patterns::Double(0, 1e7),
                      "M_c on the primary suspension [kg], range [0, 1e7]. The "
                      "paper: 13.4 t.");
    prm.declare_entry("Suspension stiffness",
                      "1.15e6",
                      Patterns::Double(0, 1e12),
                      "K of the primary suspension [N/m], range [0, 1e12].");
    prm.declare_entry("Suspension damping",
                      "2500",
                      Patterns::Double(0, 1e9),
                      "C of the primary suspension [N s/m], range [0, 1e9].");
    prm.declare_entry("Axle rotational inertia",
                      "20",
                      Patterns::Double(0, 1e6),
                      "Polar moment of inertia of the axle about y, in addition to "
                      "the FE wheel's [kg m^2], range [0, 1e6].");
    prm.declare_entry("Rolling speed",
                      "38.8889",
                      Patterns::Double(0, 200),
                      "V of the rolling run [m/s], range [0, 200]; 140 km/h = "
                      "38.8889 m/s.");
    prm.declare_entry("Nominal traction coefficient",
                      "0",
                      Patterns::Double(0, 1),
                      "mu_n = T / (R_w F_N,static): sets the driving torque T "
                      "about the axle [-], range [0, 1].");
    flags.mark("Nominal traction coefficient", EntryFlag::static_start_free);
    prm.declare_entry("Torque ramp time",
                      "0",
                      Patterns::Double(0, 10),
                      "The torque rises linearly from 0 over this time [s], "
                      "range [0, 10]; 0 = applied at once.");
    flags.mark("Torque ramp time", EntryFlag::static_start_free);
    prm.declare_entry("Initial creepage",
                      "0",
                      Patterns::Double(-0.1, 0.1),
                      "Longitudinal creepage xi_0 = (V - omega r) / V with which the "
                      "wheel starts rolling [-], range [-0.1, 0.1]; negative for a "
                      "driving wheel (omega r > V), 0 = free rolling.");
    flags.mark("Initial creepage", EntryFlag::static_start_free);
    prm.declare_entry("Creepage control time",
                      "0",
                      Patterns::Double(0, 10),
                      "Until this time the wheel's angular velocity is held at "
                      "v_x (1 - xi_0) / r (creepage control: the axle supplies "
                      "whatever torque that takes, and its work enters the energy "
                      "balance); after it the torque of the nominal traction "
                      "coefficient drives the wheel [s], range [0, 10]; 0 = torque "
                      "control from the start. Holding the creepage removes the "
                      "spin-up of the wheelset under a torque (a first-order lag of "
                      "about 1 ms); the wheel's torsional vibration that the onset "
                      "of traction excites is removed by the run-up damping.");
    flags.mark("Creepage control time", EntryFlag::static_start_free);
    prm.declare_entry("Lateral creepage",
                      "0",
                      Patterns::Double(-0.1, 0.1),
                      "Lateral creepage eta = v_s / V of the rolling wheel [-], range "
                      "[-0.1, 0.1], used within [-0.02, 0.02]: the rigid axle (and with it "
                      "the bore nodes, and every wheel node's initial velocity) moves "
                      "laterally at the constant velocity v_y = eta V from the start of "
                      "rolling, y towards the flange (SPEC 10: v the wheel's rigid velocity "
                      "relative to the rail at the contact point, s = n x x; on a contact "
                      "at angle delta, v_s = v_y cos(delta) - v_z sin(delta)). The axle's "
                      "lateral guide supplies the force that keeps v_y constant, and its "
                      "work enters the energy balance. Kalker's linear theory: the lateral "
                      "creep force on the wheel is F_y = -G c^2 C22 eta. 0 = none; not "
                      "together with Yaw angle.");
    flags.mark("Lateral creepage", EntryFlag::static_start_free);
    prm.declare_entry("Yaw angle",
                      "0",
                      Patterns::Double(-0.1, 0.1),
                      "Yaw angle psi of the wheelset about z (the axle turned from y "
                      "towards -x for psi > 0) [rad], range [-0.1, 0.1], used within "
                      "[-0.02, 0.02]. Small-angle kinematics: the mesh is not turned; a "
                      "wheelset moving forward at V with yaw psi has, in its own frame, "
                      "the lateral velocity -psi V relative to the track (to first order "
                      "in psi, the error psi^2 / 2), so psi is realised as the lateral "
                      "creepage eta = -psi (the same run as Lateral creepage = -psi). "
                      "0 = none; not together with Lateral creepage.");
    flags.mark("Yaw angle", EntryFlag::static_start_free);
    prm.declare_entry("Run-up damping",
                      "0",
                      Patterns::Double(0, 1e6),
                      "alpha of a mass-proportional damping of the FE nodes' "
                      "velocity relative to the rigid motion of the wheelset "
                      "(wheel nodes: axle velocity + omega e_y x r; rail nodes: 0), "
                      "f = -alpha m (v - v_rigid), acting until Run-up time [1/s], "
                      "range [0, 1e6]; 0 = none. It removes the wheel's torsional "
                      "and bending vibrations that the onset of traction excites "
                      "(about 680 Hz, lightly damped: mu_a swings by +-13 % for "
                      "several ms) so that the traction is steady when the patch is "
                      "sampled. With Run-up damping shape = nodes it also acts on "
                      "the rolling deformation convected through the patch "
                      "(v - v_rigid = -V du/dx there, about 0.04 m/s), so it is for "
                      "the run-up only, before the patch is sampled; with wheel "
                      "rigid motion it may act for the whole run. Critical for a "
                      "mode of angular frequency w at "
                      "alpha = 2 w. Its dissipation enters "
                      "the energy balance.");
    flags.mark("Run-up damping", EntryFlag::static_start_free);
    prm.declare_entry("Run-up time",
                      "0",
                      Patterns::Double(0, 10),
                      "The run-up damping acts while t < this time [s], range [0, 10].");
    flags.mark("Run-up time", EntryFlag::static_start_free);
    prm.declare_entry("Run-up damping shape",
                      "nodes",
                      Patterns::Selection("nodes|wheel rigid motion"),
                      "What the run-up damping acts on. nodes: every node's "
                      "velocity relative to the wheelset's rigid motion (rail nodes: "
                      "relative to rest); it damps all vibrations but also the "
                      "rolling deformation convected through the patch. wheel rigid "
                      "motion: only the wheel's rigid motion in the rolling plane "
                      "relative to the axle's, w = (V_c - V_a) + (Omega - omega) e_y x "
                      "(r - r_c) with V_c the velocity of the wheel's centre of mass "
                      "r_c and Omega its mean angular velocity about it (the "
                      "mass-weighted rigid fit), f = -alpha m w(r): the wheel's motion "
                      "on its web (the torsional mode that the onset of traction "
                      "excites); a steadily rolling wheel has w = 0, so this damping "
                      "may act while the patch is sampled (Run-up time = End time).");
    flags.mark("Run-up damping shape", EntryFlag::static_start_free);
    prm.declare_entry("Static start",
                      "true",
                      Patterns::Bool(),
                      "Before the explicit run, find the static equilibrium at A "
                      "(wheel on the rail under gravity and the static load) with "
                      "the implicit contact solve.");
    prm.declare_entry("Static start state",
                      "",
                      Patterns::Anything(),
                      "A directory for the state of the static start (with Static "
                      "start = true): a run finds it there when an earlier run of the "
                      "same static problem wrote it, and skips the implicit solve; "
                      "otherwise the run solves and writes it. The static problem is "
                      "every entry but those that act only once the wheel rolls "
                      "(friction, creepage and torque control, run-up damping, "
                      "initial conditions, End time) and those of the output: a state "
                      "written with another value of any other entry, another rank "
                      "count or mesh stops the run naming them. For the runs of a "
                      "creep curve or a traction sweep (scripts/creep_curve.py, "
                      "sweep.py). Empty: always solved, nothing written.");
    flags.mark("Static start state", EntryFlag::static_start_free);
    prm.leave_subsection();
  }



  void
  WheelsetParameters::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Wheelset");
    unsprung_mass         = prm.get_double("Unsprung mass");
    sprung_mass           = prm.get_double("Sprung mass");
    suspension_stiffness  = prm.get_double("Suspension stiffness");
    suspension_damping    = prm.get_double("Suspension damping");
    axle_inertia          = prm.get_double("Axle rotational inertia");
    rolling_speed         = prm.get_double("Rolling speed");
    traction_coefficient  = prm.get_double("Nominal traction coefficient");
    torque_ramp_time      = prm.get_double("Torque ramp time");
    initial_creepage      = prm.get_double("Initial creepage");
    creepage_control_time = prm.get_double("Creepage control time");
    lateral_creepage      = prm.get_double("Lateral creepage");
    yaw_angle             = prm.get_double("Yaw angle");
    runup_damping         = prm.get_double("Run-up damping");
    runup_time            = prm.get_double("Run-up time");
    runup_damping_shape   = prm.get("Run-up damping shape");
    static_start          = prm.get_bool("Static start");
    static_start_state    = prm.get("Static start state");
    prm.leave_subsection();
  }
} // namespace WheelRail
