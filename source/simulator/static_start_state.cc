/**
 * The static start on disk (Wheelset/Static start state): the run that
 * solves the static problem writes its state, later runs of the same static
 * problem (the points of a creep curve or a traction sweep) read it and skip
 * the implicit solve. The files are rank files of the checkpoint format
 * (checkpoint.h): the header with every parameter, the solver's and the
 * contact's state as a checkpoint holds them, then the static result.
 */
#include <deal.II/base/mpi.h>
#include <deal.II/base/utilities.h>

#include <wheelrail/base/checkpoint.h>
#include <wheelrail/parameters/entry_flags.h>
#include <wheelrail/simulator/simulator.h>
#include <wheelrail/solver/static_solver.h>

#include <unistd.h>

#include <filesystem>
#include <fstream>

namespace WheelRail
{
  namespace
  {
    /** The static result after the solver's and the contact's state. */
    template <class Archive>
    void
    serialize_result(Archive &ar, StaticResult &r)
    {
      ar.pod(r.axle_displacement);
      ar.pod(r.contact_force);
      ar.pod(r.load_iterations);
      ar.pod(r.newton_iterations);
      ar.pod(r.linear_iterations);
    }
  } // namespace



  bool
  Simulator::read_static_start(StaticResult &result)
  {
    const std::string &directory = parameters.wheelset.static_start_state;
    if (directory.empty())
      return false;
    AssertThrow(!std::filesystem::exists(directory) || std::filesystem::exists(directory + "/info"),
                ExcMessage("Wheelset/Static start state: '" + directory +
                           "' exists and holds no static start; name a new directory."));
    if (!std::filesystem::exists(directory + "/info"))
      return false;
    const unsigned int rank  = Utilities::MPI::this_mpi_process(mpi_communicator);
    const unsigned int ranks = Utilities::MPI::n_mpi_processes(mpi_communicator);
    const std::string  name  = Checkpoint::rank_file(directory, rank);
    const std::string  where = "Wheelset/Static start state: the state in '" + directory + "'";

    auto [header, error, stored_ranks] = Checkpoint::read_rank_header(directory, mpi_communicator);
    if (stored_ranks != 0 && stored_ranks != ranks)
      error = where + " was written by " + std::to_string(stored_ranks) +
              " MPI rank(s); this run has " + std::to_string(ranks) +
              ". Run with as many, or set another directory";
    else if (!error.empty())
      error = where + ": " + error;
    else if (header.cells != triangulation.n_global_active_cells() ||
             header.dofs != solver->get_dof_handler().n_dofs())
      error = where + " was written for a mesh of " + std::to_string(header.cells) + " cells and " +
              std::to_string(header.dofs) + " DoFs; this run's has " +
              std::to_string(triangulation.n_global_active_cells()) + " and " +
              std::to_string(solver->get_dof_handler().n_dofs());
    if (!error.empty())
      error += ".";
    throw_first_error(error, mpi_communicator);

    std::vector<Checkpoint::Change> allowed, refused;
    Checkpoint::compare_parameters(
      header.parameters,
      parameter_record,
      allowed,
      refused,
      EntryFlags::entries(EntryFlag::static_start_free));
    if (!refused.empty())
      {
        std::string message =
          where + " is of another static problem: " + std::to_string(refused.size()) + " entr" +
          (refused.size() == 1 ? "y differs" : "ies differ") + " (state -> this run):";
        for (const auto &c : refused)
          message += "\n" + c.entry + ": " + c.old_value + " -> " + c.new_value;
        message += "\nSet another directory (or none) for this run, or remove that one.";
        AssertThrow(false, ExcMessage(message));
      }

    std::ifstream      file(name, std::ios::binary);
    Checkpoint::Reader in(file, name);
    Checkpoint::read_header(in, name);
    solver->serialize(in);
    contact->serialize(in);
    serialize_result(in, result);
    std::uint64_t magic = 0;
    in.pod(magic);
    AssertThrow(magic == Checkpoint::magic, ExcMessage(where + " is corrupt ('" + name + "')."));
    return true;
  }



  void
  Simulator::write_static_start(const StaticResult &result)
  {
    const std::string &directory = parameters.wheelset.static_start_state;
    if (directory.empty())
      return;
    const unsigned int rank  = Utilities::MPI::this_mpi_process(mpi_communicator);
    const unsigned int ranks = Utilities::MPI::n_mpi_processes(mpi_communicator);
    // every rank writes into a directory of its own run's name beside the
    // target, which rank 0 then renames: a run that reads the state sees
    // all of it or none, also while another run writes the same
    const std::string fresh =
      directory + ".new." +
      std::to_string(Utilities::MPI::broadcast(mpi_communicator, static_cast<int>(getpid()), 0));
    std::string error;
    // removes the directory if a failure throws before the end
    std::unique_ptr<TemporaryPath> guard;
    if (rank == 0)
      {
        guard = std::make_unique<TemporaryPath>(fresh);
        std::error_code ec;
        std::filesystem::remove_all(fresh, ec);
        std::filesystem::create_directories(fresh, ec);
        if (ec)
          error =
            "Wheelset/Static start state: cannot create '" + fresh + "' (" + ec.message() + ").";
      }
    throw_first_error(error, mpi_communicator);

    const bool written = Checkpoint::write_rank_file(Checkpoint::rank_file(fresh, rank),
                                                     state_header(),
                                                     [&](Checkpoint::Writer &out) {
                                                       solver->serialize(out);
                                                       contact->serialize(out);
                                                       StaticResult r = result;
                                                       serialize_result(out, r);
                                                     });
    int        ok      = Utilities::MPI::min(written ? 1 : 0, mpi_communicator);
    if (rank == 0)
      {
        std::error_code ec;
        if (ok)
          {
            std::ofstream info(fresh + "/info");
            info << "wheelrail static start: " << ranks << " rank(s), wheel load "
                 << result.contact_force << " N, axle lowered by " << result.axle_displacement
                 << " m\n";
            info.flush();
            ok = info.good() ? 1 : 0;
          }
        if (ok && !std::filesystem::exists(directory))
          std::filesystem::rename(fresh, directory, ec);
        else if (ok && !std::filesystem::exists(directory + "/info"))
          error = "Wheelset/Static start state: '" + directory +
                  "' exists and holds no static start; name a new directory.";
        // else another run has written the same state meanwhile
        if (!ok)
          error = "Wheelset/Static start state: cannot write the state in '" + fresh +
                  "' (disk full or no permission).";
        else if (ec)
          error = "Wheelset/Static start state: cannot rename '" + fresh + "' to '" + directory +
                  "' (" + ec.message() + ").";
        std::filesystem::remove_all(fresh, ec);
      }
    throw_first_error(error, mpi_communicator);
  }
} // namespace WheelRail
