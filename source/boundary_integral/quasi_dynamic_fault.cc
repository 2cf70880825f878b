// The boundary-integral fault as a system of ordinary differential
// equations: elastic traction from the slip, the slip rate from friction
// with radiation damping point by point, the state's rates from the law.

#include <rupture/base/binary_io.h>
#include <rupture/boundary_integral/quasi_dynamic_fault.h>
#include <rupture/boundary_integral/text.h>

#include <deal.II/base/exceptions.h>
#include <deal.II/base/mpi.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

namespace rupture
{
  namespace BoundaryIntegral
  {
    QuasiDynamicFault::QuasiDynamicFault(
      const Stiffness           &geometry,
      const Friction::Interface &law,
      const std::vector<double> &normal_stress,
      const std::vector<double> &initial_shear,
      const double               damping,
      const double               plate_rate,
      const MPI_Comm             communicator)
      : geometry(geometry)
      , law(law)
      , communicator(communicator)
      , n(geometry.size())
      , sigma(normal_stress)
      , tau0(initial_shear)
      , eta(damping)
      , plate_rate(plate_rate)
      , states(n)
      , current(n, 0.)
      , velocity(n, plate_rate)
      , traction(initial_shear)
      , normal_now(normal_stress)
      , coupled(geometry.changes_normal_stress())
      , signed_velocity(n, plate_rate)
      , event_start(n, 0.)
      , event_peak(n, 0.)
    {
      AssertThrow(sigma.size() == n && tau0.size() == n, ExcInternalError());
      for (unsigned int i = 0; i < n; ++i)
        {
          double x = 0, y = 0;
          geometry.position(geometry.depth(i), x, y);
          points.emplace_back(x, y, 0.);
          // The law holds at the start: S(V_p, state) = tau0 - eta V_p.
          const double friction =
            sigma[i] > 0 ? (std::abs(tau0[i]) - eta * plate_rate) / sigma[i] :
                           std::numeric_limits<double>::quiet_NaN();
          law.initialize_state(points[i], friction, states[i]);
        }
      n_variables = states.empty() ? 0 : states[0].variables.size();
      for (unsigned int v = 0; v < n_variables; ++v)
        {
          logarithmic.push_back(law.state_interpolates_in_logarithm(v));
          if (law.state_relaxes(v))
            relaxing_variables.push_back(v);
        }
      variables.assign(n_variables, std::vector<double>(n));
      for (unsigned int i = 0; i < n; ++i)
        for (unsigned int v = 0; v < n_variables; ++v)
          {
            variables[v][i] = states[i].variables[v];
            // (Integrated in its logarithm, the state must be positive.)
            AssertThrow(
              !logarithmic[v] || variables[v][i] > 0,
              ExcMessage(
                "The friction law's state variable " + std::to_string(v + 1) +
                (law.state_names().size() > v ?
                   " (" + law.state_names()[v] + " in the output)" :
                   std::string()) +
                " is " + number(variables[v][i]) +
                " at the fault element at depth " + number(geometry.depth(i)) +
                " m; the boundary-integral method integrates it "
                "in its logarithm, so it must be > 0. Give a "
                "positive <Initial state> of the law in <Fault> "
                "(with <Fault/Slowness law/Evolution effect> = 0 "
                "the computed initial state is 0)."));
          }

      // Rows by rank.
      const unsigned int ranks =
        dealii::Utilities::MPI::n_mpi_processes(communicator);
      const unsigned int rank =
        dealii::Utilities::MPI::this_mpi_process(communicator);
      counts.resize(ranks);
      offsets.resize(ranks);
      for (unsigned int r = 0; r < ranks; ++r)
        {
          const unsigned int begin = std::size_t(n) * r / ranks;
          const unsigned int end   = std::size_t(n) * (r + 1) / ranks;
          counts[r]                = end - begin;
          offsets[r]               = begin;
          if (r == rank)
            {
              row_begin = begin;
              row_end   = end;
            }
        }
      stiffness = geometry.rows(row_begin, row_end);
      if (coupled)
        normal_stiffness = geometry.normal_rows(row_begin, row_end);
      AssertThrow(normal_stiffness.size() == (coupled ? stiffness.size() : 0),
                  ExcInternalError());
    }



