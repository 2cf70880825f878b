// The fault's state between steps: gathering node records, phases, time, and
// statistics.

#include <rupture/base/binary_io.h>
#include <rupture/base/utilities.h>
#include <rupture/fault/fault.h>
#include <rupture/fault/location_index.h>

#include <deal.II/base/mpi.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/mapping_q1.h>
#include <deal.II/hp/fe_values.h>
#include <deal.II/hp/mapping_collection.h>
#include <deal.II/hp/q_collection.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>

#include <boost/serialization/vector.hpp>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <limits>
#include <map>
#include <set>
#include <sstream>

namespace rupture
{
  namespace Fault
  {
    template <int dim>
    std::vector<typename Fault<dim>::NodeRecord>
    Fault<dim>::gather(const std::set<types::global_dof_index> *keys) const
    {
      // Each record is flattened to doubles (the DoF key is exact below
      // 2^53) and the ranks' arrays are gathered with one MPI_Gatherv: a
      // serialised, compressed gather took most of an output's time.
      const unsigned int  n_state = friction_law->state_names().size();
      const unsigned int  stride  = 5 + 6 * dim + n_state;
      std::vector<double> mine;
      for (const auto &pair : pairs)
        if (!keys || keys->count(pair.minus[0]))
          {
            mine.push_back(static_cast<double>(pair.minus[0]));
            const auto add = [&mine](const Tensor<1, dim> &t) {
              for (unsigned int d = 0; d < dim; ++d)
                mine.push_back(t[d]);
            };
            add(pair.location);
            add(pair.normal);
            add(pair.slip - pair.slip_at_start);
            add(pair.slip_velocity);
            add(pair.trial.traction);
            add(pair.trial.sliding);
            mine.push_back(pair.state.slip_path);
            mine.push_back(pair.trial.friction);
            mine.push_back(pair.rupture_time);
            mine.push_back(static_cast<int>(pair.trial.status));
            const std::vector<double> state =
              friction_law->state_output(pair.state);
            for (unsigned int i = 0; i < n_state; ++i)
              mine.push_back(i < state.size() ? state[i] : 0.);
          }

      const unsigned int n_ranks =
        dealii::Utilities::MPI::n_mpi_processes(communicator);
      const bool root =
        dealii::Utilities::MPI::this_mpi_process(communicator) == 0;
      const int        count = mine.size();
      std::vector<int> counts(n_ranks), offsets(n_ranks, 0);
      MPI_Gather(
        &count, 1, MPI_INT, counts.data(), 1, MPI_INT, 0, communicator);
      for (unsigned int r = 1; r < n_ranks; ++r)
        offsets[r] = offsets[r - 1] + counts[r - 1];
      std::vector<double> all(root ? offsets.back() + counts.back() : 0);
      MPI_Gatherv(mine.data(),
                  count,
                  MPI_DOUBLE,
                  all.data(),
                  counts.data(),
                  offsets.data(),
                  MPI_DOUBLE,
                  0,
                  communicator);

      std::vector<NodeRecord> result(all.size() / stride);
      for (unsigned int n = 0; n < result.size(); ++n)
        {
          const double *v = &all[n * stride];
          NodeRecord   &r = result[n];
          r.key           = static_cast<types::global_dof_index>(*v++);
          const auto get  = [&v](Tensor<1, dim> &t) {
            for (unsigned int d = 0; d < dim; ++d)
              t[d] = *v++;
          };
          get(r.location);
          get(r.normal);
          get(r.slip);
          get(r.slip_velocity);
          get(r.traction);
          get(r.sliding);
          r.slip_path    = *v++;
          r.friction     = *v++;
          r.rupture_time = *v++;
          r.status       = static_cast<int>(*v++);
          r.state_values.assign(v, v + n_state);
        }
      return result;
    }



    template <int dim>
    std::vector<std::vector<types::global_dof_index>>
    Fault<dim>::gather_faces() const
    {
      const auto all =
        dealii::Utilities::MPI::gather(communicator, owned_faces, 0);
      std::vector<std::vector<types::global_dof_index>> result;
      for (const auto &part : all)
        result.insert(result.end(), part.begin(), part.end());
      return result;
    }



    template <int dim>
    unsigned long
    Fault<dim>::status_signature() const
    {
      unsigned long signature = 0;
      for (const auto &pair : pairs)
        signature += (static_cast<unsigned long>(pair.trial.status) + 1) *
                     (pair.minus[0] % 1000003 + 1);
      return dealii::Utilities::MPI::sum(signature, communicator);
    }



