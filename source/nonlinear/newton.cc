// Newton's method for implicit Newmark and quasi-static steps with a penalty
// fault (the step cuts are TimeIntegration::ImplicitNewmark's).

#include <rupture/discretization/discretization.h>
#include <rupture/elasticity/system.h>
#include <rupture/fault/fault.h>
#include <rupture/nonlinear/newton.h>
#include <rupture/operators/multigrid.h>
#include <rupture/solver/linear_solver.h>
#include <rupture/time_integration/time_state.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <sstream>
#include <vector>


namespace rupture
{
  namespace Nonlinear
  {
    namespace
    {
      /**
       * The relative tolerance of the linear solve in Newton iteration @p k
       * of an inexact Newton method: Eisenstat and Walker's choice 2,
       * eta_k = 0.9 (|F_k| / |F_k-1|)^2 with their safeguard, at most
       * @p cap (<Solver/Newton forcing>). @p eta carries the last value.
       * Solving far below what the force tolerance still asks for is wasted,
       * so the tolerance is never tighter than a hundredth of it (the last
       * solve keeps the residual, and so the energy budget, well inside the
       * tolerance). Once the force criterion holds, only the displacement
       * criterion is left, and it needs a nearly exact correction: a loose
       * one stalled the line search at 10 km cells (contrib/iteration-study),
       * so those solves go to 1e-3.
       */
      double
      forcing_tolerance(const unsigned int k,
                        const double       norm,
                        const double       last_norm,
                        const double       force_goal,
                        const double       cap,
                        double            &eta)
      {
        if (k > 0)
          {
            const double ratio   = norm / std::max(last_norm, 1e-300);
            const double guarded = 0.9 * eta * eta;
            eta                  = 0.9 * ratio * ratio;
            if (guarded > 0.1)
              eta = std::max(eta, guarded);
            eta = std::min(eta, cap);
          }
        if (norm <= force_goal)
          return std::min(eta, 1e-3);
        return std::max(eta,
                        std::min(0.5,
                                 0.01 * force_goal / std::max(norm, 1e-300)));
      }
    } // namespace



    template <int dim>
    Newton<dim>::Newton(
      TimeIntegration::TimeState                &state,
      const Discretization::Discretization<dim> &discretization,
      Elasticity::System<dim>                   &system,
      Solver::LinearSolver                      &linear_solver,
      TimerOutput                               &timer,
      ConditionalOStream                        &pcout,
      const FiniteCheck                         &check_finite)
      : state(state)
      , discretization(discretization)
      , system(system)
      , linear_solver(linear_solver)
      , timer(timer)
      , pcout(pcout)
      , check_finite(check_finite)
    {}



    template <int dim>
    void
    Newton<dim>::parse_parameters(ParameterHandler &prm)
    {
      controls.force_tolerance = prm.get_double("Newton force tolerance");
      controls.displacement_tolerance =
        prm.get_double("Newton displacement tolerance");
      controls.max_iterations   = prm.get_integer("Maximum Newton iterations");
      controls.max_step_cuts    = prm.get_integer("Maximum step cuts");
      controls.stall_iterations = prm.get_integer("Newton stall iterations");
      controls.forcing          = prm.get_double("Newton forcing");
      controls.print_iterations = prm.get_bool("Print Newton iterations");
      controls.predictor        = prm.get("Newton predictor");
      controls.limit_stick_crossings = prm.get_bool("Limit stick crossings");
    }



    template <int dim>
    void
    Newton<dim>::assemble_contact(VectorType  &force,
                                  const bool   with_tangent,
                                  const double sign)
    {
      TimerOutput::Scope t(timer, "Fault contact");
      fault->assemble(discretization.ghosted_copy(0, state.displacement),
                      state.time_step,
                      discretization.hanging_constraints(),
                      force,
                      discretization.increment_constraints(),
                      with_tangent ? &system.effective_matrix() : nullptr,
                      sign);
    }



