#include <wheelrail/base/stop_signal.h>

#include <csignal>

namespace WheelRail
{
  namespace StopSignal
  {
    namespace
    {
      volatile std::sig_atomic_t signal_received = 0;

      extern "C" void
      record(const int signal)
      {
        signal_received = signal;
      }
    } // namespace



    void
    install()
    {
      struct sigaction action = {};
      action.sa_handler       = record;
      sigemptyset(&action.sa_mask);
      // SA_RESTART: a read or write in progress goes on instead of failing
      // with EINTR; SA_RESETHAND: the next signal has its default action
      action.sa_flags = SA_RESTART | SA_RESETHAND;
      for (const int signal : {SIGTERM, SIGINT})
        {
          // a signal ignored on entry stays ignored (a background job of a
          // script ignores SIGINT meant for the job in the foreground)
          struct sigaction before = {};
          if (sigaction(signal, nullptr, &before) == 0 && before.sa_handler == SIG_IGN)
            continue;
          sigaction(signal, &action, nullptr);
        }
    }



    int
    received()
    {
      return signal_received;
    }



    int
    agreed(MPI_Comm comm)
    {
      int ranks = 1;
      MPI_Comm_size(comm, &ranks);
      int signal = signal_received;
      if (ranks > 1)
        MPI_Allreduce(MPI_IN_PLACE, &signal, 1, MPI_INT, MPI_MAX, comm);
      return signal;
    }



    std::string
    name(const int signal)
    {
      return signal == SIGTERM ? "SIGTERM" :
             signal == SIGINT  ? "SIGINT" :
                                 "signal " + std::to_string(signal);
    }



    void
    stop_if_received(MPI_Comm comm, const std::string &when, const std::string &what)
    {
      if (const int signal = agreed(comm))
        throw Stopped(signal, "stopped by " + name(signal) + " " + when + ": " + what + ".");
    }
  } // namespace StopSignal
} // namespace WheelRail
