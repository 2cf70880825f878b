#include <rupture/adaptivity/fault_refinement.h>
#include <rupture/base/interruption.h>
#include <rupture/base/time_units.h>
#include <rupture/base/utilities.h>
#include <rupture/operators/multigrid.h>
#include <rupture/output/statistics_columns.h>
#include <rupture/simulator/simulator.h>

#include <deal.II/base/index_set.h>
#include <deal.II/base/utilities.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_nothing.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/mapping_q1.h>
#include <deal.II/hp/mapping_collection.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/sparsity_tools.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <sstream>


namespace rupture
{
  template <int dim>
  Simulator<dim>::Simulator(const MPI_Comm     communicator,
                            ParameterHandler  &prm,
                            const bool         resume,
                            const unsigned int refinements)
    : communicator(communicator)
    , pcout(log.stream(),
            dealii::Utilities::MPI::this_mpi_process(communicator) == 0)
    , timer(MPI_COMM_SELF, pcout, TimerOutput::never, TimerOutput::wall_times)
    , discretization(communicator)
    , elastic_system(discretization,
                     materials,
                     boundary_conditions,
                     time_parameters,
                     state,
                     linear_solver,
                     timer,
                     pcout,
                     communicator)
    , newton(state,
             discretization,
             elastic_system,
             linear_solver,
             timer,
             pcout,
             [this](const VectorType &v, const std::string &what) {
               check_finite(v, what);
             })
    , stable_time_step(0)
  {
    this->checkpoints.resume      = resume;
    this->checkpoints.refinements = refinements;
    parse_parameters(prm);
    if (resume)
      {
        // The newest complete checkpoint of this output directory, written
        // with the same parameters (before anything is built).
        checkpoints.resume_from = newest_checkpoint();
        AssertThrow(!checkpoints.resume_from.empty(),
                    ExcMessage("--resume: the output directory <" +
                               output_directory->name() +
                               "> holds no complete checkpoint "
                               "(checkpoint/step-*/state). Checkpoints are "
                               "written when <Checkpoint/Interval> or "
                               "<Checkpoint/Wall-clock interval> is set; run "
                               "without --resume to start anew."));
        check_checkpoint_parameters(prm);
        pcout << "Continuing from the checkpoint " << checkpoints.resume_from
              << "\n";
      }

    pcout << "rupture: " << dim << "-D, scheme "
          << time_parameters.scheme_name() << ", "
          << dealii::Utilities::MPI::n_mpi_processes(communicator)
          << " MPI rank(s)\n";
    if (mesh_refinement.enabled() && mesh_refinement.levels > 2)
      pcout
        << "   Note: <Mesh refinement/Levels> = " << mesh_refinement.levels
        << ". Below base cells more than four times the front's, TPV3's "
           "final slip came out 5.8 % too large (three levels below 750 "
           "m cells), and 4.1 % with a fixed mesh of the same finest "
           "cells in the same base: the coarse cells around the fine "
           "ones cause most of it, not the adaptation. Two levels below base "
           "cells at most four times the front's were within 0.5 % "
           "(doc/performance.md, \"TPV3 with three levels\").\n";

    record_memory("start");
    {
      TimerOutput::Scope t(timer, "Set up mesh");
      discretization.make_mesh(*scene,
                               materials,
                               checkpoints.resume ?
                                 checkpoints.resume_from + "/mesh" :
                                 std::string(),
                               pcout);
    }
    record_memory("mesh");
    setup_dofs();
    record_memory("DoFs and fault");
    AssertThrow(
      mesh_refinement.max_dofs == 0 ||
        mesh_refinement.max_dofs >= discretization.dof_handler().n_dofs(),
      ExcMessage(
        "<Mesh refinement/Maximum degrees of freedom> = " +
        std::to_string(static_cast<long long>(mesh_refinement.max_dofs)) +
        " is below the " +
        std::to_string(discretization.dof_handler().n_dofs()) +
        " degrees of freedom of the base mesh, which the "
        "adaptation never coarsens. Allowed: 0 (no limit) "
        "or at least the base mesh's."));
    assemble_physics_matrices();
    record_memory("operators");
    // A body force or initial conditions that are not finite at t = 0 are
    // input errors too (Elasticity::System::assemble_load() and
    // interpolate_initial_conditions() name the entry and the place).
    if (elastic_system.has_body_force())
      {
        VectorType load(discretization.locally_owned_dofs(), communicator);
        elastic_system.assemble_load(0, load);
      }
    interpolate_initial_conditions();
    // The dynamic phase after a loading phase is prepared only when the
    // loading ends: its step count is checked now (with a step of its own;
    // the explicit scheme's automatic step needs the loaded state's phase).
    if (time_parameters.loading_phase && time_parameters.time_step > 0)
      n_steps_of_phase(time_parameters.end_time, time_parameters.time_step);
    // Time functions that are not finite somewhere in the run.
    if (fault)
      fault->check_time_functions(time_parameters.end_time);

    // Everything that can reject the input has run; only now is the output
    // directory touched, so a bad input never destroys earlier results.
    prepare_output_directory(prm);
  }