    template <int dim>
    void
    Fault<dim>::set_time(const double time)
    {
      friction_law->set_time(time);
      current_time = time;
      if (traction_perturbation)
        {
          // The perturbation acts in the dynamic phase only, as forced
          // slip.
          const double t = time - dynamic_start;
          perturbation_time_function->set_time(0);
          const double       g = forced_slip_active ?
                                   perturbation_time_function->value(Point<1>(t)) :
                                   0.;
          std::ostringstream message;
          message << "<Fault/Traction perturbation/Time function> must be "
                     "finite, but is "
                  << g << " at t = " << t << " s.";
          AssertThrow(std::isfinite(g), ExcMessage(message.str()));
          for (auto &pair : pairs)
            pair.initial_traction =
              pair.background_traction + g * pair.perturbation;
        }
    }



    template <int dim>
    void
    Fault<dim>::check_time_functions(const double duration) const
    {
      if (!traction_perturbation)
        return;
      perturbation_time_function->set_time(0);
      for (unsigned int i = 0; i <= 1000; ++i)
        {
          const double       t = duration * i / 1000.;
          const double       g = perturbation_time_function->value(Point<1>(t));
          std::ostringstream message;
          message << "<Fault/Traction perturbation/Time function> must be "
                     "finite, but is "
                  << g << " at t = " << t
                  << " s. Allowed: expressions of t that are finite over the "
                     "whole run.";
          AssertThrow(std::isfinite(g), ExcMessage(message.str()));
        }
    }



    template <int dim>
    Tensor<1, dim>
    Fault<dim>::imposed_slip(const NodePair &pair, const double delay) const
    {
      const double t = current_time + delay - dynamic_start;
      forced_slip->set_time(t);
      const double       s = forced_slip->value(pair.location);
      std::ostringstream message;
      message << "<Fault/Forced slip/Slip> must be finite and >= 0 (m), but "
              << "is " << s << " at " << pair.location << " and t = " << t
              << " s.";
      AssertThrow(std::isfinite(s) && s >= 0, ExcMessage(message.str()));
      return s * pair.forced_direction;
    }



    template <int dim>
    void
    Fault<dim>::start_dynamic_phase(const double time)
    {
      friction_law->start_dynamic_phase(time);
      friction_law->enable_weakening(true);
      dynamic_start      = time;
      forced_slip_active = true;
      // Slip, rupture times and the ruptured area count from here on.
      for (auto &pair : pairs)
        {
          pair.slip_at_start = pair.slip;
          pair.rupture_time  = -1;
          pair.rupture_rate  = 0;
        }
      // Weakening counts the slip of the dynamic phase: a bonded zone
      // breaks when the dynamic phase starts.
      for (auto &pair : pairs)
        pair.state.slip_path = 0;
    }



    template <int dim>
    void
    Fault<dim>::continue_dynamic_phase(const double time)
    {
      friction_law->start_dynamic_phase(time);
      friction_law->enable_weakening(true);
      dynamic_start      = time;
      forced_slip_active = true;
    }



    template <int dim>
    void
    Fault<dim>::start_loading_phase()
    {
      friction_law->enable_weakening(false);
      forced_slip_active = false;
    }



    template <int dim>
    unsigned int
    Fault<dim>::n_weakening() const
    {
      unsigned int n = 0;
      for (const auto &pair : pairs)
        if (pair.trial.status == ContactStatus::slip &&
            friction_law->can_weaken(to_3d(pair.location), pair.state))
          ++n;
      return dealii::Utilities::MPI::sum(n, communicator);
    }



    template <int dim>
    bool
    Fault<dim>::all_stuck() const
    {
      unsigned int n = 0;
      for (const auto &pair : pairs)
        if (pair.trial.status != ContactStatus::stick)
          ++n;
      return dealii::Utilities::MPI::sum(n, communicator) == 0;
    }



    template <int dim>
    std::vector<Point<dim>>
    Fault<dim>::active_locations(const double rate,
                                 const double time,
                                 const double memory,
                                 const bool   overstressed) const
    {
      std::vector<Point<dim>> active;
      const bool              by_strength =
        overstressed && !friction_law->depends_on_slip_rate();
      for (const auto &pair : pairs)
        {
          if (by_strength && pair.trial.status == ContactStatus::slip)
            {
              active.push_back(pair.location);
              continue;
            }
          const bool ruptured =
            pair.rupture_time >= 0 &&
            (memory < 0 || time - pair.rupture_time < memory);
          if (pair.state.slip_rate > rate || ruptured ||
              (memory < 0 && pair.rupture_time == NodeState<dim>::unknown_time))
            active.push_back(pair.location);
        }
      return active;
    }



