#include <rupture/base/utilities.h>
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

namespace rupture
{
  template <int dim>
  void
  Simulator<dim>::declare_parameters(ParameterHandler &prm)
  {
    prm.declare_entry("Dimension",
                      "2",
                      Patterns::Integer(2, 3),
                      "Space dimension of the run: 2 (plane strain) or 3.");
    prm.declare_entry("Output directory",
                      "output",
                      Patterns::DirectoryName(),
                      "Directory for all results: log.txt, parameters.prm, "
                      "statistics, solution.pvd with solution/*.vtu. It is "
                      "created if missing; files of an earlier run in it are "
                      "overwritten only once the new input has been checked.");
    prm.declare_entry("Test mode",
                      "false",
                      Patterns::Bool(),
                      "Leave out timings, iteration counts and other output "
                      "that changes from machine to machine, so that the "
                      "screen output can be compared in the test suite.");

    prm.enter_subsection("Discretization");
    {
      prm.declare_entry("Initial global refinement",
                        "0",
                        Patterns::Integer(0, 12),
                        "Number of times each coarse cell of the scene is "
                        "refined (each halves the cell size).");
      prm.declare_entry(
        "Refinement region",
        "0",
        Patterns::Anything(),
        "Cells whose centre makes this function of position (x, y and, in "
        "3-D, z) positive are refined <Refinement region levels> more times "
        "after the global refinement, e.g. 'x < 1000 ? 1 : 0' or "
        "'abs(z) < 5000'. Neighbouring cells differ by at most one level; "
        "the hanging nodes between them are constrained. The fault must be "
        "refined alike on both sides: a region that ends on the fault is "
        "an error.");
      prm.declare_entry("Refinement region levels",
                        "0",
                        Patterns::Integer(0, 6),
                        "How many times the cells of <Refinement region> "
                        "are refined (each halves their size). 0 leaves the "
                        "mesh as the global refinement made it.");
      prm.declare_entry("Polynomial degree",
                        "1",
                        Patterns::Integer(1, 2),
                        "Degree of the FE_Q displacement elements: 1 "
                        "(trilinear, the paper's) or 2.");
      prm.declare_entry(
        "Stiffness operator",
        "matrix free",
        Patterns::Selection("matrix free|matrix"),
        "How products with the stiffness matrix K (residuals, energies, the "
        "explicit step) are formed. 'matrix free' stores no K: each product "
        "is computed cell by cell with sum factorisation (deal.II's "
        "MatrixFree), which needs far less memory and, for an explicit "
        "run, is the fastest. 'matrix' assembles and stores K (about 1 kB "
        "per DoF for trilinear elements in 3-D). Implicit and quasi-static "
        "runs store their system matrix for the linear solver either way; "
        "the choice only concerns K itself.");
      prm.declare_entry("Mass matrix",
                        "consistent",
                        Patterns::Selection("consistent|lumped"),
                        "Mass matrix of the implicit scheme. The explicit "
                        "scheme always uses the lumped (diagonal) mass from "
                        "Gauss-Lobatto quadrature.");
    }
    prm.leave_subsection();

    prm.enter_subsection("Damping");
    {
      prm.declare_entry("Rayleigh alpha",
                        "0",
                        Patterns::Double(0),
                        "Mass-proportional coefficient (1/s) of the Rayleigh "
                        "damping C = alpha M + beta K of the paper's eq. 13.");
      prm.declare_entry("Rayleigh beta",
                        "0",
                        Patterns::Double(0),
                        "Stiffness-proportional coefficient (s) of the "
                        "Rayleigh damping.");
    }
    prm.leave_subsection();

    prm.enter_subsection("Loads");
    {
      prm.declare_entry("Gravity",
                        "0",
                        Patterns::Double(0),
                        "Gravitational acceleration (m/s^2), pointing in the "
                        "negative direction of the last coordinate. The body "
                        "force is density times gravity.");
      prm.declare_entry("Body force",
                        "",
                        Patterns::Anything(),
                        "An extra body force (N/m^3) as a function of x, y "
                        "(, z) and t, one expression per component separated "
                        "by ';'. Empty for none. Used for manufactured "
                        "solutions.");
    }
    prm.leave_subsection();

    prm.enter_subsection("Initial conditions");
    {
      prm.declare_entry("Displacement",
                        "",
                        Patterns::Anything(),
                        "Initial displacement (m) as a function of x, y (, "
                        "z), one expression per component separated by ';'. "
                        "Empty for zero.");
      prm.declare_entry("Velocity",
                        "",
                        Patterns::Anything(),
                        "Initial velocity (m/s), in the same form. Empty for "
                        "zero.");
    }
    prm.leave_subsection();

    prm.enter_subsection("Verification");
    {
      prm.declare_entry("Exact displacement",
                        "",
                        Patterns::Anything(),
                        "The exact displacement (m) as a function of x, y (, "
                        "z) and t, if known; the L2 error against it is then "
                        "reported at every step. Empty for none.");
    }
    prm.leave_subsection();

    prm.enter_subsection("Output");
    {
      prm.declare_entry("Output interval",
                        "0",
                        Patterns::Double(),
                        "Simulated time (s) between volume outputs for "
                        "ParaView. 0 writes every step; a negative value "
                        "writes none.");
      prm.declare_entry("Screen output interval",
                        "1",
                        Patterns::Integer(1),
                        "Print the step line every this many steps.");
      prm.declare_entry(
        "Receivers",
        "",
        Patterns::Anything(),
        "Off-fault stations: 'name: x, y[, z]' entries separated by ';', "
        "e.g. 'body030st120dp000: 12000, 3000'. The displacement and "
        "velocity there (interpolated, global components) are recorded "
        "every step and written to <output>/<name>.dat with the columns 't "
        "x-disp x-vel y-disp y-vel [z-disp z-vel]', in the layout of the "
        "SCEC off-fault station files. After a loading phase the series "
        "starts with the dynamic phase. A point outside the mesh is an "
        "error.");
    }
    prm.leave_subsection();

    Scene::declare_parameters(prm);
    Fault::Fault<dim>::declare_parameters(prm);
    Fault::FaultOutput<dim>::declare_parameters(prm);
    Material::ElasticMaterials::declare_parameters(prm);
    Scene::BoundaryConditions<dim>::declare_parameters(prm);
    TimeIntegration::Parameters::declare_parameters(prm);
    Solver::LinearSolver::declare_parameters(prm);
    prm.enter_subsection("Solver");
    {
      prm.declare_entry("Newton force tolerance",
                        "1e-8",
                        Patterns::Double(0, 1),
                        "Newton's method (with a fault) has converged when "
                        "the force residual has fallen below this fraction "
                        "of its first value (or of the load) ...");
      prm.declare_entry("Newton displacement tolerance",
                        "1e-6",
                        Patterns::Double(0, 1),
                        "... and the last displacement increment is below "
                        "this fraction of the displacement change of the "
                        "step (the paper's two criteria, Fig. 6). A step in "
                        "which every fault node stuck in the last two "
                        "iterations is linear and needs only the first.");
      prm.declare_entry("Maximum step cuts",
                        "4",
                        Patterns::Integer(0, 20),
                        "When Newton's method fails in an implicit step, "
                        "the step is redone as two half steps, recursively, "
                        "up to this many times; then the run stops with a "
                        "diagnosis. 0 stops at the first failure. After a "
                        "cut, the following steps are taken as sub-steps of "
                        "the size that converged, which double again after "
                        "two steps without a cut; the output times stay "
                        "those of <Time integration/Time step>.");
      prm.declare_entry("Maximum Newton iterations",
                        "25",
                        Patterns::Integer(1),
                        "A step that has not converged after this many "
                        "Newton iterations stops the run with a diagnosis.");
      prm.declare_entry("Print Newton iterations",
                        "false",
                        Patterns::Bool(),
                        "Print every Newton iteration: the force residual "
                        "relative to its first value, the line-search step "
                        "length, the numbers of slipping and open fault "
                        "nodes, and a hash of the pattern of stick, slip "
                        "and open nodes (a repeating hash means cycling).");
      prm.declare_entry(
        "Newton predictor",
        "old displacement",
        Patterns::Selection(
          "constant velocity|constant acceleration|old displacement"),
        "Where Newton's method starts in an implicit dynamic step: the old "
        "displacement moved on with the old velocity, u + dt v ('constant "
        "velocity'), also with the old acceleration, u + dt v + dt^2/2 a "
        "('constant acceleration'), or the old displacement itself ('old "
        "displacement'). A sliding fault keeps sliding from a predictor "
        "that moves on; from the old displacement every node starts stuck. "
        "'constant velocity' needs fewer iterations (on "
        "northeast-japan-fault-coarse.prm 6 times fewer), but where a "
        "rupture is marginal Newton's method can converge to another "
        "solution of the step from there: a node that would stay stuck "
        "from the old displacement slips (doc/stability.md, Poisson ratio "
        "0.49: final slip 0.17 m against 0.061 m, explicit 0.063 m). So "
        "the default is 'old displacement', whose nodes slip only where "
        "equilibrium makes them (measured in doc/performance.md). "
        "Quasi-static steps start from the old displacement.");
      prm.declare_entry(
        "Limit stick crossings",
        "true",
        Patterns::Bool(),
        "Newton safeguard for penalty contact: a fault node that slips and "
        "whose full Newton update would carry it straight across the stick "
        "region into slip again (typically reversing its slip direction: a "
        "node coming to rest, whose penalty stiffness far exceeds the "
        "stiffness of the body around it) gets only the part of the update "
        "of its slip that ends inside the stick region; the other nodes get "
        "the full update, and the line search is skipped in that "
        "iteration. A step that fails to converge after limiting is tried "
        "once more without the limit before it is cut (a node whose "
        "solution does lie on the far side can cycle between the two "
        "sides otherwise). Without it such nodes jump from one side of the stick "
        "region to the other and only the global line search holds them, "
        "at the price of short steps for every node: on "
        "northeast-japan-fault-coarse.prm 6 times more Newton iterations "
        "(doc/performance.md).");
      prm.declare_entry(
        "Newton stall iterations",
        "6",
        Patterns::Integer(0),
        "Newton's method gives up on a step as soon as its force residual "
        "has not fallen below half of its best earlier value within this "
        "many iterations (it cycles, typically because a few fault nodes "
        "switch back and forth between stick and slip), so that the step is "
        "cut without iterating up to <Maximum Newton iterations>. Only in "
        "implicit dynamic steps that can still be cut (not in quasi-static "
        "steps, nor after <Maximum step cuts> cuts). 0 never gives up "
        "early.");
      prm.declare_entry(
        "Newton forcing",
        "0.1",
        Patterns::Double(0, 0.9),
        "Inexact Newton (matrix-free solves, <Preconditioner> = block "
        "Jacobi, with a fault): the Krylov solve of a Newton iteration stops "
        "at the relative residual eta_k = 0.9 (|F_k| / |F_k-1|)^2 "
        "(Eisenstat and Walker's second choice, with their safeguard), at "
        "most this value, at least <Linear solver tolerance>, and never "
        "tighter than what the force tolerance of the step still needs. "
        "Far from convergence a loose solve is enough; near it the "
        "forcing falls and Newton converges superlinearly. 0 solves every "
        "iteration to <Linear solver tolerance>.");
    }
    prm.leave_subsection();
  }



