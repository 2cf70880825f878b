#ifndef rupture_base_interruption_h
#define rupture_base_interruption_h

#include <stdexcept>
#include <string>

namespace rupture
{
  /**
   * A clean stop on SIGTERM and SIGINT, and a checkpoint on SIGUSR1: the
   * signal only sets a flag; the
   * time loop looks at it after every step (together on all ranks), writes
   * everything that is pending and throws Interruption::Stopped, and the
   * program exits with the conventional code 128 + signal. A second SIGINT
   * (Ctrl-C twice) ends the program at once.
   */
  namespace Interruption
  {
    /**
     * While an object of this class lives, SIGTERM and SIGINT request a
     * stop instead of ending the program; the earlier handlers come back
     * with its destruction.
     */
    class Handlers
    {
    public:
      Handlers();
      ~Handlers();
      Handlers(const Handlers &) = delete;
      Handlers &
      operator=(const Handlers &) = delete;
    };

    /**
     * The signal that requested a stop, or 0.
     */
    int
    requested();

    /**
     * Whether SIGUSR1 arrived since the last call (and forget it): a
     * request for a checkpoint now, after which the run goes on.
     */
    bool
    take_checkpoint_request();

    /**
     * The name of a signal ("SIGTERM").
     */
    std::string
    signal_name(const int signal);

    /**
     * What the time loop throws once it stopped cleanly after @p signal.
     */
    class Stopped : public std::runtime_error
    {
    public:
      Stopped(const int signal, const std::string &what)
        : std::runtime_error(what)
        , signal(signal)
      {}

      const int signal;
    };
  } // namespace Interruption
} // namespace rupture

#endif