    template <int dim>
    std::vector<std::pair<Point<dim>, double>>
    Fault<dim>::process_zone_widths() const
    {
      std::vector<std::pair<Point<dim>, double>> widths;
      for (const auto &pair : pairs)
        if (!pair.hanging)
          {
            double normal = pair.trial.traction * pair.normal;
            if (normal == 0)
              normal = pair.initial_traction * pair.normal;
            const double width =
              friction_law->process_zone_width(to_3d(pair.location),
                                               pair.state,
                                               std::max(-normal, 0.),
                                               pair.shear_modulus);
            if (std::isfinite(width))
              widths.emplace_back(pair.location, width);
          }
      return widths;
    }



    template <int dim>
    double
    Fault<dim>::state_evolution_time() const
    {
      double shortest = std::numeric_limits<double>::infinity();
      for (const auto &pair : pairs)
        if (!pair.hanging && pair.state.slip_rate > 0)
          {
            const double L =
              friction_law->slip_scale(to_3d(pair.location), pair.state);
            if (std::isfinite(L))
              shortest = std::min(shortest, L / pair.state.slip_rate);
          }
      return dealii::Utilities::MPI::min(shortest, communicator);
    }



    template <int dim>
    std::pair<double, Point<dim>>
    Fault<dim>::fastest_pair() const
    {
      // (MPI_MAXLOC over the ranks' largest rates, then the owner's
      // location.)
      struct
      {
        double rate;
        int    rank;
      } mine{-1.,
             static_cast<int>(
               dealii::Utilities::MPI::this_mpi_process(communicator))},
        largest;
      Point<dim> where;
      for (const auto &pair : pairs)
        if (!pair.hanging && pair.rupture_rate > mine.rate)
          {
            mine.rate = pair.rupture_rate;
            where     = pair.location;
          }
      MPI_Allreduce(
        &mine, &largest, 1, MPI_DOUBLE_INT, MPI_MAXLOC, communicator);
      double coordinates[dim];
      for (unsigned int d = 0; d < dim; ++d)
        coordinates[d] = where[d];
      MPI_Bcast(coordinates, dim, MPI_DOUBLE, largest.rank, communicator);
      for (unsigned int d = 0; d < dim; ++d)
        where[d] = coordinates[d];
      return {std::max(largest.rate, 0.), where};
    }



    template <int dim>
    void
    Fault<dim>::start_event()
    {
      for (auto &pair : pairs)
        {
          pair.event_slip      = pair.slip;
          pair.event_peak_rate = pair.rupture_rate;
        }
    }



    template <int dim>
    void
    Fault<dim>::track_event()
    {
      for (auto &pair : pairs)
        pair.event_peak_rate =
          std::max(pair.event_peak_rate, pair.rupture_rate);
    }



    template <int dim>
    EventSummary<dim>
    Fault<dim>::event_summary(const double threshold) const
    {
      EventSummary<dim> s;
      double            sums[3] = {0, 0, 0}; // moment, area, area x slip
      for (const auto &pair : pairs)
        if (!pair.hanging)
          {
            const double slip = (pair.slip - pair.event_slip).norm();
            sums[0] += pair.shear_modulus * pair.area * slip;
            s.peak_rate = std::max(s.peak_rate, pair.event_peak_rate);
            if (pair.event_peak_rate >= threshold)
              {
                sums[1] += pair.area;
                sums[2] += pair.area * slip;
                s.largest_slip = std::max(s.largest_slip, slip);
              }
          }
      dealii::Utilities::MPI::sum(sums, communicator, sums);
      s.moment    = sums[0];
      s.area      = sums[1];
      s.slip_area = sums[2];
      s.peak_rate = dealii::Utilities::MPI::max(s.peak_rate, communicator);
      s.largest_slip =
        dealii::Utilities::MPI::max(s.largest_slip, communicator);
      return s;
    }