  template <int dim>
  Simulator<dim>::~Simulator()
  {
    // The integrator holds references into this object: it goes first.
    integrator.reset();
    linear_solver.clear();
    // A run that stops with an error (a Newton or solver failure, a
    // non-finite value) still leaves the statistics of every step it
    // completed; statistics live on rank 0 only, so no communication.
    // Nothing is written if the input was refused (the output directory
    // was never touched).
    if (output_directory && output_directory->is_open() &&
        statistics.n_rows() > 0 &&
        dealii::Utilities::MPI::this_mpi_process(communicator) == 0)
      try
        {
          statistics.write();
        }
      catch (...)
        {}
  }



  template <int dim>
  void
  Simulator<dim>::prepare_output_directory(ParameterHandler &prm)
  {
    // Collective: the lock, and the removal of the earlier run's files.
    output_directory->open(checkpoints.resume);
    std::ostringstream parameters;
    prm.print_parameters(parameters, ParameterHandler::ShortPRM);
    checkpoints.parameters_text = parameters.str();
    if (dealii::Utilities::MPI::this_mpi_process(communicator) == 0)
      {
        log.attach_file(output_directory->record("log.txt"),
                        checkpoints.resume);
        output_directory->write("parameters.prm", checkpoints.parameters_text);
      }
    // Where the results go (not in test mode: the path is the machine's).
    if (!test_mode)
      pcout << "   Output directory: " << output_directory->absolute_name()
            << std::endl;
    // The time series keep their rows in scratch files of the directory,
    // on the process that writes them.
    if (dealii::Utilities::MPI::this_mpi_process(communicator) == 0)
      {
        statistics.keep_in_files(output_directory->record("statistics"),
                                 output_directory->record(".statistics.rows"));
        receivers->keep_series_in(*output_directory);
        if (fault)
          fault_output->keep_series_in(*output_directory);
      }
    else
      statistics.keep_no_rows();
    volume_output = std::make_unique<Output::VolumeOutput<dim>>(
      *output_directory, materials, volume_settings, communicator);
  }



  template <int dim>
  void
  Simulator<dim>::run()
  {
    // However the run ends once its output directory is open, its
    // summary.json says how.
    try
      {
        run_sequence();
      }
    catch (const Interruption::Stopped &stopped)
      {
        write_summary("interrupted", stopped.what());
        throw;
      }
    catch (const ExceptionBase &e)
      {
        write_failure_summary(Utilities::user_message(e));
        throw;
      }
    catch (const std::exception &e)
      {
        write_failure_summary(e.what());
        throw;
      }
  }



  template <int dim>
  void
  Simulator<dim>::write_failure_summary(const std::string &message)
  {
    // (Never a second exception while the first is on its way.)
    if (output_directory && output_directory->is_open())
      try
        {
          write_summary("failed", message);
        }
      catch (...)
        {}
  }



  template <int dim>
  void
  Simulator<dim>::run_sequence()
  {
    cost.wall_time_start   = MPI_Wtime();
    checkpoints.last_write = cost.wall_time_start;
    if (checkpoints.resume)
      run_continued();
    else
      run_from_start();
    finish_run();
  }