  template <int dim>
  Simulator<dim>::Simulator(const MPI_Comm communicator, ParameterHandler &prm)
    : communicator(communicator)
    , pcout(log.stream(),
            dealii::Utilities::MPI::this_mpi_process(communicator) == 0)
    , timer(MPI_COMM_SELF, pcout, TimerOutput::never, TimerOutput::wall_times)
    , triangulation(communicator,
                    typename Triangulation<dim>::MeshSmoothing(
                      Triangulation<dim>::smoothing_on_refinement |
                      Triangulation<dim>::smoothing_on_coarsening))
    , n_sides(1)
    , has_absorbing(false)
    , time(0)
    , time_step(0)
    , stable_time_step(0)
    , step(0)
    , initial_energy(0)
    , kinetic_energy(0)
    , strain_energy(0)
    , external_work(0)
    , damping_dissipation(0)
    , absorbed_energy(0)
    , fault_work(0)
    , last_linear_iterations(0)
    , last_newton_iterations(0)
    , wall_time_start(0)
    , next_output_time(0)
  {
    parse_parameters(prm);

    pcout << "rupture: " << dim << "-D, scheme "
          << time_parameters.scheme_name() << ", "
          << dealii::Utilities::MPI::n_mpi_processes(communicator)
          << " MPI rank(s)\n";

    record_memory("start");
    make_mesh();
    record_memory("mesh");
    setup_dofs();
    record_memory("DoFs and fault");
    assemble_physics_matrices();
    record_memory("operators");

    // Everything that can reject the input has run; only now is the output
    // directory touched, so a bad input never destroys earlier results.
    prepare_output_directory(prm);
  }