    std::vector<double>
    QuasiDynamicFault::initial_values() const
    {
      std::vector<double> y(n * (1 + n_variables), 0.);
      for (unsigned int v = 0; v < n_variables; ++v)
        for (unsigned int i = 0; i < n; ++i)
          {
            const double value = states[i].variables[v];
            y[(1 + v) * std::size_t(n) + i] =
              logarithmic[v] ? std::log(value) : value;
          }
      return y;
    }



    std::vector<double>
    QuasiDynamicFault::absolute_tolerances(const double slip,
                                           const double state) const
    {
      std::vector<double> tolerance(n * (1 + n_variables), state);
      std::fill(tolerance.begin(), tolerance.begin() + n, slip);
      return tolerance;
    }



    void
    QuasiDynamicFault::unpack_state(const unsigned int         i,
                                    const std::vector<double> &y,
                                    Friction::State           &state) const
    {
      state = states[i];
      for (unsigned int v = 0; v < n_variables; ++v)
        {
          const double value = y[(1 + v) * std::size_t(n) + i];
          state.variables[v] = logarithmic[v] ? std::exp(value) : value;
        }
    }



    void
    QuasiDynamicFault::pack_state(const unsigned int     i,
                                  const Friction::State &state,
                                  std::vector<double>   &y) const
    {
      for (unsigned int v = 0; v < n_variables; ++v)
        y[(1 + v) * std::size_t(n) + i] =
          logarithmic[v] ? std::log(state.variables[v]) : state.variables[v];
    }



    void
    QuasiDynamicFault::impose(const std::vector<double> &y,
                              const std::vector<double> &signed_rates,
                              const std::vector<double> &tractions)
    {
      AssertThrow(y.size() == n * std::size_t(1 + n_variables) &&
                    signed_rates.size() == n && tractions.size() == n,
                  ExcInternalError());
      traction = tractions;
      for (unsigned int i = 0; i < n; ++i)
        {
          current[i]         = y[i];
          velocity[i]        = std::abs(signed_rates[i]);
          signed_velocity[i] = signed_rates[i];
          for (unsigned int v = 0; v < n_variables; ++v)
            {
              const double value = y[(1 + v) * std::size_t(n) + i];
              variables[v][i]    = logarithmic[v] ? std::exp(value) : value;
            }
        }
      set_heating();
    }



    double
    QuasiDynamicFault::solve_rate(const unsigned int     i,
                                  const double           tau,
                                  const double           normal_stress,
                                  const Friction::State &state) const
    {
      // g(V) = |tau| - eta V - S(V) falls with V: one root in [0, hi].
      const double target = std::abs(tau);
      double       dS = 0, dp = 0;
      const auto   g = [&](const double V, double &dg) {
        const double S =
          law.strength_at_rate(points[i], state, V, normal_stress, dS, dp);
        dg = -eta - dS;
        return target - eta * V - S;
      };
      double dg = 0;
      if (target == 0 || g(0., dg) <= 0)
        return 0;
      // (|tau| / eta brackets the root where the strength is not negative
      // there; the logarithmic law's can be, at a tiny state: then, and
      // without damping, the bracket grows until it holds the root.)
      double lo = 0, hi = eta > 0 ? target / eta : 1e-9;
      for (unsigned int k = 0; k < 400 && g(hi, dg) > 0; ++k)
        hi *= 2;
      // Newton in ln V, kept inside the bracket, bisecting (in ln V once
      // the bracket's low end is positive) where a step would leave it.
      double V = velocity[i];
      if (!(V > lo && V < hi))
        V = std::sqrt(hi * std::max(lo, 1e-30 * hi));
      for (unsigned int iteration = 0; iteration < 200; ++iteration)
        {
          const double r = g(V, dg);
          if (r > 0)
            lo = V;
          else
            hi = V;
          if (r == 0)
            return V;
          // d g / d ln V = V dg.
          double next = V * std::exp(-r / (V * dg));
          if (!(next > lo && next < hi) || !std::isfinite(next))
            next = lo > 0 ? std::sqrt(lo * hi) : 1e-3 * hi;
          if (std::abs(next - V) <= 1e-14 * V ||
              (lo > 0 && hi - lo <= 1e-14 * hi))
            return next;
          V = next;
        }
      return V;
    }