  template <int dim>
  void
  Simulator<dim>::run_continued()
  {
    // The state of the checkpoint's step, and the rest of the run: the
    // phase it was written in goes on from the step after it.
    read_checkpoint();
    if (checkpoints.refinements > 0)
      refine_continued_run();
    else if (discretization.weighted())
      repartition_continued_run();
    if (termination.any())
      pcout << termination.description() << "\n";
    pcout << "*** Continuing after step " << state.step
          << " (t = " << std::setprecision(6) << state.clock.phase_time << " s"
          << (time_parameters.loading_phase ?
                (state.clock.in_dynamic_phase ? " of the dynamic phase" :
                                                " of the loading phase") :
                "")
          << ")\n";
    if (time_parameters.loading_phase && state.clock.in_dynamic_phase)
      {
        // The dynamic phase's integrator and friction, without the resets
        // of its start (its state came from the checkpoint).
        prepare_phase(time_parameters.scheme,
                      time_parameters.time_step,
                      time_parameters.end_time,
                      state.clock.segment_first_step > 0);
        if (fault)
          fault->continue_dynamic_phase(state.clock.dynamic_start);
      }
    else if (state.clock.segment_first_step > 0)
      // A step size of the checkpoint's mesh (<Mesh refinement>), not the
      // phase's first.
      prepare_phase(current_scheme(),
                    requested_time_step(),
                    phase_duration(),
                    true);
    integrator->load(checkpoints.records);
    // A checkpoint of an implicit phase refined by --refine: as after an
    // adaptation, a loaded body's displacement moves into the finer mesh's
    // balance and the acceleration follows from the forces (without, the
    // energy balance of a dynamic phase did not close).
    if (checkpoints.refinements > 0 &&
        current_scheme() == TimeIntegration::Scheme::implicit_newmark)
      {
        const double energy_before = energy.kinetic + energy.strain;
        settle_on_new_mesh();
        refresh_step_forces();
        count_mesh_change_energy(energy_before);
      }
    run_phases(state.clock.steps_in_phase);
  }



  template <int dim>
  void
  Simulator<dim>::run_from_start()
  {
    initialize_state();
    // A mesh that follows the rupture starts refined where the fault slips
    // from the first step; the initial state is then that of the new mesh.
    // The wavefield criterion refines one level per adaptation, each from
    // the initial conditions interpolated on the mesh before: in a dynamic
    // first phase it adapts up to <Wavefield levels> times before the first
    // step, so that the initial waves start on the cells they need (not as
    // the interpolant of coarser cells, whose error the finer cells would
    // carry on).
    const unsigned int rounds =
      (mesh_refinement.wavefield &&
       current_scheme() != TimeIntegration::Scheme::quasi_static) ?
        mesh_refinement.wavefield_levels :
        1;
    for (unsigned int r = 0;
         r < rounds && mesh_refinement.enabled() &&
         adapt_mesh(phase_duration(), requested_time_step(), 0);
         ++r)
      {
        interpolate_initial_conditions();
        initialize_state();
        energy.remeshing = 0;
      }
    record_memory("initial state");

    std::vector<std::string> columns = {"Time step number",
                                        "Time (s)",
                                        "Time step size (s)",
                                        "Linear solver iterations",
                                        Output::Columns::kinetic_energy,
                                        Output::Columns::strain_energy,
                                        Output::Columns::external_work,
                                        Output::Columns::dissipated_energy,
                                        Output::Columns::balance_error,
                                        "Wall time (s)"};
    if (exact_displacement)
      columns.emplace_back(Output::Columns::l2_error);
    if (fault)
      for (const std::string c :
           {"Newton iterations",
            "Slipping fault nodes",
            "Open fault nodes",
            Output::Columns::slipping_area,
            Output::Columns::max_slip,
            Output::Columns::max_slip_rate,
            Output::Columns::seismic_moment,
            "Moment magnitude Mw (3-D only)",
            "Frictional dissipation (J)",
            "Work done on the fault: penalty springs plus friction (J)",
            "Mean normal traction on the fault (Pa, < 0 in compression)",
            Output::Columns::mean_shear_traction})
        columns.push_back(c);
    // Last, so that the columns before keep their numbers for scripts that
    // read them by position (the program reads them by name).
    if (elastic_system.has_absorbing())
      columns.emplace_back("Energy absorbed at the absorbing boundaries (J): "
                           "part of the dissipated energy");
    // A mesh that changes (<Mesh refinement>), after all others.
    if (mesh_refinement.enabled())
      for (const std::string c : {"Degrees of freedom",
                                  "Energy added by mesh changes (J)",
                                  "Mesh adaptation wall time (s)"})
        columns.push_back(c);
    // The friction law's state variables, after all others.
    if (fault)
      for (const auto &name : fault->friction().state_names())
        for (const std::string which : {"Minimum", "Maximum"})
          columns.push_back(which + " of the friction state " + name +
                            " over the fault");
    // With a loading phase the time column restarts at the start of the
    // dynamic phase: these say which phase a row is in, and its absolute
    // time.
    if (time_parameters.loading_phase)
      {
        columns.emplace_back("Phase (0: loading, 1: dynamic)");
        columns.emplace_back("Time since the start of the run (s)");
        // The loading phase's snapshots are a time series of their own.
        volume_output->start_series("loading", "solution-loading.pvd");
        if (fault)
          fault_output->start_loading_phase();
      }
    statistics.set_columns(columns);
    statistics.add_row(statistics_row());
    if (fault)
      fault_output->record(*fault, state.time);
    receivers->record(state.displacement, state.velocity, state.time);
    write_step_output(true);

    if (termination.any())
      pcout << termination.description() << "\n";
    termination.start_phase(!time_parameters.loading_phase);
    if (time_parameters.loading_phase)
      pcout << "*** Loading phase (quasi-static)\n";
    run_phases(0);
  }