  template <int dim>
  Simulator<dim>::~Simulator()
  {
    linear_solver.clear();
    // A run that stops with an error (a Newton or solver failure, a
    // non-finite value) still leaves the statistics of every step it
    // completed; statistics live on rank 0 only, so no communication.
    // Nothing is written if the input was refused (the output directory
    // was never touched).
    if (output_prepared && statistics.n_rows() > 0 &&
        dealii::Utilities::MPI::this_mpi_process(communicator) == 0)
      try
        {
          statistics.write(output_directory + "/statistics");
        }
      catch (...)
        {}
    dof_handler.clear();
  }



  template <int dim>
  void
  Simulator<dim>::parse_parameters(ParameterHandler &prm)
  {
    output_directory = prm.get("Output directory");
    test_mode        = prm.get_bool("Test mode");

    prm.enter_subsection("Discretization");
    n_global_refinements = prm.get_integer("Initial global refinement");
    n_region_refinements = prm.get_integer("Refinement region levels");
    refinement_region =
      Utilities::parse_function<dim>(prm.get("Refinement region"),
                                     1,
                                     "Discretization/Refinement region",
                                     dim == 2 ? "x,y" : "x,y,z");
    fe_degree             = prm.get_integer("Polynomial degree");
    use_lumped_mass       = (prm.get("Mass matrix") == "lumped");
    stiffness_matrix_free = (prm.get("Stiffness operator") == "matrix free");
    prm.leave_subsection();

    prm.enter_subsection("Damping");
    rayleigh_alpha = prm.get_double("Rayleigh alpha");
    rayleigh_beta  = prm.get_double("Rayleigh beta");
    prm.leave_subsection();

    prm.enter_subsection("Loads");
    gravity        = prm.get_double("Gravity");
    has_body_force = !dealii::Utilities::trim(prm.get("Body force")).empty();
    body_force     = Utilities::parse_function<dim>(prm.get("Body force"),
                                                dim,
                                                "Loads/Body force");
    prm.leave_subsection();

    prm.enter_subsection("Initial conditions");
    initial_displacement =
      Utilities::parse_function<dim>(prm.get("Displacement"),
                                     dim,
                                     "Initial conditions/Displacement");
    initial_velocity =
      Utilities::parse_function<dim>(prm.get("Velocity"),
                                     dim,
                                     "Initial conditions/Velocity");
    prm.leave_subsection();

    prm.enter_subsection("Verification");
    if (!dealii::Utilities::trim(prm.get("Exact displacement")).empty())
      exact_displacement =
        Utilities::parse_function<dim>(prm.get("Exact displacement"),
                                       dim,
                                       "Verification/Exact displacement");
    prm.leave_subsection();

    prm.enter_subsection("Output");
    output_interval = prm.get_double("Output interval");
    screen_interval = prm.get_integer("Screen output interval");
    receivers = std::make_unique<Output::Receivers<dim>>(prm.get("Receivers"),
                                                         communicator);
    prm.leave_subsection();

    prm.enter_subsection("Solver");
    newton_force_tolerance = prm.get_double("Newton force tolerance");
    newton_displacement_tolerance =
      prm.get_double("Newton displacement tolerance");
    max_newton_iterations   = prm.get_integer("Maximum Newton iterations");
    max_step_cuts           = prm.get_integer("Maximum step cuts");
    newton_stall_iterations = prm.get_integer("Newton stall iterations");
    newton_forcing          = prm.get_double("Newton forcing");
    print_newton_iterations = prm.get_bool("Print Newton iterations");
    newton_predictor        = prm.get("Newton predictor");
    limit_stick_crossings   = prm.get_bool("Limit stick crossings");
    prm.leave_subsection();

    time_parameters.parse_parameters(prm);
    if (time_parameters.scheme ==
        TimeIntegration::Scheme::explicit_central_difference)
      use_lumped_mass = true;
    materials.parse_parameters(prm);
    linear_solver.parse_parameters(prm);

    scene = Scene::create<dim>(prm);
    fault = Fault::Fault<dim>::create(prm);
    if (fault)
      {
        fault_output = std::make_unique<Fault::FaultOutput<dim>>();
        fault_output->parse_parameters(prm);
      }
    n_sides = fault ? 2 : 1;
    if (fault)
      {
        const bool is_explicit =
          (time_parameters.scheme ==
           TimeIntegration::Scheme::explicit_central_difference);
        AssertThrow(fault->uses_split_nodes() || !is_explicit,
                    ExcMessage(
                      "<Fault/Model> = penalty contact works with the "
                      "implicit Newmark and quasi-static schemes, not with "
                      "<Time integration/Scheme> = explicit central "
                      "difference. For the explicit scheme choose <Fault/"
                      "Model> = traction at split nodes."));
        AssertThrow(!fault->uses_split_nodes() || is_explicit,
                    ExcMessage(
                      "<Fault/Model> = traction at split nodes works with "
                      "<Time integration/Scheme> = explicit central "
                      "difference only. For the implicit Newmark or "
                      "quasi-static scheme choose <Fault/Model> = penalty "
                      "contact."));
        AssertThrow(!fault->uses_split_nodes() ||
                      !time_parameters.loading_phase,
                    ExcMessage(
                      "<Fault/Model> = traction at split nodes cannot run "
                      "the quasi-static <Time integration/Loading phase>: "
                      "a static fault needs penalty contact. Disable the "
                      "loading phase and give the prestress by <Fault/"
                      "Initial traction>, or use <Fault/Model> = penalty "
                      "contact with the implicit scheme."));
      }
    boundary_conditions.parse_parameters(prm, scene->get_boundary_names());
    has_absorbing = !boundary_conditions.absorbing.empty();
    AssertThrow(!(has_absorbing && time_parameters.scheme ==
                                     TimeIntegration::Scheme::quasi_static),
                ExcMessage("<Boundary conditions/Absorbing> is set, but "
                           "absorbing boundaries act on velocities and have "
                           "no meaning in a quasi-static run. Remove them "
                           "or choose a dynamic scheme."));
  }