    void
    QuasiDynamicFault::rates(const double               t,
                             const std::vector<double> &y,
                             std::vector<double>       &rate)
    {
      rate.resize(y.size());
      relative.resize(n);
      for (unsigned int j = 0; j < n; ++j)
        relative[j] = y[j] - plate_rate * t;
      const unsigned int owned = row_end - row_begin;
      shear_load.resize(owned);
      normal_load.resize(owned);
      for (unsigned int r = 0; r < owned; ++r)
        {
          const unsigned int i   = row_begin + r;
          const double      *row = &stiffness[std::size_t(r) * n];
          // (Four partial sums: the additions of one row need not wait for
          // each other, which makes the dense product about twice as fast
          // without reordering anything between runs.)
          double       sum[4] = {0, 0, 0, 0};
          unsigned int j      = 0;
          for (; j + 4 <= n; j += 4)
            for (unsigned int l = 0; l < 4; ++l)
              sum[l] += row[j + l] * relative[j + l];
          for (; j < n; ++j)
            sum[0] += row[j] * relative[j];
          shear_load[r] = tau0[i] + ((sum[0] + sum[1]) + (sum[2] + sum[3]));
          // (The normal stress changes with the slip where the body
          // couples them, as the shear traction does.)
          normal_load[r] = sigma[i];
          if (coupled)
            {
              const double *normal_row = &normal_stiffness[std::size_t(r) * n];
              double        change     = 0;
              for (unsigned int k = 0; k < n; ++k)
                change += normal_row[k] * relative[k];
              normal_load[r] += change;
            }
        }
      balance(t, y, rate);
    }



    void
    QuasiDynamicFault::balance(const double               t,
                               const std::vector<double> &y,
                               std::vector<double>       &rate)
    {
      rate.resize(y.size());
      const unsigned int owned = row_end - row_begin;
      local.resize((1 + n_variables) * std::size_t(owned));
      Friction::State     state;
      std::vector<double> state_rates;
      for (unsigned int r = 0; r < owned; ++r)
        {
          const unsigned int i             = row_begin + r;
          const double       tau           = shear_load[r];
          const double       normal_stress = normal_load[r];
          if (coupled)
            {
              normal_now[i] = normal_stress;
              // (A fault that would open: rates that are not numbers, so
              // that the integrator rejects the step and tries a smaller
              // one; remembered for the message if none helps.)
              if (!(normal_stress > 0))
                {
                  // (Not a number: a stage after one that opened.)
                  if (normal_stress < opening.first)
                    {
                      opening    = {normal_stress, t};
                      opening_at = i;
                    }
                  for (unsigned int b = 0; b < 1 + n_variables; ++b)
                    local[b * std::size_t(owned) + r] =
                      std::numeric_limits<double>::quiet_NaN();
                  traction[i] = std::numeric_limits<double>::quiet_NaN();
                  continue;
                }
            }
          unpack_state(i, y, state);
          const double V = solve_rate(i, tau, normal_stress, state);
          velocity[i]    = V; // the next solve's first guess
          local[r]       = tau < 0 ? -V : V;
          law.state_rate(points[i], state, V, state_rates);
          // (The relaxing variables change at the rates of the step's
          // start, which relax() replaces by their exact change.)
          if (!held_rates.empty())
            for (const unsigned int v : relaxing_variables)
              state_rates[v] = held_rates[v][i];
          for (unsigned int v = 0; v < n_variables; ++v)
            local[(1 + v) * std::size_t(owned) + r] =
              logarithmic[v] ? state_rates[v] / state.variables[v] :
                               state_rates[v];
          // (The owned rows' traction, for accept().)
          traction[i] = tau - eta * local[r];
        }
      // Every rank gets every rate (block by block).
      for (unsigned int b = 0; b < 1 + n_variables; ++b)
        {
          const int ierr = MPI_Allgatherv(local.data() + b * std::size_t(owned),
                                          owned,
                                          MPI_DOUBLE,
                                          rate.data() + b * std::size_t(n),
                                          counts.data(),
                                          offsets.data(),
                                          MPI_DOUBLE,
                                          communicator);
          AssertThrowMPI(ierr);
        }
    }



    void
    QuasiDynamicFault::evaluate(const double t, const std::vector<double> &y)
    {
      std::vector<double> rate;
      rates(t, y, rate);
      accept(y, rate);
      set_heating();
    }



