// The linear slip-weakening law (the GeoFEM paper's eq. 2): mu falls
// linearly from mu_0 to mu_d over L_d and stays at mu_d; its derivative;
// position-dependent parameters; the state update; bad parameters.

#include <rupture/friction/interface.h>

#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>

#include <cstdio>
#include <iostream>

using namespace dealii;

std::unique_ptr<rupture::Friction::Interface>
make(const std::string &mu0, const std::string &mud, const std::string &ld)
{
  ParameterHandler prm;
  prm.enter_subsection("Fault");
  rupture::Friction::declare_parameters(prm);
  prm.set("Friction law", "linear slip weakening");
  prm.enter_subsection("Linear slip weakening");
  prm.set("Static friction coefficient", mu0);
  prm.set("Dynamic friction coefficient", mud);
  prm.set("Slip-weakening distance", ld);
  prm.set("Cohesion", "1e6");
  prm.leave_subsection();
  auto law = rupture::Friction::create(prm);
  prm.leave_subsection();
  return law;
}

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);

  // The paper's bonded zone, and a weak patch near x = 0 via a function.
  const auto law = make("(abs(x) < 10000) ? 0.5 : 0.606", "0.6", "1");
  rupture::Friction::State state;
  const Point<3>           far(50000, 0, -20000), patch(0, 0, -20000);
  law->initialize_state(far, state);

  std::printf("slip path  mu       dmu/ds\n");
  for (const double s : {0., 0.25, 0.5, 0.999, 1., 2.})
    {
      double       d  = 0;
      const double mu = law->coefficient(far, state, s, 0.1, d);
      std::printf("%-10.3f %.6f %.6f\n", s, mu, d);
    }
  double d = 0;
  std::printf("mu in the patch (where mu_0 < mu_d is not allowed): ");
  try
    {
      law->initialize_state(patch, state);
      std::printf("accepted\n");
    }
  catch (const ExceptionBase &e)
    {
      std::printf("rejected\n");
    }
  std::printf("cohesion: %.0f Pa\n", law->cohesion(far, state));

  // The state after a step: the slip path accumulates.
  rupture::Friction::State old, updated;
  old.slip_path = 0.3;
  law->update_state(far, old, 0.2, 0.1, 0., updated);
  std::printf("slip path after 0.2 m more: %.3f m, slip rate %.3f m/s\n",
              updated.slip_path,
              updated.slip_rate);
  std::printf("mu continues from the old path: %.6f\n",
              law->coefficient(far, old, 0.2, 0.1, d));

  // Bad parameters are rejected with a message naming the entry.
  for (const auto &[mu0, mud, ld] : std::vector<std::array<std::string, 3>>{
         {"0.6", "0.5", "0"}, {"0.6", "-0.1", "1"}, {"0.6", "0.5", "x+"}})
    try
      {
        const auto bad = make(mu0, mud, ld);
        bad->initialize_state(far, state);
        std::printf("accepted mu0=%s mud=%s L=%s\n",
                    mu0.c_str(),
                    mud.c_str(),
                    ld.c_str());
      }
    catch (const ExceptionBase &e)
      {
        std::ostringstream s;
        e.print_info(s);
        std::string m = s.str();
        m.erase(0, m.find_first_not_of(' '));
        std::printf("rejected: %s", m.c_str());
      }
}