  template <int dim>
  void
  Simulator<dim>::run_phases(const unsigned int steps_done)
  {
    // (The last step of a phase writes everything: run_phase() forces it.)
    if (!time_parameters.loading_phase || state.clock.in_dynamic_phase)
      {
        run_phase(time_parameters.end_time, false, steps_done);
        return;
      }
    const bool stop_when_weakening =
      fault && time_parameters.stop_loading_when_weakening;
    if (fault)
      fault->start_loading_phase();
    // A checkpoint of the step that ended the loading phase goes on with
    // the dynamic phase at once, as that run did.
    if (!(steps_done > 0 && stop_when_weakening && fault->n_weakening() > 0))
      run_phase(time_parameters.loading_end_time,
                stop_when_weakening,
                steps_done);
    // (A wall-clock limit may end the run in its loading phase.)
    if (outcome.reason == Termination::Reason::end_time)
      {
        start_dynamic_phase_after_loading();
        run_phase(time_parameters.end_time, false);
      }
  }



  template <int dim>
  void
  Simulator<dim>::start_dynamic_phase_after_loading()
  {
    // The end state of the loading phase is the initial state of the
    // dynamic phase: displacement, stress, fault tractions and slip
    // carry over; the body starts from rest (up to the boundary
    // velocities) with the acceleration of its current forces.
    const double start = state.time;
    pcout << "*** Dynamic phase (" << time_parameters.scheme_name()
          << ") from t = " << std::setprecision(6) << start << " s\n";
    prepare_phase(time_parameters.scheme,
                  time_parameters.time_step,
                  time_parameters.end_time);
    state.clock.start_dynamic_phase(start);
    volume_output->start_series("solution", "solution.pvd");
    output_schedule.next_output_time       = 0;
    output_schedule.next_fault_output_time = 0;
    if (fault)
      {
        fault->start_dynamic_phase(start);
        fault_output->start_dynamic_phase();
        fault_output->record(*fault, 0);
      }
    receivers->clear();
    receivers->record(state.displacement, state.velocity, 0);
    if (current_scheme() != TimeIntegration::Scheme::quasi_static)
      {
        state.velocity = 0;
        discretization.set_kinematic_velocity(state.velocity, state.time);
        VectorType load(discretization.locally_owned_dofs(), communicator);
        elastic_system.assemble_load(state.time, load);
        compute_acceleration(load);
        elastic_system.damping_force(state.velocity, energy.damping_force);
        if (elastic_system.has_absorbing())
          elastic_system.absorbing_force(state.velocity,
                                         energy.absorbing_force);
      }
    // The first snapshots of the dynamic phase's time series: its
    // initial state, at its time 0.
    write_step_output(true);
    termination.start_phase(true);
  }



  template <int dim>
  typename Simulator<dim>::EnergyVerdict
  Simulator<dim>::energy_verdict() const
  {
    const double kinetic = statistics.last(Output::Columns::kinetic_energy);
    const double strain  = statistics.last(Output::Columns::strain_energy);
    // The balance error relative to the largest energy in play.
    const double scale =
      std::max({std::abs(kinetic) + std::abs(strain),
                std::abs(energy.fault_work),
                std::abs(statistics.last(Output::Columns::external_work)),
                std::abs(statistics.last(Output::Columns::dissipated_energy)),
                std::abs(energy.initial),
                1e-300});
    // The implicit and quasi-static schemes close the budget to round-off
    // (trapezoidal rule); central difference only to O(dt^2).
    const double tolerance =
      (current_scheme() ==
       TimeIntegration::Scheme::explicit_central_difference) ?
        1e-2 :
        1e-8;
    return {statistics.last(Output::Columns::balance_error), scale, tolerance};
  }