  template <int dim>
  void
  Simulator<dim>::make_mesh()
  {
    TimerOutput::Scope t(timer, "Set up mesh");
    scene->create_coarse_mesh(triangulation);
    for (const auto &cell : triangulation.active_cell_iterators())
      materials.check_material_id(cell->material_id());
    triangulation.refine_global(n_global_refinements);
    for (unsigned int level = 0; level < n_region_refinements; ++level)
      {
        std::string bad_centre;
        for (const auto &cell : triangulation.active_cell_iterators())
          if (cell->is_locally_owned())
            {
              const double value = refinement_region->value(cell->center());
              if (!std::isfinite(value) && bad_centre.empty())
                {
                  std::ostringstream where;
                  where << "(" << cell->center() << ")";
                  bad_centre = where.str();
                }
              if (value > 0)
                cell->set_refine_flag();
            }
        // Every process stops, not only the one that found the value.
        AssertThrow(dealii::Utilities::MPI::max(bad_centre.empty() ? 0 : 1,
                                                communicator) == 0,
                    ExcMessage("<Discretization/Refinement region> is not a "
                               "finite number at the cell centre " +
                               (bad_centre.empty() ? std::string("of a cell "
                                                                 "of another "
                                                                 "process") :
                                                     bad_centre) +
                               ". Allowed are expressions that are finite "
                               "everywhere in the model."));
        triangulation.execute_coarsening_and_refinement();
      }

    std::vector<double> cells_per_material(materials.n_materials(), 0.);
    for (const auto &cell : triangulation.active_cell_iterators())
      if (cell->is_locally_owned())
        cells_per_material[cell->material_id()] += 1;
    MPI_Allreduce(MPI_IN_PLACE,
                  cells_per_material.data(),
                  cells_per_material.size(),
                  MPI_DOUBLE,
                  MPI_SUM,
                  communicator);
    pcout << "   Mesh: " << triangulation.n_global_active_cells()
          << " cells (per material id:";
    for (const double n : cells_per_material)
      pcout << " " << static_cast<unsigned long>(n);
    pcout << ")\n" << materials.summary();
  }



