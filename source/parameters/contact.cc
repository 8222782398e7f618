/**
 * @file parameters/contact.cc
 * The subsection Contact: penalty node-to-segment contact, the candidate
 * search and the friction law (SPEC 4).
 */

#include <deal.II/base/exceptions.h>
#include <deal.II/base/utilities.h>

#include <wheelrail/contact/friction_law.h>
#include <wheelrail/parameters/entry_flags.h>
#include <wheelrail/parameters/parameters.h>

#include <cmath>
#include <string>

namespace WheelRail
{
  void
  ContactParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Contact");
    const EntryFlags flags("Contact");
    prm.declare_entry("Enabled",
                      "true",
                      Patterns::Bool(),
                      "Penalty node-to-segment contact between the slave and "
                      "master boundaries.");
    prm.declare_entry("Slave boundary",
                      "1",
                      Patterns::Integer(0, 255),
                      "Boundary id of the slave nodes (1 = wheel tread, 30 = "
                      "block bottom).");
    prm.declare_entry("Master boundary",
                      "10",
                      Patterns::Integer(0, 255),
                      "Boundary id of the master faces (10 = rail top, 40 = "
                      "plate top).");
    prm.declare_entry("Two pass",
                      "false",
                      Patterns::Bool(),
                      "Also treat the master boundary's nodes as slaves of the "
                      "slave boundary's faces (symmetric contact).");
    prm.declare_entry("Penalty scale factor",
                      "0.1",
                      Patterns::Double(1e-6, 100),
                      "SF in the penalty stiffness k = SF K A^2 / V (K bulk "
                      "modulus, A master face area, V its cell's volume) [-], "
                      "range [1e-6, 100].");
    prm.declare_entry("Penalty stiffness",
                      "segment",
                      Patterns::Selection("segment|area"),
                      "'segment': k = SF K A^2 / V per master face (LS-DYNA, SPEC "
                      "4): the stiffness per unit area, SF K A / V, grows as the "
                      "mesh is refined, so a wheel rolling from coarse into fine "
                      "faces is pushed up (the paper mesh: F_N from 140 to over "
                      "400 kN); 'area': k = SF K min(A, A_s) / h_ref with A_s "
                      "the slave node's tributary area, the same pressure per "
                      "penetration SF K / h_ref on every face, also where a "
                      "fine mesh meets a coarse one (a slave larger than the "
                      "face takes the face's stiffness, keeping the face's "
                      "nodes stable), equal to 'segment' on cubic cells of "
                      "size h_ref.");
    prm.declare_entry("Penalty reference length",
                      "0",
                      Patterns::Double(0, 1),
                      "h_ref of Penalty stiffness = area [m], range [0, 1]; 0: "
                      "the smallest V / A of the master faces' cells (the "
                      "finest cells, where both choices agree).");
    prm.declare_entry("Tangential stiffness factor",
                      "1",
                      Patterns::Double(1e-6, 100),
                      "k_t / k of the elastic friction predictor [-], range "
                      "[1e-6, 100].");
    flags.mark("Tangential stiffness factor", EntryFlag::static_start_free);
    prm.declare_entry("Contact damping",
                      "0",
                      Patterns::Double(0, 1),
                      "Viscous damping of the normal contact force, a fraction "
                      "of the critical damping 2 sqrt(k m) of the slave node on "
                      "its penalty spring (LS-DYNA's VDC / 100) [-], range "
                      "[0, 1]. Undamped, the contact nodes ring on their "
                      "penalty springs (MHz), their friction cones breathe "
                      "with them and slipping nodes stick in part of the "
                      "steps (doc/interface.md). It acts at each node with "
                      "zeta limited so that (w dt)^2 + 4 zeta w dt <= 2, "
                      "w = 2 sqrt(k / m): a spring stiff for the time step "
                      "is left undamped.");
    prm.declare_entry("Search interval",
                      "1000",
                      Patterns::Integer(1, 1000000),
                      "Steps between rebuilds of the candidate lists [-], range "
                      "[1, 1e6]. A backstop: the lists are also rebuilt when a "
                      "candidate has moved Rebuild fraction x Search margin and "
                      "when the approach bound finds that a slave and a face "
                      "that are not listed could meet.");
    prm.declare_entry("Search margin",
                      "0.002",
                      Patterns::Double(1e-6, 1),
                      "Distance around the master surface within which slave "
                      "nodes are candidates [m], range [1e-6, 1].");
    prm.declare_entry("Rebuild fraction",
                      "0.5",
                      Patterns::Double(0.01, 1),
                      "The candidates are also rebuilt when a candidate node "
                      "has moved more than this fraction of the search margin "
                      "since the last rebuild [-], range [0.01, 1].");
    prm.declare_entry("Initial overlap tolerance",
                      "0",
                      Patterns::Double(0, 0.01),
                      "A slave node that penetrates its master face at the start "
                      "deeper than the larger of this and 0.05 x the face's "
                      "longest edge (the faceting of curved surfaces) stops the "
                      "run: the bodies overlap as placed [m], range [0, 0.01]. "
                      "Set it to start with a deliberate overlap.");
    FrictionLaw::declare_parameters(prm);
    prm.declare_entry("Slip rate",
                      "total",
                      Patterns::Selection("total|irreversible"),
                      "The slip rate s_n the friction law is evaluated at. "
                      "'total': |de| / dt, the slave's motion relative to the "
                      "master material in the step, the elastic rate of the "
                      "tangential spring included (paper, SPEC 4); "
                      "'irreversible': that motion minus the spring's elastic "
                      "increment: 0 in stick, solved with f in slip. A point "
                      "sticks while its trial force lies within f(0) |F_n|, "
                      "so with a velocity-weakening law and no relaxation it "
                      "does not keep steady sliding below f(0), and that "
                      "sliding is unstable where it exists "
                      "(doc/friction_regularisation.md): combine it with a "
                      "relaxation.");
    flags.mark("Slip rate", EntryFlag::static_start_free);
    prm.declare_entry("Friction relaxation length",
                      "0",
                      Patterns::Double(0, 1),
                      "L [m], range [0, 1]: the local coefficient becomes a "
                      "state theta that follows the law over the slip "
                      "distance L, d theta/dt = -(s_n / L + 1 / tau)(theta - "
                      "f(s_n)) (rate-and-state style memory); 0: no "
                      "relaxation by slip.");
    flags.mark("Friction relaxation length", EntryFlag::static_start_free);
    prm.declare_entry("Friction relaxation time",
                      "0",
                      Patterns::Double(0, 1),
                      "tau [s], range [0, 1]: relaxation of the friction "
                      "state in time (see Friction relaxation length); 0: no "
                      "relaxation in time. Both 0: f = f(s_n) at once "
                      "(paper).");
    flags.mark("Friction relaxation time", EntryFlag::static_start_free);
    prm.declare_entry("Tangential damping",
                      "0",
                      Patterns::Double(0, 1),
                      "Viscous damping of the tangential contact force, a "
                      "fraction of the critical damping 2 sqrt(k_t m) of the "
                      "slave node on its tangential spring [-], range [0, 1]; "
                      "it acts in stick (the cone caps it in slip).");
    flags.mark("Tangential damping", EntryFlag::static_start_free);
    prm.leave_subsection();
  }



  void
  ContactParameters::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Contact");
    enabled                   = prm.get_bool("Enabled");
    slave_boundary            = prm.get_integer("Slave boundary");
    master_boundary           = prm.get_integer("Master boundary");
    two_pass                  = prm.get_bool("Two pass");
    penalty_scale             = prm.get_double("Penalty scale factor");
    penalty_stiffness         = penalty_stiffness_names.parse(prm.get("Penalty stiffness"));
    penalty_reference_length  = prm.get_double("Penalty reference length");
    tangential_factor         = prm.get_double("Tangential stiffness factor");
    damping_ratio             = prm.get_double("Contact damping");
    search_interval           = prm.get_integer("Search interval");
    search_margin             = prm.get_double("Search margin");
    rebuild_fraction          = prm.get_double("Rebuild fraction");
    initial_overlap_tolerance = prm.get_double("Initial overlap tolerance");
    friction_law              = prm.get("Friction law");
    law                       = FrictionLaw::create(prm);
    slip_rate                 = slip_rate_names.parse(prm.get("Slip rate"));
    relaxation_length         = prm.get_double("Friction relaxation length");
    relaxation_time           = prm.get_double("Friction relaxation time");
    tangential_damping        = prm.get_double("Tangential damping");
    prm.leave_subsection();
    AssertThrow(slave_boundary != master_boundary,
                ExcMessage("Contact/Slave boundary and Contact/Master boundary must differ."));
  }
} // namespace WheelRail
