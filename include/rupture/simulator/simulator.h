#ifndef rupture_simulator_simulator_h
#define rupture_simulator_simulator_h

#include <rupture/adaptivity/parameters.h>
#include <rupture/discretization/discretization.h>
#include <rupture/elasticity/system.h>
#include <rupture/fault/fault.h>
#include <rupture/fault/fault_output.h>
#include <rupture/material/elastic_material.h>
#include <rupture/nonlinear/newton.h>
#include <rupture/operators/element_frequency.h>
#include <rupture/output/directory.h>
#include <rupture/output/log.h>
#include <rupture/output/output_schedule.h>
#include <rupture/output/receivers.h>
#include <rupture/output/run_cost.h>
#include <rupture/output/statistics.h>
#include <rupture/output/volume_output.h>
#include <rupture/scene/boundary_conditions.h>
#include <rupture/scene/initial_conditions.h>
#include <rupture/scene/scene.h>
#include <rupture/simulator/checkpoint_control.h>
#include <rupture/simulator/termination.h>
#include <rupture/solver/linear_solver.h>
#include <rupture/solver/newton.h>
#include <rupture/time_integration/energy_budget.h>
#include <rupture/time_integration/interface.h>
#include <rupture/time_integration/newmark.h>
#include <rupture/time_integration/time_state.h>

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/function_parser.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/timer.h>
#include <deal.II/distributed/tria.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/trilinos_vector.h>

