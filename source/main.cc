/**
 * wheelrail: transient 3D frictional rolling contact of a wheel on a rail by
 * the explicit finite element method. Usage: see print_usage() or README.md.
 */
#include <deal.II/base/exceptions.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>

#include <wheelrail/base/stop_signal.h>
#include <wheelrail/parameters/parameter_file.h>
#include <wheelrail/parameters/parameters.h>
#include <wheelrail/simulator/simulator.h>
#include <wheelrail/verification/verdict.h>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <iostream>
#include <memory>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

namespace
{
  void
  print_usage(std::ostream &out)
  {
    out << "Usage: wheelrail CASE.prm          run the case\n"
           "       wheelrail CASE.prm --resume continue from the case's last checkpoint\n"
           "       mpirun -np N wheelrail CASE.prm\n"
           "       wheelrail --help             this text and every parameter with its\n"
           "                                    unit, default and allowed range\n";
  }

  /** What the command line asks for. */
  struct CommandLine
  {
    std::string input;          ///< the case file
    bool        resume = false; ///< --resume after it
    bool        help   = false; ///< --help or -h anywhere
    std::string error;          ///< what is wrong with it, naming the argument; "" if nothing
  };

  /**
   * The command line: a case file, then optionally --resume; --help or -h
   * anywhere asks for the help text. The first thing wrong is named in the
   * result's error.
   */
  CommandLine
  read_command_line(const int argc, char **argv)
  {
    CommandLine line;
    for (int i = 1; i < argc; ++i)
      line.help = line.help || std::string(argv[i]) == "--help" || std::string(argv[i]) == "-h";
    for (int i = 1; i < argc && line.error.empty() && !line.help; ++i)
      {
        const std::string arg = argv[i];
        if (arg == "--resume")
          {
            if (line.input.empty())
              line.error = "'--resume' without a case file before it: "
                           "wheelrail CASE.prm --resume";
            else if (line.resume)
              line.error = "'--resume' is given twice";
            line.resume = true;
          }
        else if (arg.size() > 1 && arg[0] == '-')
          line.error = "unknown option '" + arg + "'" +
                       (arg.size() > 4 && arg.compare(arg.size() - 4, 4, ".prm") == 0 ?
                          " (a case file whose name begins with '-' is given as ./" + arg + ")" :
                          std::string());
        else if (arg.empty())
          line.error = "argument " + std::to_string(i) + " is empty, not a case file";
        else if (!line.input.empty())
          line.error = "two case files, '" + line.input + "' and '" + arg + "': give one";
        else
          line.input = arg;
      }
    if (line.error.empty() && !line.help && line.input.empty())
      line.error = "no case file given";
    return line;
  }
  /**
   * Print the error @p message and return the exit status 1. The input
   * file @p input is named without its directory, control characters are
   * escaped. On several ranks: a check that every rank makes (the
   * parameters, the setup, a divergence) fails on all ranks at once, and
   * rank 0 prints each distinct message once; a rank that fails alone
   * while the others go on would leave them waiting in a collective, so it
   * prints its message and aborts the job. The ranks meet on @p error_comm,
   * a communicator of their own, so that a rank that failed alone cannot be
   * matched with a collective the others are waiting in.
   */
  int
  report_failure(std::string        message,
                 const std::string &input,
                 const MPI_Comm     comm,
                 const MPI_Comm     error_comm)
  {
    using namespace dealii;
    const unsigned int rank  = Utilities::MPI::this_mpi_process(comm);
    const unsigned int ranks = Utilities::MPI::n_mpi_processes(comm);
    // name the input file as the user knows it, without its directory
    // (searched from behind each replacement: a bare name in the working
    // directory is its own replacement and would be found again forever)
    const std::string name = std::filesystem::path(input).filename().string();
    if (!input.empty() && name != input)
      for (std::size_t pos = 0; (pos = message.find(input, pos)) != std::string::npos;
           pos += name.size())
        message.replace(pos, input.size(), name);
    // what the user wrote is echoed without terminal control characters
    message = WheelRail::ParameterFile::printable(message);
    if (ranks == 1)
      {
        std::cerr << "Error: " << message << std::endl;
        return 1;
      }
    MPI_Request request;
    MPI_Ibarrier(error_comm, &request);
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(5);
    int        all      = 0;
    while (!all && std::chrono::steady_clock::now() < deadline)
      {
        MPI_Test(&request, &all, MPI_STATUS_IGNORE);
        if (!all)
          std::this_thread::sleep_for(std::chrono::milliseconds(1));
      }
    if (!all)
      {
        std::cerr << "[rank " << rank << "] Error: " << message << std::endl;
        MPI_Abort(comm, 1);
      }
    const std::vector<std::string> messages = Utilities::MPI::gather(error_comm, message, 0);
    if (rank == 0)
      for (unsigned int r = 0; r < messages.size(); ++r)
        if (std::find(messages.begin(), messages.begin() + r, messages[r]) == messages.begin() + r)
          std::cerr << (r > 0 ? "[rank " + std::to_string(r) + "] " : std::string())
                    << "Error: " << messages[r] << std::endl;
    return 1;
  }



