/**
 * @file parameters/boundary_initial.cc
 * The subsections Boundary conditions (Dirichlet conditions, applied
 * forces and prescribed motions) and Initial conditions.
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



  void
  BoundaryParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Boundary conditions");
    prm.declare_entry("Fixed boundaries",
                      "11: xyz, 12: x",
                      Patterns::Map(Patterns::Integer(0, 255),
                                    Patterns::Selection("x|y|z|xy|xz|yz|xyz"),
                                    0,
                                    Patterns::Map::max_int_value,
                                    ",",
                                    ":"),
                      "Boundary ids and the displacement components held at zero, e.g. "
                      "'11: xyz, 12: x' (rail bottom fixed, rail ends fixed in x). Boundary "
                      "ids are listed in the README.");
    prm.declare_entry("Prescribed velocity boundaries",
                      "",
                      Patterns::List(Patterns::Integer(0, 255)),
                      "Boundary ids whose nodes move with the velocity "
                      "function below (all three components).");
    prm.declare_entry("Prescribed velocity",
                      "0; 0; 0",
                      Patterns::Anything(),
                      "Velocity of the prescribed boundaries [m/s]: three "
                      "muparser expressions 'vx; vy; vz' in x, y, z (reference "
                      "position, m) and t (s).");
    prm.declare_entry("Prescribed velocity constants",
                      "",
                      Patterns::Anything(),
                      "Constants for the expression, 'name=value, ...'.");
    prm.declare_entry("Applied force boundaries",
                      "",
                      Patterns::List(Patterns::Integer(0, 255)),
                      "Boundary ids loaded by the applied force below.");
    prm.declare_entry("Applied force",
                      "0; 0; 0",
                      Patterns::Anything(),
                      "Total force on the applied-force boundaries [N], three "
                      "muparser expressions 'Fx; Fy; Fz' in t (s), spread over "
                      "their nodes in proportion to the nodal area.");
    prm.declare_entry("Applied force constants",
                      "",
                      Patterns::Anything(),
                      "Constants for the expression, 'name=value, ...'.");
    prm.declare_entry("Wheel bore",
                      "spinning axle",
                      Patterns::Selection("free|fixed|spinning axle|rigid axle"),
                      "Motion of the bore nodes (boundary id 2): 'fixed'; "
                      "'spinning axle': rigid rotation about the fixed axle "
                      "with Initial conditions/Wheel angular velocity; 'rigid "
                      "axle': the wheelset of subsection Wheelset (axle "
                      "translating in x and z, turning about y, sprung mass on "
                      "the suspension, driving torque), rolling at the Rolling "
                      "speed; 'free'.");
    prm.leave_subsection();
  }



  void
  BoundaryParameters::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Boundary conditions");
    fixed.clear();
    for (const auto &entry : Utilities::split_string_list(prm.get("Fixed boundaries"), ','))
      {
        // An id given twice is rejected rather than merged: a repeated id
        // is more likely a mistyped other id than two halves of one
        // condition, and merging would hide that boundary's missing
        // condition.
        const auto kv       = Utilities::split_string_list(entry, ':');
        const auto id       = static_cast<types::boundary_id>(Utilities::string_to_int(kv[0]));
        const auto previous = fixed.find(id);
        if (previous != fixed.end())
          {
            std::string both;
            for (const char c : {'x', 'y', 'z'})
              if ((previous->second + kv[1]).find(c) != std::string::npos)
                both += c;
            AssertThrow(false,
                        ExcMessage("Boundary conditions/Fixed boundaries names boundary id " +
                                   std::to_string(id) + " twice ('" + std::to_string(id) + ": " +
                                   previous->second + "' and '" + entry +
                                   "'): give each id once with all its held components, e.g. '" +
                                   std::to_string(id) + ": " + both + "'."));
          }
        fixed[id] = kv[1];
      }
    fixed_is_default = fixed == std::map<types::boundary_id, std::string>{{11, "xyz"}, {12, "x"}};
    prescribed_velocity_ids.clear();
    for (const int id : Utilities::string_to_int(
           Utilities::split_string_list(prm.get("Prescribed velocity boundaries"))))
      prescribed_velocity_ids.push_back(id);
    prescribed_velocity_expression = prm.get("Prescribed velocity");
    prescribed_velocity_constants  = prm.get("Prescribed velocity constants");
    wheel_bore                     = wheel_bore_names.parse(prm.get("Wheel bore"));
    applied_force_ids.clear();
    for (const int id : Utilities::string_to_int(
           Utilities::split_string_list(prm.get("Applied force boundaries"))))
      applied_force_ids.push_back(id);
    applied_force_expression = prm.get("Applied force");
    applied_force_constants  = prm.get("Applied force constants");
    prm.leave_subsection();
  }



  void
  InitialParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Initial conditions");
    const EntryFlags flags("Initial conditions");
    prm.declare_entry("Wheel velocity",
                      "0, 0, 0",
                      vector_pattern(),
                      "Initial translational velocity of the wheel [m/s].");
    flags.mark("Wheel velocity", EntryFlag::static_start_free);
    prm.declare_entry("Wheel angular velocity",
                      "0",
                      Patterns::Double(-1e4, 1e4),
                      "Initial angular velocity of the wheel about +y "
                      "through its centre [rad/s], range [-1e4, 1e4]; "
                      "rolling towards +x is positive: +V/R_w (the contact "
                      "point then has omega e_y x (-R e_z) = -V e_x).");
    flags.mark("Wheel angular velocity", EntryFlag::static_start_free);
    prm.declare_entry("Velocity function",
                      "0; 0; 0",
                      Patterns::Anything(),
                      "Additional initial velocity of every node [m/s]: three "
                      "muparser expressions 'vx; vy; vz' in x, y, z (m).");
    flags.mark("Velocity function", EntryFlag::static_start_free);
    prm.declare_entry("Velocity function constants",
                      "",
                      Patterns::Anything(),
                      "Constants for the expression, 'name=value, ...'.");
    flags.mark("Velocity function constants", EntryFlag::static_start_free);
    prm.leave_subsection();
  }



  void
  InitialParameters::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Initial conditions");
    wheel_velocity         = get_vector(prm, "Wheel velocity");
    wheel_angular_velocity = prm.get_double("Wheel angular velocity");
    velocity_expression    = prm.get("Velocity function");
    velocity_constants     = prm.get("Velocity function constants");
    prm.leave_subsection();
  }
} // namespace WheelRail