  template <int dim>
  void
  Simulator<dim>::finish_run()
  {
    const double kinetic = statistics.last(Output::Columns::kinetic_energy);
    const double strain  = statistics.last(Output::Columns::strain_energy);
    const double work    = statistics.last(Output::Columns::external_work);
    const double dissipated =
      statistics.last(Output::Columns::dissipated_energy);
    const double balance = statistics.last(Output::Columns::balance_error);
    pcout << std::scientific << std::setprecision(6)
          << "Final state at t = " << state.clock.phase_time << " s";
    if (time_parameters.loading_phase)
      pcout << " of the dynamic phase (" << state.time
            << " s since the start of the run)";
    pcout << ":\n"
          << "   Initial energy       " << energy.initial << " J\n"
          << "   Kinetic energy       " << kinetic << " J\n"
          << "   Strain energy        " << strain << " J\n"
          << "   Work of loads        " << work << " J\n"
          << "   Dissipated energy    " << dissipated << " J\n";
    if (fault)
      {
        const Fault::Statistics f = fault->statistics();
        pcout << "   Fault work           " << energy.fault_work << " J\n"
              << "   Frictional energy    " << f.frictional_energy << " J\n"
              << "   Max slip             " << f.max_slip << " m\n"
              << "   Slipping nodes       " << f.n_slipping << " of "
              << f.n_nodes << "\n";
      }
    pcout << "   Max |displacement|   " << state.displacement.linfty_norm()
          << " m\n";
    if (exact_displacement)
      pcout << "   L2 error             "
            << statistics.last(Output::Columns::l2_error) << "\n";
    pcout << std::defaultfloat;
    const EnergyVerdict verdict = energy_verdict();
    pcout << "   Energy balance error below " << verdict.tolerance
          << " of the energy scale: " << (verdict.within() ? "yes" : "no")
          << "\n";
    if (elastic_system.multigrid_preconditioner())
      {
        // What multigrid is for: iteration counts that stay bounded.
        pcout << "   Krylov iterations per linear solve:";
        const char *names[] = {"quasi-static", "dynamic"};
        for (unsigned int p = 0; p < 2; ++p)
          if (newton.status().n_linear_solves[p] > 0)
            pcout << " " << std::fixed << std::setprecision(1)
                  << double(newton.status().total_linear_iterations[p]) /
                       newton.status().n_linear_solves[p]
                  << " (" << names[p] << ", "
                  << (p == 0 || linear_solver.multigrid_in_dynamic_steps() ?
                        "multigrid" :
                        "block Jacobi")
                  << ")" << std::defaultfloat;
        pcout << "\n";
        if (!test_mode)
          pcout << "   Multigrid: "
                << elastic_system.multigrid_preconditioner()->summary() << "\n";
      }
    if (!test_mode)
      {
        pcout << "   Energy balance error " << balance << " J\n";
        print_performance_summary();
        timer.print_summary();
      }
    write_summary(outcome.reason == Termination::Reason::end_time ?
                    "finished" :
                    "ended early",
                  outcome.message);
    if (!test_mode)
      pcout << "Results are in " << output_directory->absolute_name()
            << std::endl;
  }



