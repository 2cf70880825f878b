#ifndef rupture_time_integration_energy_budget_h
#define rupture_time_integration_energy_budget_h

#include <rupture/base/binary_io.h>

#include <deal.II/lac/trilinos_vector.h>

namespace rupture
{
  namespace TimeIntegration
  {
    /**
     * The energy budget of a run (J): the energies of the body at the
     * current time and the work and dissipation accumulated since its
     * start, with the forces at the end of the last step that the
     * trapezoidal rule of the next step needs. It closes when
     * balance_error() vanishes: kinetic + strain + dissipated + fault work
     * - external work - initial energy = 0 (to round-off for the implicit
     * and quasi-static schemes, to O(dt^2) for central differences).
     */
    struct EnergyBudget
    {
      using VectorType = dealii::TrilinosWrappers::MPI::Vector;

      /// Kinetic plus strain energy of the initial state.
      double initial = 0;
      double kinetic = 0;
      double strain  = 0;
      /// Work of the loads and of the reactions on kinematic boundaries.
      double external_work = 0;
      /// Energy dissipated by damping (Rayleigh, the fault zone's, the
      /// absorbing boundaries').
      double damping_dissipation = 0;
      /// The part of damping_dissipation that left through the absorbing
      /// boundaries.
      double absorbed = 0;
      /// Work done on the fault: penalty spring energy plus friction.
      double fault_work = 0;
      /// Kinetic plus strain energy that the changes of the mesh added (the
      /// interpolation of the fields to the new mesh; negative if it took
      /// energy away).
      double remeshing = 0;

      /// Total force applied to the body at the current time (loads plus
      /// reactions on kinematic boundaries).
      VectorType applied_force;
      /// Damping force at the current velocity.
      VectorType damping_force;
      /// Contact forces of the fault at the current state.
      VectorType contact_force;
      /// The force of the absorbing boundaries at the end of the last step.
      VectorType absorbing_force;

      /// The energies as named checkpoint records (the forces are fields).
      void
      save(BinaryIO::Records &records) const
      {
        records["energy/initial"]             = initial;
        records["energy/kinetic"]             = kinetic;
        records["energy/strain"]              = strain;
        records["energy/external work"]       = external_work;
        records["energy/damping dissipation"] = damping_dissipation;
        records["energy/absorbed"]            = absorbed;
        records["energy/fault work"]          = fault_work;
        records["energy/remeshing"]           = remeshing;
      }
      void
      load(const BinaryIO::Records &records)
      {
        using BinaryIO::record;
        initial             = record(records, "energy/initial");
        kinetic             = record(records, "energy/kinetic");
        strain              = record(records, "energy/strain");
        external_work       = record(records, "energy/external work");
        damping_dissipation = record(records, "energy/damping dissipation");
        absorbed            = record(records, "energy/absorbed");
        fault_work          = record(records, "energy/fault work");
        // (Checkpoints of runs on one mesh before this record had none.)
        const auto r = records.find("energy/remeshing");
        remeshing    = (r != records.end()) ? r->second : 0.;
      }

      /// What the budget misses: zero when energy is conserved.
      double
      balance_error() const
      {
        return kinetic + strain + damping_dissipation + fault_work -
               external_work - initial - remeshing;
      }
    };
  } // namespace TimeIntegration
} // namespace rupture

#endif
