#ifndef rupture_simulator_checkpoint_control_h
#define rupture_simulator_checkpoint_control_h

#include <rupture/base/binary_io.h>

#include <string>

namespace rupture
{
  /**
   * When a run writes checkpoints (the Checkpoint subsection) and what a
   * resumed run continues from (doc/manual.md, "Checkpoints and
   * restart").
   */
  struct CheckpointControl
  {
    /// <Checkpoint/Interval> (steps) and <Wall-clock interval> (minutes);
    /// both 0: no checkpoints.
    unsigned int interval = 0;
    double       minutes  = 0;
    /// Wall time (MPI_Wtime) of the last checkpoint.
    double last_write = 0;
    /// Set by the step's output: a checkpoint is due after this step.
    bool requested = false;
    /// Whether this run continues from a checkpoint, and which (a
    /// directory).
    bool        resume = false;
    std::string resume_from;
    /// The checkpoint's mesh is refined this many more times everywhere
    /// before the run continues (--refine).
    unsigned int refinements = 0;
    /// The run's parameters as written to parameters.prm (ShortPRM), which
    /// a checkpoint keeps for the compatibility check.
    std::string parameters_text;
    /// The named records read from a checkpoint; the time integrator's are
    /// restored once the phase's integrator is prepared.
    BinaryIO::Records records;
  };
} // namespace rupture

#endif
