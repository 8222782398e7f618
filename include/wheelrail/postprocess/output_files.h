/**
 * @file postprocess/output_files.h
 * How the run's files reach the output directory: a lock that keeps a
 * second run out of a directory in use, and writers that put each file in
 * place complete or not at all (a temporary name, then a rename), so that a
 * run killed while writing leaves the previous version of every file.
 */
#ifndef wheelrail_postprocess_output_files_h
#define wheelrail_postprocess_output_files_h

#include <deal.II/base/data_out_base.h>
#include <deal.II/base/mpi.h>

#include <functional>
#include <string>
#include <utility>

namespace WheelRail
{
  /**
   * An exclusive flock() on DIRECTORY/.wheelrail.lock, held while the object
   * lives. The kernel drops it when the process ends in any way, so a
   * killed run leaves no stale lock. The file is left in place (removing
   * it would let two runs lock two different files of the same name); it
   * names the holder: pid, host and start time.
   */
  class DirectoryLock
  {
  public:
    /** Take the lock, or throw an exception naming @p directory and the
     *  holder, without changing anything in the directory. @p entry is the
     *  parameter that chose the directory, for the message. */
    DirectoryLock(const std::string &directory, const std::string &entry);
    ~DirectoryLock();

    DirectoryLock(const DirectoryLock &) = delete;
    DirectoryLock &
    operator=(const DirectoryLock &) = delete;

    /** Name of the lock file in a directory. */
    static std::string
    file_name(const std::string &directory);

    /** Empty, or why the directory could not be locked although nobody
     *  holds it (a file system without flock()): the run goes on unlocked. */
    const std::string &
    warning() const
    {
      return why_unlocked;
    }

  private:
    int         fd = -1;
    std::string why_unlocked;
  };

  /** What @p action threw (the message of a deal.II exception or a
   *  std::exception), or "" if it returned: an error on one rank as text
   *  that throw_first_error() hands to every rank. */
  std::string
  error_message_of(const std::function<void()> &action);

  /** Collective: if @p error is non-empty on any rank, throw on every rank
   *  the message of the lowest such rank (one message, all ranks stop). */
  void
  throw_first_error(const std::string &error, const MPI_Comm comm);

  /**
   * A file or directory written under a temporary name (FILE.tmp,
   * checkpoint.new): removed when the guard goes out of scope, unless
   * commit() said that it has been renamed into place. A failure that
   * throws on the way therefore leaves no temporary behind.
   */
  class TemporaryPath
  {
  public:
    explicit TemporaryPath(std::string path)
      : path(std::move(path))
    {}
    ~TemporaryPath();

    TemporaryPath(const TemporaryPath &) = delete;
    TemporaryPath &
    operator=(const TemporaryPath &) = delete;

    const std::string &
    name() const
    {
      return path;
    }

    /** The temporary has been renamed (or is no longer ours to remove). */
    void
    commit()
    {
      committed = true;
    }

  private:
    std::string path;
    bool        committed = false;
  };

  /** Write @p content to @p path through @p path.tmp and a rename. */
  void
  write_file_atomically(const std::string &path, const std::string &content);

  /**
   * DataOutInterface::write_vtu_with_pvtu_record() (one file per rank, the
   * same names: BASE_CCCCC.R.vtu and BASE_CCCCC.pvtu, C the @p counter in
   * @p n_digits digits), each file written to a temporary name and renamed;
   * the .pvtu record only once every rank's .vtu is in place. Collective;
   * returns the name of the .pvtu file without the directory.
   */
  std::string
  write_vtu_with_pvtu_record(const dealii::DataOutInterface<3, 3> &data_out,
                             const std::string                    &directory,
                             const std::string                    &base,
                             const unsigned int                    counter,
                             const unsigned int                    n_digits,
                             const MPI_Comm                        comm);
} // namespace WheelRail

#endif