#include <array>
#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace rupture
{
  namespace Adaptivity
  {
    template <int dim>
    class FaultRefinement;
  }

  using namespace dealii;

  /**
   * Drives a run: reads the parameters, builds the discretization
   * (Discretization::Discretization: mesh, DoFs, constraints) and the
   * elastic system on it (Elasticity::System), holds the state of the run
   * and steps it through its phases with the time integrators; writes the
   * outputs and checkpoints, and carries the state to a new mesh when the
   * mesh adapts. Physics (materials, scene, boundary conditions, fault,
   * friction), the time integration and the linear solver each live in their
   * own room; this class wires them together.
   *
   * The work is split over several files, as in ASPECT: simulator.cc (set
   * up and time loop), setup.cc (the DoFs and what depends on them),
   * assembly.cc (the phases: time step and integrator), time_stepping.cc
   * (initial state and energies), refine.cc and adapt.cc (a new mesh
   * during the run). The time integrators (TimeIntegration::Interface, one
   * class per scheme) step the state through the contracts of their
   * TimeIntegration::Context: the elastic system, the discretization's
   * constraints, and the nonlinear solve (Nonlinear::Newton).
   */
  template <int dim>
  class Simulator
  {
  public:
    using VectorType = TrilinosWrappers::MPI::Vector;

    /**
     * Set up a run from @p prm; with @p resume, continue the run of the
     * same parameters from the newest checkpoint in its output directory,
     * on the checkpoint's mesh refined @p refinements more times (the
     * command line's --refine).
     */
    Simulator(const MPI_Comm     communicator,
              ParameterHandler  &prm,
              const bool         resume      = false,
              const unsigned int refinements = 0);
    ~Simulator();

    /**
     * Declare every parameter of the program (all rooms).
     */
    static void
    declare_parameters(ParameterHandler &prm);

    void
    run();

  private:
    /// What the time integrators work with (built once per phase).
    TimeIntegration::Context<dim>
    integrator_context();

    // --- set up (simulator.cc) ---
    void
    parse_parameters(ParameterHandler &prm);
    /// A continued run on a finer mesh (--refine, refine.cc): refine the
    /// checkpoint's mesh, carry the fields and the fault's state over and
    /// set everything up again.
    void
    refine_continued_run();
    /// A continued run whose partition weighs the fault's cells
    /// (<Discretization/Fault cell weight>, refine.cc): deal.II's load()
    /// partitions the checkpoint's mesh by cells; partition it again with
    /// the weights, carry the fields and the fault's state over and set
    /// everything up again.
    void
    repartition_continued_run();
    /// The forces of the last step that the energy sums take up (as
    /// initialize_state() computes them), for the state as it is.
    void
    refresh_step_forces();
    /// The force the energy sums count as applied: @p load at free DoFs,
    /// at held DoFs (all in a quasi-static phase) the force the body is
    /// in balance with, K u (@p ku) + M a (@p ma) + damping + contact
    /// (time_stepping.cc).
    void
    set_applied_force(const VectorType &load,
                      const VectorType &ku,
                      const VectorType &ma);
    /// Refine and coarsen the mesh as flagged, carry the displacement,
    /// velocity and acceleration and the fault's state to the new mesh and
    /// set up its DoFs (refine.cc); the energy sums' forces are left to
    /// refresh_step_forces(). @p reflag may flag the next level of the same
    /// adaptation on each new mesh (Discretization::refine()): the state is
    /// then carried once through all of them, and only the last is set up.
    /// Returns the number of new fault pairs that had no old pair near.
    /// With @p carry_forces the energy sums' forces are carried as well
    /// (a repartition of the same mesh, where they stay exact).
    unsigned int
    execute_refinement(const std::function<bool()> &reflag       = {},
                       const bool                   carry_forces = false);
    /**
     * Adapt the mesh to the criteria of <Mesh refinement> after the
     * current step of the phase of @p duration (run with the requested
     * step @p requested_time_step), @p steps_done of its steps done: flag,
     * refine and coarsen, carry the state over, and set up the operators,
     * the time step and the integrator again. Returns whether the mesh
     * changed. With @p steps_done = 0, before the first step of a run, the
     * nodes that slip from the start (overstressed) count as active too.
     */
    bool
    adapt_mesh(const double       duration,
               const double       requested_time_step,
               const unsigned int steps_done);
    /// After an adaptation (or a --refine continuation) in the implicit
    /// dynamic phase of a run with a loading phase: the integrator moves
    /// the displacement into balance on the new mesh (<Mesh
    /// refinement/Balance after adaptation>); a failed solve leaves the
    /// interpolated state and says so.
    void
    balance_after_adaptation();
    /// Implicit Newmark on a new mesh (an adaptation, --refine): a loaded
    /// body's displacement balanced (balance_after_adaptation()), then the
    /// acceleration from the forces. Other schemes: nothing.
    void
    settle_on_new_mesh();
    /// The kinetic and strain energy of the state on the present mesh, and
    /// their change from @p energy_before (the old mesh's) added to
    /// EnergyBudget::remeshing.
    void
    count_mesh_change_energy(const double energy_before);
    /// The time step the current phase asks for (0: the explicit
    /// scheme's Courant fraction of the stable step).
    double
    requested_time_step() const
    {
      return (time_parameters.loading_phase && !state.clock.in_dynamic_phase) ?
               time_parameters.loading_time_step :
               time_parameters.time_step;
    }
    /// The duration of the current phase (the loading phase's until the
    /// dynamic phase has started).
    double
    phase_duration() const
    {
      return (time_parameters.loading_phase && !state.clock.in_dynamic_phase) ?
               time_parameters.loading_end_time :
               time_parameters.end_time;
    }
    /// Interpolate the initial displacement and velocity (with a fault's
    /// initial slip velocity); a value that is not finite is an input
    /// error. Runs before the output directory is touched.
    void
    interpolate_initial_conditions();
    /// The DoFs of the current mesh, the elastic system's operators on them,
    /// the state's vectors and the outputs (again after each change of the
    /// mesh).
    void
    setup_dofs();
    void
    prepare_output_directory(ParameterHandler &prm);

    // --- phases (assembly.cc) ---
    /// Assemble the elastic system of the mesh; with @p prepare_first_phase,
    /// the first phase's time step and integrator too.
    void
    assemble_physics_matrices(const bool prepare_first_phase = true);
    /// The number of steps of at most @p requested_time_step in a phase of
    /// @p duration; a count that is not 1 to 1e9 is an input error.
    double
    n_steps_of_phase(const double duration,
                     const double requested_time_step) const;
    /**
     * Set the time step of a phase of the run, tell the elastic system its
     * scheme, create its time integrator and let it build what its steps
     * need: the effective stiffness and its preconditioner (implicit,
     * quasi-static), or the diagonal (explicit, after the stability check
     * here). With @p within_phase, the mesh of the current phase changed:
     * the time step of the rest of its current segment (state.clock) and
     * the integrator are set up again, its state kept.
     */
    void
    prepare_phase(const TimeIntegration::Scheme scheme,
                  const double                  requested_time_step,
                  const double                  duration,
                  const bool                    within_phase = false);
    /**
     * Acceleration from M a = f - K u - C v - F_contact on the free DoFs.
     */
    void
    compute_acceleration(const VectorType &load);
    /**
     * Step over @p duration from the current time with the current scheme;
     * returns false if a stop criterion ended the phase early.
     */
    bool
    run_phase(const double       duration,
              const bool         stop_when_weakening,
              const unsigned int steps_done = 0);
    /// The load sequence of run(), which adds the summary of a run that
    /// stops by a signal or an error.
    void
    run_sequence();
    /// A new run: the initial state and output, then the phases.
    void
    run_from_start();
    /// A run continued from a checkpoint (--resume).
    void
    run_continued();
    /// The phases from the current one on (the loading phase, if any and
    /// not over, then the dynamic phase), the current one after
    /// @p steps_done of its steps.
    void
    run_phases(const unsigned int steps_done);
    /// summary.json of a run stopped by an error, if the output directory
    /// is open (never throws).
    void
    write_failure_summary(const std::string &message);
    /// The end of a run: the final state on the screen, summary.json.
    void
    finish_run();
    /// The hand-over from the loading phase to the dynamic phase.
    void
    start_dynamic_phase_after_loading();

    // Checkpoints (checkpoint.cc).
    CheckpointControl checkpoints;
    bool
    checkpoints_enabled() const
    {
      return checkpoints.interval > 0 || checkpoints.minutes > 0;
    }
    /// The newest complete checkpoint in the output directory, or "".
    std::string
    newest_checkpoint() const;
    /// Refuse a checkpoint written with other parameters, naming the entry.
    void
    check_checkpoint_parameters(ParameterHandler &prm) const;
    /// The fields a checkpoint holds.
    std::vector<VectorType *>
    checkpoint_fields();
    /// Write a checkpoint of the state after the current step. Collective.
    void
    write_checkpoint();
    /// Restore the state after the mesh and the DoFs are set up.
    void
    read_checkpoint();
    /// The explicit scheme's highest element frequency, remembered by
    /// cell shape across meshes.
    Operators::ElementFrequencies<dim> element_frequencies;
    double
    compute_l2_error(const double time) const;

    // --- time stepping (time_stepping.cc) ---
    void
    initialize_state();
    /**
     * The fault forces of the traction-at-split-node method in the initial
     * state, for the residual @p residual of the other forces, with the
     * lumped mass (the explicit steps use their effective diagonal).
     */
    void
    initial_split_node_force(const VectorType &residual, VectorType &force);
    /// Stop the run if @p v (the @p what of the step) is not finite, or
    /// @p overflowed, naming the place and the likely cause.
    void
    check_finite(const VectorType  &v,
                 const std::string &what,
                 const bool         overflowed = false) const;
    /// Stop an explicit run above the stable step whose energy balance
    /// error has grown to half of the energy in play.
    void
    check_explicit_energy_balance() const;

    // --- output (simulator.cc) ---
    /**
     * Write what is due after a step: the volume and the fault surface at
     * their intervals; receivers, fault tables and statistics with them
     * and at least once a minute of wall time. With @p force (the first
     * and last step) everything. Collective: it also looks for a SIGTERM or
     * SIGINT on any rank, and after one writes everything and throws
     * Interruption::Stopped.
     */
    void
    write_step_output(const bool force);
    std::vector<double>
    statistics_row() const;
    /// Wall time of the time steps per DoF-step, and the peak memory.
    void
    print_performance_summary() const;
    /**
     * Record the resident memory of all ranks now, at the end of set-up
     * stage @p stage, for the memory breakdown of the performance summary.
     * Collective.
     */
    void
    record_memory(const std::string &stage);

    MPI_Comm            communicator;
    Output::Log         log;
    ConditionalOStream  pcout;
    mutable TimerOutput timer;

    // Parameters.
    /// The output directory: its lock, manifest and atomic files.
    std::unique_ptr<Output::Directory> output_directory;
    bool                               test_mode;
    /// <Output>'s entries of the volume snapshots.
    typename Output::VolumeOutput<dim>::Settings volume_settings;
    TimeIntegration::Parameters                  time_parameters;
    /// The time integrator of the phase being run.
    std::unique_ptr<TimeIntegration::Interface<dim>> integrator;
    /// Its scheme.
    TimeIntegration::Scheme
    current_scheme() const
    {
      return integrator->scheme();
    }
    Scene::InitialConditions<dim>        initial_conditions;
    std::unique_ptr<FunctionParser<dim>> exact_displacement;

    // Components.
    std::unique_ptr<Scene::Interface<dim>>   scene;
    std::unique_ptr<Fault::Fault<dim>>       fault;
    std::unique_ptr<Fault::FaultOutput<dim>> fault_output;
    std::unique_ptr<Output::Receivers<dim>>  receivers;
    Material::ElasticMaterials               materials;
    /// The fastest phase speed of the model on the current mesh (spatial
    /// factors included; setup_dofs()).
    double                         fastest_wave_speed = 0;
    Scene::BoundaryConditions<dim> boundary_conditions;
    Solver::LinearSolver           linear_solver;

    /// The mesh, the elements, the DoFs and their constraints.
    Discretization::Discretization<dim> discretization;

    /// Displacement, velocity, acceleration, time, step, its number and
    /// the phase clock.
    TimeIntegration::TimeState state;
    /// The elastic body on the discretization: its operators, matrices,
    /// loads and the preconditioners of its effective stiffness. Declared
    /// after everything it refers to, so that it is destroyed first (its
    /// matrix-free operator subscribes to the DoF handler).
    Elasticity::System<dim> elastic_system;
    /// The nonlinear solve of an implicit or quasi-static step, its
    /// controls and what it reports (after the elastic system it solves
    /// with).
    Nonlinear::Newton<dim> newton;
    /// Early ends (the Termination subsection), why the run ended and the
    /// largest slip rate of the dynamic phase, for summary.json.
    Termination::Criteria termination;
    Termination::Outcome  outcome;
    /// The sample of the criteria after the current step (collective when
    /// the wall clock is watched).
    Termination::Sample
    termination_sample(const std::vector<double> &row) const;
    /**
     * Write <output>/summary.json: how the run ended (@p status
     * "finished", "ended early", "interrupted" or "failed", with
     * @p message), its size and cost, and the fault's outcome. Collective
     * unless @p status is "failed" (rank 0 then writes what it knows).
     */
    void
    write_summary(const std::string &status, const std::string &message);

    /**
     * The energy balance at the last step: its error (J), the largest
     * energy in play (J) and the scheme's relative tolerance (round-off
     * for the implicit and quasi-static schemes, O(dt^2) for central
     * differences).
     */
    struct EnergyVerdict
    {
      double error, scale, tolerance;
      bool
      within() const
      {
        return std::abs(error) < tolerance * scale;
      }
    };
    EnergyVerdict
           energy_verdict() const;
    double stable_time_step;
    /// The energy budget and the forces of its trapezoidal rule.
    TimeIntegration::EnergyBudget energy;
    /// Wall times, DoF-steps and memory of the run so far.
    Output::RunCost cost;
    /// When volume, fault surface, screen and tables are written.
    Output::OutputSchedule output_schedule;

    std::unique_ptr<Output::VolumeOutput<dim>> volume_output;
    Output::Statistics                         statistics;
    /// <Mesh refinement>: the mesh that follows the rupture.
    Adaptivity::Parameters mesh_refinement;
    /// Which cells the mesh that follows the rupture refines and
    /// coarsens, and how many adaptations it made (with <Mesh refinement>
    /// only).
    std::unique_ptr<Adaptivity::FaultRefinement<dim>> fault_refinement;
    /// What balance_after_adaptation() did: adaptations balanced, their
    /// Newton iterations, solves that failed.
    struct
    {
      unsigned int  adaptations = 0;
      unsigned long iterations  = 0;
      unsigned int  failures    = 0;
    } balance_report;
  };
} // namespace rupture

#endif
