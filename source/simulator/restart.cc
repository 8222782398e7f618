/**
 * The checkpoint of an explicit run: Simulator::write_checkpoint(),
 * check_checkpoint() and read_checkpoint(); the state after the header is
 * listed once, in Simulator::serialize(). The file format is in
 * checkpoint.h.
 */
#include <deal.II/base/mpi.h>
#include <deal.II/base/utilities.h>

#include <wheelrail/base/checkpoint.h>
#include <wheelrail/parameters/entry_flags.h>
#include <wheelrail/postprocess/output_files.h>
#include <wheelrail/simulator/format.h>
#include <wheelrail/simulator/simulator.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iomanip>
#include <memory>
#include <sstream>

namespace WheelRail
{
  using Report::fmt;

  template <class Archive>
  void
  Simulator::serialize(Archive &ar)
  {
    const double time_step = solver->time_step();
    solver->serialize(ar);
    if constexpr (Archive::is_loading)
      AssertThrow(solver->time_step() == time_step,
                  ExcMessage("The checkpoint '" + ar.file_name() +
                             "' was written with the time step " + fmt(solver->time_step(), 10) +
                             " s; this run's is " + fmt(time_step, 10) +
                             " s (another executable?)."));
    // an object a run may lack: a flag, then its state; the flag must be
    // this run's
    const auto optional = [&ar](auto *object, const std::string &what) {
      bool has = object != nullptr;
      ar.pod(has);
      AssertThrow(has == (object != nullptr),
                  ExcMessage("The checkpoint's " + what + " setting differs."));
      if (object)
        object->serialize(ar);
    };
    optional(contact.get(), "contact");
    optional(wheelset.get(), "wheelset");
    for (Postprocessor *postprocessor : checkpointed)
      if constexpr (Archive::is_loading)
        postprocessor->load(ar);
      else
        postprocessor->save(ar);
  }



  Checkpoint::Header
  Simulator::state_header() const
  {
    Checkpoint::Header header;
    header.ranks      = Utilities::MPI::n_mpi_processes(mpi_communicator);
    header.cells      = triangulation.n_global_active_cells();
    header.dofs       = solver->get_dof_handler().n_dofs();
    header.step       = solver->step_number();
    header.time       = solver->time();
    header.time_step  = solver->time_step();
    header.parameters = parameter_record;
    return header;
  }



  void
  Simulator::write_checkpoint()
  {
    // every rank writes its part into checkpoint.new/, then rank 0 swaps
    // it for checkpoint/: the previous checkpoint stays until the new one
    // is complete. A failure on the way removes checkpoint.new/ (rank 0's
    // guard) and stops every rank with one message.
    const unsigned int             rank   = Utilities::MPI::this_mpi_process(mpi_communicator);
    const unsigned int             ranks  = Utilities::MPI::n_mpi_processes(mpi_communicator);
    const std::string              fresh  = output_directory + "/checkpoint.new";
    const std::string              target = output_directory + "/checkpoint";
    const std::string              old    = output_directory + "/checkpoint.old";
    std::unique_ptr<TemporaryPath> guard;
    std::string                    error;
    if (rank == 0)
      {
        guard = std::make_unique<TemporaryPath>(fresh);
        std::error_code ec;
        std::filesystem::remove_all(fresh, ec);
        if (!ec)
          std::filesystem::create_directories(fresh, ec);
        if (ec)
          error = "Cannot create '" + fresh + "' for the checkpoint (" + ec.message() +
                  "); the previous checkpoint is kept.";
      }
    throw_first_error(error, mpi_communicator);
    const bool written =
      Checkpoint::write_rank_file(Checkpoint::rank_file(fresh, rank),
                                  state_header(),
                                  [this](Checkpoint::Writer &out) { serialize(out); });
    const int ok = Utilities::MPI::min(written ? 1 : 0, mpi_communicator);
    AssertThrow(ok,
                ExcMessage("Cannot write the checkpoint in '" + fresh +
                           "' (disk full or no permission); the previous checkpoint is kept."));
    if (rank == 0)
      {
        std::ofstream info(fresh + "/info");
        info << "wheelrail checkpoint: step " << solver->step_number() << ", t = " << solver->time()
             << " s, " << ranks << " rank(s)\n";
        info.flush();
        if (!info.good())
          error = "Cannot write '" + fresh +
                  "/info' (disk full or no permission); the previous checkpoint is kept.";
        info.close();
        if (error.empty())
          {
            std::error_code ec;
            std::filesystem::remove_all(old, ec);
            if (!ec && std::filesystem::exists(target))
              std::filesystem::rename(target, old, ec);
            if (!ec)
              std::filesystem::rename(fresh, target, ec);
            if (ec)
              error = "Cannot put the checkpoint '" + fresh + "' in place of '" + target + "' (" +
                      ec.message() + ").";
            else
              {
                guard->commit();
                std::filesystem::remove_all(old, ec);
              }
          }
      }
    throw_first_error(error, mpi_communicator);
  }