    template <int dim>
    Statistics
    Fault<dim>::statistics() const
    {
      Statistics s;
      double     area = 0, moment = 0, normal = 0, shear = 0, total_area = 0;
      double     ruptured[2] = {0, 0};
      unsigned   n_slip = 0, n_open = 0, unstable = 0;
      double     max_slip = 0, max_rate = 0;
      for (const auto &pair : pairs)
        {
          if (pair.trial.status == ContactStatus::slip)
            {
              ++n_slip;
              area += pair.area;
            }
          if (pair.trial.status == ContactStatus::open)
            ++n_open;
          if (pair.trial.unstable_softening)
            ++unstable;
          const double slip = (pair.slip - pair.slip_at_start).norm();
          max_slip          = std::max(max_slip, slip);
          // (The Euclidean slip rate: the law's state holds |A V| with
          // anisotropic friction.)
          max_rate = std::max(max_rate,
                              anisotropic_friction ? pair.slip_velocity.norm() :
                                                     pair.state.slip_rate);
          moment += pair.shear_modulus * pair.area * slip;
          if (pair.rupture_time != NodeState<dim>::not_ruptured)
            {
              ruptured[0] += pair.area;
              ruptured[1] += pair.area * slip;
            }
          const double tn = pair.trial.traction * pair.normal;
          normal += pair.area * tn;
          shear += pair.area * (pair.trial.traction - tn * pair.normal).norm();
          total_area += pair.area;
        }
      total_area = dealii::Utilities::MPI::sum(total_area, communicator);
      if (total_area > 0)
        {
          s.mean_normal_traction =
            dealii::Utilities::MPI::sum(normal, communicator) / total_area;
          s.mean_shear_traction =
            dealii::Utilities::MPI::sum(shear, communicator) / total_area;
        }
      dealii::Utilities::MPI::sum(ruptured, communicator, ruptured);
      s.ruptured_area  = ruptured[0];
      s.mean_slip      = ruptured[0] > 0 ? ruptured[1] / ruptured[0] : 0;
      s.n_nodes        = n_global_split;
      s.n_slipping     = dealii::Utilities::MPI::sum(n_slip, communicator);
      s.n_open         = dealii::Utilities::MPI::sum(n_open, communicator);
      s.slipping_area  = dealii::Utilities::MPI::sum(area, communicator);
      s.seismic_moment = dealii::Utilities::MPI::sum(moment, communicator);
      s.max_slip       = dealii::Utilities::MPI::max(max_slip, communicator);
      s.max_slip_rate  = dealii::Utilities::MPI::max(max_rate, communicator);
      s.frictional_energy =
        dealii::Utilities::MPI::sum(frictional_energy, communicator);
      s.unstable_softening =
        dealii::Utilities::MPI::sum(unstable, communicator) > 0;
      const unsigned int n_states = friction_law->state_names().size();
      s.state_minimum.assign(n_states, std::numeric_limits<double>::max());
      s.state_maximum.assign(n_states, std::numeric_limits<double>::lowest());
      for (const auto &pair : pairs)
        {
          const std::vector<double> values =
            friction_law->state_output(pair.state);
          for (unsigned int i = 0; i < n_states; ++i)
            {
              s.state_minimum[i] = std::min(s.state_minimum[i], values[i]);
              s.state_maximum[i] = std::max(s.state_maximum[i], values[i]);
            }
        }
      for (unsigned int i = 0; i < n_states; ++i)
        {
          s.state_minimum[i] =
            dealii::Utilities::MPI::min(s.state_minimum[i], communicator);
          s.state_maximum[i] =
            dealii::Utilities::MPI::max(s.state_maximum[i], communicator);
        }
      return s;
    }



    template <int dim>
    unsigned int
    Fault<dim>::n_split_nodes() const
    {
      return n_global_split;
    }



    template <int dim>
    unsigned int
    Fault<dim>::n_welded_nodes() const
    {
      return n_global_welded;
    }



