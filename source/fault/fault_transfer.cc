// The fault's state on a changed mesh: the pairs' state as finite element
// fields that deal.II's SolutionTransfer carries across refinement,
// coarsening and repartitioning, and the state of the new pairs taken from
// them (interpolation along the fault faces).

#include <rupture/fault/fault.h>

#include <deal.II/base/mpi.h>
#include <deal.II/base/numbers.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace rupture
{
  namespace Fault
  {
    namespace
    {
      /**
       * Where a field holds the transferred values of a pair (w is the
       * weight, 1 at every pair and 0 elsewhere; the other values come
       * multiplied by it, so that w divides them out again where a new
       * node lies between pairs and welded nodes).
       */
      enum Slot : unsigned int
      {
        weight,
        mark,
        slip_path,
        slip_rate,
        rupture_rate,
        ruptured,
        rupture_time,
        friction_value,
        first_vector // then plastic slip, slip, slip velocity, slip at the
                     // start of the dynamic phase, traction, frictional slip
                     // rate (dim each), then the state variables
      };

      constexpr unsigned int n_vectors = 6;

      /// The vectors of a pair (const or not) that a transfer carries, in
      /// their order after first_vector.
      template <class Pair>
      auto
      transferred_vectors(Pair &pair)
      {
        return std::array<decltype(&pair.slip), n_vectors>{
          {&pair.plastic_slip,
           &pair.slip,
           &pair.slip_velocity,
           &pair.slip_at_start,
           &pair.trial.traction,
           &pair.trial.sliding}};
      }
    } // namespace



    template <int dim>
    unsigned int
    Fault<dim>::n_transfer_values() const
    {
      unsigned int n_variables = 0;
      for (const auto &pair : pairs)
        n_variables =
          std::max<unsigned int>(n_variables, pair.state.variables.size());
      n_variables = dealii::Utilities::MPI::max(n_variables, communicator);
      return first_vector + n_vectors * dim + n_variables;
    }



    template <int dim>
    double
    Fault<dim>::transfer_length() const
    {
      // The extent of the fault: the same on every mesh of its geometry
      // (its extreme nodes are vertices of the coarse mesh).
      std::array<double, dim> low, high;
      low.fill(std::numeric_limits<double>::max());
      high.fill(-std::numeric_limits<double>::max());
      for (const auto &pair : pairs)
        for (unsigned int d = 0; d < dim; ++d)
          {
            low[d]  = std::min(low[d], pair.location[d]);
            high[d] = std::max(high[d], pair.location[d]);
          }
      double extent = 0;
      for (unsigned int d = 0; d < dim; ++d)
        extent = std::max(extent,
                          dealii::Utilities::MPI::max(high[d], communicator) +
                            dealii::Utilities::MPI::max(-low[d], communicator));
      return extent > 0 ? extent / 1000 : 1.;
    }



    template <int dim>
    double
    Fault<dim>::location_mark(const Point<dim> &x, const double length)
    {
      // A smooth function of the location that no interpolation between
      // other nodes reproduces (three waves of incommensurate lengths and
      // directions): the mark tells a node that existed before from one
      // between old nodes.
      static const double direction[3][3] = {
        {0.7548776662, 0.5698402910, 0.3247179572},
        {-0.4301597090, 0.8566748839, 0.2846296766},
        {0.2207440846, -0.3819660113, 0.8975077208}};
      double mark = 2;
      for (unsigned int j = 0; j < 3; ++j)
        {
          double phase = 1.234567 * (j + 1);
          for (unsigned int d = 0; d < dim; ++d)
            phase += 2 * numbers::PI * direction[j][d] * x[d] / length;
          mark += 0.3 * std::sin(phase);
        }
      return mark;
    }



    template <int dim>
    std::vector<typename Fault<dim>::VectorType>
    Fault<dim>::state_fields(const IndexSet &locally_owned_dofs) const
    {
      const unsigned int      n      = n_transfer_values();
      const double            length = transfer_length();
      std::vector<VectorType> fields((n + dim - 1) / dim);
      for (auto &field : fields)
        field.reinit(locally_owned_dofs, communicator);
      std::vector<double> values(n);
      for (const auto &pair : pairs)
        {
          std::fill(values.begin(), values.end(), 0.);
          values[weight]       = 1;
          values[mark]         = location_mark(pair.location, length);
          values[slip_path]    = pair.state.slip_path;
          values[slip_rate]    = pair.state.slip_rate;
          values[rupture_rate] = pair.rupture_rate;
          // (A pair whose rupture time is unknown has ruptured too.)
          values[ruptured] =
            pair.rupture_time != NodeState<dim>::not_ruptured ? 1 : 0;
          values[rupture_time]   = values[ruptured] * pair.rupture_time;
          values[friction_value] = pair.trial.friction;
          const auto vectors     = transferred_vectors(pair);
          for (unsigned int v = 0; v < n_vectors; ++v)
            for (unsigned int d = 0; d < dim; ++d)
              values[first_vector + v * dim + d] = (*vectors[v])[d];
          for (unsigned int i = 0; i < pair.state.variables.size(); ++i)
            {
              const double x = pair.state.variables[i];
              values[first_vector + n_vectors * dim + i] =
                friction_law->state_interpolates_in_logarithm(i) ?
                  std::log(std::max(x, std::numeric_limits<double>::min())) :
                  x;
            }
          for (unsigned int k = 0; k < n; ++k)
            for (const auto *side : {&pair.minus, &pair.plus})
              fields[k / dim]((*side)[k % dim]) = values[k];
        }
      for (auto &field : fields)
        field.compress(VectorOperation::insert);
      return fields;
    }



    template <int dim>
    unsigned int
    Fault<dim>::interpolate_new_pairs(const std::vector<VectorType> &fields)
    {
      const unsigned int n      = n_transfer_values();
      const double       length = transfer_length();
      AssertThrow(fields.size() == (n + dim - 1) / dim,
                  ExcMessage("The fault's state fields do not match the "
                             "fault (another friction law or dimension)."));
      unsigned int        n_without = 0;
      std::vector<double> values(n);
      for (const unsigned int p : new_pair_indices)
        {
          NodePair &pair = pairs[p];
          for (unsigned int k = 0; k < n; ++k)
            values[k] = fields[k / dim](pair.minus[k % dim]);
          const double w = values[weight];
          // No pair near this node before (w is 0 away from pairs): it
          // keeps the initial state.
          if (!(w > 1e-6))
            {
              ++n_without;
              continue;
            }
          for (auto &v : values)
            v /= w;
          pair.state.slip_path = values[slip_path];
          pair.state.slip_rate = values[slip_rate];
          pair.rupture_rate    = values[rupture_rate];
          pair.trial.friction  = values[friction_value];
          const auto vectors   = transferred_vectors(pair);
          for (unsigned int v = 0; v < n_vectors; ++v)
            for (unsigned int d = 0; d < dim; ++d)
              (*vectors[v])[d] = values[first_vector + v * dim + d];
          for (unsigned int i = 0; i < pair.state.variables.size(); ++i)
            {
              const double x = values[first_vector + n_vectors * dim + i];
              pair.state.variables[i] =
                friction_law->state_interpolates_in_logarithm(i) ? std::exp(x) :
                                                                   x;
            }
          // The rupture time is history: a node that existed before (its
          // mark came along unchanged, on another process) keeps its own;
          // at a node between old ones it is unknown if the rupture had
          // passed a neighbour, and the node has not ruptured otherwise.
          const bool existed =
            std::abs(values[mark] - location_mark(pair.location, length)) <
            1e-9;
          if (existed)
            pair.rupture_time =
              values[ruptured] < 0.5      ? NodeState<dim>::not_ruptured :
              values[rupture_time] < -1.5 ? NodeState<dim>::unknown_time :
                                            values[rupture_time];
          else
            pair.rupture_time = values[ruptured] > 1e-12 ?
                                  NodeState<dim>::unknown_time :
                                  NodeState<dim>::not_ruptured;
        }
      return dealii::Utilities::MPI::sum(n_without, communicator);
    }



    template class Fault<2>;
    template class Fault<3>;
  } // namespace Fault
} // namespace rupture
