#include <rupture/base/interruption.h>

#include <csignal>

namespace rupture
{
  namespace Interruption
  {
    namespace
    {
      volatile std::sig_atomic_t signal_received     = 0;
      volatile std::sig_atomic_t checkpoint_received = 0;

      struct sigaction old_term, old_int, old_usr1;

      extern "C" void
      request_checkpoint(const int)
      {
        checkpoint_received = 1;
      }

      extern "C" void
      request_stop(const int signal)
      {
        // Only async-signal-safe work here: a flag, or the default action
        // for a second Ctrl-C.
        if (signal_received != 0 && signal == SIGINT)
          {
            std::signal(signal, SIG_DFL);
            std::raise(signal);
            return;
          }
        signal_received = signal;
      }
    } // namespace



    Handlers::Handlers()
    {
      signal_received         = 0;
      struct sigaction action = {};
      action.sa_handler       = request_stop;
      sigemptyset(&action.sa_mask);
      action.sa_flags = SA_RESTART;
      sigaction(SIGTERM, &action, &old_term);
      sigaction(SIGINT, &action, &old_int);
      checkpoint_received         = 0;
      struct sigaction checkpoint = {};
      checkpoint.sa_handler       = request_checkpoint;
      sigemptyset(&checkpoint.sa_mask);
      checkpoint.sa_flags = SA_RESTART;
      sigaction(SIGUSR1, &checkpoint, &old_usr1);
    }



    Handlers::~Handlers()
    {
      sigaction(SIGTERM, &old_term, nullptr);
      sigaction(SIGINT, &old_int, nullptr);
      sigaction(SIGUSR1, &old_usr1, nullptr);
    }



    bool
    take_checkpoint_request()
    {
      const bool requested = checkpoint_received != 0;
      checkpoint_received  = 0;
      return requested;
    }



    int
    requested()
    {
      return signal_received;
    }



    std::string
    signal_name(const int signal)
    {
      switch (signal)
        {
          case SIGTERM:
            return "SIGTERM";
          case SIGINT:
            return "SIGINT";
          default:
            return "signal " + std::to_string(signal);
        }
    }
  } // namespace Interruption
} // namespace rupture