    template <int dim>
    void
    Fault<dim>::save(std::ostream &out) const
    {
      BinaryIO::write(out,
                      std::vector<double>{double(forced_slip_active),
                                          dynamic_start,
                                          current_time,
                                          frictional_energy});
      BinaryIO::write(out, static_cast<std::uint64_t>(pairs.size()));
      std::vector<double> v;
      for (const auto &pair : pairs)
        {
          v.clear();
          for (unsigned int d = 0; d < dim; ++d)
            v.push_back(pair.location[d]);
          pair.NodeState<dim>::append_to(v);
          const auto &t = pair.trial;
          NodeState<dim>::append(v, t.traction);
          NodeState<dim>::append(v, t.trial_traction);
          for (unsigned int d = 0; d < dim; ++d)
            NodeState<dim>::append(v, t.tangent[d]);
          v.push_back(static_cast<double>(t.status));
          v.push_back(t.slip_increment);
          NodeState<dim>::append(v, t.plastic_slip);
          v.push_back(t.friction);
          v.push_back(t.friction_derivative);
          v.push_back(t.unstable_softening);
          NodeState<dim>::append(v, pair.trial_slip);
          // (Added with the event catalogue: older checkpoints end here.)
          NodeState<dim>::append(v, pair.event_slip);
          v.push_back(pair.event_peak_rate);
          // (Added with anisotropic friction's output.)
          NodeState<dim>::append(v, t.sliding);
          BinaryIO::write(out, v);
        }
    }



    template <int dim>
    void
    Fault<dim>::load(const std::vector<std::string> &files)
    {
      const unsigned int rank =
        dealii::Utilities::MPI::this_mpi_process(communicator);
      const bool same_ranks =
        files.size() == dealii::Utilities::MPI::n_mpi_processes(communicator);
      std::vector<Point<dim>>          saved_locations;
      std::vector<std::vector<double>> saved;
      double                           energy = 0;
      for (unsigned int f = 0; f < files.size(); ++f)
        {
          std::ifstream in(files[f], std::ios::binary);
          AssertThrow(in,
                      ExcMessage("The checkpoint file <" + files[f] +
                                 "> cannot be read."));
          std::vector<double> clock;
          BinaryIO::read(in, clock);
          AssertThrow(clock.size() == 4,
                      ExcMessage("The checkpoint file <" + files[f] +
                                 "> is damaged."));
          forced_slip_active = clock[0] != 0;
          dynamic_start      = clock[1];
          current_time       = clock[2];
          // The frictional energy is a sum over the ranks: on the same
          // ranks each keeps its own part (the same sums to the last
          // digit), else rank 0 takes the whole.
          if (same_ranks ? f == rank : rank == 0)
            energy += clock[3];
          const std::uint64_t n = BinaryIO::read_size(in);
          std::vector<double> v;
          for (std::uint64_t k = 0; k < n; ++k)
            {
              BinaryIO::read(in, v);
              AssertThrow(v.size() > dim,
                          ExcMessage("The checkpoint file <" + files[f] +
                                     "> is damaged."));
              Point<dim> location;
              for (unsigned int d = 0; d < dim; ++d)
                location[d] = v[d];
              saved_locations.push_back(location);
              saved.push_back(v);
            }
        }
      frictional_energy = energy;
      // Pairs are found by location (the DoFs change with the number of
      // processes).
      const LocationIndex<dim> index(saved_locations,
                                     location_tolerance(pairs));
      for (auto &pair : pairs)
        {
          const unsigned int at = index.find(pair.location);
          if (at == LocationIndex<dim>::invalid)
            {
              std::ostringstream where;
              where << pair.location;
              AssertThrow(false,
                          ExcMessage("The checkpoint has no fault state at "
                                     "the node pair at (" +
                                     where.str() +
                                     "): it was written for another mesh "
                                     "or fault."));
            }
          const std::vector<double> &v = saved[at];
          unsigned int               i = dim;
          pair.NodeState<dim>::read_from(v, i);
          auto &t          = pair.trial;
          t.traction       = NodeState<dim>::take(v, i);
          t.trial_traction = NodeState<dim>::take(v, i);
          for (unsigned int d = 0; d < dim; ++d)
            t.tangent[d] = NodeState<dim>::take(v, i);
          t.status              = static_cast<ContactStatus>(v.at(i++));
          t.slip_increment      = v.at(i++);
          t.plastic_slip        = NodeState<dim>::take(v, i);
          t.friction            = v.at(i++);
          t.friction_derivative = v.at(i++);
          t.unstable_softening  = v.at(i++) != 0;
          pair.trial_slip       = NodeState<dim>::take(v, i);
          // (Checkpoints before the event catalogue end here.)
          if (i + dim + 1 <= v.size())
            {
              pair.event_slip      = NodeState<dim>::take(v, i);
              pair.event_peak_rate = v.at(i++);
            }
          if (i + dim <= v.size())
            t.sliding = NodeState<dim>::take(v, i);
        }
    }



    template class Fault<2>;
    template class Fault<3>;
  } // namespace Fault
} // namespace rupture