    template <int dim>
    void
    Newton<dim>::solve(const VectorType            &old_u,
                       const std::function<void()> &update_rates,
                       const std::function<void()> &compute_residual,
                       VectorType                  &residual,
                       const VectorType            *predicted_increment,
                       const bool                   hold)
    {
      // A balance at a fixed time: every closed pair sticks for the solve
      // (the fault's forces follow its springs only).
      struct Release
      {
        Fault::Fault<dim> *fault;
        ~Release()
        {
          if (fault)
            fault->hold(false);
        }
      } release{hold ? fault : nullptr};
      if (release.fault)
        release.fault->hold(true);

      VectorType free_residual(residual), increment(residual),
        scratch(residual);

      state.displacement = old_u;
      if (predicted_increment)
        {
          // Only at the free DoFs: the prescribed ones follow their boundary
          // motion, the hanging ones their parents.
          scratch = *predicted_increment;
          discretization.increment_constraints().set_zero(scratch);
          state.displacement += scratch;
        }
      if (!hold)
        discretization.impose_kinematic_motion(state.displacement,
                                               state.displacement,
                                               state.time,
                                               state.time_step);
      discretization.distribute_hanging(state.displacement);

      double reference = 0;
      // The displacement that the step's force scale produces through the
      // stiffest diagonal entry: what round-off in the solve still resolves.
      double        displacement_scale = 0;
      double        increment_norm     = 0;
      double        increment_ratio    = 0;
      unsigned long last_signature     = 0;
      unsigned int  linear_iterations  = 0;
      report.last_linear_iterations    = 0;
      report.stick_crossings_limited   = 0;
      std::vector<double>        norms;
      std::vector<unsigned long> signatures;
      // The inexact Newton forcing term (<Solver/Newton forcing>).
      double eta       = controls.forcing;
      double last_norm = 0;
      // The line search leaves the residual of the new iterate behind.
      bool residual_current = false;
      for (unsigned int k = 0;; ++k)
        {
          if (!residual_current)
            {
              update_rates();
              compute_residual();
              free_residual = residual;
              discretization.increment_constraints().set_zero(free_residual);
            }
          residual_current  = false;
          const double norm = free_residual.l2_norm();
          // Every fault node sticks in this iterate (a collective test,
          // done once per iteration).
          const bool stuck = fault && fault->all_stuck();
          // Names the place and the likely cause, and stops the run.
          if (!std::isfinite(norm))
            check_finite(free_residual,
                         "force residual of Newton iteration " +
                           std::to_string(k));

          if (!fault)
            {
              // Linear: the first solve is exact up to the solver tolerance.
              if (k == 1)
                break;
            }
          else
            {
              const unsigned long signature = fault->status_signature();
              if (k == 0)
                {
                  // The force scale of the step: the residual may start tiny
                  // (a body near equilibrium), so the internal forces count.
                  system.apply_stiffness(old_u, scratch);
                  discretization.increment_constraints().set_zero(scratch);
                  // A prestressed fault at rest: the forces of its initial
                  // traction.
                  reference = std::max({norm,
                                        scratch.l2_norm(),
                                        fault->initial_force_norm(),
                                        1e-300});
                  displacement_scale =
                    reference /
                    std::max(system.max_effective_diagonal(), 1e-300);
                }
              else
                {
                  // The paper's two criteria (Fig. 6). A step in which every
                  // node stuck in this and the last iteration was linear, so
                  // its one solve is exact.
                  const double change = [&]() {
                    scratch = state.displacement;
                    scratch -= old_u;
                    return scratch.l2_norm();
                  }();
                  const bool force_ok =
                    norm <= controls.force_tolerance * reference;
                  // A step that changes the displacement very little (the
                  // first dynamic steps after a long loading phase: 1e-11 m
                  // on a field of metres; a fault creeping at 1e-20 m/s)
                  // cannot ask for a correction below what round-off in the
                  // penalty system still resolves: a correction below 1e-11
                  // of the whole displacement, or of the displacement the
                  // step's force scale produces, counts as converged.
                  const double round_off =
                    1e-11 *
                    std::max(state.displacement.l2_norm(), displacement_scale);
                  const bool displacement_ok =
                    increment_norm <=
                    std::max(controls.displacement_tolerance * change,
                             round_off);
                  increment_ratio   = increment_norm / std::max(change, 1e-300);
                  const bool linear = (signature == last_signature) && stuck;
                  if (force_ok && (displacement_ok || linear))
                    break;
                }
              // A step whose residual has not halved in the last <Newton
              // stall iterations> iterations is cycling (typically a few
              // nodes switching between stick and slip): give up at once, so
              // that the step is cut instead of iterating to the limit (only
              // where it can be cut: not in quasi-static steps, nor at the
              // last level of cuts).
              norms.push_back(norm);
              signatures.push_back(signature);
              const unsigned int window = controls.stall_iterations;
              const bool         stalled =
                report.may_cut && (window > 0) && (norms.size() > window) &&
                (*std::min_element(norms.end() - window, norms.end()) >
                 0.5 * *std::min_element(norms.begin(), norms.end() - window));
              if (k == controls.max_iterations || stalled)
                fail(stalled, norm, reference, increment_ratio, signatures);
              last_signature = signature;
            }

          if (fault && !linear_solver.matrix_free())
            {
              // Effective stiffness plus the contact tangent (nonsymmetric
              // where nodes slip), for this iteration only.
              scratch = 0;
              assemble_contact(scratch, true, +1);
              // The preconditioner is rebuilt when the pattern of stick, slip
              // and open nodes changes; in between GMRES solves with the
              // current tangent and the last preconditioner (with the fault
              // pair transform it holds its own copy of the matrix).
              const unsigned long signature = fault->status_signature();
              if (k == 0 || signature != report.preconditioner_signature ||
                  !linear_solver.keeps_own_matrix())
                {
                  TimerOutput::Scope t(timer, "Preconditioner set-up");
                  linear_solver.initialize(system.effective_matrix(),
                                           system.near_null_space(),
                                           false,
                                           discretization.degree() > 1);
                  report.preconditioner_signature = signature;
                }
            }
          // Where every fault node sticks the step is linear and one exact
          // solve (tolerance 0: <Linear solver tolerance>) ends it.
          const double linear_tolerance =
            (fault && linear_solver.matrix_free() && controls.forcing > 0 &&
             !stuck) ?
              forcing_tolerance(k,
                                norm,
                                last_norm,
                                controls.force_tolerance * reference,
                                // Multigrid meets a loose tolerance in one
                                // or two iterations, with directions that
                                // lead Newton astray at contact (the 10 km
                                // Northeast-Japan loading: no convergence
                                // at 0.1, 6 iterations at 1e-3).
                                system.use_multigrid_now() ?
                                  std::min(controls.forcing, 1e-3) :
                                  controls.forcing,
                                eta) :
              0.;
          last_norm = norm;
          increment = 0;
          {
            TimerOutput::Scope t(timer, "Linear solve");
            if (linear_solver.matrix_free())
              {
                // The contact tangent is that of the pairs' trial states, from
                // the last residual.
                if (system.use_multigrid_now())
                  {
                    TimerOutput::Scope t(timer, "Multigrid set-up");
                    const auto        &c = system.effective_factors();
                    system.multigrid_preconditioner()->set_operator(
                      c.stiffness,
                      c.mass,
                      fault ?
                        fault->pair_tangents() :
                        std::vector<
                          std::pair<std::array<types::global_dof_index, dim>,
                                    Tensor<2, dim>>>());
                  }
                else if (fault)
                  {
                    TimerOutput::Scope t(timer, "Block Jacobi");
                    fault->prepare_pair_preconditioner(
                      system.effective_diagonal(), system.free_dof_mask());
                  }
                linear_iterations = linear_solver.solve(
                  [this](const VectorType &x, VectorType &y) {
                    system.apply_system(x, y);
                  },
                  [this](const VectorType &r, VectorType &z) {
                    system.precondition_system(r, z);
                  },
                  !fault || stuck,
                  increment,
                  free_residual,
                  linear_tolerance);
              }
            else
              linear_iterations = linear_solver.solve(system.effective_matrix(),
                                                      increment,
                                                      free_residual);
            report.last_linear_iterations += linear_iterations;
            {
              const unsigned int p = (system.current_scheme() ==
                                      TimeIntegration::Scheme::quasi_static) ?
                                       0 :
                                       1;
              report.total_linear_iterations[p] += linear_iterations;
              ++report.n_linear_solves[p];
            }
          }
          if (fault && !linear_solver.matrix_free())
            {
              scratch = 0;
              assemble_contact(scratch, true, -1);
            }
          discretization.increment_constraints().distribute(increment);
          // Nodes that would jump across the stick region stop inside it
          // (Fault::limit_stick_crossings()).
          unsigned int n_limited = 0;
          if (fault && controls.limit_stick_crossings &&
              !report.stick_crossing_limit_suspended)
            {
              scratch   = 0;
              n_limited = fault->limit_stick_crossings(
                discretization.ghosted_copy(1, increment),
                discretization.increment_constraints(),
                scratch);
              report.stick_crossings_limited += n_limited;
              if (n_limited > 0)
                {
                  increment += scratch;
                  discretization.increment_constraints().distribute(increment);
                }
            }
          if (fault)
            {
              // Backtracking line search: slip weakening and changes between
              // stick and slip can make a full Newton step overshoot. A step
              // with limited stick crossings is taken in full: it is no longer
              // a Newton step, and it puts those nodes into stick, from where
              // the next iteration is exact for them; a shortened step would
              // leave them slipping and the limit would repeat.
              const VectorType u_iteration(state.displacement);
              double           alpha = 1;
              for (unsigned int trial = 0;; ++trial)
                {
                  state.displacement = u_iteration;
                  state.displacement.add(alpha, increment);
                  update_rates();
                  compute_residual();
                  free_residual = residual;
                  discretization.increment_constraints().set_zero(
                    free_residual);
                  if (free_residual.l2_norm() <= (1 - 1e-4 * alpha) * norm ||
                      trial == 6 || n_limited > 0)
                    break;
                  alpha *= 0.5;
                }
              increment *= alpha;
              residual_current = true;
              if (controls.print_iterations)
                {
                  const Fault::Statistics f = fault->statistics();
                  pcout << "      Newton " << k << ": residual "
                        << norm / reference
                        << ", linear solve: " << linear_iterations
                        << " iterations, residual "
                        << linear_solver.last_relative_residual()
                        << ", factorisations "
                        << linear_solver.n_factorizations() << ", line search "
                        << alpha;
                  if (controls.limit_stick_crossings &&
                      !report.stick_crossing_limit_suspended)
                    pcout << ", " << n_limited << " limited";
                  pcout << ", " << f.n_slipping << " slipping, " << f.n_open
                        << " open, pattern " << std::hex
                        << (signatures.back() & 0xffffff) << std::dec << "\n";
                }
            }
          else
            state.displacement += increment;
          increment_norm         = increment.l2_norm();
          report.last_iterations = k + 1;
        }
      check_finite(state.displacement, "displacement");
    }



