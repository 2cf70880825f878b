// The run-time parameters of the simulator: their declaration and parsing.

#include <rupture/adaptivity/fault_refinement.h>
#include <rupture/adaptivity/parameters.h>
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
#include <map>


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
      Discretization::Discretization<dim>::declare_parameters(prm);
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
        "runs with <Solver/Preconditioner> = AMG or a direct solver store "
        "their system matrix either way; block Jacobi needs 'matrix free' "
        "and stores no matrix at all.");
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
      prm.declare_entry(
        "Fault zone damping",
        "0",
        Patterns::Double(0, 10),
        "Kelvin-Voigt damping in the cells that touch the fault region "
        "(by a face, an edge or a vertex), as a fraction of the time step: "
        "the stress there is C : (eps + eta d eps/dt) with eta = this "
        "fraction times the time step, so it shrinks with the cells as the "
        "step does, and acts in dynamic steps only. It damps the "
        "grid-scale oscillation that follows a rupture front; 0.1 is what "
        "spectral-element fault codes use (doc/verification.md measures it "
        "against independent references). The explicit scheme's stable "
        "step shrinks by the factor 1 / sqrt(1 + 2 fraction), which "
        "<Time integration/Courant fraction> takes into account. 0 turns it "
        "off.");
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

    Scene::InitialConditions<dim>::declare_parameters(prm);

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
      prm.declare_entry(
        "Volume fields",
        "displacement, velocity, stress, material_id, mpi_rank",
        Patterns::MultipleSelection(
          "displacement|velocity|stress|material_id|mpi_rank|level"),
        "The fields of the volume snapshots: displacement and velocity at "
        "the mesh nodes; the stress tensor (Pa), the material id, the MPI "
        "rank and the refinement level (0: the scene's coarse cells; it "
        "shows a mesh that follows the rupture) on the cells (the stress at "
        "each cell's centre; ParaView's "
        "Cell Data to Point Data filter smooths it). Leaving out the stress "
        "saves about a third of a snapshot's time and half of its size. "
        "Empty: the mesh only.");
      prm.declare_entry(
        "Compression",
        "mesh",
        Patterns::Selection("mesh|all|none"),
        "What zlib compresses (at its fastest level) in the volume snapshots: "
        "'mesh' the points, cells and integer cell fields (once, at the first "
        "snapshot), which shrink to a quarter or less, and not the "
        "floating-point fields (displacement, velocity, stress), which shrink "
        "by only 20-30 % where waves have passed, at several times the cost "
        "of the rest; 'all' everything (the smallest files, most so where "
        "the model is still at rest; the slowest output); 'none' nothing.");
      prm.declare_entry(
        "Cells per output piece",
        "32768",
        Patterns::Integer(1),
        "Each rank writes its cells of a volume snapshot in pieces of at "
        "most this many cells, one .vtu file per piece, all listed in the "
        "snapshot's .pvtu file (ParaView opens that one, or solution.pvd "
        "for all times). Smaller pieces need less memory while writing: "
        "writing 650 000 cells in one piece took some 2 GB, in pieces of "
        "32768 cells 0.1 GB; ParaView can also read many pieces in "
        "parallel.");
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
    Termination::Criteria::declare_parameters(prm);
    Adaptivity::Parameters::declare_parameters(prm);

    prm.enter_subsection("Checkpoint");
    {
      prm.declare_entry(
        "Interval",
        "0",
        Patterns::Integer(0),
        "Write a checkpoint every this many steps, from which 'rupture "
        "file.prm --resume' continues the run (doc/manual.md, \"Checkpoints "
        "and restart\"). 0: not by steps. With checkpoints on (this or "
        "<Wall-clock interval>), one is also written at the end of the run "
        "and when SIGTERM or SIGINT stops it. The two newest are kept, in "
        "<Output directory>/checkpoint/.");
      prm.declare_entry("Wall-clock interval",
                        "0",
                        Patterns::Double(0),
                        "Write a checkpoint every this many minutes of "
                        "wall-clock time (checked after every step). 0: not "
                        "by time.");
    }
    prm.leave_subsection();
    prm.enter_subsection("Solver");
    {
      prm.declare_entry("Newton force tolerance",
                        "1e-8",
                        Patterns::Double(0, 1),
                        "Newton's method (with a fault) has converged when "
                        "the force residual has fallen below this fraction "
                        "of the step's force scale: the largest of its "
                        "first value, the internal forces of the last "
                        "displacement and the nodal forces of the fault's "
                        "initial traction (a prestressed fault at rest has "
                        "a tiny first residual) ...");
      prm.declare_entry("Newton displacement tolerance",
                        "1e-6",
                        Patterns::Double(0, 1),
                        "... and the last displacement increment is below "
                        "this fraction of the displacement change of the "
                        "step (the paper's two criteria, Fig. 6), or below "
                        "1e-11 of the whole displacement or of the "
                        "displacement of the step's force scale (the force "
                        "scale over the largest diagonal entry of the "
                        "system), which round-off no longer resolves (a "
                        "quiet step after a long loading phase, a fault "
                        "creeping at 1e-20 m/s). A step in "
                        "which every fault node stuck in the last two "
                        "iterations is linear and needs only the first.");
      prm.declare_entry(
        "Maximum step cuts",
        "4",
        Patterns::Integer(0, 20),
        "When Newton's method fails in an implicit or "
        "quasi-static step, "
        "the step is redone as two half steps, recursively, "
        "up to this many times; then the run stops with a "
        "diagnosis. 0 stops at the first failure. After a "
        "cut, the implicit scheme's following steps are taken as sub-steps of "
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
        "Jacobi or multigrid, with a fault): the Krylov solve of a Newton iteration stops "
        "at the relative residual eta_k = 0.9 (|F_k| / |F_k-1|)^2 "
        "(Eisenstat and Walker's second choice, with their safeguard), at "
        "most this value, at least <Linear solver tolerance>, and never "
        "tighter than what the force tolerance of the step still needs. "
        "Far from convergence a loose solve is enough; near it the "
        "forcing falls and Newton converges superlinearly. 0 solves every "
        "iteration to <Linear solver tolerance>. With <Preconditioner> = "
        "multigrid the cap is at most 1e-3: its first iteration or two "
        "already meet a loose tolerance, with directions that lead Newton "
        "astray at the contact. Large rupture models want a tight value: "
        "at 10 km cells the Northeast-Japan rupture steps took 172 Newton "
        "iterations at 0.1 and 55 at 1e-5, five times less time "
        "(doc/performance.md).");
    }
    prm.leave_subsection();
  }



  template <int dim>
  void
  Simulator<dim>::parse_parameters(ParameterHandler &prm)
  {
    {
      // An empty name would put every file at the root of the file system
      // ("/log.txt", "/solution/"); the directory is only touched once the
      // whole input has been checked (prepare_output_directory()).
      const std::string name =
        dealii::Utilities::trim(prm.get("Output directory"));
      Output::Directory::check_name(name, "Output directory");
      output_directory =
        std::make_unique<Output::Directory>(name, communicator);
    }
    test_mode = prm.get_bool("Test mode");

    prm.enter_subsection("Discretization");
    discretization.parse_parameters(prm);
    prm.leave_subsection();
    elastic_system.parse_parameters(prm, test_mode);

    initial_conditions.parse_parameters(prm);

    prm.enter_subsection("Verification");
    if (!dealii::Utilities::trim(prm.get("Exact displacement")).empty())
      exact_displacement =
        Utilities::parse_function<dim>(prm.get("Exact displacement"),
                                       dim,
                                       "Verification/Exact displacement");
    prm.leave_subsection();

    prm.enter_subsection("Output");
    output_schedule.interval = prm.get_double("Output interval");
    volume_settings.parse_parameters(prm);
    output_schedule.screen_interval = prm.get_integer("Screen output interval");
    receivers = std::make_unique<Output::Receivers<dim>>(prm.get("Receivers"),
                                                         communicator);
    prm.leave_subsection();

    prm.enter_subsection("Solver");
    newton.parse_parameters(prm);
    prm.leave_subsection();

    time_parameters.parse_parameters(prm);
    if (time_parameters.scheme ==
        TimeIntegration::Scheme::explicit_central_difference)
      elastic_system.use_lumped_mass_always();
    materials.parse_parameters(prm, dim);
    linear_solver.parse_parameters(prm);
    // deal.II 9.4's coarsening sequence fails on locally refined meshes.
    AssertThrow(
      !linear_solver.multigrid() || discretization.n_region_refinements() == 0,
      ExcMessage("<Solver/Preconditioner> = multigrid needs a mesh "
                 "without regional refinement, but <Discretization/"
                 "Refinement region levels> is " +
                 std::to_string(discretization.n_region_refinements()) +
                 ". Set it to 0, or use <Solver/Preconditioner> = "
                 "block Jacobi or AMG."));

    scene = Scene::create<dim>(prm);
    fault = Fault::Fault<dim>::create(prm);
    if (fault)
      {
        fault_output = std::make_unique<Fault::FaultOutput<dim>>();
        fault_output->parse_parameters(prm);
        output_schedule.fault_interval =
          fault_output->surface_interval(output_schedule.interval);
      }
    discretization.set_fault(fault.get());
    elastic_system.set_fault(fault.get());
    newton.set_fault(fault.get());
    termination.parse_parameters(prm, fault != nullptr);
    AssertThrow(!termination.uses_events() ||
                  (fault_output && fault_output->has_event_catalogue()),
                ExcMessage("<Termination/Number of events> counts the events "
                           "of the event catalogue: set <Fault/Output/Event "
                           "catalogue> = true."));
    prm.enter_subsection("Checkpoint");
    checkpoints.interval = prm.get_integer("Interval");
    checkpoints.minutes  = prm.get_double("Wall-clock interval");
    prm.leave_subsection();
    AssertThrow(std::isfinite(checkpoints.minutes),
                ExcMessage("<Checkpoint/Wall-clock interval> must be a "
                           "finite number of minutes (0: off)."));
    // Station and receiver files share the directory: two series with one
    // file name would silently lose one.
    {
      std::map<std::string, std::string> owner;
      if (fault)
        owner["rupture_time"] = "the fault's rupture-time file";
      const auto claim = [&](const std::string &name,
                             const std::string &entry) {
        const auto [it, inserted] = owner.emplace(name, entry);
        AssertThrow(inserted,
                    ExcMessage("The name <" + name + "> in <" + entry +
                               "> is also used by " + it->second +
                               ": both would write <" + name +
                               ".dat>. Give every station and receiver a "
                               "name of its own, other than "
                               "'rupture_time'."));
      };
      if (fault)
        for (const auto &name : fault_output->station_names())
          claim(name, "Fault/Output/Stations");
      for (const auto &name : receivers->names())
        claim(name, "Output/Receivers");
    }
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
        AssertThrow(
          fault->radiation_damping_coefficient() == 0 ||
            time_parameters.scheme == TimeIntegration::Scheme::quasi_static,
          ExcMessage("<Fault/Radiation damping> stands in for the waves of "
                     "a quasi-static run (<Time integration/Scheme> = "
                     "quasi-static); with <Time integration/Scheme> = " +
                     time_parameters.scheme_name() +
                     " the waves radiate themselves. Allowed: 0 with a "
                     "dynamic scheme."));
      }
    mesh_refinement.parse_parameters(prm);
    if (mesh_refinement.enabled())
      {
        AssertThrow(!fault_output || !fault_output->has_event_catalogue(),
                    ExcMessage("<Fault/Output/Event catalogue> = true cannot "
                               "be combined with <Mesh refinement> yet (the "
                               "slip at an event's start is not carried to "
                               "a new mesh). Use one of them."));
        AssertThrow(!linear_solver.multigrid(),
                    ExcMessage("<Solver/Preconditioner> = multigrid cannot "
                               "follow a mesh that <Mesh refinement/Criteria> "
                               "refines locally (deal.II 9.4 builds no "
                               "coarsening sequence for it). Use <Solver/"
                               "Preconditioner> = AMG or block Jacobi."));
        AssertThrow(time_parameters.scheme !=
                        TimeIntegration::Scheme::explicit_central_difference ||
                      time_parameters.time_step == 0,
                    ExcMessage("<Mesh refinement/Criteria> changes the "
                               "stable step of the explicit scheme during the "
                               "run, so <Time integration/Time step> must be "
                               "0 (the step is then <Courant fraction> times "
                               "the stable step of each mesh), but it is " +
                               std::to_string(time_parameters.time_step) +
                               " s."));
        AssertThrow(fault != nullptr || (!mesh_refinement.follow_front &&
                                         !mesh_refinement.process_zone),
                    ExcMessage("<Mesh refinement/Criteria> = " +
                               prm.get({"Mesh refinement"}, "Criteria") +
                               ": rupture front and process zone follow a "
                               "fault, but <Fault/Model> = none. Allowed "
                               "without a fault: wavefield alone."));
        AssertThrow(!mesh_refinement.wavefield ||
                      mesh_refinement.wavefield_threshold > 0,
                    ExcMessage("<Mesh refinement/Wavefield threshold> is 0, "
                               "which would refine every cell that moves at "
                               "all. Allowed: a positive jump in strain rate "
                               "(1/s); the log gives the largest at each "
                               "adaptation."));
        AssertThrow(!mesh_refinement.wavefield ||
                      time_parameters.scheme !=
                        TimeIntegration::Scheme::quasi_static,
                    ExcMessage("<Mesh refinement/Criteria> = wavefield "
                               "follows waves, which a quasi-static run "
                               "(<Time integration/Scheme> = quasi-static) "
                               "has none of. Allowed: rupture front and "
                               "process zone, or a dynamic scheme."));
        AssertThrow(!mesh_refinement.process_zone ||
                      fault->friction().has_process_zone_width(),
                    ExcMessage("<Mesh refinement/Criteria> = process zone "
                               "needs the friction law's estimate of its "
                               "process zone, which <Fault/Friction law> = " +
                               prm.get({"Fault"}, "Friction law") +
                               " does not give (it has no slip distance over "
                               "which it weakens). Allowed: linear slip "
                               "weakening and the rate-and-state laws, or "
                               "the criterion rupture front alone."));
        fault_refinement = std::make_unique<Adaptivity::FaultRefinement<dim>>(
          mesh_refinement,
          discretization.triangulation(),
          fault.get(),
          [this](const typename Triangulation<dim>::cell_iterator &cell) {
            return discretization.base_level(cell);
          },
          discretization.degree());
      }
    boundary_conditions.parse_parameters(prm, scene->get_boundary_names());
    AssertThrow(!(elastic_system.has_absorbing() &&
                  time_parameters.scheme ==
                    TimeIntegration::Scheme::quasi_static),
                ExcMessage("<Boundary conditions/Absorbing> is set, but "
                           "absorbing boundaries act on velocities and have "
                           "no meaning in a quasi-static run. Remove them "
                           "or choose a dynamic scheme."));
  }



  template class Simulator<2>;
  template class Simulator<3>;
} // namespace rupture