  template <int dim>
  bool
  Simulator<dim>::run_phase(const double       duration,
                            const bool         stop_when_weakening,
                            const unsigned int steps_done)
  {
    // Steps are counted in the phase's own time: after a long loading
    // phase the absolute time has lost the digits of a short dynamic
    // phase (3e9 s + 0.3 s). A run continued from a checkpoint goes on
    // from the step after steps_done of the phase that started at
    // phase_start_time.
    TimeIntegration::PhaseClock &clock = state.clock;
    const double start = clock.begin_phase(state.time, steps_done);
    // (A phase whose mesh changed counts the steps of its segments.)
    // A step controller other than "fixed" chooses each step: the loop
    // then goes by time, one step at a time (n_steps is the step after
    // the current one until the last).
    const bool   adaptive = integrator->adaptive_steps();
    unsigned int n_steps  = adaptive ?
                              steps_done + 1 :
                              static_cast<unsigned int>(
                               clock.steps_of_phase(duration, state.time_step));
    pcout << "   Time step " << std::setprecision(6) << state.time_step << " s"
          << Utilities::readable_time(state.time_step, duration) << ", ";
    if (adaptive)
      pcout << "then chosen by the '" << time_parameters.step_controller.name
            << "' controller,";
    else
      pcout << n_steps;
    pcout << " steps to t = " << (start - state.clock.dynamic_start) + duration
          << " s"
          << Utilities::readable_time((start - state.clock.dynamic_start) +
                                        duration,
                                      duration)
          << "\n";
    const double loop_start = MPI_Wtime();
    // The time loop's wall time, for the performance summary, however the
    // phase ends.
    struct LoopTimer
    {
      double &seconds;
      double  start;
      ~LoopTimer()
      {
        seconds += MPI_Wtime() - start;
      }
    } loop_timer{cost.time_loop_seconds, loop_start};

    for (unsigned int i = steps_done + 1; i <= n_steps; ++i)
      {
        ++state.step;
        if (adaptive)
          {
            // The controller's step, the last one shortened (or a little
            // lengthened) to end at the phase's end.
            const double now  = state.time;
            const double left = (clock.phase_start_time + duration) - now;
            const double dt   = integrator->next_time_step();
            const bool   last = (left <= dt * (1 + 1e-9));
            state.time_step   = last ? left : dt;
            n_steps           = last ? i : i + 1;
            state.time        = clock.enter_adaptive_step(
              i, now, state.time_step, duration, last);
          }
        else
          // The time since the start of the dynamic phase, without the
          // round-off of the absolute time after a long loading phase.
          state.time = clock.enter_step(i, n_steps, duration, state.time_step);
        if (fault)
          fault->set_time(state.time);

        integrator->step();
        cost.dof_steps += discretization.dof_handler().n_dofs();
        cost.peak_dofs =
          std::max(cost.peak_dofs,
                   double(discretization.dof_handler().n_dofs()));
        check_finite(state.displacement, "displacement");
        // The displacement may still be finite when the energies computed
        // from it overflow: that is a blow-up too, and no value that is
        // not finite is ever written.
        const std::vector<double> row = statistics_row();
        check_finite(state.displacement,
                     "energy computed from the displacement",
                     !std::all_of(row.begin(), row.end(), [](double x) {
                       return std::isfinite(x);
                     }));
        check_explicit_energy_balance();
        statistics.add_row(row);
        if (fault)
          fault_output->record(*fault, state.clock.phase_time);
        receivers->record(state.displacement,
                          state.velocity,
                          state.clock.phase_time);

        // Early ends, and the peak slip rate of the watched phase.
        const Termination::Sample sample = termination_sample(row);
        if (!time_parameters.loading_phase || state.clock.in_dynamic_phase)
          outcome.peak_slip_rate =
            std::max(outcome.peak_slip_rate, sample.max_slip_rate);
        std::string               message;
        const Termination::Reason reason =
          termination.any() ? termination.check(sample, message) :
                              Termination::Reason::end_time;
        const bool ends_early = (reason != Termination::Reason::end_time);

        const bool stop = stop_when_weakening && fault->n_weakening() > 0;
        if (state.step % output_schedule.screen_interval == 0 || i == n_steps ||
            stop || ends_early)
          {
            pcout << "*** Step " << state.step << ": t = " << std::scientific
                  << std::setprecision(4) << state.clock.phase_time << " s"
                  << Utilities::readable_time(state.clock.phase_time, duration);
            if (state.clock.in_dynamic_phase)
              pcout << " (" << state.time << " s since the start of the run)";
            pcout << ", dt = " << std::setprecision(2) << state.time_step
                  << " s";
            if (fault)
              {
                const Fault::Statistics f = fault->statistics();
                pcout << "\n    ";
                if (!fault->uses_split_nodes())
                  pcout << "Newton: " << newton.status().last_iterations
                        << " iterations; ";
                pcout << "fault: " << f.n_slipping << " slipping, " << f.n_open
                      << " open nodes, max slip " << std::setprecision(3)
                      << f.max_slip << " m, max slip rate " << f.max_slip_rate
                      << " m/s";
              }
            if (!test_mode)
              {
                // (Adaptive steps: the fraction of the phase's time.)
                const double elapsed = MPI_Wtime() - cost.wall_time_start;
                const double done =
                  adaptive ?
                    std::max((state.time - clock.phase_start_time) / duration,
                             1e-300) :
                    double(i) / n_steps;
                const double left = adaptive ?
                                      elapsed * (1 - done) / done :
                                      elapsed / state.step * (n_steps - i);
                pcout << "  [" << std::fixed << std::setprecision(0)
                      << 100. * done << "%, " << std::setprecision(1) << left
                      << " s left]";
                if (current_scheme() !=
                    TimeIntegration::Scheme::explicit_central_difference)
                  pcout << "\n    Linear solver: "
                        << newton.status().last_linear_iterations
                        << " iterations";
              }
            pcout << std::defaultfloat << std::endl;
          }
        write_step_output(i == n_steps || stop || ends_early);
        // The mesh follows the rupture, from the first step of a phase on
        // (where a nucleation patch starts to slip), and at the step at
        // which the first fault node becomes active if no fault cell is
        // fine yet; the checkpoint of the step holds the new mesh.
        if (mesh_refinement.enabled() && i < n_steps && !stop && !ends_early &&
            (i == 1 ||
             mesh_refinement.due(state.step,
                                 state.clock.phase_time,
                                 state.time_step) ||
             fault_refinement->front_outside_fine_cells(
               state.clock.phase_time)) &&
            adapt_mesh(duration, requested_time_step(), i) && !adaptive)
          n_steps = static_cast<unsigned int>(
            clock.steps_of_phase(duration, state.time_step));
        // Every <Interval> steps, when write_step_output() found one asked
        // for (wall-clock interval, SIGUSR1), and at the end of the run.
        if (checkpoints_enabled() &&
            ((checkpoints.interval > 0 &&
              state.step % checkpoints.interval == 0) ||
             checkpoints.requested || i == n_steps || ends_early))
          write_checkpoint();
        if (ends_early)
          {
            outcome.reason  = reason;
            outcome.message = message;
            pcout << "*** The run ends early at t = " << std::setprecision(6)
                  << state.clock.phase_time << " s: " << message << std::endl;
            return false;
          }
        if (stop)
          {
            pcout << "   A bonded zone of the fault reached its strength at "
                  << "t = " << std::setprecision(6) << state.time
                  << " s: the loading phase ends.\n";
            return false;
          }
      }
    return true;
  }



