/**
 * @file parameters/parameters.cc
 * All parameters of a run: the subsections declared in the order of the
 * parameter file and --help, read and checked.
 */

#include <deal.II/base/exceptions.h>
#include <deal.II/base/utilities.h>

#include <wheelrail/geometry/interface.h>
#include <wheelrail/parameters/consistency.h>
#include <wheelrail/parameters/parameter_file.h>
#include <wheelrail/parameters/parameters.h>

#include <filesystem>
#include <string>
#include <tuple>

namespace WheelRail
{
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
    OutputParameters::declare_checkpoint_interval(prm);
  }



  void
  Parameters::parse(ParameterHandler &prm, const std::string &filename)
  {
    const ParameterFile::ExpandedText text = ParameterFile::parse(prm, filename);
    problem.parse_parameters(prm);
    geometry.parse_parameters(prm);
    geometry.file_directory = [text](const std::string &section, const std::string &entry) {
      return text.directory_of(section, entry);
    };
    geometry_model = Geometry::GeometryModel::create(problem.geometry, geometry, prm);
    std::tie(geometry.zone_y_lo, geometry.zone_y_hi) = geometry_model->zone_span();
    material.parse_parameters(prm);
    solver.parse_parameters(prm);
    boundary.parse_parameters(prm);
    initial.parse_parameters(prm);
    contact.parse_parameters(prm);
    statics.parse_parameters(prm);
    wheelset.parse_parameters(prm);
    output.parse_parameters(prm);
    verification.parse_parameters(prm);
    // the directory's name is printed as it is
    AssertThrow(ParameterFile::printable(problem.output_directory) == problem.output_directory,
                ExcMessage("Problem/Output directory '" +
                           ParameterFile::printable(problem.output_directory) +
                           "' holds a terminal control character or a byte that is no UTF-8: "
                           "name the directory in printable characters."));
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
    // the entries against each other, before anything is built
    Consistency::check_loads(*this);
    Consistency::check_wheel_and_rail(*this);
    Consistency::check_wheelset_kinematics(*this);
  }
} // namespace WheelRail
