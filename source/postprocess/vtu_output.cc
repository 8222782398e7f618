#include <deal.II/numerics/data_out.h>

#include <wheelrail/postprocess/output_files.h>
#include <wheelrail/postprocess/vtu_output.h>

#include <sstream>

namespace WheelRail
{
  DataOutBase::VtkFlags::ZlibCompressionLevel
  vtu_compression_level(const VtuCompression setting)
  {
    // smaller files for more time
    return setting == VtuCompression::best ? DataOutBase::VtkFlags::best_compression :
           setting == VtuCompression::none ? DataOutBase::VtkFlags::no_compression :
                                             DataOutBase::VtkFlags::best_speed;
  }



  VtuOutput::VtuOutput(const SimulatorAccess &access)
    : access(access)
  {}



  void
  VtuOutput::write()
  {
    const auto    stresses = access.solver.cell_stresses();
    Vector<float> von_mises(access.triangulation.n_active_cells());
    Vector<float> material(access.triangulation.n_active_cells());
    Vector<float> rank(access.triangulation.n_active_cells());
    for (const auto &cell : access.triangulation.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          von_mises[cell->active_cell_index()] = stresses[cell->active_cell_index()].von_mises;
          material[cell->active_cell_index()]  = cell->material_id();
          rank[cell->active_cell_index()]      = access.triangulation.locally_owned_subdomain();
        }
    DataOut<dim> data_out;
    data_out.attach_dof_handler(access.solver.get_dof_handler());
    const std::vector<DataComponentInterpretation::DataComponentInterpretation> vector_type(
      dim, DataComponentInterpretation::component_is_part_of_vector);
    data_out.add_data_vector(access.solver.displacement(),
                             std::vector<std::string>(dim, "displacement"),
                             DataOut<dim>::type_dof_data,
                             vector_type);
    data_out.add_data_vector(access.solver.velocity(),
                             std::vector<std::string>(dim, "velocity"),
                             DataOut<dim>::type_dof_data,
                             vector_type);
    data_out.add_data_vector(von_mises, "von_mises_Pa", DataOut<dim>::type_cell_data);
    data_out.add_data_vector(material, "material_id", DataOut<dim>::type_cell_data);
    data_out.add_data_vector(rank, "mpi_rank", DataOut<dim>::type_cell_data);
    data_out.build_patches();
    DataOutBase::VtkFlags flags;
    flags.time              = access.solver.time();
    flags.cycle             = counter;
    flags.compression_level = vtu_compression_level(access.parameters.output.vtu_compression);
    data_out.set_flags(flags);
    const std::string name = write_vtu_with_pvtu_record(
      data_out, access.output_directory + "/", "solution", counter++, 5, access.mpi_communicator);
    records.emplace_back(access.solver.time(), name);
    std::ostringstream pvd;
    DataOutBase::write_pvd_record(pvd, records);
    access.write_file("solution.pvd", pvd.str());
  }



  void
  VtuOutput::execute(const StepInfo &step)
  {
    const OutputParameters &op = access.parameters.output;
    if (!access.parameters.problem.test_mode && op.vtu_interval > 0 &&
        (step.step + 1) % op.vtu_interval == 0 && step.step + 1 < step.n_steps)
      write();
  }
} // namespace WheelRail
