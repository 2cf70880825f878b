// The return mapping of penalty contact with Coulomb friction (GeoFEM
// paper, section 3.2) at one fault point: traction in stick, slip, slip
// while weakening, slip beyond L_d and opening; the Coulomb condition; and
// the consistent tangent against central finite differences of the
// return-mapped traction, in 2-D and 3-D with an oblique fault normal.

#include <rupture/fault/contact.h>
#include <rupture/friction/interface.h>

#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>

#include <cstdio>

using namespace dealii;
using rupture::Fault::ContactStatus;

const char *
name(const ContactStatus s)
{
  return s == ContactStatus::stick ?
           "stick" :
           (s == ContactStatus::slip ? "slip" : "open");
}

template <int dim>
void
check(const std::string                  &title,
      const rupture::Friction::Interface &law,
      const Tensor<1, dim>               &delta,
      const Tensor<1, dim>               &t0,
      const double                        slip_path)
{
  Tensor<1, dim> n;
  if (dim == 2)
    {
      n[0] = 0.6;
      n[1] = 0.8;
    }
  else
    {
      n[0] = 1. / 3;
      n[1] = 2. / 3;
      n[2] = 2. / 3;
    }
  const double             pn = 5e11, pt = 4e11, dt = 0.1;
  Tensor<1, dim>           old_plastic;
  rupture::Friction::State state;
  state.slip_path = slip_path;
  const Point<3> x;

  const auto r = rupture::Fault::return_map<dim>(
    delta, n, t0, pn, pt, old_plastic, state, law, x, dt);

  // Central differences of the traction.
  double max_error = 0, scale = 0;
  for (unsigned int j = 0; j < dim; ++j)
    {
      const double   h    = 1e-9;
      Tensor<1, dim> plus = delta, minus = delta;
      plus[j] += h;
      minus[j] -= h;
      const auto rp = rupture::Fault::return_map<dim>(
        plus, n, t0, pn, pt, old_plastic, state, law, x, dt);
      const auto rm = rupture::Fault::return_map<dim>(
        minus, n, t0, pn, pt, old_plastic, state, law, x, dt);
      for (unsigned int i = 0; i < dim; ++i)
        {
          const double fd = (rp.traction[i] - rm.traction[i]) / (2 * h);
          max_error       = std::max(max_error, std::abs(fd - r.tangent[i][j]));
          scale           = std::max(scale, std::abs(r.tangent[i][j]));
        }
    }
  const double tn = r.traction * n;
  const double tt = (r.traction - tn * n).norm();
  const double strength =
    r.friction * std::max(-tn, 0.) + law.cohesion(x, state);
  std::printf("%d-D %-34s %-5s T_n = %9.4f MPa, |T_t| = %8.4f MPa, "
              "strength %8.4f MPa, slip increment %.4e m, mu %.4f\n",
              dim,
              title.c_str(),
              name(r.status),
              tn / 1e6,
              tt / 1e6,
              strength / 1e6,
              r.slip_increment,
              r.friction);
  std::printf("      Coulomb |T_t| <= strength: %s; tangent matches finite "
              "differences to 1e-5: %s\n",
              tt <= strength * (1 + 1e-12) + 1e-6 ? "yes" : "no",
              max_error <= 1e-5 * std::max(scale, 1.) ? "yes" : "no");
}

template <int dim>
void
run(const rupture::Friction::Interface &law,
    const rupture::Friction::Interface &steep_law)
{
  Tensor<1, dim> n, s, t0;
  if (dim == 2)
    {
      n[0] = 0.6;
      n[1] = 0.8;
      s[0] = -0.8;
      s[1] = 0.6;
    }
  else
    {
      n[0] = 1. / 3;
      n[1] = 2. / 3;
      n[2] = 2. / 3;
      s[0] = 2. / 3;
      s[1] = 1. / 3;
      s[2] = -2. / 3;
    }
  // Initial traction: 120 MPa compression, 70 MPa shear along s (TPV3).
  t0 = -120e6 * n + 70e6 * s;
  check<dim>("stick (small slip)", law, 1e-6 * s - 1e-6 * n, t0, 0.);
  check<dim>("slip, weakening (s < L_d)", law, 1e-4 * s, t0, 0.);
  check<dim>("slip, weakening across L_d", law, 1e-4 * s, t0, 0.39999);
  check<dim>("slip beyond L_d (mu = mu_d)", law, 1e-4 * s, t0, 1.);
  check<dim>("slip with oblique trial", law, 1e-4 * s + 2e-5 * n, t0, 0.1);
  check<dim>("open (tension)", law, 1e-3 * n + 1e-4 * s, t0, 0.);
  // L_d = 0.1 mm: the weakening slope is 45 % of the tangential penalty.
  check<dim>("slip, steep weakening", steep_law, 3e-5 * s, t0, 0.);
}

std::unique_ptr<rupture::Friction::Interface>
make(const std::string &weakening_distance)
{
  ParameterHandler prm;
  prm.enter_subsection("Fault");
  rupture::Friction::declare_parameters(prm);
  prm.set("Friction law", "linear slip weakening");
  prm.enter_subsection("Linear slip weakening");
  prm.set("Static friction coefficient", "0.677");
  prm.set("Dynamic friction coefficient", "0.525");
  prm.set("Slip-weakening distance", weakening_distance);
  prm.leave_subsection();
  auto law = rupture::Friction::create(prm);
  prm.leave_subsection();
  return law;
}

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const auto                       law       = make("0.4");
  const auto                       steep_law = make("1e-4");
  run<2>(*law, *steep_law);
  run<3>(*law, *steep_law);
}