    void
    QuasiDynamicFault::set_heating()
    {
      heating.resize(n);
      for (unsigned int i = 0; i < n; ++i)
        heating[i] = std::abs(traction[i]) * velocity[i];
      if (relaxing_variables.empty())
        return;
      held_rates.assign(n_variables, std::vector<double>(n, 0.));
      held_start = variables;
      Friction::State     state;
      std::vector<double> rates;
      for (unsigned int i = 0; i < n; ++i)
        {
          state = states[i];
          for (unsigned int v = 0; v < n_variables; ++v)
            state.variables[v] = variables[v][i];
          law.relaxation_rate(points[i], state, heating[i], rates);
          for (const unsigned int v : relaxing_variables)
            held_rates[v][i] = rates[v];
        }
    }



    std::vector<double>
    QuasiDynamicFault::relax(const double         t,
                             std::vector<double> &y,
                             const double         dt)
    {
      // (Every rank holds all of y and advances every element alike.)
      Friction::State state;
      for (unsigned int i = 0; i < n; ++i)
        {
          unpack_state(i, y, state);
          // (From the step's start: y holds them moved at the held rates.)
          for (const unsigned int v : relaxing_variables)
            state.variables[v] = held_start[v][i];
          law.relax_state(points[i],
                          state,
                          0.5 *
                            (heating[i] + std::abs(traction[i]) * velocity[i]),
                          dt);
          for (const unsigned int v : relaxing_variables)
            y[(1 + v) * std::size_t(n) + i] = logarithmic[v] ?
                                                std::log(state.variables[v]) :
                                                state.variables[v];
        }
      // (The slip and the time are the step's end, where the pair's last
      // stage computed the loads: only the balance is solved anew.)
      std::vector<double> rate;
      balance(t, y, rate);
      accept(y, rate);
      set_heating();
      // (The new step's held rates, in its first stage.)
      for (const unsigned int v : relaxing_variables)
        for (unsigned int i = 0; i < n; ++i)
          rate[(1 + v) * std::size_t(n) + i] =
            logarithmic[v] ? held_rates[v][i] / variables[v][i] :
                             held_rates[v][i];
      return rate;
    }



    void
    QuasiDynamicFault::accept(const std::vector<double> &y,
                              const std::vector<double> &rate)
    {
      std::vector<double> owned(traction.begin() + row_begin,
                                traction.begin() + row_end);
      const int           ierr = MPI_Allgatherv(owned.data(),
                                      owned.size(),
                                      MPI_DOUBLE,
                                      traction.data(),
                                      counts.data(),
                                      offsets.data(),
                                      MPI_DOUBLE,
                                      communicator);
      AssertThrowMPI(ierr);
      opening = {std::numeric_limits<double>::infinity(), 0.};
      if (coupled)
        {
          std::vector<double> mine(normal_now.begin() + row_begin,
                                   normal_now.begin() + row_end);
          const int           error = MPI_Allgatherv(mine.data(),
                                           mine.size(),
                                           MPI_DOUBLE,
                                           normal_now.data(),
                                           counts.data(),
                                           offsets.data(),
                                           MPI_DOUBLE,
                                           communicator);
          AssertThrowMPI(error);
        }
      for (unsigned int i = 0; i < n; ++i)
        {
          current[i]         = y[i];
          velocity[i]        = std::abs(rate[i]);
          signed_velocity[i] = rate[i];
          for (unsigned int v = 0; v < n_variables; ++v)
            {
              const double value = y[(1 + v) * std::size_t(n) + i];
              variables[v][i]    = logarithmic[v] ? std::exp(value) : value;
            }
        }
    }