  template <int dim>
  void
  Simulator<dim>::check_explicit_energy_balance() const
  {
    // Only steps above the stable limit (<Allow unstable time step>) can
    // blow up. Central differences miss the budget by O(dt^2), at most a
    // few per cent even there while the run is stable (doc/stability.md);
    // an error of half of all the energy in play is a blow-up that has not
    // overflowed yet.
    if (current_scheme() !=
          TimeIntegration::Scheme::explicit_central_difference ||
        !(state.time_step > stable_time_step))
      return;
    const double error = energy.balance_error();
    const double scale =
      std::max({std::abs(energy.kinetic) + std::abs(energy.strain),
                std::abs(energy.external_work),
                std::abs(energy.damping_dissipation),
                std::abs(energy.fault_work),
                std::abs(energy.initial)});
    if (!(scale > 0) || std::abs(error) <= 0.5 * scale)
      return;
    // (Collective: every rank has the same energies.)
    const std::string where = discretization.locate_largest(state.displacement);
    std::ostringstream message;
    message << "At step " << state.step << " (t = " << state.clock.phase_time
            << " s) the energy balance error is " << std::abs(error) / scale
            << " of the energy in play, with the displacement " << where
            << ": the explicit scheme is unstable, and the run was stopped "
               "before writing this step. Its time step is "
            << state.time_step << " s against the stable limit "
            << stable_time_step << " s. Reduce <Time integration/Time step>.";
    AssertThrow(false, ExcMessage(message.str()));
  }