  template <int dim>
  void
  Simulator<dim>::setup_dofs()
  {
    TimerOutput::Scope t(timer, "Set up DoFs");

    // One displacement field per side: component s*dim + c is component c
    // on side s, and FE_Nothing gives the other side no DoFs on a cell.
    fe_collection = hp::FECollection<dim>();
    if (!fault)
      fe_collection.push_back(FESystem<dim>(FE_Q<dim>(fe_degree), dim));
    else
      {
        fe_collection.push_back(
          FESystem<dim>(FE_Q<dim>(fe_degree), dim, FE_Nothing<dim>(), dim));
        fe_collection.push_back(
          FESystem<dim>(FE_Nothing<dim>(), dim, FE_Q<dim>(fe_degree), dim));
      }
    dof_handler.reinit(triangulation);
    if (fault)
      for (const auto &cell : dof_handler.active_cell_iterators())
        if (cell->is_locally_owned())
          cell->set_active_fe_index(fault->side(cell));
    dof_handler.distribute_dofs(fe_collection);

    locally_owned_dofs = dof_handler.locally_owned_dofs();
    DoFTools::extract_locally_relevant_dofs(dof_handler, locally_relevant_dofs);

    hanging_constraints.clear();
    hanging_constraints.reinit(locally_relevant_dofs);
    DoFTools::make_hanging_node_constraints(dof_handler, hanging_constraints);
    if (fault)
      {
        std::vector<double> shear_modulus;
        for (unsigned int m = 0; m < materials.n_materials(); ++m)
          shear_modulus.push_back(materials.get(m).mu);
        fault->setup(dof_handler,
                     locally_owned_dofs,
                     locally_relevant_dofs,
                     hanging_constraints,
                     shear_modulus,
                     communicator);
      }
    hanging_constraints.close();
    hanging_distributor.reinit(hanging_constraints,
                               locally_owned_dofs,
                               communicator);

    // Kinematic boundary conditions: collect the constrained DoFs of each
    // named boundary (first condition wins where boundaries meet).
    increment_constraints.clear();
    increment_constraints.reinit(locally_relevant_dofs);
    kinematic_dofs.clear();
    for (const auto &bc : boundary_conditions.kinematic)
      for_each_support_point(
        [&](const auto &cell) {
          if (cell->is_artificial())
            return false;
          for (const auto f : cell->face_indices())
            if (cell->face(f)->at_boundary() &&
                cell->face(f)->boundary_id() == bc.id)
              return true;
          return false;
        },
        [&](const auto                                 &cell,
            const std::vector<types::global_dof_index> &dofs,
            const std::vector<Point<dim>>              &points) {
          const auto &fe = cell->get_fe();
          for (const auto f : cell->face_indices())
            if (cell->face(f)->at_boundary() &&
                cell->face(f)->boundary_id() == bc.id)
              for (unsigned int i = 0; i < dofs.size(); ++i)
                {
                  if (!fe.has_support_on_face(i, f))
                    continue;
                  const unsigned int c =
                    fe.system_to_component_index(i).first % dim;
                  const auto dof = dofs[i];
                  if (!bc.components[c] ||
                      increment_constraints.is_constrained(dof) ||
                      hanging_constraints.is_constrained(dof))
                    continue;
                  increment_constraints.add_line(dof);
                  if (locally_owned_dofs.is_element(dof))
                    kinematic_dofs.push_back(
                      {dof, c, points[i], bc.velocity.get()});
                }
        });
    increment_constraints.merge(
      hanging_constraints,
      AffineConstraints<double>::MergeConflictBehavior::left_object_wins);
    increment_constraints.close();

    using Scheme        = TimeIntegration::Scheme;
    const Scheme scheme = time_parameters.scheme;
    // The matrix-free solver applies the system and the consistent mass
    // through the elastic operator instead.
    const bool matrix_free_system = linear_solver.matrix_free();
    AssertThrow(!matrix_free_system || stiffness_matrix_free,
                ExcMessage("<Solver/Preconditioner> = block Jacobi stores no "
                           "matrix and needs <Discretization/Stiffness "
                           "operator> = matrix free."));
    const bool needs_system_matrix =
      (scheme != Scheme::explicit_central_difference ||
       time_parameters.loading_phase) &&
      !matrix_free_system;
    const bool needs_mass_matrix =
      (scheme == Scheme::implicit_newmark && !use_lumped_mass) &&
      !matrix_free_system;

    // The sparsity pattern, only if some matrix is stored (an explicit run
    // with the matrix-free operator stores none).
    DynamicSparsityPattern dsp;
    if (!stiffness_matrix_free || needs_system_matrix || needs_mass_matrix)
      {
        dsp.reinit(locally_relevant_dofs.size(),
                   locally_relevant_dofs.size(),
                   locally_relevant_dofs);
        DoFTools::make_sparsity_pattern(dof_handler,
                                        dsp,
                                        hanging_constraints,
                                        true);
        if (fault)
          fault->add_sparsity(dsp);
        SparsityTools::distribute_sparsity_pattern(dsp,
                                                   locally_owned_dofs,
                                                   communicator,
                                                   locally_relevant_dofs);
      }
    // A scene pays only for what it uses: no mass matrix without inertia or
    // with lumping, no system matrix (hence no solver) in explicit runs.
    if (stiffness_matrix_free)
      {
        stiffness_matrix.clear();
        setup_matrix_free_stiffness();
      }
    else
      stiffness_matrix.reinit(locally_owned_dofs,
                              locally_owned_dofs,
                              dsp,
                              communicator);
    if (needs_mass_matrix)
      mass_matrix.reinit(locally_owned_dofs,
                         locally_owned_dofs,
                         dsp,
                         communicator);
    else
      mass_matrix.clear();
    // The preconditioner and the direct solver's factors refer to the old
    // matrix.
    linear_solver.clear();
    if (needs_system_matrix)
      system_matrix.reinit(locally_owned_dofs,
                           locally_owned_dofs,
                           dsp,
                           communicator);
    else
      system_matrix.clear();

    for (VectorType *v : {&displacement,
                          &velocity,
                          &acceleration,
                          &applied_force,
                          &damping_force,
                          &contact_force,
                          &constant_load})
      v->reinit(locally_owned_dofs, communicator);
    if (use_lumped_mass)
      lumped_mass.reinit(locally_owned_dofs, communicator);
    if (has_absorbing)
      absorbing_damping.reinit(locally_owned_dofs, communicator);
    for (VectorType *v : {&stiffness_diagonal,
                          &consistent_mass_diagonal,
                          &system_diagonal,
                          &free_dofs,
                          &system_work})
      v->clear();
    if (matrix_free_system && (scheme != Scheme::explicit_central_difference ||
                               time_parameters.loading_phase))
      {
        TimerOutput::Scope                         t(timer, "System diagonal");
        LinearAlgebra::distributed::Vector<double> k, m;
        elastic_operator->compute_diagonals(k, m);
        for (VectorType *v :
             {&stiffness_diagonal, &consistent_mass_diagonal, &free_dofs})
          v->reinit(locally_owned_dofs, communicator);
        const unsigned int n = k.locally_owned_size();
        std::copy(k.begin(), k.begin() + n, stiffness_diagonal.begin());
        std::copy(m.begin(), m.begin() + n, consistent_mass_diagonal.begin());
        for (const auto i : locally_owned_dofs)
          free_dofs(i) = increment_constraints.is_constrained(i) ? 0. : 1.;
        free_dofs.compress(VectorOperation::insert);
      }

    pcout << "   Degrees of freedom: " << dof_handler.n_dofs() << "\n";
    if (fault)
      pcout << "   Fault: " << fault->n_split_nodes() << " split node pairs, "
            << fault->n_welded_nodes() << " welded interface nodes\n";
    receivers->setup(dof_handler, locally_owned_dofs);
    // The rigid-body modes are the near null space of the algebraic
    // multigrid: only runs with a system matrix need them.
    null_space.clear();
    if (needs_system_matrix)
      null_space = rigid_body_modes();
    if (fault)
      {
        fault_output->setup(*fault, communicator);
        if (!fault->uses_split_nodes() && system_matrix.m() > 0)
          linear_solver.set_fault_pairs(fault->dof_pairs(),
                                        locally_owned_dofs,
                                        communicator);
      }
  }



