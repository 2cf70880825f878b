#ifndef rupture_fault_event_source_h
#define rupture_fault_event_source_h

#include <deal.II/base/mpi.h>
#include <deal.II/base/point.h>

#include <utility>

namespace rupture
{
  namespace Fault
  {
    using namespace dealii;

    /**
     * An earthquake's sums over the fault since EventSource::start_event(),
     * over all ranks (EventCatalogue).
     */
    template <int dim>
    struct EventSummary
    {
      /// The largest frictional slip rate any pair reached (m/s).
      double peak_rate = 0;
      /// Sum of mu A |slip - slip at the event's start| (N m; N/m in 2-D).
      double moment = 0;
      /// The area (m^2; m in 2-D) of the pairs whose slip rate reached the
      /// threshold, and the sum of area x slip over them.
      double area      = 0;
      double slip_area = 0;
      /// The largest slip of a pair in the event (m).
      double largest_slip = 0;
    };

    /**
     * What the event catalogue asks of a fault: the finite-element fault
     * (Fault::Fault) and the boundary-integral one
     * (BoundaryIntegral::QuasiDynamicFault) both answer it, so that one
     * catalogue serves both methods.
     */
    template <int dim>
    class EventSource
    {
    public:
      virtual ~EventSource() = default;

      /// The largest frictional slip rate over the fault and the location
      /// of a point that has it. Collective.
      virtual std::pair<double, Point<dim>>
      fastest_pair() const = 0;

      /// An earthquake starts: each point keeps its slip as the event's
      /// start.
      virtual void
      start_event() = 0;

      /// After each step of an event: each point's peak slip rate.
      virtual void
      track_event() = 0;

      /// The event's sums since start_event(), points counted as ruptured
      /// where their peak slip rate reached @p threshold. Collective.
      virtual EventSummary<dim>
      event_summary(const double threshold) const = 0;

      /// The communicator of the collective calls.
      virtual MPI_Comm
      mpi_communicator() const = 0;
    };
  } // namespace Fault
} // namespace rupture

#endif