    std::string
    QuasiDynamicFault::opening_report() const
    {
      // (The lowest normal stress of the open trial stages on any rank.)
      struct
      {
        double value;
        int    rank;
      } mine         = {opening.first,
                        int(dealii::Utilities::MPI::this_mpi_process(communicator))},
        lowest       = mine;
      const int ierr = MPI_Allreduce(
        &mine, &lowest, 1, MPI_DOUBLE_INT, MPI_MINLOC, communicator);
      AssertThrowMPI(ierr);
      if (!(lowest.value <= 0))
        return "";
      double    where[2] = {opening.second,
                         opening_at < n ? geometry.depth(opening_at) : 0.};
      const int error =
        MPI_Bcast(where, 2, MPI_DOUBLE, lowest.rank, communicator);
      AssertThrowMPI(error);
      return "The fault would open: at t = " + number(where[0]) +
             " s the slip made the normal stress " + number(lowest.value) +
             " Pa at " + number(std::abs(where[1])) +
             " m down the fault, in every step the integrator tried down to "
             "the minimum time step. The boundary-integral method models a "
             "fault that stays closed: give a larger <Boundary "
             "integral/Normal stress>.";
    }



    double
    QuasiDynamicFault::state(const unsigned int i) const
    {
      if (n_variables == 0)
        return std::numeric_limits<double>::quiet_NaN();
      Friction::State s;
      for (unsigned int v = 0; v < n_variables; ++v)
        s.variables.push_back(variables[v][i]);
      return law.state_output(s).at(0);
    }



    std::string
    QuasiDynamicFault::state_name() const
    {
      const auto names = law.state_names();
      return names.empty() ? std::string() : names[0];
    }



    double
    QuasiDynamicFault::max_slip_rate() const
    {
      return n > 0 ? *std::max_element(velocity.begin(), velocity.end()) : 0.;
    }



    void
    QuasiDynamicFault::save(std::ostream &out) const
    {
      // (The guesses of all elements: they are the slip rates of the last
      // evaluate(), except where a later stage of this rank changed them.)
      std::vector<std::vector<double>> fields = {
        current, velocity, traction, event_start, event_peak};
      // (The normal stress only where it changes: the checkpoints of the
      // antiplane problem stay as they were.)
      if (coupled)
        fields.push_back(normal_now);
      BinaryIO::write(out, fields);
      BinaryIO::write(out, variables);
    }



    void
    QuasiDynamicFault::load(std::istream &in)
    {
      std::vector<std::vector<double>> fields, state;
      BinaryIO::read(in, fields);
      BinaryIO::read(in, state);
      AssertThrow(fields.size() == (coupled ? 6u : 5u) &&
                    state.size() == n_variables,
                  ExcMessage("The checkpoint's fault is damaged."));
      for (const auto &f : fields)
        AssertThrow(f.size() == n,
                    ExcMessage("The checkpoint's fault has another number "
                               "of elements than <Boundary integral/Fault "
                               "depth> and <Element size> give."));
      current     = fields[0];
      velocity    = fields[1];
      traction    = fields[2];
      event_start = fields[3];
      event_peak  = fields[4];
      if (coupled)
        normal_now = fields[5];
      // (The sense of each slip rate is the traction's, which the balance
      // gives V.)
      for (unsigned int i = 0; i < n; ++i)
        signed_velocity[i] = std::copysign(velocity[i], traction[i]);
      variables = state;
      set_heating();
    }



    std::pair<double, Point<2>>
    QuasiDynamicFault::fastest_pair() const
    {
      const auto fastest   = std::max_element(velocity.begin(), velocity.end());
      const unsigned int i = fastest - velocity.begin();
      double             x = 0, y = 0;
      geometry.position(geometry.depth(i), x, y);
      return {*fastest, Point<2>(x, y)};
    }



    void
    QuasiDynamicFault::start_event()
    {
      event_start = current;
      event_peak  = velocity;
    }



    void
    QuasiDynamicFault::track_event()
    {
      for (unsigned int i = 0; i < n; ++i)
        event_peak[i] = std::max(event_peak[i], velocity[i]);
    }



    Fault::EventSummary<2>
    QuasiDynamicFault::event_summary(const double threshold) const
    {
      Fault::EventSummary<2> s;
      for (unsigned int i = 0; i < n; ++i)
        {
          const double slip = std::abs(current[i] - event_start[i]);
          s.peak_rate       = std::max(s.peak_rate, event_peak[i]);
          const double h    = geometry.length(i);
          s.moment += geometry.shear_modulus() * h * slip;
          if (event_peak[i] >= threshold)
            {
              s.area += h;
              s.slip_area += h * slip;
            }
          s.largest_slip = std::max(s.largest_slip, slip);
        }
      return s;
    }
  } // namespace BoundaryIntegral
} // namespace rupture
