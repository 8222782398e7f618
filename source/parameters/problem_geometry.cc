/**
 * @file parameters/problem_geometry.cc
 * The subsections Problem (what is computed, where the output goes) and
 * Geometry (wheel, rail, mesh, and the simple test bodies), SPEC 1.
 */

#include <deal.II/base/exceptions.h>
#include <deal.II/base/utilities.h>

#include <wheelrail/geometry/interface.h>
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
  ProblemParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Problem");
    const EntryFlags flags("Problem");
    prm.declare_entry("Geometry",
                      "wheel and rail",
                      Patterns::Selection(Geometry::GeometryModel::names()),
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
    flags.mark("Output directory", EntryFlag::resumable);
    prm.declare_entry("Test mode",
                      "false",
                      Patterns::Bool(),
                      "Reproducible screen output for the test suite: no wall "
                      "times, no paths, no VTU files; results in mm, kN, MPa.");
    flags.mark("Test mode", EntryFlag::static_start_free);
    prm.declare_entry("Dry run",
                      "false",
                      Patterns::Bool(),
                      "Parse, build the mesh, print the setup summary and "
                      "stop without time stepping.");
    flags.mark("Dry run", EntryFlag::resumable);
    prm.declare_entry("Partition",
                      "work",
                      Patterns::Selection("work|cells"),
                      "How the cells are split between the MPI ranks: 'work' "
                      "gives each rank about the same work of the explicit "
                      "step, from each cell's kind (family or not), its faces "
                      "with hanging nodes and its contact faces, fixed "
                      "weights that make the partition the same in every run "
                      "(include/wheelrail/mesh/partition_weights.h); 'cells' "
                      "gives each rank the same number of cells. p4est keeps "
                      "its order of the cells either way. One rank: no "
                      "effect.");
    prm.leave_subsection();
  }



  void
  ProblemParameters::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Problem");
    geometry         = prm.get("Geometry");
    mode             = run_mode_names.parse(prm.get("Mode"));
    output_directory = prm.get("Output directory");
    test_mode        = prm.get_bool("Test mode");
    dry_run          = prm.get_bool("Dry run");
    partition        = partition_by_names.parse(prm.get("Partition"));
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
    // the entries of the geometries that declare their own
    Geometry::GeometryModel::declare_parameters(prm);
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
      zone_y_lo        = -zone_half_width;
      zone_y_hi        = zone_half_width;
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
} // namespace WheelRail