    template <int dim>
    void
    Newton<dim>::fail(const bool                        stalled,
                      const double                      norm,
                      const double                      reference,
                      const double                      increment_ratio,
                      const std::vector<unsigned long> &signatures) const
    {
      const unsigned int      window = controls.stall_iterations;
      const Fault::Statistics f      = fault->statistics();
      std::ostringstream      message;
      message << "Newton's method did not converge in step " << state.step
              << " (t = " << state.clock.phase_time << " s): ";
      if (stalled)
        {
          std::vector<unsigned long> recent(signatures.end() - window,
                                            signatures.end());
          std::sort(recent.begin(), recent.end());
          const auto patterns =
            std::unique(recent.begin(), recent.end()) - recent.begin();
          message << "the force residual stalled at " << norm / reference
                  << " of its first value (wanted " << controls.force_tolerance
                  << ") and did not halve in the last " << window
                  << " iterations, which went through " << patterns
                  << " different patterns of stick, slip and open "
                     "fault nodes";
        }
      else
        message << "within " << controls.max_iterations
                << " iterations the force residual fell to " << norm / reference
                << " of its first value (wanted " << controls.force_tolerance
                << ")";
      if (norm <= controls.force_tolerance * reference)
        message << ", but the last correction was " << increment_ratio
                << " of the step's displacement change (wanted "
                << controls.displacement_tolerance
                << ", or below 1e-11 of the whole displacement or of "
                   "the displacement of the step's forces)";
      message << "; " << f.n_slipping << " slipping and " << f.n_open
              << " open fault nodes. ";
      // The effective stiffness without the contact (the matrix
      // has it added for each solve only).
      VectorType diagonal(system.effective_diagonal());
      if (!linear_solver.matrix_free())
        {
          diagonal.reinit(discretization.locally_owned_dofs(),
                          discretization.communicator());
          for (const auto i : discretization.locally_owned_dofs())
            diagonal(i) = system.effective_matrix().diag_element(i);
          diagonal.compress(VectorOperation::insert);
        }
      const unsigned int n_steep = fault->n_steeper_than_body(diagonal);
      std::string        reason =
        stalled ? "the residual stalled" : "too many iterations";
      if (f.unstable_softening)
        {
          message << "Slip weakening is steeper than the "
                     "tangential penalty at some nodes ((mu_0 - "
                     "mu_d) / L_d |T_n| > p_t), so their traction "
                     "drops to the residual strength at once: "
                     "raise <Fault/Tangential penalty> or L_d.";
          reason += "; weakening steeper than the penalty";
        }
      else if (n_steep > 0)
        {
          message << "At " << n_steep
                  << " slipping fault node(s) slip weakening is "
                     "steeper than the stiffness of the body that "
                     "holds them (the tangent is indefinite there): "
                     "reduce <Time integration/Time step> (the "
                     "inertia term stiffens as 1/dt^2), or raise "
                     "the slip-weakening distance or the mesh "
                     "resolution.";
          reason += "; weakening steeper than the body at " +
                    std::to_string(n_steep) + " node(s)";
        }
      else
        message << "Reduce <Time integration/Time step>, or raise "
                   "<Solver/Maximum Newton iterations> (or "
                   "<Solver/Newton stall iterations>).";
      throw Solver::NewtonFailure(message.str(), reason);
    }



    template class Newton<2>;
    template class Newton<3>;
  } // namespace Nonlinear
} // namespace rupture
