#include <deal.II/base/exceptions.h>
#include <deal.II/base/utilities.h>

#include <wheelrail/postprocess/output_files.h>

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <functional>
#include <sstream>
#include <vector>

namespace WheelRail
{
  using namespace dealii;

  std::string
  DirectoryLock::file_name(const std::string &directory)
  {
    return directory + "/.wheelrail.lock";
  }



  DirectoryLock::DirectoryLock(const std::string &directory, const std::string &entry)
  {
    const std::string name = file_name(directory);
    fd                     = ::open(name.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
    AssertThrow(fd >= 0,
                ExcMessage("Cannot create the lock file '" + name + "' in " + entry + " '" +
                           directory + "': " + std::strerror(errno)));
    if (::flock(fd, LOCK_EX | LOCK_NB) != 0)
      {
        const int error = errno;
        if (error != EWOULDBLOCK)
          {
            why_unlocked = "cannot lock '" + name + "' (" + std::strerror(error) +
                           "): nothing keeps a second run out of " + entry + " '" + directory + "'";
            return;
          }
        // the holder wrote who it is; read it without changing the file
        char          text[256] = {};
        const ssize_t n         = ::pread(fd, text, sizeof(text) - 1, 0);
        ::close(fd);
        fd                 = -1;
        std::string holder = n > 0 ? std::string(text, n) : std::string();
        while (!holder.empty() && (holder.back() == '\n' || holder.back() == ' '))
          holder.pop_back();
        AssertThrow(false,
                    ExcMessage(entry + " '" + directory + "' is in use by another wheelrail run" +
                               (holder.empty() ? std::string() : " (" + holder + ")") +
                               ": wait until it ends, or choose another directory. Nothing "
                               "was written there."));
      }
    char host[256] = {};
    ::gethostname(host, sizeof(host) - 1);
    const std::time_t now = std::time(nullptr);
    char              when[64];
    std::strftime(when, sizeof(when), "%Y-%m-%d %H:%M:%S UTC", std::gmtime(&now));
    const std::string text =
      "pid " + std::to_string(::getpid()) + " on host " + host + ", started " + when + "\n";
    if (::ftruncate(fd, 0) != 0 ||
        ::pwrite(fd, text.data(), text.size(), 0) != static_cast<ssize_t>(text.size()))
      {
        // the lock is held; only the note on the holder is missing
      }
  }



  DirectoryLock::~DirectoryLock()
  {
    if (fd >= 0)
      ::close(fd);
  }



  std::string
  error_message_of(const std::function<void()> &action)
  {
    try
      {
        action();
      }
    catch (const ExceptionBase &e)
      {
        std::ostringstream info;
        e.print_info(info);
        return info.str();
      }
    catch (const std::exception &e)
      {
        return e.what();
      }
    return "";
  }



  void
  throw_first_error(const std::string &error, const MPI_Comm comm)
  {
    const int any = Utilities::MPI::max(error.empty() ? 0 : 1, comm);
    if (any == 0)
      return;
    const unsigned int rank = Utilities::MPI::this_mpi_process(comm);
    const unsigned int first =
      Utilities::MPI::min(error.empty() ? Utilities::MPI::n_mpi_processes(comm) : rank, comm);
    const std::string message = Utilities::MPI::broadcast(comm, error, first);
    AssertThrow(false, ExcMessage(message));
  }



  TemporaryPath::~TemporaryPath()
  {
    if (!committed)
      {
        std::error_code ec;
        std::filesystem::remove_all(path, ec);
      }
  }



  void
  write_file_atomically(const std::string &path, const std::string &content)
  {
    TemporaryPath     guard(path + ".tmp");
    const std::string tmp = guard.name();
    {
      std::ofstream out(tmp);
      out << content;
      out.flush();
      AssertThrow(out.good(),
                  ExcMessage("Cannot write '" + tmp + "' (disk full or no permission)."));
    }
    std::error_code ec;
    std::filesystem::rename(tmp, path, ec);
    AssertThrow(!ec, ExcMessage("Cannot rename '" + tmp + "' to '" + path + "': " + ec.message()));
    guard.commit();
  }



  std::string
  write_vtu_with_pvtu_record(const DataOutInterface<3, 3> &data_out,
                             const std::string            &directory,
                             const std::string            &base,
                             const unsigned int            counter,
                             const unsigned int            n_digits,
                             const MPI_Comm                comm)
  {
    const unsigned int rank    = Utilities::MPI::this_mpi_process(comm);
    const unsigned int n_ranks = Utilities::MPI::n_mpi_processes(comm);
    // the names of DataOutInterface::write_vtu_with_pvtu_record()
    const unsigned int rank_digits = Utilities::needed_digits(std::max(0, int(n_ranks) - 1));
    const std::string  stem        = base + "_" + Utilities::int_to_string(counter, n_digits);
    const auto         piece       = [&](const unsigned int r) {
      return stem + "." + Utilities::int_to_string(r, rank_digits) + ".vtu";
    };


    throw_first_error(
      error_message_of([&]() {
        // straight into the file: a piece can be large
        const std::string path = directory + piece(rank);
        TemporaryPath     guard(path + ".tmp");
        const std::string tmp = guard.name();
        {
          std::ofstream out(tmp, std::ios::binary);
          AssertThrow(out.good(), ExcMessage("Cannot write '" + tmp + "' (no permission?)."));
          data_out.write_vtu(out);
          out.flush();
          AssertThrow(out.good(),
                      ExcMessage("Cannot write '" + tmp + "' (disk full or no permission)."));
        }
        std::error_code ec;
        std::filesystem::rename(tmp, path, ec);
        AssertThrow(!ec,
                    ExcMessage("Cannot rename '" + tmp + "' to '" + path + "': " + ec.message()));
        guard.commit();
      }),
      comm);

    // every piece is in place: the record that lists them
    throw_first_error(error_message_of([&]() {
                        if (rank != 0)
                          return;
                        std::vector<std::string> pieces;
                        for (unsigned int r = 0; r < n_ranks; ++r)
                          pieces.push_back(piece(r));
                        std::ostringstream pvtu;
                        data_out.write_pvtu_record(pvtu, pieces);
                        write_file_atomically(directory + stem + ".pvtu", pvtu.str());
                      }),
                      comm);
    return stem + ".pvtu";
  }
} // namespace WheelRail
