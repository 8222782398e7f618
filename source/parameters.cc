#include <deal.II/base/exceptions.h>
#include <deal.II/base/utilities.h>

#include <wheelrail/checkpoint.h>
#include <wheelrail/parameter_file.h>
#include <wheelrail/parameters.h>

#include <cctype>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace WheelRail
{
  namespace
  {
    /** Pattern for a vector of three real numbers "a, b, c". */
    Patterns::List
    vector_pattern()
    {
      return Patterns::List(Patterns::Double(), 3, 3, ",");
    }

    Tensor<1, 3>
    get_vector(const ParameterHandler &prm, const std::string &name)
    {
      const auto values =
        Utilities::string_to_double(Utilities::split_string_list(prm.get(name), ','));
      Tensor<1, 3> t;
      for (unsigned int d = 0; d < 3; ++d)
        t[d] = values[d];
      return t;
    }
  } // namespace



  void
  ProblemParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Problem");
    prm.declare_entry("Geometry",
                      "wheel and rail",
                      Patterns::Selection("wheel and rail|bar|block on plate"),
                      "Bodies to mesh: 'wheel and rail' is the model of the "
                      "paper (SPEC 1); 'bar' is a straight prismatic bar "
                      "(subsection Geometry/Bar) and 'block on plate' a block "
                      "resting on a plate (Geometry/Block on plate), both for "
                      "verification.");
    prm.declare_entry("Mode",
                      "explicit dynamics",
                      Patterns::Selection(
                        "explicit dynamics|static contact|patch test|rigid rotation"),
                      "'explicit dynamics': central-difference time integration. "
                      "'static contact': the implicit equilibrium of the wheel pressed "
                      "onto the rail with Static solve/Axle load, compared with Hertz. "
                      "'patch test': impose the linear displacement u = G X "
                      "(Verification/Displacement gradient) on every node and compare the "
                      "element stresses with the exact St. Venant-Kirchhoff stress and the "
                      "interior nodal forces with zero. 'rigid rotation': impose "
                      "u = (R - I)(X - c) on the wheel (or the bar), R a rotation by "
                      "Verification/Rotation angle, and report stress and internal force "
                      "(exactly zero for an objective element).");
    prm.declare_entry("Output directory",
                      "results",
                      Patterns::DirectoryName(),
                      "Directory for all files of the run; created if "
                      "missing. Must not be named 'output' in a test.");
    prm.declare_entry("Test mode",
                      "false",
                      Patterns::Bool(),
                      "Reproducible screen output for the test suite: no wall "
                      "times, no paths, no VTU files; results in mm, kN, MPa.");
    prm.declare_entry("Dry run",
                      "false",
                      Patterns::Bool(),
                      "Parse, build the mesh, print the setup summary and "
                      "stop without time stepping.");
    prm.leave_subsection();
  }



  void
  ProblemParameters::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Problem");
    geometry         = prm.get("Geometry");
    mode             = prm.get("Mode");
    output_directory = prm.get("Output directory");
    test_mode        = prm.get_bool("Test mode");
    dry_run          = prm.get_bool("Dry run");
    prm.leave_subsection();
    AssertThrow(!output_directory.empty(),
                ExcMessage("Problem/Output directory must not be empty."));
  }



  void
  GeometryParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Geometry");
    {
      prm.enter_subsection("Wheel");
      prm.declare_entry("Radius",
                        "0.46",
                        Patterns::Double(0.05, 2.0),
                        "Rolling radius R_w of the cylindrical tread [m], "
                        "range [0.05, 2].");
      prm.declare_entry("Bore radius",
                        "0.09",
                        Patterns::Double(0.005, 1.9),
                        "Radius of the hub bore [m], range [0.005, 1.9]; must "
                        "be below 0.8 R_w.");
      prm.declare_entry("Tread width",
                        "0.07",
                        Patterns::Double(0.005, 0.5),
                        "Width of the wheel (tread) along the axle y [m], "
                        "range [0.005, 0.5].");
      prm.declare_entry("Centre x",
                        "-0.15",
                        Patterns::Double(-10, 10),
                        "Initial x of the wheel centre (position A = -L1) [m], "
                        "range [-10, 10]; must lie on the rail.");
      prm.declare_entry("Initial gap",
                        "0.0",
                        Patterns::Double(-0.001, 0.1),
                        "Vertical gap between the lowest tread point and O "
                        "before any load [m], range [-0.001, 0.1].");
      prm.declare_entry("Circumferential cells",
                        "0",
                        Patterns::Integer(0, 4096),
                        "Number of coarse cells around the wheel [-], "
                        "range [0, 4096]; 0 = chosen from the coarse cell "
                        "size at the tread (and the only value allowed with "
                        "Mesh/Align coarse cells with zone).");
      prm.leave_subsection();

      prm.enter_subsection("Rail");
      prm.declare_entry("Head height",
                        "0.036",
                        Patterns::Double(0.005, 0.5),
                        "Height H1 of the rail head at y = 0 [m], range "
                        "[0.005, 0.5].");
      prm.declare_entry("Head width",
                        "0.07",
                        Patterns::Double(0.005, 0.5),
                        "Lateral width of the rail head [m], range "
                        "[0.005, 0.5].");
      prm.declare_entry("Profile radius",
                        "0.3",
                        Patterns::Double(0.01, 1e6),
                        "Radius of the circular rail-top profile in the y-z "
                        "plane [m], range [0.01, 1e6]; must exceed half the "
                        "head width.");
      prm.declare_entry("Start x",
                        "-0.3",
                        Patterns::Double(-10, 10),
                        "x of the rail's rear end [m], range [-10, 10].");
      prm.declare_entry("End x",
                        "0.12",
                        Patterns::Double(-10, 10),
                        "x of the rail's front end [m], range [-10, 10]; "
                        "must exceed Start x.");
      prm.leave_subsection();

      prm.enter_subsection("Mesh");
      prm.declare_entry("Coarse cell size",
                        "0.012",
                        Patterns::Double(1e-4, 1.0),
                        "Target edge length of the coarse mesh at the rail "
                        "and at the wheel tread [m], range [1e-4, 1].");
      prm.declare_entry("Minimum cell size",
                        "0.00033",
                        Patterns::Double(1e-5, 1.0),
                        "h_min: the solution zone (rail) and the matching "
                        "arc of the wheel tread are refined until their "
                        "cells' longest edge is at most this [m], range "
                        "[1e-5, 1]. The paper: 0.33 mm.");
      prm.declare_entry("Solution zone length",
                        "0.03",
                        Patterns::Double(0, 1),
                        "Length L2 of the solution zone along x, centred on "
                        "O [m], range [0, 1]; 0 = no local refinement.");
      prm.declare_entry("Solution zone half width",
                        "0.01",
                        Patterns::Double(0, 0.5),
                        "Lateral half-width of the solution zone [m], range "
                        "[0, 0.5].");
      prm.declare_entry("Solution zone depth",
                        "0.005",
                        Patterns::Double(0, 0.5),
                        "Depth of the solution zone below the rail top (and "
                        "below the wheel tread) [m], range [0, 0.5].");
      prm.declare_entry("Grading",
                        "0.5",
                        Patterns::Double(0.05, 4),
                        "Growth of the target cell size with the distance d "
                        "of a cell's centre from the solution zone, h = h_min "
                        "+ Grading d [-], range [0.05, 4] (the rolling path "
                        "likewise). Cells that reach into the zone (path) get "
                        "its size whatever the grading; from about 2 on, the "
                        "mesh is the smallest 2:1 balanced one around the "
                        "zones (paper case: 268,704 cells, 312,615 at 0.5).");
      prm.declare_entry("Rolling path cell size",
                        "0",
                        Patterns::Double(0, 1),
                        "Target cell size along the whole rolling path [m], "
                        "range [0, 1], 0 = off: the rail top over its length "
                        "and the wheel tread arc that rolls over it, within "
                        "the zone's half width and depth, graded outside. "
                        "The faces of coarse cells cut the curved surfaces "
                        "(sag L^2 / 8R: 47 um for 10.6 mm faces on the rail "
                        "profile), so a wheel rolling from coarse into fine "
                        "cells meets a surface that rises by that much; a "
                        "path of a few mm keeps the sag at a few um.");
      prm.declare_entry("Refine wheel",
                        "true",
                        Patterns::Bool(),
                        "Refine the arc of the wheel tread that meets the "
                        "solution zone when the wheel rolls from Centre x "
                        "to O.");
      prm.declare_entry("Align coarse cells with zone",
                        "false",
                        Patterns::Bool(),
                        "Lay the coarse mesh lines so that the coarse cells "
                        "over the solution zone refine onto Minimum cell size "
                        "(wheel: one cell of 4 x the coarse size over the "
                        "zone's arc, width and depth, its lateral lines half a "
                        "zone cell off centre; rail: cells of the coarse size "
                        "over the zone, anchored at the rail top, shrunk by "
                        "the arc top's slope and 4 % shorter along x), the "
                        "rest of each body divided into cells no larger. Wheel "
                        "and rail nodes thus never coincide (coincident grids "
                        "give a checkerboard pressure). Off: uniform coarse "
                        "divisions, whose zone cells come out 0.8-1 x Minimum "
                        "cell size.");
      prm.leave_subsection();

      prm.enter_subsection("Block on plate");
      prm.declare_entry("Plate size",
                        "0.2, 0.06, 0.02",
                        vector_pattern(),
                        "Plate extent along x, y, z [m]; it spans [0, Lx] x "
                        "[-Ly/2, Ly/2] x [-Lz, 0], its top at z = 0.");
      prm.declare_entry("Plate cells",
                        "20, 6, 2",
                        Patterns::List(Patterns::Integer(1, 10000), 3, 3, ","),
                        "Plate cells along x, y, z [-].");
      prm.declare_entry("Block size",
                        "0.02, 0.02, 0.01",
                        vector_pattern(),
                        "Block extent along x, y, z [m]; centred on y = 0.");
      prm.declare_entry("Block cells",
                        "4, 4, 2",
                        Patterns::List(Patterns::Integer(1, 10000), 3, 3, ","),
                        "Block cells along x, y, z [-].");
      prm.declare_entry("Block x",
                        "0.02",
                        Patterns::Double(-100, 100),
                        "x of the block's rear face [m].");
      prm.declare_entry("Block gap",
                        "0",
                        Patterns::Double(-0.001, 1),
                        "Height of the block's bottom above the plate top [m], "
                        "range [-0.001, 1].");
      prm.leave_subsection();

      prm.enter_subsection("Bar");
      prm.declare_entry("Length",
                        "1.0",
                        Patterns::Double(1e-4, 100),
                        "Bar length along x [m], range [1e-4, 100]. The bar "
                        "spans [0, L] x [-w/2, w/2] x [-h/2, h/2].");
      prm.declare_entry("Width",
                        "0.02",
                        Patterns::Double(1e-5, 100),
                        "Bar width along y [m], range [1e-5, 100].");
      prm.declare_entry("Height",
                        "0.02",
                        Patterns::Double(1e-5, 100),
                        "Bar height along z [m], range [1e-5, 100].");
      prm.declare_entry("Cells",
                        "50, 2, 2",
                        Patterns::List(Patterns::Integer(1, 100000), 3, 3, ","),
                        "Cells along x, y, z [-], each in [1, 100000].");
      prm.declare_entry("Distortion",
                        "0",
                        Patterns::Double(0, 0.3),
                        "Interior vertices are moved by this fraction of the "
                        "cell size in a fixed pseudo-random direction [-], "
                        "range [0, 0.3] (patch tests on distorted meshes).");
      prm.leave_subsection();
    }
    prm.leave_subsection();
  }



  void
  GeometryParameters::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Geometry");
    {
      prm.enter_subsection("Wheel");
      wheel_radius                = prm.get_double("Radius");
      bore_radius                 = prm.get_double("Bore radius");
      tread_width                 = prm.get_double("Tread width");
      wheel_centre_x              = prm.get_double("Centre x");
      initial_gap                 = prm.get_double("Initial gap");
      wheel_circumferential_cells = prm.get_integer("Circumferential cells");
      prm.leave_subsection();

      prm.enter_subsection("Rail");
      rail_head_height    = prm.get_double("Head height");
      rail_head_width     = prm.get_double("Head width");
      rail_profile_radius = prm.get_double("Profile radius");
      rail_start_x        = prm.get_double("Start x");
      rail_end_x          = prm.get_double("End x");
      prm.leave_subsection();

      prm.enter_subsection("Mesh");
      coarse_cell_size = prm.get_double("Coarse cell size");
      h_min            = prm.get_double("Minimum cell size");
      zone_length      = prm.get_double("Solution zone length");
      zone_half_width  = prm.get_double("Solution zone half width");
      zone_depth       = prm.get_double("Solution zone depth");
      grading          = prm.get_double("Grading");
      refine_wheel     = prm.get_bool("Refine wheel");
      path_cell_size   = prm.get_double("Rolling path cell size");
      align_zone       = prm.get_bool("Align coarse cells with zone");
      prm.leave_subsection();

      prm.enter_subsection("Bar");
      bar_length = prm.get_double("Length");
      bar_width  = prm.get_double("Width");
      bar_height = prm.get_double("Height");
      bar_cells.clear();
      for (const int n :
           Utilities::string_to_int(Utilities::split_string_list(prm.get("Cells"), ',')))
        bar_cells.push_back(n);
      bar_distortion = prm.get_double("Distortion");
      prm.leave_subsection();

      prm.enter_subsection("Block on plate");
      const auto cells = [&](const std::string &name) {
        std::vector<unsigned int> n;
        for (const int i :
             Utilities::string_to_int(Utilities::split_string_list(prm.get(name), ',')))
          n.push_back(i);
        return n;
      };
      plate_size  = get_vector(prm, "Plate size");
      plate_cells = cells("Plate cells");
      block_size  = get_vector(prm, "Block size");
      block_cells = cells("Block cells");
      block_x     = prm.get_double("Block x");
      block_gap   = prm.get_double("Block gap");
      for (unsigned int d = 0; d < 3; ++d)
        AssertThrow(plate_size[d] > 0 && block_size[d] > 0,
                    ExcMessage(
                      "Geometry/Block on plate: Plate size and Block size must be positive."));
      prm.leave_subsection();
    }
    prm.leave_subsection();
    check();
  }



  void
  GeometryParameters::check() const
  {
    AssertThrow(bore_radius < 0.8 * wheel_radius,
                ExcMessage("Geometry/Wheel/Bore radius (" + std::to_string(bore_radius) +
                           " m) must be below 0.8 x Geometry/Wheel/Radius."));
    AssertThrow(rail_end_x > rail_start_x, ExcMessage("Geometry/Rail/End x must exceed Start x."));
    AssertThrow(wheel_centre_x > rail_start_x && wheel_centre_x < rail_end_x,
                ExcMessage("Geometry/Wheel/Centre x must lie between "
                           "Geometry/Rail/Start x and End x."));
    AssertThrow(rail_profile_radius > 0.5 * rail_head_width,
                ExcMessage("Geometry/Rail/Profile radius must exceed half "
                           "of Geometry/Rail/Head width."));
    AssertThrow(h_min <= coarse_cell_size,
                ExcMessage("Geometry/Mesh/Minimum cell size must not exceed "
                           "Geometry/Mesh/Coarse cell size."));
    AssertThrow(coarse_cell_size / h_min < 1025.,
                ExcMessage("Geometry/Mesh/Coarse cell size / Minimum cell "
                           "size exceeds 1024 (more than 10 refinement "
                           "levels): choose a larger Minimum cell size."));
    AssertThrow(zone_depth < rail_head_height,
                ExcMessage("Geometry/Mesh/Solution zone depth must be below "
                           "Geometry/Rail/Head height."));
    AssertThrow(!align_zone || wheel_circumferential_cells == 0,
                ExcMessage("Geometry/Wheel/Circumferential cells = " +
                           std::to_string(wheel_circumferential_cells) +
                           " cannot be combined with Geometry/Mesh/Align coarse "
                           "cells with zone = true, which chooses the wheel's "
                           "divisions itself: set one of them back (0, false)."));
  }



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
    prm.declare_entry("End time",
                      "1e-4",
                      Patterns::Double(0, 10),
                      "Simulated time of the explicit run [s], range [0, 10].");
    prm.declare_entry("Time step",
                      "0",
                      Patterns::Double(0, 1e-2),
                      "Time step of the central-difference scheme [s], range "
                      "[0, 1e-2]; 0 = the stable step times the Courant "
                      "factor. A value above the stable step is an error. "
                      "The paper: 2.6e-8 s.");
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
    prm.leave_subsection();
  }



  void
  SolverParameters::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Time integration");
    end_time                      = prm.get_double("End time");
    time_step                     = prm.get_double("Time step");
    courant_factor                = prm.get_double("Courant factor");
    hourglass_coefficient         = prm.get_double("Hourglass coefficient");
    damping_model                 = prm.get("Damping model");
    stiffness_damping_coefficient = prm.get_double("Stiffness damping coefficient");
    rayleigh_beta                 = prm.get_double("Rayleigh beta");
    gravity                       = get_vector(prm, "Gravity");
    prm.leave_subsection();
  }



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
    wheel_bore                     = prm.get("Wheel bore");
    applied_force_ids.clear();
    for (const int id : Utilities::string_to_int(
           Utilities::split_string_list(prm.get("Applied force boundaries"))))
      applied_force_ids.push_back(id);
    applied_force_expression = prm.get("Applied force");
    applied_force_constants  = prm.get("Applied force constants");
    prm.leave_subsection();
  }



  void
  ContactParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Contact");
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
                      "400 kN); 'area': k = SF K A / h_ref, the same pressure per "
                      "penetration SF K / h_ref on every face, equal to "
                      "'segment' on cubic cells of size h_ref.");
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
    prm.declare_entry("Contact damping",
                      "0",
                      Patterns::Double(0, 1),
                      "Viscous damping of the normal contact force, a fraction "
                      "of the critical damping 2 sqrt(k m) of the slave node on "
                      "its penalty spring (LS-DYNA's VDC / 100) [-], range "
                      "[0, 1]; it damps the chatter of bodies resting on each "
                      "other.");
    prm.declare_entry("Search interval",
                      "10",
                      Patterns::Integer(1, 1000000),
                      "Steps between rebuilds of the candidate lists [-], range "
                      "[1, 1e6].");
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
    prm.declare_entry("Friction law",
                      "exponential",
                      Patterns::Selection("none|constant|exponential"),
                      "'none': frictionless; 'constant': Coulomb, f = Static "
                      "friction coefficient; 'exponential': f = f_D + (f_S - "
                      "f_D) exp(-k s_n) (paper eq. 1), s_n the micro-slip "
                      "velocity.");
    prm.declare_entry("Static friction coefficient",
                      "0.5",
                      Patterns::Double(0, 10),
                      "f_S [-], range [0, 10].");
    prm.declare_entry("Dynamic friction coefficient",
                      "0.32",
                      Patterns::Double(0, 10),
                      "f_D [-], range [0, 10].");
    prm.declare_entry("Decay coefficient",
                      "6",
                      Patterns::Double(0, 1e6),
                      "k of the exponential law [s/m], range [0, 1e6].");
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
    penalty_stiffness         = prm.get("Penalty stiffness");
    penalty_reference_length  = prm.get_double("Penalty reference length");
    tangential_factor         = prm.get_double("Tangential stiffness factor");
    damping_ratio             = prm.get_double("Contact damping");
    search_interval           = prm.get_integer("Search interval");
    search_margin             = prm.get_double("Search margin");
    rebuild_fraction          = prm.get_double("Rebuild fraction");
    initial_overlap_tolerance = prm.get_double("Initial overlap tolerance");
    friction_law              = prm.get("Friction law");
    static_coefficient        = prm.get_double("Static friction coefficient");
    dynamic_coefficient       = prm.get_double("Dynamic friction coefficient");
    decay                     = prm.get_double("Decay coefficient");
    prm.leave_subsection();
    AssertThrow(slave_boundary != master_boundary,
                ExcMessage("Contact/Slave boundary and Contact/Master boundary must differ."));
  }



  void
  WheelsetParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Wheelset");
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
    prm.declare_entry("Torque ramp time",
                      "0",
                      Patterns::Double(0, 10),
                      "The torque rises linearly from 0 over this time [s], "
                      "range [0, 10]; 0 = applied at once.");
    prm.declare_entry("Static start",
                      "true",
                      Patterns::Bool(),
                      "Before the explicit run, find the static equilibrium at A "
                      "(wheel on the rail under gravity and the static load) with "
                      "the implicit contact solve.");
    prm.leave_subsection();
  }



  void
  WheelsetParameters::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Wheelset");
    unsprung_mass        = prm.get_double("Unsprung mass");
    sprung_mass          = prm.get_double("Sprung mass");
    suspension_stiffness = prm.get_double("Suspension stiffness");
    suspension_damping   = prm.get_double("Suspension damping");
    axle_inertia         = prm.get_double("Axle rotational inertia");
    rolling_speed        = prm.get_double("Rolling speed");
    traction_coefficient = prm.get_double("Nominal traction coefficient");
    torque_ramp_time     = prm.get_double("Torque ramp time");
    static_start         = prm.get_bool("Static start");
    prm.leave_subsection();
  }



  void
  StaticParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Static solve");
    prm.declare_entry("Axle load",
                      "140300",
                      Patterns::Double(0, 1e8),
                      "Vertical force F_N of the wheel on the rail sought by "
                      "the static contact solve [N], range [0, 1e8]; the paper: "
                      "(13.4 t + 0.9 t) g = 140.3 kN.");
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
                      "false",
                      Patterns::Bool(),
                      "Solve each Newton step only as accurately as the next "
                      "iterate can use (Eisenstat-Walker): CG stops at the "
                      "relative residual 0.5 x Newton tolerance x load / "
                      "Newton residual, kept within [Linear solver tolerance, "
                      "1e-2]. The converged state meets the same Newton "
                      "tolerance with fewer CG iterations; false: every step "
                      "to Linear solver tolerance.");
    prm.declare_entry("AMG near null space",
                      "translations",
                      Patterns::Selection("translations|rigid body modes"),
                      "Near null space of the AMG preconditioner of the static "
                      "solve: 'translations' (3 constant modes, aggregation "
                      "threshold 0.02) or 'rigid body modes' (translations "
                      "and rotations, threshold 1e-4): about 3.5 x fewer CG "
                      "iterations and 2 x faster on the paper mesh, but about "
                      "1.4 x the peak memory (2.5 instead of 1.8 GB per rank "
                      "of 2).");
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
    amg_null_space        = prm.get("AMG near null space");
    prm.leave_subsection();
  }



  void
  InitialParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Initial conditions");
    prm.declare_entry("Wheel velocity",
                      "0, 0, 0",
                      vector_pattern(),
                      "Initial translational velocity of the wheel [m/s].");
    prm.declare_entry("Wheel angular velocity",
                      "0",
                      Patterns::Double(-1e4, 1e4),
                      "Initial angular velocity of the wheel about +y "
                      "through its centre [rad/s], range [-1e4, 1e4]; "
                      "rolling towards +x is positive: +V/R_w (the contact "
                      "point then has omega e_y x (-R e_z) = -V e_x).");
    prm.declare_entry("Velocity function",
                      "0; 0; 0",
                      Patterns::Anything(),
                      "Additional initial velocity of every node [m/s]: three "
                      "muparser expressions 'vx; vy; vz' in x, y, z (m).");
    prm.declare_entry("Velocity function constants",
                      "",
                      Patterns::Anything(),
                      "Constants for the expression, 'name=value, ...'.");
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



  void
  OutputParameters::declare_parameters(ParameterHandler &prm)
  {
    std::string resumable;
    for (const std::string &entry : Checkpoint::resumable_entries())
      resumable += (resumable.empty() ? "" : ", ") + entry;
    prm.enter_subsection("Output");
    prm.declare_entry("Report interval",
                      "1000",
                      Patterns::Integer(1, 1000000000),
                      "Steps between screen reports of time and energies "
                      "[-], range [1, 1e9].");
    prm.declare_entry("Statistics interval",
                      "100",
                      Patterns::Integer(1, 1000000000),
                      "Steps between rows of the statistics file [-], range "
                      "[1, 1e9].");
    prm.declare_entry("VTU interval",
                      "0",
                      Patterns::Integer(0, 1000000000),
                      "Steps between VTU/PVTU snapshots [-], range [0, 1e9]; "
                      "0 = first and last step only.");
    prm.declare_entry("VTU compression",
                      "fast",
                      Patterns::Selection("fast|best|none"),
                      "zlib level of the VTU snapshots: 'fast' (about 3 s "
                      "less per snapshot of the paper mesh than 'best', "
                      "files about 30 % larger), 'best', or 'none'.");
    prm.declare_entry("Probe point",
                      "0, 0, 0",
                      vector_pattern(),
                      "A velocity history is recorded at the node nearest "
                      "to this point [m] (file probe.csv).");
    prm.declare_entry("Probe component",
                      "0",
                      Patterns::Integer(0, 2),
                      "Component (0 = x, 1 = y, 2 = z) used by the "
                      "verification checks on the probe [-].");
    prm.declare_entry("Divergence limit",
                      "0.5",
                      Patterns::Double(1e-12, 1e6),
                      "The run stops with a diagnosis when the relative energy "
                      "balance error exceeds this [-], range [1e-12, 1e6] "
                      "(an exploding energy; NaN or infinite energies always "
                      "stop it). Checked at statistics steps.");
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
    prm.declare_entry("Checkpoint minutes",
                      "0",
                      Patterns::Double(0, 1e6),
                      "Wall-clock minutes between checkpoints [min], range "
                      "[0, 1e6]; 0 = none.");
    prm.declare_entry("Stop after step",
                      "0",
                      Patterns::Integer(0, 2000000000),
                      "Stop the explicit run after this step with a "
                      "checkpoint [-], range [0, 2e9]; 0 = run to the end "
                      "(for splitting a run, and the restart test).");
    prm.declare_entry("Resume",
                      "false",
                      Patterns::Bool(),
                      "Continue from the checkpoint in the output directory "
                      "(the same as the command line flag --resume); see "
                      "Checkpoint interval for what may change.");
    prm.declare_entry("Timing warm-up steps",
                      "0",
                      Patterns::Integer(0, 1000000000),
                      "Steps before the timers of the explicit run start [-], "
                      "range [0, 1e9]: the time split (elements, contact, "
                      "update, communication, output) and ns per "
                      "element-step printed at the end and written to "
                      "timing.csv count only the steps after them (a "
                      "benchmark leaves out the first, cold steps).");
    prm.leave_subsection();
  }



  void
  OutputParameters::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Output");
    report_interval     = prm.get_integer("Report interval");
    statistics_interval = prm.get_integer("Statistics interval");
    vtu_interval        = prm.get_integer("VTU interval");
    vtu_compression     = prm.get("VTU compression");
    probe_point         = Point<3>(get_vector(prm, "Probe point"));
    probe_component     = prm.get_integer("Probe component");
    timing_warmup_steps = prm.get_integer("Timing warm-up steps");
    divergence_limit    = prm.get_double("Divergence limit");
    checkpoint_interval = prm.get_integer("Checkpoint interval");
    checkpoint_minutes  = prm.get_double("Checkpoint minutes");
    stop_after_step     = prm.get_integer("Stop after step");
    resume              = prm.get_bool("Resume");
    prm.leave_subsection();
  }



  void
  VerificationParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Verification");
    prm.declare_entry(
      "Check",
      "none",
      Patterns::Selection(
        "none|wave arrival|longitudinal frequency|bending frequency|energy balance|"
        "inclined plane|tangential sliding|impact|static start|traction|free rolling"),
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
      "trailing part near zero.");
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
    prm.declare_entry("Wave threshold",
                      "0.5",
                      Patterns::Double(0.01, 0.99),
                      "Fraction of the far-end steady velocity that marks "
                      "the arrival of the front [-], range [0.01, 0.99].");
    prm.declare_entry("Hourglass limit",
                      "0.1",
                      Patterns::Double(0, 10),
                      "Largest accepted ratio of hourglass-mode energy to "
                      "internal energy [-], range [0, 10].");
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
    prm.leave_subsection();
  }



  namespace
  {
    /**
     * A user constant's name must be an identifier that is neither a
     * variable of the expression nor a name muparser (or deal.II's
     * FunctionParser) already gives a meaning: such a name would shadow it
     * or make the expression fail to parse.
     */
    void
    check_constant_name(const std::string &name,
                        const std::string &variables,
                        const std::string &entry)
    {
      bool identifier =
        !name.empty() && (std::isalpha(static_cast<unsigned char>(name[0])) || name[0] == '_');
      for (const char ch : name)
        identifier = identifier && (std::isalnum(static_cast<unsigned char>(ch)) || ch == '_');
      AssertThrow(identifier,
                  ExcMessage(entry + " constants: '" + name +
                             "' is not a name (letters, digits and '_', not starting with a "
                             "digit)."));
      for (const auto &v : Utilities::split_string_list(variables))
        AssertThrow(name != v,
                    ExcMessage(entry + " constants: '" + name +
                               "' is a variable of the expression (" + variables +
                               ") and cannot be a constant."));
      static const char *reserved[] = {"_pi",   "_e",        "sin",   "cos",   "tan",  "asin",
                                       "acos",  "atan",      "sinh",  "cosh",  "tanh", "asinh",
                                       "acosh", "atanh",     "log2",  "log10", "log",  "ln",
                                       "exp",   "sqrt",      "sign",  "rint",  "abs",  "min",
                                       "max",   "sum",       "avg",   "if",    "int",  "ceil",
                                       "cot",   "csc",       "floor", "sec",   "pow",  "erfc",
                                       "rand",  "rand_seed", "atan2", "fmod"};
      for (const char *r : reserved)
        AssertThrow(name != r,
                    ExcMessage(entry + " constants: '" + name +
                               "' is a built-in function or constant of the expression parser."));
    }
  } // namespace



  std::unique_ptr<FunctionParser<3>>
  make_vector_function(const std::string &expression,
                       const std::string &constants_text,
                       const std::string &variables,
                       const std::string &entry)
  {
    std::map<std::string, double> constants = {{"pi", M_PI}};
    for (const auto &c : Utilities::split_string_list(constants_text))
      {
        const auto kv = Utilities::split_string_list(c, '=');
        AssertThrow(kv.size() == 2,
                    ExcMessage(entry + " constants: cannot read '" + c + "' as name=value."));
        const std::string &name = kv[0];
        check_constant_name(name, variables, entry);
        AssertThrow(constants.count(name) == 0,
                    ExcMessage(entry + " constants: '" + name +
                               (name == "pi" ?
                                  "' is built in (pi = 3.14159...) and cannot be redefined." :
                                  "' is defined twice.")));
        double value = 0;
        try
          {
            value = Utilities::string_to_double(kv[1]);
          }
        catch (...)
          {
            AssertThrow(false, ExcMessage(entry + " constants: '" + kv[1] + "' is not a number."));
          }
        AssertThrow(std::isfinite(value),
                    ExcMessage(entry + " constants: " + name + " = " + kv[1] + " is not finite."));
        constants[name] = value;
      }
    const auto components = Utilities::split_string_list(expression, ';');
    AssertThrow(components.size() == 3,
                ExcMessage(entry + " = '" + expression +
                           "' must have three expressions separated by ';'."));
    auto function = std::make_unique<FunctionParser<3>>(3);
    try
      {
        function->initialize(variables,
                             components,
                             constants,
                             variables.find('t') != std::string::npos);
        for (unsigned int d = 0; d < 3; ++d)
          AssertThrow(std::isfinite(function->value(Point<3>(), d)), ExcMessage("not finite at 0"));
      }
    catch (const ExceptionBase &e)
      {
        AssertThrow(false,
                    ExcMessage(entry + " = '" + expression + "' cannot be evaluated (variables " +
                               variables + "; constants pi and " +
                               (constants_text.empty() ? std::string("none") : constants_text) +
                               ")."));
      }
    return function;
  }



  void
  Parameters::declare_parameters(ParameterHandler &prm)
  {
    ProblemParameters::declare_parameters(prm);
    GeometryParameters::declare_parameters(prm);
    MaterialParameters::declare_parameters(prm);
    SolverParameters::declare_parameters(prm);
    BoundaryParameters::declare_parameters(prm);
    InitialParameters::declare_parameters(prm);
    ContactParameters::declare_parameters(prm);
    StaticParameters::declare_parameters(prm);
    WheelsetParameters::declare_parameters(prm);
    OutputParameters::declare_parameters(prm);
    VerificationParameters::declare_parameters(prm);
  }



  void
  Parameters::parse(ParameterHandler &prm, const std::string &filename)
  {
    ParameterFile::parse(prm, filename);
    problem.parse_parameters(prm);
    geometry.parse_parameters(prm);
    material.parse_parameters(prm);
    solver.parse_parameters(prm);
    boundary.parse_parameters(prm);
    initial.parse_parameters(prm);
    contact.parse_parameters(prm);
    statics.parse_parameters(prm);
    wheelset.parse_parameters(prm);
    output.parse_parameters(prm);
    verification.parse_parameters(prm);
    // validate the expressions now, so that a typo stops the run at once
    make_vector_function(initial.velocity_expression,
                         initial.velocity_constants,
                         "x,y,z",
                         "Initial conditions/Velocity function");
    make_vector_function(boundary.applied_force_expression,
                         boundary.applied_force_constants,
                         "x,y,z,t",
                         "Boundary conditions/Applied force");
    make_vector_function(boundary.prescribed_velocity_expression,
                         boundary.prescribed_velocity_constants,
                         "x,y,z,t",
                         "Boundary conditions/Prescribed velocity");
  }
} // namespace WheelRail
