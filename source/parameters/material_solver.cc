/**
 * @file parameters/material_solver.cc
 * The subsections Material (linear elasticity, SPEC 2) and Time
 * integration (element, damping and the central-difference step).
 */

#include <deal.II/base/exceptions.h>
#include <deal.II/base/utilities.h>

#include <wheelrail/parameters/entry_flags.h>
#include <wheelrail/parameters/parameters.h>
#include <wheelrail/parameters/vector_entry.h>

#include <cmath>
#include <string>

namespace WheelRail
{
  using ParameterEntries::get_vector;
  using ParameterEntries::vector_pattern;



  double
  MaterialParameters::wave_speed() const
  {
    return std::sqrt((lambda() + 2. * mu()) / density);
  }



  double
  MaterialParameters::bar_wave_speed() const
  {
    return std::sqrt(youngs_modulus / density);
  }



  void
  MaterialParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Material");
    prm.declare_entry("Young's modulus",
                      "2.1e11",
                      Patterns::Double(1e6, 1e13),
                      "E of wheel and rail steel [Pa], range [1e6, 1e13].");
    prm.declare_entry("Poisson's ratio",
                      "0.3",
                      Patterns::Double(0, 0.49),
                      "nu [-], range [0, 0.49].");
    prm.declare_entry("Density", "7800", Patterns::Double(1, 1e5), "rho [kg/m^3], range [1, 1e5].");
    prm.leave_subsection();
  }



  void
  MaterialParameters::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Material");
    youngs_modulus = prm.get_double("Young's modulus");
    poisson_ratio  = prm.get_double("Poisson's ratio");
    density        = prm.get_double("Density");
    prm.leave_subsection();
  }



  void
  SolverParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Time integration");
    const EntryFlags flags("Time integration");
    prm.declare_entry("End time",
                      "1e-4",
                      Patterns::Double(0, 10),
                      "Simulated time of the explicit run [s], range [0, 10].");
    flags.mark("End time", EntryFlag::resumable);
    prm.declare_entry("Time step",
                      "0",
                      Patterns::Double(0, 1e-2),
                      "Time step of the central-difference scheme [s], range "
                      "[0, 1e-2]; 0 = the stable step times the Courant "
                      "factor. A value above the stable step is an error, one "
                      "under a thousandth of it needs Allow long runs. "
                      "The paper: 2.6e-8 s.");
    prm.declare_entry("Allow long runs",
                      "false",
                      Patterns::Bool(),
                      "Confirms an explicit run of more than 1e8 steps (End time / "
                      "step), or with a Time step below a thousandth of the stable "
                      "step [-]: without it such a run is refused before it starts, "
                      "with its step count and an estimate of its wall time.");
    flags.mark("Allow long runs", EntryFlag::resumable);
    prm.declare_entry("Courant factor",
                      "0.9",
                      Patterns::Double(0.01, 1.0),
                      "C in dt = C min_e(L_e/c) (with the damping reduction) "
                      "[-], range [0.01, 1].");
    prm.declare_entry("Hourglass coefficient",
                      "0.1",
                      Patterns::Double(0, 1),
                      "QM of the Flanagan-Belytschko stiffness hourglass "
                      "control [-], range [0, 1]; 0 switches it off.");
    prm.declare_entry("Damping model",
                      "stiffness",
                      Patterns::Selection("none|stiffness|Rayleigh"),
                      "'stiffness': LS-DYNA part stiffness damping, "
                      "beta_e = 2 COEF/omega_e per element (SPEC 2); "
                      "'Rayleigh': classical C = beta K with beta in seconds; "
                      "'none'.");
    prm.declare_entry("Damping form",
                      "strain rate",
                      Patterns::Selection("strain rate|nodal field"),
                      "How the explicit step evaluates the Damping model [-]. "
                      "'strain rate': the viscous stress beta_e C : dE/dt of "
                      "each element, from its velocities. 'nodal field': the "
                      "internal force at w = u + beta_n v, beta_n the smallest "
                      "beta_e of the node's cells, which equals beta_e C : dE/dt "
                      "to first order and also damps the hourglass modes; the "
                      "force loop reads one nodal field instead of two (the "
                      "undamped kernel on w). Its dissipation is sampled at the "
                      "statistics steps, v . (f_int(w) - f_int(u)), and "
                      "integrated by the trapezoidal rule "
                      "(doc/notes/damping_nodal_field.md).");
    prm.declare_entry("Stiffness damping coefficient",
                      "1e-4",
                      Patterns::Double(0, 1),
                      "COEF of the stiffness damping, a fraction of critical "
                      "damping at each element's highest frequency [-], range "
                      "[0, 1]. The paper: 1e-4.");
    prm.declare_entry("Rayleigh beta",
                      "0",
                      Patterns::Double(0, 1),
                      "beta of Rayleigh damping C = beta K [s], range [0, 1]; "
                      "used with Damping model = Rayleigh.");
    prm.declare_entry("Gravity",
                      "0, 0, -9.81",
                      vector_pattern(),
                      "Gravitational acceleration vector [m/s^2].");
    prm.declare_entry("Element geometry precision",
                      "double",
                      Patterns::Selection("double|single"),
                      "Storage of the elements' constant gradient and hourglass "
                      "vectors in the explicit force loop [-]: 'double', or "
                      "'single' (floats, 46 % fewer bytes streamed per element "
                      "and step; arithmetic and sums stay double, the gradient "
                      "is taken over u_a - u_0 so that a rigid translation adds "
                      "no strain; the strain energies of the statistics come "
                      "from the same factors; doc/performance.md gives its "
                      "effect).");
    prm.declare_entry("Element geometry sharing",
                      "identical",
                      Patterns::Selection("identical|within rounding"),
                      "Which batches of 8 cells share one copy of the "
                      "single-precision element data in the force loop [-] "
                      "(with Element geometry precision = single). "
                      "'identical': those whose data are the same bit for bit; "
                      "the results are those of unshared data. 'within "
                      "rounding': each cell's gradient factors are first rounded "
                      "to multiples of 2^-23 of the power of two below its "
                      "largest one (at most half a float unit of that factor), "
                      "its hourglass factors to the same relative grid, V0, the "
                      "hourglass stiffness and the damping time constant to 24 "
                      "bits, so that cells that differ by less than the floats' "
                      "rounding, such as the translated copies of a structured "
                      "zone, share one copy and the loop streams less "
                      "(doc/notes/performance_shared_geometry.md).");
    prm.leave_subsection();
  }



  void
  SolverParameters::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Time integration");
    end_time                      = prm.get_double("End time");
    time_step                     = prm.get_double("Time step");
    allow_long_runs               = prm.get_bool("Allow long runs");
    courant_factor                = prm.get_double("Courant factor");
    hourglass_coefficient         = prm.get_double("Hourglass coefficient");
    damping_model                 = damping_model_names.parse(prm.get("Damping model"));
    damping_form                  = damping_form_names.parse(prm.get("Damping form"));
    stiffness_damping_coefficient = prm.get_double("Stiffness damping coefficient");
    rayleigh_beta                 = prm.get_double("Rayleigh beta");
    gravity                       = get_vector(prm, "Gravity");
    single_precision_geometry     = prm.get("Element geometry precision") == "single";
    geometry_sharing = geometry_sharing_names.parse(prm.get("Element geometry sharing"));
    AssertThrow(geometry_sharing == GeometrySharing::identical || single_precision_geometry,
                ExcMessage("Time integration/Element geometry sharing = within rounding "
                           "needs Time integration/Element geometry precision = single "
                           "(it rounds the single-precision element data)."));
    prm.leave_subsection();
  }
} // namespace WheelRail
