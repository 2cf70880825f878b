// Every class of bad input gets one clear message naming the entry, the
// value and what is allowed, a non-zero exit code, and leaves the results
// of an earlier run in the output directory untouched.

#include <deal.II/base/mpi.h>

#include "../tests.h"

#include <cstdio>
#include <filesystem>
#include <fstream>

namespace
{
  // A valid small run; each case changes one thing.
  const std::string base = R"(set Dimension = 2
set Test mode = true
set Output directory = earlier-run
subsection Scene
  set Model = box
  subsection Box
    set Number of cells = 2
  end
end
subsection Boundary conditions
  set Fixed = bottom
end
subsection Time integration
  set Time step = 0.01
  set End time = 0.02
end
)";

  void
  write(const std::string &file, const std::string &text)
  {
    std::ofstream(file) << text;
  }

  /// valid.prm with @p entries set (each "Entry=value") and a penalty
  /// contact fault on the plane y = @p y.
  std::vector<std::string>
  with_fault(const std::string &y, const std::vector<std::string> &entries)
  {
    std::vector<std::string> args = {"valid.prm"};
    for (const std::string &entry :
         std::vector<std::string>{"Fault/Model=penalty contact",
                                  "Fault/Plane point=0, " + y,
                                  "Fault/Plane normal=0, 1"})
      args.insert(args.end(), {"--set", entry});
    for (const std::string &entry : entries)
      args.insert(args.end(), {"--set", entry});
    return args;
  }

  void
  check(const std::string &title, const std::vector<std::string> &args)
  {
    std::string errors;
    const int   code = tests::run_capture(args, errors);
    // Keep the message, drop blank lines.
    while (!errors.empty() && (errors[0] == '\n'))
      errors.erase(0, 1);
    std::printf("* %s\n  exit code: %d\n  %s",
                title.c_str(),
                code,
                errors.c_str());
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);

  // An earlier run's results that no bad input may destroy.
  std::filesystem::create_directories("earlier-run");
  write("earlier-run/statistics", "earlier results\n");
  write("earlier-run/log.txt", "earlier log\n");

  write("valid.prm", base);
  write("unknown_entry.prm",
        base + "subsection Material\n  set Densty = 2700\nend\n");
  write("malformed_value.prm",
        base + "subsection Material\n  set Density = heavy\nend\n");
  write("bad_dimension.prm", "set Dimension = 4\n");
  write("missing_mesh.prm",
        base + "subsection Scene\n  set Model = gmsh\n  subsection Gmsh\n"
               "    set Mesh file = no-such-mesh.msh\n  end\nend\n");
  write("garbage.msh", "this is not a mesh\n");
  write("unreadable_mesh.prm",
        base + "subsection Scene\n  set Model = gmsh\n  subsection Gmsh\n"
               "    set Mesh file = garbage.msh\n  end\nend\n");
  write("poisson.prm",
        base + "subsection Material\n  set Parametrization = Young's modulus "
               "and Poisson's ratio\n  set Poisson's ratio = 0.5\nend\n");
  write("density.prm", base + "subsection Material\n  set Density = 0\nend\n");
  write("wave_speeds.prm",
        base + "subsection Material\n  set P-wave speed = 3000\n"
               "  set S-wave speed = 3000\nend\n");
  write("time_step.prm",
        base + "subsection Time integration\n  set Time step = -0.01\nend\n");
  write("explicit_step.prm",
        base + "subsection Time integration\n  set Scheme = explicit central "
               "difference\n  set Time step = 1\nend\n");
  write("boundary_name.prm",
        base + "subsection Boundary conditions\n  set Fixed = botom\nend\n");
  write("roller.prm",
        base + "subsection Boundary conditions\n  set Fixed =\n"
               "  set Roller = bottom: z\nend\n");
  write("material_id.prm",
        base + "subsection Scene\n  subsection Box\n    set Layer interfaces "
               "= 500\n  end\nend\n");
  write("grading_core.prm",
        base + "subsection Scene\n  subsection Box\n    subsection Grading\n"
               "      set Growth factor = 1.2\n      set Core lower corner = "
               "-100, 0\n    end\n  end\nend\n");
  write("stiffness_factor.prm",
        base + "subsection Material\n  set Stiffness factor = 1 - x / "
               "500\nend\n");
  write("density_factor.prm",
        base + "subsection Material\n  set Density factor = -2\nend\n");
  // Wave speeds as functions of position: vp falls below sqrt(2) vs at
  // x = 500; a function density for an anisotropic material; a field
  // that is neither a number nor a function.
  write("wave_speed_function.prm",
        base + "subsection Material\n  set P-wave speed = 6000 - 10*x\n"
               "end\n");
  write("anisotropic_density_function.prm",
        base + "subsection Material\n  set Density = 2700 + y\n  set "
               "Symmetry = orthotropic\n  set Stiffness = C11 = 9e10, C22 = "
               "9e10, C33 = 9e10, C12 = 3e10, C13 = 3e10, C23 = 3e10, C44 = "
               "3e10, C55 = 3e10, C66 = 3e10\nend\n");
  write("comma_function.prm",
        base + "subsection Material\n  set Names = a, b\n  set P-wave "
               "speed = 6000, 5000 + 0.5*y\nend\n");
  write("density_nan.prm",
        base + "subsection Material\n  set Density = nan\nend\n");
  write("function_with_factor.prm",
        base + "subsection Material\n  set Density = 2700 + 0*x\n  set "
               "Density factor = 1e4\nend\n");
  write("density_field.prm",
        base + "subsection Material\n  set Names = a, b\n  set Density = "
               "2700; 2700 + w\nend\n");
  write("anisotropic_friction_normal.prm",
        base + "set Dimension = 3\nsubsection Fault\n  set Model = penalty "
               "contact\n  set Plane point = 0, 500, 0\n  set Plane "
               "normal = 0, 1, 0\n  subsection Anisotropic friction\n    set "
               "Strength ratio = 2\n    set First direction = 0, 2, 0\n  "
               "end\nend\n");
  write("anisotropic_friction_oblique_2d.prm",
        base + "subsection Fault\n  set Model = penalty contact\n  set "
               "Plane point = 0, 500\n  set Plane normal = 0, 1\n  "
               "subsection Anisotropic friction\n    set Strength ratio = "
               "2\n    set First direction = 1, 0, 1\n  end\nend\n");
  write("radiation_damping_text.prm",
        base + "subsection Fault\n  set Model = penalty contact\n  set "
               "Plane point = 0, 500\n  set Plane normal = 0, 1\n  set "
               "Radiation damping = fast\nend\n");
  write("anisotropic_2d.prm",
        base + "subsection Material\n  set Symmetry = transversely "
               "isotropic\n  set Stiffness = C11 = 6e10, C33 = 4e10, C13 = "
               "1.5e10, C44 = 1.2e10, C66 = 2e10\n  set Material axes = 1, 0, "
               "1\nend\n");
  // Anisotropic constants as functions: a tensor that stops being
  // positive definite at x = 500 (C66 < 0), a constant that is NaN on
  // part of the cells, one that is no function, and in 2-D a C16 that
  // couples in-plane and out-of-plane motion away from the origin.
  const std::string orthotropic =
    "subsection Material\n  set Symmetry = general\n  set Stiffness = "
    "C11 = 9e10, C22 = 9e10, C33 = 9e10, C12 = 3e10, C13 = 3e10, C23 = "
    "3e10, C44 = 3e10, C55 = 3e10, C14 = 0, C15 = 0, C16 = 0, C24 = 0, "
    "C25 = 0, C26 = 0, C34 = 0, C35 = 0, C36 = 0, C45 = 0, C46 = 0, "
    "C56 = 0, ";
  write("tensor_not_positive.prm",
        base + orthotropic + "C66 = 3e10 - 6e7*x\nend\n");
  write("tensor_nan.prm",
        base + orthotropic + "C66 = 3e10*sqrt(250 - y)/10\nend\n");
  write("tensor_not_function.prm", base + orthotropic + "C66 = 3e10*w\nend\n");
  write("tensor_mirror_2d.prm",
        base + "subsection Material\n  set Symmetry = general\n  set "
               "Stiffness = C11 = 9e10, C22 = 9e10, C33 = 9e10, C12 = 3e10, "
               "C13 = 3e10, C23 = 3e10, C44 = 3e10, C55 = 3e10, C66 = 3e10, "
               "C14 = 1e7*x, C15 = 0, C16 = 0, C24 = 0, C25 = 0, C26 = 0, "
               "C34 = 0, C35 = 0, C36 = 0, C45 = 0, C46 = 0, C56 = 0\nend\n");
  write("function.prm",
        base + "subsection Initial conditions\n  set Displacement = "
               "sin(q*x); 0\nend\n");

  const std::string fault =
    "subsection Fault\n  set Model = penalty contact\n"
    "  set Plane point = 0, 500\n  set Plane normal = 0, 1\n";
  write("fault_plane.prm",
        base + "subsection Fault\n  set Model = penalty contact\n"
               "  set Plane point = 0, 300\n  set Plane normal = 0, 1\nend\n");
  write("fault_penalty.prm", base + fault + "  set Normal penalty = -1\nend\n");
  // Not bad input, but a run that fails: a Krylov solve limited to one
  // iteration on 32 x 32 cells, far from the smallest tolerance allowed. Its
  // message must reach the screen (ML's smoother once crashed in the
  // destructor and swallowed it) and the code must be 1.
  write("solver_fails.prm",
        base + fault +
          "end\nsubsection Solver\n  set Maximum linear iterations = 1\n"
          "  set Linear solver tolerance = 1e-15\n"
          "end\nsubsection Scene\n  subsection Box\n    set Number of cells "
          "= 32\n  end\nend\n"
          "subsection Boundary conditions\n  set Traction = top: 1e6; "
          "-1e7\nend\nset Output directory = failed-run\n");
  write("refinement_region_nan.prm",
        base + "subsection Discretization\n  set Refinement region = log(x - "
               "2000)\n  set Refinement region levels = 1\nend\n");
  write("fault_explicit.prm",
        base + fault +
          "end\nsubsection Time integration\n  set Scheme = explicit "
          "central difference\n  set Time step = 0\nend\n");
  write("split_node_implicit.prm",
        base + "subsection Fault\n  set Model = traction at split nodes\n"
               "  set Plane point = 0, 500\n  set Plane normal = 0, 1\nend\n");
  write("split_node_loading.prm",
        base + "subsection Fault\n  set Model = traction at split nodes\n"
               "  set Plane point = 0, 500\n  set Plane normal = 0, 1\nend\n"
               "subsection Time integration\n  set Scheme = explicit central "
               "difference\n  set Time step = 0\n  subsection Loading phase\n"
               "    set Enabled = true\n  end\nend\n");
  write("forced_direction.prm",
        base + fault +
          "  subsection Forced slip\n    set Region = 1\n    set Slip = "
          "t\n    set Direction = 0, 1\n  end\nend\n");
  write("fault_friction.prm",
        base + fault +
          "  subsection Linear slip weakening\n    set Static friction "
          "coefficient = 0.5\n    set Dynamic friction coefficient = 0.6\n"
          "  end\nend\n");

  write("empty.prm", "");
  write("comments_only.prm", "# a parameter file\n\n# with nothing set\n");
  std::filesystem::create_directories("directory.prm");
  write("gmsh_version.msh",
        "$MeshFormat\n3.0 0 8\n$EndMeshFormat\n$Nodes\n0\n$EndNodes\n");
  write("gmsh_header_body.msh",
        "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n$Nodes\n4\n1 0 0 0\n"
        "2 1 0 0\n3 1 1 0\n4 0 1 0\n$EndNodes\n$Elements\n1\n1 3 2 0 1 "
        "1 2 3 4\n$EndElements\n");
  const std::string gmsh =
    "subsection Scene\n  set Model = gmsh\n  subsection Gmsh\n"
    "    set Mesh file = ";
  write("gmsh_version.prm", base + gmsh + "gmsh_version.msh\n  end\nend\n");
  write("gmsh_header_body.prm",
        base + gmsh + "gmsh_header_body.msh\n  end\nend\n");
  write("fault_region_nan.prm",
        base + fault + "  set Fault region = 0/0\nend\n");
  // A quadrilateral in Gmsh 2.2 with a named bottom edge: a twisted one
  // (nodes 3 and 4 swapped) and one with a repeated node.
  const auto quad = [](const std::string &nodes) {
    return "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$PhysicalNames\n2\n"
           "1 1 \"bottom\"\n2 2 \"rock\"\n$EndPhysicalNames\n$Nodes\n4\n"
           "1 0 0 0\n2 1 0 0\n3 1 1 0\n4 0 1 0\n$EndNodes\n$Elements\n2\n"
           "1 1 2 1 1 1 2\n2 3 2 2 1 " +
           nodes + "\n$EndElements\n";
  };
  // One hexahedron: a 3-D mesh given to a 2-D run.
  write("gmsh_hexahedron.msh",
        "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n8\n1 0 0 0\n2 1 0 0\n"
        "3 1 1 0\n4 0 1 0\n5 0 0 1\n6 1 0 1\n7 1 1 1\n8 0 1 1\n$EndNodes\n"
        "$Elements\n1\n1 5 2 1 1 1 2 3 4 5 6 7 8\n$EndElements\n");
  write("gmsh_hexahedron.prm",
        base + gmsh + "gmsh_hexahedron.msh\n  end\nend\n");
  write("gmsh_bow_tie.msh", quad("1 2 4 3"));
  write("gmsh_repeated_node.msh", quad("1 2 3 3"));
  write("gmsh_bow_tie.prm", base + gmsh + "gmsh_bow_tie.msh\n  end\nend\n");
  write("gmsh_repeated_node.prm",
        base + gmsh + "gmsh_repeated_node.msh\n  end\nend\n");
  write("self_include.prm", base + "include self_include.prm\n");
  write("include_a.prm", base + "include include_b.prm\n");
  write("include_b.prm", "include include_a.prm\n");
  write("deep.json", std::string(100000, '[') + std::string(100000, ']'));
  write("broken.json",
        "{\n  \"Dimension\": 2,\n  \"Output directory\" \"x\"\n}\n");
  write("broken.xml",
        "<?xml version=\"1.0\"?>\n<ParameterHandler>\n"
        "<Dimension><value>2</value>\n</ParameterHandler>\n");
  write("unknown.xml",
        "<?xml version=\"1.0\"?>\n<ParameterHandler>"
        "<Foo><value>1</value></Foo></ParameterHandler>\n");

  check("unknown entry", {"unknown_entry.prm"});
  check("malformed value", {"malformed_value.prm"});
  check("dimension out of range", {"bad_dimension.prm"});
  check("missing mesh file", {"missing_mesh.prm"});
  check("unreadable mesh file", {"unreadable_mesh.prm"});
  check("Poisson's ratio 0.5", {"poisson.prm"});
  check("density 0", {"density.prm"});
  check("P-wave speed too low for the S-wave speed", {"wave_speeds.prm"});
  check("negative time step", {"time_step.prm"});
  check("explicit time step above the stable limit", {"explicit_step.prm"});
  check("boundary name the scene does not have", {"boundary_name.prm"});
  check("roller component that does not exist in 2-D", {"roller.prm"});
  check("material id without material", {"material_id.prm"});
  check("graded box whose core leaves the box", {"grading_core.prm"});
  check("function with an unknown variable", {"function.prm"});
  check("stiffness factor not positive on the cells", {"stiffness_factor.prm"});
  check("negative density factor", {"density_factor.prm"});
  check("P-wave speed function below sqrt(2) vs", {"wave_speed_function.prm"});
  check("density function of an anisotropic material",
        {"anisotropic_density_function.prm"});
  check("density field with an unknown variable", {"density_field.prm"});
  check("a function in a list separated by commas", {"comma_function.prm"});
  check("anisotropic constants as functions: not positive definite on the "
        "cells",
        {"tensor_not_positive.prm"});
  check("anisotropic constants as functions: NaN on the cells",
        {"tensor_nan.prm"});
  check("anisotropic constant neither number nor function",
        {"tensor_not_function.prm"});
  check("anisotropic constants as functions: 2-D model plane not a mirror "
        "plane away from the origin",
        {"tensor_mirror_2d.prm"});
  check("density nan", {"density_nan.prm"});
  check("density function times a density factor above 1e6",
        {"function_with_factor.prm"});
  check("anisotropic friction direction normal to the fault",
        {"anisotropic_friction_normal.prm"});
  check("2-D anisotropic friction whose first direction is oblique to the "
        "model plane",
        {"anisotropic_friction_oblique_2d.prm"});
  check("radiation damping neither a number nor auto",
        {"radiation_damping_text.prm"});
  check("2-D anisotropic material without a mirror plane",
        {"anisotropic_2d.prm"});
  check("fault plane that cuts through cells", {"fault_plane.prm"});
  check("negative fault penalty", {"fault_penalty.prm"});
  check("penalty contact with the explicit scheme", {"fault_explicit.prm"});
  check("traction at split nodes with the implicit scheme",
        {"split_node_implicit.prm"});
  check("traction at split nodes with a loading phase",
        {"split_node_loading.prm"});
  check("mu_0 below mu_d", {"fault_friction.prm"});
  check("forced slip normal to the fault", {"forced_direction.prm"});
  check("linear solve that does not converge", {"solver_fails.prm"});
  check("refinement region that is not finite", {"refinement_region_nan.prm"});
  check("more than 1e9 time steps",
        {"valid.prm", "--set", "Time integration/End time=1e9"});
  check("unknown format of --print-parameters", {"--print-parameters", "json"});
  check("--refine without --resume", {"valid.prm", "--refine", "1"});
  check("--refine with a bad number",
        {"valid.prm", "--resume", "--refine", "x"});
  check("empty output directory", {"valid.prm", "--set", "Output directory="});
  check("block Jacobi with a direct solver",
        {"valid.prm",
         "--set",
         "Solver/Linear solver=MUMPS",
         "--set",
         "Solver/Preconditioner=block Jacobi"});
  check("multigrid with a refinement region",
        {"valid.prm",
         "--set",
         "Solver/Preconditioner=multigrid",
         "--set",
         "Discretization/Refinement region=1",
         "--set",
         "Discretization/Refinement region levels=1"});
  check("multigrid with a fault that is not on faces of the coarse mesh",
        with_fault("250",
                   {"Solver/Preconditioner=multigrid",
                    "Discretization/Initial global refinement=1"}));
  check("mesh refinement with multigrid",
        {"valid.prm",
         "--set",
         "Mesh refinement/Criteria=rupture front",
         "--set",
         "Solver/Preconditioner=multigrid"});
  check("mesh refinement with a fixed explicit time step",
        {"valid.prm",
         "--set",
         "Mesh refinement/Criteria=rupture front",
         "--set",
         "Time integration/Scheme=explicit central difference"});
  check("mesh refinement without a fault",
        {"valid.prm", "--set", "Mesh refinement/Criteria=rupture front"});
  check("mesh refinement to the process zone of a law without one",
        with_fault("250",
                   {"Mesh refinement/Criteria=process zone",
                    "Fault/Friction law=cochard madariaga"}));
  check("the wavefield criterion in a quasi-static run",
        with_fault("500",
                   {"Mesh refinement/Criteria=wavefield",
                    "Time integration/Scheme=quasi-static"}));
  check("a wavefield threshold of 0",
        with_fault("500",
                   {"Mesh refinement/Criteria=wavefield",
                    "Mesh refinement/Wavefield threshold=0"}));
  check("a DoF budget below the base mesh",
        with_fault("500",
                   {"Mesh refinement/Criteria=rupture front",
                    "Mesh refinement/Maximum degrees of freedom=10"}));
  check("an adaptive step controller with a dynamic scheme",
        {"valid.prm",
         "--set",
         "Time integration/Step controller/Controller=rate and state"});
  check("a step controller's bounds in the wrong order",
        {"valid.prm",
         "--set",
         "Time integration/Step controller/Minimum time step=10",
         "--set",
         "Time integration/Step controller/Maximum time step=1"});
  check("a state evolution fraction above 1",
        {"valid.prm",
         "--set",
         "Time integration/Step controller/State evolution fraction=2"});
  // The valid run with a penalty fault and one more setting.
  const auto with_fault = [](const std::string &setting) {
    return std::vector<std::string>{"valid.prm",
                                    "--set",
                                    "Fault/Model=penalty contact",
                                    "--set",
                                    "Fault/Plane point=0, 500",
                                    "--set",
                                    "Fault/Plane normal=0, 1",
                                    "--set",
                                    setting};
  };
  auto refined = with_fault("Fault/Output/Event catalogue=true");
  refined.insert(refined.end(),
                 {"--set", "Mesh refinement/Criteria=rupture front"});
  check("an event catalogue with mesh refinement", refined);
  check("an event slip rate of 0",
        with_fault("Fault/Output/Event slip rate=0"));
  check("an event end slip rate above the event slip rate",
        with_fault("Fault/Output/Event end slip rate=2e-3"));
  check("a number of events without an event catalogue",
        with_fault("Termination/Number of events=3"));
  // The boundary-integral method's one-element slider with one more
  // setting.
  const auto boundary_integral = [](const std::string &setting) {
    return std::vector<std::string>{
      std::string(SOURCE_DIR) +
        "/../boundary_integral/inputs/spring_slider.prm",
      "--set",
      "Output directory=earlier-run",
      "--set",
      setting};
  };
  check("the boundary-integral method with a law without a state rate",
        boundary_integral("Fault/Friction law=linear slip weakening"));
  {
    auto arguments = boundary_integral("Fault/Friction law=slowness law");
    arguments.insert(arguments.end(),
                     {"--set", "Fault/Slowness law/Initial state=0"});
    check("the boundary-integral method with a state of 0, which it "
          "integrates in its logarithm",
          arguments);
  }
  check("the boundary-integral method with elements of 0 m",
        boundary_integral("Boundary integral/Element size=0"));
  check("the boundary-integral method with a station off the fault",
        boundary_integral("Fault/Output/Stations=off: 100, -200"));
  check("the boundary-integral method without an initial shear stress",
        boundary_integral("Boundary integral/Initial shear stress="));
  check("the boundary-integral method with a tensile normal stress",
        boundary_integral("Boundary integral/Normal stress=-1e6"));
  const auto finite_elements = [&](const std::string &setting) {
    // (Degree 1: the slider's one element is its one node.)
    auto arguments = boundary_integral("Boundary integral/Stiffness=finite "
                                       "elements");
    arguments.insert(
      arguments.end(),
      {"--set", "Boundary integral/Finite-element degree=1", "--set", setting});
    return arguments;
  };
  check("the finite-element stiffness of degree 5",
        finite_elements("Boundary integral/Finite-element degree=5"));
  check("the finite-element stiffness with nodes farther apart than the "
        "fault is deep at degree 2",
        finite_elements("Boundary integral/Finite-element degree=2"));
  check("the finite-element stiffness in a box smaller than twice the fault",
        finite_elements("Boundary integral/Domain size=700"));
  check("the finite-element stiffness with cells growing by 3",
        finite_elements("Boundary integral/Cell growth factor=3"));
  check("fully dynamic events with the Green's function",
        boundary_integral("Boundary integral/Events=fully dynamic"));
  {
    auto arguments = finite_elements("Boundary integral/Events=fully dynamic");
    arguments.insert(arguments.end(),
                     {"--set", "Boundary integral/Quasi-dynamic below=1e-3"});
    check("fully dynamic events whose phases would end where they start",
          arguments);
  }
  {
    auto arguments = finite_elements("Boundary integral/Events=fully dynamic");
    arguments.insert(arguments.end(),
                     {"--set", "Boundary integral/Courant number=1.5"});
    check("fully dynamic events with a Courant number of 1.5", arguments);
  }
  {
    auto arguments = finite_elements("Boundary integral/Events=fully dynamic");
    arguments.insert(arguments.end(),
                     {"--set", "Boundary integral/Kelvin-Voigt damping=2"});
    check("fully dynamic events with a Kelvin-Voigt damping of 2 steps",
          arguments);
  }
  // A dipping fault in a plane-strain body (SEAS BP3) with one more
  // setting, its nodes 10 km apart.
  const auto plane_strain = [](const std::string &setting) {
    return std::vector<std::string>{std::string(SOURCE_DIR) +
                                      "/../../prm/seas/bp3-qd-60.prm",
                                    "--set",
                                    "Output directory=earlier-run",
                                    "--set",
                                    "Boundary integral/Element size=10000",
                                    "--set",
                                    setting};
  };
  check("a dip with the antiplane half-space",
        boundary_integral("Boundary integral/Dip=60"));
  check("the plane-strain body with the Green's function",
        plane_strain("Boundary integral/Stiffness=Green's function"));
  check("the plane-strain body with a dip of 5 degrees",
        plane_strain("Boundary integral/Dip=5"));
  check("the plane-strain body with a P-wave speed below 2 / sqrt(3) times "
        "the S-wave speed",
        plane_strain("Material/P-wave speed=3900"));
  check("the plane-strain body with a station off the dipping fault",
        plane_strain("Fault/Output/Stations=off: 0, -5000"));
  check("the plane-strain body with a station below the fault's end",
        plane_strain("Fault/Output/Stations=deep: 25000, -43301.3"));
  check("the plane-strain body with a surface station beyond the box",
        plane_strain("Boundary integral/Surface stations=far: 500000, 0"));
  check("the plane-strain body with a surface station named as a fault "
        "station",
        plane_strain("Boundary integral/Surface stations=fltst_dp100: 100, "
                     "0"));
  auto resumed = boundary_integral("Boundary integral/Element size=400");
  resumed.push_back("--resume");
  check("the boundary-integral method continued without a checkpoint", resumed);
  check("missing parameter file", {"no-such-file.prm"});
  check("no parameter file", {});
  check("unknown option", {"--frobnicate", "valid.prm"});
  check("--set of an unknown entry",
        {"valid.prm", "--set", "Time integration/End tme=1"});
  check("--set with a malformed value",
        {"valid.prm", "--set", "Time integration/End time=soon"});
  check("--set with a non-physical value",
        {"valid.prm", "--set", "Time integration/End time=-1"});
  check("--set without an entry", {"valid.prm", "--set", "=1"});
  check("--set with an empty path part",
        {"valid.prm", "--set", "Time integration//End time=1"});
  check("empty parameter file", {"empty.prm"});
  check("parameter file of comments only", {"comments_only.prm"});
  check("parameter file that is a directory", {"directory.prm"});
  check("output directory at the root of the file system",
        {"valid.prm", "--set", "Output directory=/"});
  check("output directory that is a file",
        {"valid.prm", "--set", "Output directory=valid.prm"});
  check("Gmsh format 3.0", {"gmsh_version.prm"});
  check("Gmsh header 4.1 over a 2.2 body", {"gmsh_header_body.prm"});
  check("fault region that is not finite", {"fault_region_nan.prm"});
  check("Gmsh cell with crossing edges", {"gmsh_bow_tie.prm"});
  check("Gmsh cell with a repeated node", {"gmsh_repeated_node.prm"});
  check("parameter file that includes itself", {"self_include.prm"});
  check("parameter files that include each other", {"include_a.prm"});
  check("JSON parameter file nested 100 000 deep", {"deep.json"});
  check("JSON parameter file with a missing colon", {"broken.json"});
  check("XML parameter file with an element not closed", {"broken.xml"});
  check("XML parameter file with an unknown entry", {"unknown.xml"});
  check("body force that is not finite",
        {"valid.prm", "--set", "Loads/Body force=1/0; 0"});
  check("gravity whose force density overflows",
        {"valid.prm", "--set", "Loads/Gravity=1e308"});
  check("density whose moduli overflow",
        {"valid.prm", "--set", "Material/Density=1e308"});
  check("receiver at nan",
        {"valid.prm", "--set", "Output/Receivers=r1: nan, 0"});
  check("initial traction that is not finite",
        {"fault_penalty.prm",
         "--set",
         "Fault/Normal penalty=1e11",
         "--set",
         "Fault/Initial traction=0/0; -1e6"});
  check("traction perturbation that is not finite",
        {"fault_penalty.prm",
         "--set",
         "Fault/Normal penalty=1e11",
         "--set",
         "Fault/Traction perturbation/Traction=log(0); 0"});
  check("a 3-D Gmsh mesh in a 2-D run", {"gmsh_hexahedron.prm"});
  check("initial velocity that is not finite",
        {"valid.prm", "--set", "Initial conditions/Velocity=0; 1/0"});
  check("a quasi-static model that no boundary condition holds",
        {"valid.prm",
         "--set",
         "Boundary conditions/Fixed=",
         "--set",
         "Time integration/Scheme=quasi-static"});
  check("fault penalties far above the elements' stiffness",
        {"fault_penalty.prm",
         "--set",
         "Fault/Normal penalty=1e30",
         "--set",
         "Fault/Tangential penalty=1e11"});
  check("a scene length far below a millimetre",
        {"valid.prm",
         "--set",
         "Scene/Model=northeast japan",
         "--set",
         "Scene/Northeast Japan/Crust thickness=1e-300"});
  check("box coordinates beyond 1e9 m",
        {"valid.prm", "--set", "Scene/Box/Upper corner=1e308, 1e308"});
  check("wave speeds above the speed of light",
        {"valid.prm", "--set", "Material/P-wave speed=4e8"});
  // A Gmsh file whose header is valid and whose body is garbage, or has no
  // sections at all: named with its line, not by a missing boundary.
  write("gmsh_garbage_nodes.msh",
        "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n4\n1 0 0 0\n"
        "xx yy\n$EndNodes\n");
  write("gmsh_no_sections.msh",
        "$MeshFormat\n2.2 0 8\n$EndMeshFormat\nsome text that is not a "
        "section\n");
  for (const std::string name : {"gmsh_garbage_nodes", "gmsh_no_sections"})
    {
      write(name + ".prm", base + gmsh + name + ".msh\n  end\nend\n");
      check("a Gmsh file with a valid header and a damaged body (" + name + ")",
            {name + ".prm"});
    }
  check("a linear solver tolerance below what double precision reaches",
        {"valid.prm", "--set", "Solver/Linear solver tolerance=1e-300"});
  check("a fault zone damping that is not finite",
        {"valid.prm", "--set", "Damping/Fault zone damping=nan"});
  check("a fault zone damping above ten time steps",
        {"valid.prm", "--set", "Damping/Fault zone damping=11"});
  check("fault sides by material ids without <Plus side> = material ids",
        {"valid.prm",
         "--set",
         "Fault/Model=penalty contact",
         "--set",
         "Fault/Plus side material ids=1"});
  // The memory of the machine is in the message: only its parts are
  // printed.
  for (const std::string &set : {"Scene/Box/Number of cells=100000, 100000",
                                 "Discretization/Initial global refinement=12"})
    {
      // 2-D for the box of 1e10 cells, 3-D for 8 cells refined 12 times.
      const std::string dimension =
        set[0] == 'S' ? "Dimension=2" : "Dimension=3";
      std::string errors;
      const int   code =
        tests::run_capture({"valid.prm", "--set", dimension, "--set", set},
                           errors);
      std::printf("* a mesh too large for the machine (%s)\n  exit code: %d\n"
                  "  names the cell count, the refinement, the memory and "
                  "what is allowed: %s\n",
                  set.c_str(),
                  code,
                  errors.find("The mesh would have about ") !=
                        std::string::npos &&
                      errors.find("<Discretization/Initial global "
                                  "refinement>") != std::string::npos &&
                      errors.find("GB of memory of the") != std::string::npos &&
                      errors.find("Allowed:") != std::string::npos ?
                    "yes" :
                    "no");
    }

  std::printf("* earlier results kept: %s\n",
              tests::read_file("earlier-run/statistics") ==
                    "earlier results\n" &&
                  tests::read_file("earlier-run/log.txt") == "earlier log\n" ?
                "yes" :
                "no");
  std::printf("* a valid run exits with code %d\n", tests::run({"valid.prm"}));
}