  void
  Simulator::check_checkpoint()
  {
    const unsigned int ranks = Utilities::MPI::n_mpi_processes(mpi_communicator);
    // checkpoint.old exists only if a run died between the two renames
    checkpoint_directory = output_directory + "/checkpoint";
    if (!std::filesystem::exists(checkpoint_directory + "/info") &&
        std::filesystem::exists(output_directory + "/checkpoint.old/info"))
      checkpoint_directory = output_directory + "/checkpoint.old";
    // each rank its own file; the first rank with a problem tells, but
    // another rank count comes first (rank 0's file says)
    auto [header, error, stored_ranks] =
      Checkpoint::read_rank_header(checkpoint_directory, mpi_communicator);
    if (stored_ranks != 0 && stored_ranks != ranks)
      error = "the checkpoint in '" + checkpoint_directory + "' was written by " +
              std::to_string(stored_ranks) + " MPI rank(s); resume it with as many (this run has " +
              std::to_string(ranks) + ")";
    if (!error.empty())
      error = "--resume: " + error + ".";
    if (error.find("no checkpoint file") != std::string::npos)
      error += " Output/Checkpoint interval, Checkpoint minutes or Stop after step write one "
               "in Problem/Output directory.";
    throw_first_error(error, mpi_communicator);

    // the parameters: the same on every rank, so every rank decides alike
    std::vector<Checkpoint::Change> allowed, refused;
    const std::set<std::string> &resumable = EntryFlags::entries(EntryFlag::resumable);
    Checkpoint::compare_parameters(
      header.parameters, parameter_record, allowed, refused, resumable);
    if (!refused.empty())
      {
        std::string message = "--resume: the checkpoint in '" + checkpoint_directory +
                              "' was written with other values of " +
                              std::to_string(refused.size()) + " entr" +
                              (refused.size() == 1 ? "y" : "ies") +
                              " that change the computed state (checkpoint -> this run):";
        for (const auto &c : refused)
          message += "\n" + c.entry + ": " + c.old_value + " -> " + c.new_value;
        message += "\nResume with the checkpoint's values, or start the run again. Only these "
                   "entries may change on resume:";
        for (const auto &entry : resumable)
          message += " " + entry + (entry == *resumable.rbegin() ? "." : ",");
        AssertThrow(false, ExcMessage(message));
      }

    // a resumed run must have steps left
    const unsigned long n_steps =
      static_cast<unsigned long>(std::ceil(parameters.solver.end_time / header.time_step - 1e-9));
    AssertThrow(n_steps > header.step,
                ExcMessage(
                  "--resume: Time integration/End time = " + fmt(parameters.solver.end_time) +
                  " s is reached at step " + std::to_string(n_steps) + ", and the checkpoint in '" +
                  checkpoint_directory + "' is at step " + std::to_string(header.step) +
                  " (t = " + fmt(header.time) + " s): nothing to resume. Set a later End time."));

    // listed once the state is read (read_checkpoint())
    resumed_changes = allowed;
  }



  void
  Simulator::read_checkpoint()
  {
    const unsigned int rank  = Utilities::MPI::this_mpi_process(mpi_communicator);
    const unsigned int ranks = Utilities::MPI::n_mpi_processes(mpi_communicator);
    // check_checkpoint() has verified the files and set the directory
    const std::string  name = Checkpoint::rank_file(checkpoint_directory, rank);
    std::ifstream      file(name, std::ios::binary);
    Checkpoint::Reader in(file, name);
    // every rank's file must fit before any rank reads its state (which
    // exchanges ghost values): the header, and the first record of the
    // state, the owned part of the displacement (ExplicitSolver::serialize()),
    // whose size a rank file of another rank shows unless the parts are
    // equal
    std::string error = error_message_of([&]() {
      AssertThrow(file.good(), ExcMessage("--resume: cannot open '" + name + "'."));
      const Checkpoint::Header header = Checkpoint::read_header(in, name);
      AssertThrow(header.ranks == ranks && header.cells == triangulation.n_global_active_cells() &&
                    header.dofs == solver->get_dof_handler().n_dofs(),
                  ExcMessage("The checkpoint in '" + checkpoint_directory +
                             "' was written by a run with " + std::to_string(header.ranks) +
                             " rank(s), " + std::to_string(header.cells) + " cells and " +
                             std::to_string(header.dofs) + " DoFs; this run has " +
                             std::to_string(ranks) + ", " +
                             std::to_string(triangulation.n_global_active_cells()) + " and " +
                             std::to_string(solver->get_dof_handler().n_dofs()) +
                             ": resume with the same parameters, rank count and executable."));
      const std::streampos start = file.tellg();
      std::uint64_t        owned = 0;
      in.pod(owned);
      file.seekg(start);
      const std::uint64_t mine = solver->partitioner()->locally_owned_size();
      AssertThrow(owned == mine,
                  ExcMessage("--resume: the checkpoint file '" + name + "' holds " +
                             std::to_string(owned) + " displacement entries, and rank " +
                             std::to_string(rank) + " owns " + std::to_string(mine) +
                             " in this run: the rank files were renamed or exchanged, or "
                             "come from another executable."));
    });
    throw_first_error(error, mpi_communicator);
    error = error_message_of([&]() {
      serialize(in);
      std::uint64_t magic = 0;
      in.pod(magic);
      AssertThrow(magic == Checkpoint::magic,
                  ExcMessage("The checkpoint '" + name + "' is corrupt."));
    });
    throw_first_error(error, mpi_communicator);
    pcout << "Resumed from " << checkpoint_directory << " at step " << solver->step_number()
          << ", t = " << fmt(solver->time() * 1e3) << " ms" << std::endl;
    if (!resumed_changes.empty())
      {
        pcout << "Resumed with changed entries:" << std::endl;
        for (const auto &c : resumed_changes)
          pcout << "  " << c.entry << ": " << c.old_value << " -> " << c.new_value << std::endl;
      }
  }
} // namespace WheelRail
