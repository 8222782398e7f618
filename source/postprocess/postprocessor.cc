#include <deal.II/base/mpi.h>

#include <wheelrail/postprocess/output_files.h>
#include <wheelrail/postprocess/postprocessor.h>

namespace WheelRail
{
  void
  SimulatorAccess::write_file(const std::string &name, const std::string &content) const
  {
    if (Utilities::MPI::this_mpi_process(mpi_communicator) != 0)
      return;
    write_file_atomically(output_directory + "/" + name, content);
  }
} // namespace WheelRail
