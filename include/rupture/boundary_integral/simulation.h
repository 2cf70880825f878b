#ifndef rupture_boundary_integral_simulation_h
#define rupture_boundary_integral_simulation_h

#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>

namespace rupture
{
  namespace BoundaryIntegral
  {
    using namespace dealii;

    /**
     * Declare <Method> (finite elements or the boundary-integral method)
     * and the subsection <Boundary integral>.
     */
    void
    declare_parameters(ParameterHandler &prm);

    /**
     * Whether <Method> chooses the boundary-integral method.
     */
    bool
    chosen(ParameterHandler &prm);

    /**
     * Run the quasi-dynamic earthquake-cycle problem of <Boundary
     * integral> (the review paper's dual method on the antiplane
     * half-space, SEAS BP1): read the parameters (the friction law of
     * <Fault>, the radiation damping, the stations and the event catalogue
     * of <Fault/Output>, the medium of <Material>, the end time and the
     * step bounds of <Time integration>), integrate the fault's slip and
     * state with the Dormand-Prince pair to the end time (or the given
     * number of events), and write the stations, the slip profiles, the
     * statistics and events.csv as they grow. With checkpoints
     * (<Checkpoint/Interval> or <Wall-clock interval>) it writes
     * <output>/checkpoint/boundary_integral.bin, from which @p resume
     * continues the run to the last digit. Collective.
     */
    void
    run(ParameterHandler &prm, const MPI_Comm communicator, const bool resume);
  } // namespace BoundaryIntegral
} // namespace rupture

#endif