  template <int dim>
  void
  Simulator<dim>::prepare_output_directory(ParameterHandler &prm)
  {
    if (dealii::Utilities::MPI::this_mpi_process(communicator) == 0)
      {
        std::error_code error;
        std::filesystem::create_directories(output_directory + "/solution",
                                            error);
        AssertThrow(!error,
                    ExcMessage("The output directory <" + output_directory +
                               "> cannot be created: " + error.message()));
        log.attach_file(output_directory + "/log.txt");
        std::ostringstream parameters;
        prm.print_parameters(parameters, ParameterHandler::ShortPRM);
        Utilities::write_file_atomically(output_directory + "/parameters.prm",
                                         parameters.str());
      }
    MPI_Barrier(communicator);
    output_prepared = true;
    volume_output =
      std::make_unique<Output::VolumeOutput<dim>>(output_directory,
                                                  materials,
                                                  communicator);
  }



  template <int dim>
  void
  Simulator<dim>::run()
  {
    wall_time_start = MPI_Wtime();
    initialize_state();
    record_memory("initial state");

    std::vector<std::string> columns = {
      "Time step number",
      "Time (s)",
      "Time step size (s)",
      "Linear solver iterations",
      "Kinetic energy (J)",
      "Strain energy (J)",
      "Work of loads and boundary reactions (J)",
      "Energy dissipated by damping and "
      "absorbing boundaries (J)",
      "Energy balance error (J): kinetic + "
      "strain + dissipated + fault work - work - initial "
      "energy",
      "Wall time (s)"};
    if (exact_displacement)
      columns.emplace_back("L2 error of the displacement (m m^(dim/2))");
    if (fault)
      for (const std::string c :
           {"Newton iterations",
            "Slipping fault nodes",
            "Open fault nodes",
            "Slipping area (m^2, m in 2-D)",
            "Maximum slip (m)",
            "Maximum slip rate (m/s)",
            "Seismic moment (N m, N in 2-D)",
            "Moment magnitude Mw (3-D only)",
            "Frictional dissipation (J)",
            "Work done on the fault: penalty springs plus friction (J)",
            "Mean normal traction on the fault (Pa, < 0 in compression)",
            "Mean shear traction on the fault (Pa)"})
        columns.push_back(c);
    // Last, so that the columns before keep their numbers.
    if (has_absorbing)
      columns.emplace_back("Energy absorbed at the absorbing boundaries (J): "
                           "part of the dissipated energy");
    statistics.set_columns(columns);
    statistics.add_row(statistics_row());
    if (fault)
      fault_output->record(*fault, time);
    receivers->record(displacement, velocity, time);
    write_step_output(true);

    if (time_parameters.loading_phase)
      {
        pcout << "*** Loading phase (quasi-static)\n";
        if (fault)
          fault->start_loading_phase();
        run_phase(time_parameters.loading_end_time,
                  fault && time_parameters.stop_loading_when_weakening);

        // The end state of the loading phase is the initial state of the
        // dynamic phase: displacement, stress, fault tractions and slip
        // carry over; the body starts from rest (up to the boundary
        // velocities) with the acceleration of its current forces.
        const double start = time;
        current_scheme     = time_parameters.scheme;
        pcout << "*** Dynamic phase (" << time_parameters.scheme_name()
              << ") from t = " << std::setprecision(6) << start << " s\n";
        prepare_phase(current_scheme,
                      time_parameters.time_step,
                      time_parameters.end_time);
        dynamic_start = start;
        if (fault)
          {
            fault->start_dynamic_phase(start);
            fault_output->start_dynamic_phase();
            fault_output->record(*fault, 0);
          }
        receivers->clear();
        receivers->record(displacement, velocity, 0);
        if (current_scheme != TimeIntegration::Scheme::quasi_static)
          {
            velocity = 0;
            set_kinematic_velocity(velocity);
            VectorType load(locally_owned_dofs, communicator);
            assemble_load_vector(time, load);
            compute_acceleration(load);
            compute_damping_force(velocity, damping_force);
            if (has_absorbing)
              compute_absorbing_force(velocity, absorbing_force);
          }
        run_phase(time_parameters.end_time, false);
      }
    else
      run_phase(time_parameters.end_time, false);

    if (fault)
      fault_output->write_tables(*fault,
                                 output_directory,
                                 time_step,
                                 test_mode);
    if (dealii::Utilities::MPI::this_mpi_process(communicator) == 0)
      statistics.write(output_directory + "/statistics");

    const auto &last = statistics.last_row();
    pcout << std::scientific << std::setprecision(6)
          << "Final state at t = " << time << " s:\n"
          << "   Initial energy       " << initial_energy << " J\n"
          << "   Kinetic energy       " << last[4] << " J\n"
          << "   Strain energy        " << last[5] << " J\n"
          << "   Work of loads        " << last[6] << " J\n"
          << "   Dissipated energy    " << last[7] << " J\n";
    if (fault)
      {
        const Fault::Statistics f = fault->statistics();
        pcout << "   Fault work           " << fault_work << " J\n"
              << "   Frictional energy    " << f.frictional_energy << " J\n"
              << "   Max slip             " << f.max_slip << " m\n"
              << "   Slipping nodes       " << f.n_slipping << " of "
              << f.n_nodes << "\n";
      }
    pcout << "   Max |displacement|   " << displacement.linfty_norm() << " m\n";
    if (exact_displacement)
      pcout << "   L2 error             " << last[10] << "\n";
    pcout << std::defaultfloat;
    // The balance error relative to the largest energy in play.
    const double scale = std::max({std::abs(last[4]) + std::abs(last[5]),
                                   std::abs(fault_work),
                                   std::abs(last[6]),
                                   std::abs(last[7]),
                                   std::abs(initial_energy),
                                   1e-300});
    // The implicit and quasi-static schemes close the budget to round-off
    // (trapezoidal rule); central difference only to O(dt^2).
    const double tolerance =
      (current_scheme == TimeIntegration::Scheme::explicit_central_difference) ?
        1e-2 :
        1e-8;
    pcout << "   Energy balance error below " << tolerance
          << " of the energy scale: "
          << (std::abs(last[8]) < tolerance * scale ? "yes" : "no") << "\n";
    if (!test_mode)
      {
        pcout << "   Energy balance error " << last[8] << " J\n";
        print_performance_summary();
        timer.print_summary();
      }
  }