  /** A deal.II exception's message without print_info()'s indentation and
   *  blank lines. */
  std::string
  compact_message(const dealii::ExceptionBase &e)
  {
    std::ostringstream info;
    e.print_info(info);
    std::string        compact;
    std::istringstream lines(info.str());
    for (std::string line; std::getline(lines, line);)
      {
        const auto first = line.find_first_not_of(" \t");
        if (first == std::string::npos)
          continue;
        compact += (compact.empty() ? "" : "\n  ") + line.substr(first);
      }
    return compact.empty() ? std::string(e.get_exc_name()) : compact;
  }



  /** What the command line asks for: the help text, the usage after an
   *  error in it, or the case. Returns the exit status. */
  int
  run_command_line(const CommandLine &command_line, const MPI_Comm comm)
  {
    using namespace dealii;
    const unsigned int    rank = Utilities::MPI::this_mpi_process(comm);
    ParameterHandler      prm;
    WheelRail::Parameters parameters;
    WheelRail::Parameters::declare_parameters(prm);
    if (command_line.help)
      {
        if (rank == 0)
          {
            print_usage(std::cout);
            std::cout << "\nParameters (defaults shown):\n\n";
            prm.print_parameters(std::cout, ParameterHandler::Text);
          }
        return 0;
      }
    if (!command_line.error.empty())
      {
        if (rank == 0)
          {
            std::cerr << "Error: " << WheelRail::ParameterFile::printable(command_line.error)
                      << "\n\n";
            print_usage(std::cerr);
          }
        return 1;
      }
    parameters.parse(prm, command_line.input);
    if (command_line.resume)
      parameters.output.resume = true;
    WheelRail::Simulator simulator(parameters, prm, comm);
    simulator.run();
    // in test mode a check that said "no" fails the run
    WheelRail::Verification::check_verdicts(parameters, comm);
    return 0;
  }
} // namespace



int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const MPI_Comm                           comm = MPI_COMM_WORLD;

  // SIGTERM and SIGINT from here on stop the run cleanly (stop_signal.h)
  WheelRail::StopSignal::install();

  const CommandLine command_line = read_command_line(argc, argv);
  MPI_Comm          error_comm;
  MPI_Comm_dup(comm, &error_comm);
  const std::unique_ptr<MPI_Comm, void (*)(MPI_Comm *)> free_error_comm(&error_comm,
                                                                        [](MPI_Comm *c) {
                                                                          MPI_Comm_free(c);
                                                                        });
  const auto fail = [&](const std::string &message) {
    return report_failure(message, command_line.input, comm, error_comm);
  };
  try
    {
      return run_command_line(command_line, comm);
    }
  catch (const WheelRail::StopSignal::Stopped &e)
    {
      // every rank stops alike; the status a shell gives a process ended by
      // the signal
      fail(e.what());
      return 128 + e.signal();
    }
  catch (const dealii::ExceptionBase &e)
    {
      return fail(compact_message(e));
    }
  catch (const std::exception &e)
    {
      return fail(e.what());
    }
  catch (...)
    {
      return fail("unknown exception");
    }
}
