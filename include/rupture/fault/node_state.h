#ifndef rupture_fault_node_state_h
#define rupture_fault_node_state_h

#include <rupture/friction/interface.h>

#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>
#include <deal.II/base/types.h>

#include <array>
#include <vector>

namespace rupture
{
  namespace Fault
  {
    /**
     * Where a node pair of the fault is and what it connects: found from
     * the mesh at every set-up (Fault::setup()).
     */
    template <int dim>
    struct PairTopology
    {
      std::array<types::global_dof_index, dim> minus;
      std::array<types::global_dof_index, dim> plus;
      Point<dim>                               location;
      /// The material of the cell the pair was found from (its shear
      /// stiffness across the fault: PairData::shear_modulus).
      types::material_id material = 0;
      /// Tributary area (m^2; m in 2-D) and unit normal (minus to plus).
      double         area = 0;
      Tensor<1, dim> normal;
      /// On hanging nodes (a fault refined more on one part than on the
      /// next): the pair's displacements follow other pairs' (constrained
      /// pairs, see Fault::setup()).
      bool hanging = false;
    };



    /**
     * What the parameters say at a pair's location: evaluated at set-up
     * from the functions of position of the "Fault" section.
     */
    template <int dim>
    struct PairData
    {
      /// The traction the displacement does not carry: the initial
      /// traction plus the perturbation at the current time.
      Tensor<1, dim> initial_traction;
      /// <Fault/Initial traction> here, and <Fault/Traction
      /// perturbation/Traction>.
      Tensor<1, dim> background_traction;
      Tensor<1, dim> perturbation;
      double         normal_penalty     = 0;
      double         tangential_penalty = 0;
      double         shear_modulus      = 0;
      /// Radiation damping eta here (Pa s/m): <Fault/Radiation damping>,
      /// or with 'auto' half the shear impedance across the fault,
      /// sqrt(rho shear_modulus) / 2.
      double radiation_damping = 0;
      /// Slip imposed (Fault/Forced slip) instead of friction.
      bool           forced = false;
      Tensor<1, dim> forced_direction;
    };



    /**
     * The committed state of a node pair: what an accepted step leaves
     * behind and the next step starts from. It belongs to the point of the
     * fault, not to the mesh: a new set-up keeps it where a pair's
     * location is unchanged, and a checkpoint stores it.
     */
    template <int dim>
    struct NodeState
    {
      /// The friction law's state (slip path, slip rate, state variables
      /// and the law's constants at this point).
      Friction::State state;
      Tensor<1, dim>  plastic_slip;
      Tensor<1, dim>  slip;
      Tensor<1, dim>  slip_velocity;
      /// rupture_time before the pair ruptures.
      static constexpr double not_ruptured = -1;
      /// rupture_time of a pair that a changed mesh added where the rupture
      /// had passed its neighbours: its own rupture time is unknown (the
      /// statistics count it as ruptured, outputs as not ruptured).
      static constexpr double unknown_time = -2;

      /// The first time (since the start of the dynamic phase) the slip
      /// rate exceeded 1 mm/s, not_ruptured before, or unknown_time.
      double rupture_time = not_ruptured;
      /// The slip rate that the rupture time is measured on, at the end of
      /// the last step (see Fault::commit()).
      double rupture_rate = 0;
      /// Slip at the start of the dynamic phase: output and statistics
      /// count the slip from there (coseismic slip).
      Tensor<1, dim> slip_at_start;
      /// Slip at the start of the current earthquake and the peak
      /// frictional slip rate since (the event catalogue's; not carried to
      /// a new mesh).
      Tensor<1, dim> event_slip;
      double         event_peak_rate = 0;

      /**
       * Append the state to @p v in the order of the checkpoint (the law's
       * constants are not written: set-up evaluates them again).
       */
      void
      append_to(std::vector<double> &v) const
      {
        v.push_back(state.slip_path);
        v.push_back(state.slip_rate);
        v.push_back(state.variables.size());
        v.insert(v.end(), state.variables.begin(), state.variables.end());
        append(v, plastic_slip);
        append(v, slip);
        append(v, slip_velocity);
        v.push_back(rupture_time);
        v.push_back(rupture_rate);
        append(v, slip_at_start);
      }

      /**
       * Read what append_to() wrote, from @p v at position @p i, which
       * moves past it. Throws std::out_of_range if @p v is too short.
       */
      void
      read_from(const std::vector<double> &v, unsigned int &i)
      {
        state.slip_path = v.at(i++);
        state.slip_rate = v.at(i++);
        state.variables.resize(static_cast<unsigned int>(v.at(i++)));
        for (auto &x : state.variables)
          x = v.at(i++);
        plastic_slip  = take(v, i);
        slip          = take(v, i);
        slip_velocity = take(v, i);
        rupture_time  = v.at(i++);
        rupture_rate  = v.at(i++);
        slip_at_start = take(v, i);
      }

      static void
      append(std::vector<double> &v, const Tensor<1, dim> &t)
      {
        for (unsigned int d = 0; d < dim; ++d)
          v.push_back(t[d]);
      }

      static Tensor<1, dim>
      take(const std::vector<double> &v, unsigned int &i)
      {
        Tensor<1, dim> t;
        for (unsigned int d = 0; d < dim; ++d)
          t[d] = v.at(i++);
        return t;
      }
    };
  } // namespace Fault
} // namespace rupture

#endif