  template <int dim>
  bool
  Simulator<dim>::run_phase(const double duration,
                            const bool   stop_when_weakening)
  {
    // Steps are counted in the phase's own time: after a long loading
    // phase the absolute time has lost the digits of a short dynamic
    // phase (3e9 s + 0.3 s).
    const double       start    = time;
    const double       end_time = start + duration;
    const unsigned int n_steps =
      static_cast<unsigned int>(std::ceil(duration / time_step - 1e-9));
    pcout << "   Time step " << std::setprecision(6) << time_step << " s, "
          << n_steps << " steps to t = " << end_time << " s\n";
    substep_depth           = 0;
    steps_without_cut       = 0;
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
    } loop_timer{time_loop_seconds, loop_start};

    for (unsigned int i = 1; i <= n_steps; ++i)
      {
        ++step;
        time = (i == n_steps) ? end_time : start + i * time_step;
        // The time since the start of the dynamic phase, without the
        // round-off of the absolute time after a long loading phase.
        const double phase_time =
          (start - dynamic_start) + ((i == n_steps) ? duration : i * time_step);
        if (fault)
          fault->set_time(time);

        switch (current_scheme)
          {
            case TimeIntegration::Scheme::implicit_newmark:
              implicit_step();
              break;
            case TimeIntegration::Scheme::explicit_central_difference:
              explicit_step();
              break;
            case TimeIntegration::Scheme::quasi_static:
              quasi_static_step();
              break;
          }
        check_finite(displacement, "displacement");
        {
          // The displacement may still be finite when the energies computed
          // from it overflow: that is a blow-up too, and no value that is
          // not finite is ever written.
          const std::vector<double> row = statistics_row();
          const bool finite = std::all_of(row.begin(), row.end(), [](double x) {
            return std::isfinite(x);
          });
          check_finite(displacement,
                       "energy computed from the displacement",
                       !finite);
          check_explicit_energy_balance();
          statistics.add_row(row);
        }
        if (fault)
          fault_output->record(*fault, phase_time);
        receivers->record(displacement, velocity, phase_time);

        const bool stop = stop_when_weakening && fault->n_weakening() > 0;
        if (step % screen_interval == 0 || i == n_steps || stop)
          {
            pcout << "*** Step " << step << ": t = " << std::scientific
                  << std::setprecision(4) << time;
            pcout << " s";
            if (dynamic_start != 0)
              pcout << " (dynamic phase t = " << phase_time << " s)";
            pcout << ", dt = " << std::setprecision(2) << time_step << " s";
            if (fault)
              {
                const Fault::Statistics f = fault->statistics();
                pcout << "\n    ";
                if (!fault->uses_split_nodes())
                  pcout << "Newton: " << last_newton_iterations
                        << " iterations; ";
                pcout << "fault: " << f.n_slipping << " slipping, " << f.n_open
                      << " open nodes, max slip " << std::setprecision(3)
                      << f.max_slip << " m, max slip rate " << f.max_slip_rate
                      << " m/s";
              }
            if (!test_mode)
              {
                const double elapsed = MPI_Wtime() - wall_time_start;
                const double left    = elapsed / step * (n_steps - i);
                pcout << "  [" << std::fixed << std::setprecision(0)
                      << 100. * i / n_steps << "%, " << std::setprecision(1)
                      << left << " s left]";
                if (current_scheme !=
                    TimeIntegration::Scheme::explicit_central_difference)
                  pcout << "\n    Linear solver: " << last_linear_iterations
                        << " iterations";
              }
            pcout << std::defaultfloat << std::endl;
          }
        write_step_output(i == n_steps || stop);
        if (stop)
          {
            pcout << "   A bonded zone of the fault reached its strength at "
                  << "t = " << std::setprecision(6) << time
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
    if (current_scheme !=
          TimeIntegration::Scheme::explicit_central_difference ||
        !(time_step > stable_time_step))
      return;
    const double error = kinetic_energy + strain_energy + damping_dissipation +
                         fault_work - external_work - initial_energy;
    const double scale =
      std::max({std::abs(kinetic_energy) + std::abs(strain_energy),
                std::abs(external_work),
                std::abs(damping_dissipation),
                std::abs(fault_work),
                std::abs(initial_energy)});
    if (!(scale > 0) || std::abs(error) <= 0.5 * scale)
      return;
    // (Collective: every rank has the same energies.)
    const std::string  where = locate_largest(displacement);
    std::ostringstream message;
    message << "At step " << step << " (t = " << time
            << " s) the energy balance error is " << std::abs(error) / scale
            << " of the energy in play, with the displacement " << where
            << ": the explicit scheme is unstable, and the run was stopped "
               "before writing this step. Its time step is "
            << time_step << " s against the stable limit " << stable_time_step
            << " s. Reduce <Time integration/Time step>.";
    AssertThrow(false, ExcMessage(message.str()));
  }



  template <int dim>
  std::vector<double>
  Simulator<dim>::statistics_row() const
  {
    std::vector<double> row = {static_cast<double>(step),
                               time,
                               time_step,
                               static_cast<double>(last_linear_iterations),
                               kinetic_energy,
                               strain_energy,
                               external_work,
                               damping_dissipation,
                               kinetic_energy + strain_energy +
                                 damping_dissipation + fault_work -
                                 external_work - initial_energy,
                               test_mode ? 0. : MPI_Wtime() - wall_time_start};
    if (exact_displacement)
      row.push_back(compute_l2_error(time));
    if (fault)
      {
        const Fault::Statistics f  = fault->statistics();
        const double            mw = (dim == 3 && f.seismic_moment > 0) ?
                                       2. / 3. * (std::log10(f.seismic_moment) - 9.1) :
                                       0.;
        for (const double v : {static_cast<double>(last_newton_iterations),
                               static_cast<double>(f.n_slipping),
                               static_cast<double>(f.n_open),
                               f.slipping_area,
                               f.max_slip,
                               f.max_slip_rate,
                               f.seismic_moment,
                               mw,
                               f.frictional_energy,
                               fault_work,
                               f.mean_normal_traction,
                               f.mean_shear_traction})
          row.push_back(v);
      }
    if (has_absorbing)
      row.push_back(absorbed_energy);
    return row;
  }



  template <int dim>
  void
  Simulator<dim>::write_step_output(const bool force)
  {
    // Receiver series are small: written at every output time and at the
    // end, also when no volume output is wanted.
    if (force ||
        (output_interval >= 0 && time >= next_output_time - 1e-9 * time_step))
      receivers->write(output_directory, time_step);
    if (output_interval < 0)
      return;
    if (!force && time < next_output_time - 1e-9 * time_step)
      return;
    TimerOutput::Scope t(timer, "Output");
    VectorType u_ghost(locally_owned_dofs, locally_relevant_dofs, communicator);
    VectorType v_ghost(locally_owned_dofs, locally_relevant_dofs, communicator);
    u_ghost = displacement;
    v_ghost = velocity;
    volume_output->write(dof_handler, u_ghost, v_ghost, time, step);
    if (fault)
      {
        fault_output->write_surface(*fault, output_directory, time, step);
        fault_output->write_tables(*fault,
                                   output_directory,
                                   time_step,
                                   test_mode);
      }
    if (dealii::Utilities::MPI::this_mpi_process(communicator) == 0)
      statistics.write(output_directory + "/statistics");
    next_output_time = time + output_interval;
  }



  template class Simulator<2>;
  template class Simulator<3>;
} // namespace rupture
