#include <rupture/fault/fault.h>
#include <rupture/time_integration/implicit_newmark.h>

#include <cmath>
#include <functional>
#include <sstream>

namespace rupture
{
  namespace TimeIntegration
  {
    template <int dim>
    Scheme
    ImplicitNewmark<dim>::scheme() const
    {
      return Scheme::implicit_newmark;
    }



    template <int dim>
    void
    ImplicitNewmark<dim>::set_time_step(const double h)
    {
      Context<dim> &s   = this->context;
      s.state.time_step = h;
      // Effective stiffness of eq. 14: K + a0 M + a1 C, with
      // C = alpha M + beta K + C_absorbing.
      const NewmarkCoefficients c(s.time_parameters.beta,
                                  s.time_parameters.gamma,
                                  h);
      const double stiffness_factor = 1 + c.a1 * s.system.rayleigh_beta(),
                   mass_factor      = c.a0 + c.a1 * s.system.rayleigh_alpha();
      if (!std::isfinite(stiffness_factor) || !std::isfinite(mass_factor))
        {
          std::ostringstream message;
          message << "The effective stiffness K + a0 M + a1 C of the implicit "
                     "step is not finite: with the time step "
                  << h << " s, <Damping/Rayleigh alpha> = "
                  << s.system.rayleigh_alpha()
                  << " 1/s and <Damping/Rayleigh beta> = "
                  << s.system.rayleigh_beta() << " s give the factors "
                  << stiffness_factor << " of K and " << mass_factor
                  << " of M. Allowed: damping coefficients for which both are "
                     "finite (a few percent of critical damping is "
                     "alpha ~ 0.1-1 1/s, beta ~ 1e-4-1e-3 s).";
          AssertThrow(false, ExcMessage(message.str()));
        }
      s.system.set_effective_stiffness(stiffness_factor, mass_factor, c.a1);
    }



    template <int dim>
    void
    ImplicitNewmark<dim>::save_scheme(BinaryIO::Records &records) const
    {
      records["integrator/substep depth"]     = substep_depth;
      records["integrator/steps without cut"] = steps_without_cut;
    }



    template <int dim>
    void
    ImplicitNewmark<dim>::load_scheme(const BinaryIO::Records &records)
    {
      substep_depth = static_cast<unsigned int>(
        BinaryIO::record(records, "integrator/substep depth"));
      steps_without_cut = static_cast<unsigned int>(
        BinaryIO::record(records, "integrator/steps without cut"));
    }



    template <int dim>
    void
    ImplicitNewmark<dim>::prepare()
    {
      substep_depth     = 0;
      steps_without_cut = 0;
      set_time_step(this->context.state.time_step);
    }



    template <int dim>
    void
    ImplicitNewmark<dim>::step()
    {
      // Try the step; if Newton's method fails, redo it as two half steps,
      // recursively, up to <Solver/Maximum step cuts> times. The fault
      // state and the energy budget change only when a (sub)step has
      // converged. After a cut the following steps start from the sub-step
      // size that converged (a step that failed at full size tends to fail
      // again in the next one), and double it again after two steps
      // without a cut.
      using Solver::NewtonFailure;
      Context<dim>      &s   = this->context;
      const double       end = s.state.time, dt = s.state.time_step;
      const unsigned int cuts    = s.newton_parameters.max_step_cuts;
      unsigned int       deepest = 0;
      bool               cut     = false;
      std::function<void(double, double, unsigned int)> attempt =
        [&](const double t_start, const double h, const unsigned int depth) {
          const VectorType u(s.state.displacement), v(s.state.velocity),
            a(s.state.acceleration);
          if (h != s.state.time_step)
            set_time_step(h);
          s.state.time = t_start + h;
          if (s.fault)
            s.fault->set_time(s.state.time);
          // Give up early on a stalled Newton iteration only where the
          // step can still be cut; at the last level it iterates on.
          s.newton.may_cut = (depth < cuts);
          try
            {
              try
                {
                  substep();
                }
              catch (const NewtonFailure &failure)
                {
                  // The stick-crossing limit can keep a node from the far
                  // side of its stick region where its solution lies (seen
                  // with time steps 100-1000 times the explicit limit): try
                  // the step once more without it before cutting it.
                  if (s.newton.stick_crossings_limited == 0)
                    throw;
                  s.state.displacement = u;
                  s.state.velocity     = v;
                  s.state.acceleration = a;
                  s.pcout << "    Newton failed with dt = " << h << " s ("
                          << failure.reason
                          << ") after limiting stick crossings: the step is "
                             "tried again without the limit\n";
                  // (If it fails again, the catch below ends the
                  // suspension.)
                  s.newton.stick_crossing_limit_suspended = true;
                  substep();
                  s.newton.stick_crossing_limit_suspended = false;
                }
              s.newton.may_cut = false;
              deepest          = std::max(deepest, depth);
            }
          catch (const NewtonFailure &failure)
            {
              s.newton.may_cut                        = false;
              s.newton.stick_crossing_limit_suspended = false;
              if (depth == cuts)
                throw NewtonFailure(std::string(failure.what()) +
                                      " The step was cut " +
                                      std::to_string(depth) +
                                      " times (<Solver/Maximum step cuts>).",
                                    failure.reason);
              s.state.displacement = u;
              s.state.velocity     = v;
              s.state.acceleration = a;
              s.pcout << "    Newton failed with dt = " << h << " s ("
                      << failure.reason << "): the step is cut in half\n";
              ++s.newton.n_step_cuts;
              ++s.newton.total_step_cuts;
              cut = true;
              attempt(t_start, h / 2, depth + 1);
              attempt(t_start + h / 2, h / 2, depth + 1);
            }
        };
      const unsigned int start_depth = std::min(substep_depth, cuts);
      const unsigned int n_substeps  = 1u << start_depth;
      if (n_substeps > 1)
        s.pcout << "    taken as " << n_substeps << " sub-steps of "
                << dt / n_substeps << " s after an earlier step cut\n";
      for (unsigned int i = 0; i < n_substeps; ++i)
        attempt(end - dt + i * (dt / n_substeps), dt / n_substeps, start_depth);
      if (cut)
        {
          substep_depth     = deepest;
          steps_without_cut = 0;
        }
      else if (substep_depth > 0 && ++steps_without_cut >= 2)
        {
          --substep_depth;
          steps_without_cut = 0;
        }
      if (s.state.time_step != dt)
        set_time_step(dt);
      s.state.time = end;
    }