  template <int dim>
  std::vector<double>
  Simulator<dim>::statistics_row() const
  {
    std::vector<double> row = {
      static_cast<double>(state.step),
      state.clock.phase_time,
      state.time_step,
      static_cast<double>(newton.status().last_linear_iterations),
      energy.kinetic,
      energy.strain,
      energy.external_work,
      energy.damping_dissipation,
      energy.balance_error(),
      test_mode ? 0. : MPI_Wtime() - cost.wall_time_start};
    if (exact_displacement)
      row.push_back(compute_l2_error(state.time));
    // One reduction over the fault for all its columns.
    const Fault::Statistics f =
      fault ? fault->statistics() : Fault::Statistics();
    if (fault)
      {
        const double mw = (dim == 3 && f.seismic_moment > 0) ?
                            2. / 3. * (std::log10(f.seismic_moment) - 9.1) :
                            0.;
        for (const double v :
             {static_cast<double>(newton.status().last_iterations),
              static_cast<double>(f.n_slipping),
              static_cast<double>(f.n_open),
              f.slipping_area,
              f.max_slip,
              f.max_slip_rate,
              f.seismic_moment,
              mw,
              f.frictional_energy,
              energy.fault_work,
              f.mean_normal_traction,
              f.mean_shear_traction})
          row.push_back(v);
      }
    if (elastic_system.has_absorbing())
      row.push_back(energy.absorbed);
    if (mesh_refinement.enabled())
      {
        row.push_back(
          static_cast<double>(discretization.dof_handler().n_dofs()));
        row.push_back(energy.remeshing);
        row.push_back(test_mode ? 0. : fault_refinement->seconds());
      }
    // The friction state's range, after all others.
    for (unsigned int i = 0; i < f.state_minimum.size(); ++i)
      {
        row.push_back(f.state_minimum[i]);
        row.push_back(f.state_maximum[i]);
      }
    if (time_parameters.loading_phase)
      {
        row.push_back(state.clock.in_dynamic_phase ? 1 : 0);
        row.push_back(state.time);
      }
    return row;
  }



  template <int dim>
  void
  Simulator<dim>::write_step_output(const bool force)
  {
    // Decided together: a signal may reach one rank only, and the clocks
    // of the ranks differ.
    const bool root =
      dealii::Utilities::MPI::this_mpi_process(communicator) == 0;
    // The third flag: a checkpoint is asked for (SIGUSR1 on any rank, or
    // rank 0's clock says <Checkpoint/Wall-clock interval> has passed),
    // written by run_phase() after this output.
    int flags[3] = {
      Interruption::requested(),
      root && (MPI_Wtime() - output_schedule.last_table_write >= 60.),
      (Interruption::take_checkpoint_request() ||
       (root && checkpoints.minutes > 0 &&
        MPI_Wtime() - checkpoints.last_write >= 60 * checkpoints.minutes)) ?
        1 :
        0};
    MPI_Allreduce(MPI_IN_PLACE, flags, 3, MPI_INT, MPI_MAX, communicator);
    const int signal      = flags[0];
    checkpoints.requested = flags[2] != 0;

    // The volume and the fault have intervals of their own: the fault's
    // files scale with the fault, so a large model may write its fault
    // often and its volume rarely. A forced output (the first and last
    // step, a stop on a signal) writes everything that is written at all.
    const bool all = force || signal != 0;
    const auto due = [&](const double interval, const double next) {
      return interval >= 0 &&
             (all || state.clock.phase_time >= next - 1e-9 * state.time_step);
    };
    const bool volume_due =
      due(output_schedule.interval, output_schedule.next_output_time);
    const bool fault_due = fault && due(output_schedule.fault_interval,
                                        output_schedule.next_fault_output_time);

    // Receiver series, the fault's tables and the statistics are small:
    // written at every output time, at the end and once a minute.
    if (!(all || volume_due || fault_due || flags[1] != 0))
      return;
    TimerOutput::Scope t(timer, "Output");
    receivers->write(*output_directory, state.time_step);
    if (volume_due)
      {
        volume_output->write(discretization.dof_handler(),
                             discretization.ghosted_copy(0, state.displacement),
                             discretization.ghosted_copy(1, state.velocity),
                             state.clock.phase_time,
                             state.step);
        output_schedule.next_output_time =
          state.clock.phase_time + output_schedule.interval;
      }
    if (fault_due)
      {
        fault_output->write_surface(*fault,
                                    *output_directory,
                                    state.clock.phase_time,
                                    state.step);
        output_schedule.next_fault_output_time =
          state.clock.phase_time + output_schedule.fault_interval;
      }
    if (fault)
      fault_output->write_tables(*fault,
                                 *output_directory,
                                 state.time_step,
                                 test_mode);
    if (root)
      statistics.write();
    output_schedule.last_table_write = MPI_Wtime();

    if (signal != 0)
      {
        if (checkpoints_enabled())
          write_checkpoint();
        std::ostringstream what;
        what << "Stopped by " << Interruption::signal_name(signal)
             << " after step " << state.step
             << " (t = " << state.clock.phase_time
             << " s). The results of every step done are written in "
             << output_directory->absolute_name() << ".";
        throw Interruption::Stopped(signal, what.str());
      }
  }



  template class Simulator<2>;
  template class Simulator<3>;
} // namespace rupture
