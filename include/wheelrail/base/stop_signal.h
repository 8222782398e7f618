/**
 * @file stop_signal.h
 * SIGTERM and SIGINT (what a batch scheduler sends before it kills a job,
 * and Ctrl-C) stop a run cleanly: the handler only records the signal in a
 * `volatile std::sig_atomic_t`; the time loop combines the ranks' records
 * in one collective every check_interval steps, so that all ranks stop
 * after the same step, writes a checkpoint there and throws Stopped. Before
 * the time loop the run asks agreed() at fixed points and stops without a
 * checkpoint. The handlers reset themselves (SA_RESETHAND): a second
 * signal, e.g. while the checkpoint is written, ends the process at once,
 * as if no handler were installed.
 */
#ifndef wheelrail_stop_signal_h
#define wheelrail_stop_signal_h

#include <mpi.h>

#include <stdexcept>
#include <string>

namespace WheelRail
{
  namespace StopSignal
  {
    /** The time loop combines the ranks' signals after every step whose
     *  number is a multiple of this (after every step with Output/Checkpoint
     *  minutes, whose collective it shares): one collective per 50 steps
     *  costs nothing measurable even with steps of a few microseconds,
     *  and delays the stop by at most 49 steps. */
    constexpr unsigned long check_interval = 50;

    /** Install the handlers of SIGTERM and SIGINT (once, in main()); a
     *  signal that the process was started ignoring stays ignored. */
    void
    install();

    /** The signal this rank has received, 0 if none. */
    int
    received();

    /** Collective on @p comm: the signal some rank has received (the
     *  largest number if they differ), 0 if none; on one rank no MPI call. */
    int
    agreed(MPI_Comm comm);

    /** "SIGTERM", "SIGINT" or "signal N". */
    std::string
    name(const int signal);

    /** A run stopped by @p signal; main() prints what() and exits with
     *  128 + signal, as a shell reports a process ended by it. */
    class Stopped : public std::runtime_error
    {
    public:
      Stopped(const int signal, const std::string &message)
        : std::runtime_error(message)
        , number(signal)
      {}

      int
      signal() const
      {
        return number;
      }

    private:
      int number;
    };

    /** Collective: if agreed() is non-zero, throw Stopped saying that the
     *  run stopped @p when (e.g. "during the setup") and that @p what. */
    void
    stop_if_received(MPI_Comm comm, const std::string &when, const std::string &what);
  } // namespace StopSignal
} // namespace WheelRail

#endif