    template <int dim>
    unsigned int
    ImplicitNewmark<dim>::balance_displacement()
    {
      Context<dim>      &s = this->context;
      TimerOutput::Scope t(s.timer, "Implicit step: balance a new mesh");
      const VectorType   old_u(s.state.displacement);
      VectorType         load(old_u), residual(old_u), tmp(old_u);
      // The forces that stay: the loads less the carried inertia and
      // damping. The fault is held stuck on its springs (a sliding,
      // weakening fault has no static balance).
      s.system.assemble_load(s.state.time, load);
      s.system.apply_mass(s.state.acceleration, tmp);
      load -= tmp;
      s.system.damping_force(s.state.velocity, tmp);
      load -= tmp;
      const auto compute_residual = [&]() {
        this->static_residual(load, residual, tmp);
      };
      // (The counts of the last step and of the phase's steps stay what
      // their reports say.)
      const Solver::NewtonStatus counts         = s.newton;
      const auto                 restore_counts = [&]() {
        s.newton.last_iterations = counts.last_iterations;
        s.newton.last_linear_iterations = counts.last_linear_iterations;
        s.newton.total_linear_iterations = counts.total_linear_iterations;
        s.newton.n_linear_solves = counts.n_linear_solves;
      };
      s.newton.may_cut = false;
      try
        {
          s.system.set_effective_stiffness(1, 0, 0);
          s.nonlinear.solve(
            old_u, []() {}, compute_residual, residual, nullptr, true);
        }
      catch (...)
        {
          restore_counts();
          s.state.displacement = old_u;
          set_time_step(s.state.time_step);
          // The fault's trial state of the carried displacement again (the
          // failed solve left its last iterate's).
          if (s.fault)
            {
              tmp = 0;
              s.nonlinear.add_contact_force(tmp);
            }
          throw;
        }
      set_time_step(s.state.time_step);
      // The balance slid no pair: its accepted slip is that of the
      // balanced displacement, so that the next step's slip rate does not
      // count the correction.
      if (s.fault)
        s.fault->accept_held_slip();
      const unsigned int iterations = s.newton.last_iterations;
      restore_counts();
      return iterations;
    }



    template <int dim>
    void
    ImplicitNewmark<dim>::substep()
    {
      Context<dim>             &s = this->context;
      TimerOutput::Scope        t(s.timer, "Implicit step");
      const double              dt    = s.state.time_step;
      const double              gamma = s.time_parameters.gamma;
      const NewmarkCoefficients a(s.time_parameters.beta, gamma, dt);

      const VectorType old_u(s.state.displacement), old_v(s.state.velocity),
        old_a(s.state.acceleration);
      VectorType load(s.state.displacement), residual(s.state.displacement),
        tmp(s.state.displacement), cv(s.state.displacement);
      s.system.assemble_load(s.state.time, load);

      // New velocity and acceleration as functions of the new displacement
      // (Newmark, eq. 12), and the residual f - M a - C v - K u -
      // F_contact.
      const auto update_rates = [&]() {
        s.state.acceleration = s.state.displacement;
        s.state.acceleration -= old_u;
        s.state.acceleration *= a.a0;
        s.state.acceleration.add(-a.a2, old_v, -a.a3, old_a);
        s.state.velocity = old_v;
        s.state.velocity.add((1 - gamma) * dt,
                             old_a,
                             gamma * dt,
                             s.state.acceleration);
      };
      const auto compute_residual = [&]() {
        residual = load;
        s.system.apply_stiffness(s.state.displacement, tmp);
        residual -= tmp;
        s.system.apply_mass(s.state.acceleration, tmp);
        residual -= tmp;
        s.system.damping_force(s.state.velocity, cv);
        residual -= cv;
        if (s.fault)
          {
            tmp = 0;
            s.nonlinear.add_contact_force(tmp);
            residual -= tmp;
          }
      };

      // The predictor: the old motion carried on over the step.
      std::unique_ptr<VectorType> predicted;
      if (s.newton_parameters.predictor != "old displacement")
        {
          predicted = std::make_unique<VectorType>(old_v);
          *predicted *= dt;
          if (s.newton_parameters.predictor == "constant acceleration")
            predicted->add(0.5 * dt * dt, old_a);
        }
      s.nonlinear.solve(
        old_u, update_rates, compute_residual, residual, predicted.get());
      this->accept_step(old_u, load, residual, cv);
    }



    template class ImplicitNewmark<2>;
    template class ImplicitNewmark<3>;
  } // namespace TimeIntegration
} // namespace rupture
