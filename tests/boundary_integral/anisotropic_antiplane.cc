// The antiplane problem in an anisotropic body whose model plane is a
// plane of mirror symmetry and whose C45 vanishes: C55 u,xx + C44 u,yy = 0
// for the out-of-plane displacement, the fault at x = 0, the free surface
// at y = 0. Stretching the depths by sqrt(C55 / C44) makes it the
// isotropic problem of modulus C55, and since the fault's kernel is
// homogeneous of degree -1 in the depths, the fault sees the isotropic
// body of modulus sqrt(C44 C55). Checked three ways:
//  - The finite-element model of the body (AntiplaneFiniteElements, which
//    assembles C55 u,x v,x + C44 u,y v,y and knows nothing of the
//    argument), degree 2, nodes 500 m apart: the surface-breaking crack
//    whose slip is elliptical with the modulus sqrt(C44 C55) has its
//    uniform stress drop to the accuracy of the isotropic case
//    (finite_element_kernel), and not with the modulus C55.
//  - A whole run of SEAS BP1-QD (prm/seas/bp1-qd-bi.prm, 500 m elements,
//    its first 250 years, through the first event) in transversely
//    isotropic rock with the axis vertical, C55 = C66 = 4 mu and C44 =
//    mu / 4, takes the isotropic run's steps digit for digit (the same
//    statistics and station rows); its moments are 4 times larger (C55).
//  - Refused, with messages: C45 not zero (the axis oblique in the model
//    plane), an axis out of the model plane, a stiffness factor.

#include <rupture/boundary_integral/antiplane_finite_elements.h>

#include <deal.II/base/mpi.h>

#include "../tests.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

using rupture::BoundaryIntegral::AntiplaneFiniteElements;

namespace
{
  // (mu = 2670 kg/m^3 (3464 m/s)^2, BP1's rock.)
  const double mu = 32038120320., dtau = 3e6, a = 10e3;

  /// The largest relative error of -dtau over the upper 75 % of the
  /// crack for the elliptical slip of modulus @p modulus.
  double
  crack_error(const AntiplaneFiniteElements &fault, const double modulus)
  {
    const unsigned int  n = fault.size();
    const auto          K = fault.rows(0, n);
    std::vector<double> slip(n, 0.);
    for (unsigned int j = 0; j < n; ++j)
      if (fault.depth(j) < a)
        slip[j] = 2 * dtau / modulus *
                  std::sqrt(a * a - fault.depth(j) * fault.depth(j));
    double error = 0;
    for (unsigned int i = 0; i < n; ++i)
      if (fault.depth(i) < 0.75 * a)
        {
          double tau = 0;
          for (unsigned int j = 0; j < n; ++j)
            tau += K[i * n + j] * slip[j];
          error = std::max(error, std::abs(tau + dtau) / dtau);
        }
    return error;
  }

  const std::string ti_material =
    "Material/Stiffness=C11 = 512609925120, C33 = 512609925120, C13 = "
    "64076240640, "
    "C44 = 8009530080, C66 = 128152481280";
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);

  for (const auto &[C55, C44] : {std::pair{mu, mu},
                                 std::pair{4 * mu, mu / 4},
                                 std::pair{mu / 4, 4 * mu},
                                 std::pair{2 * mu, 2 * mu}})
    {
      AntiplaneFiniteElements::Settings s;
      s.fault_depth            = 40e3;
      s.node_spacing           = 500;
      s.degree                 = 2;
      s.shear_modulus          = C55;
      s.vertical_shear_modulus = C44;
      const AntiplaneFiniteElements fault(s, MPI_COMM_WORLD);
      const double effective = crack_error(fault, std::sqrt(C44 * C55));
      const double naive     = crack_error(fault, C55);
      std::printf("C55 = %4.2f mu, C44 = %4.2f mu: crack with sqrt(C44 C55) "
                  "within 1e-2: %s; with C55 within 1e-2: %s\n",
                  C55 / mu,
                  C44 / mu,
                  effective < 1e-2 ? "yes" : "no",
                  naive < 1e-2 ? "yes" : "no");
    }

  // Whole runs: isotropic, and TI with the axis vertical (the material's
  // 3-axis along y: C55 = C66 = 4 mu, C44 = mu / 4).
  const std::string prm =
    std::string(SOURCE_DIR) + "/../../prm/seas/bp1-qd-bi.prm";
  const std::vector<std::string> settings = {
    "Boundary integral/Element size=500",
    "Time integration/End time=7.9e9",
    "Boundary integral/Profile interval between events=0",
    "Boundary integral/Profile interval during events=0",
    "Test mode=true"};
  auto ti = settings;
  ti.insert(ti.end(),
            {"Material/Symmetry=transversely isotropic",
             ti_material,
             "Material/Material axes=0, 1, 0"});
  const int isotropic   = tests::run_in("isotropic", {prm}, settings);
  const int anisotropic = tests::run_in("anisotropic", {prm}, ti);
  if (dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
    {
      std::printf("runs: exit codes %d and %d\n", isotropic, anisotropic);
      for (const std::string file : {"statistics.dat", "fltst_dp075.dat"})
        std::printf("%s the same: %s\n",
                    file.c_str(),
                    tests::read_file("isotropic/" + file) ==
                        tests::read_file("anisotropic/" + file) ?
                      "yes" :
                      "no");
      const auto one = tests::read_csv("isotropic/events.csv");
      const auto two = tests::read_csv("anisotropic/events.csv");
      // The moment (column 9) takes C55 = 4 mu.
      bool four = !one.empty() && one.size() == two.size();
      for (unsigned int e = 0; four && e < one.size(); ++e)
        four = one[e].size() > 8 && two[e].size() > 8 &&
               std::abs(two[e][8] - 4 * one[e][8]) <= 1e-9 * two[e][8];
      std::printf("events: %zu and %zu, moments 4 times the isotropic "
                  "run's: %s\n",
                  one.size(),
                  two.size(),
                  four ? "yes" : "no");
    }

  // Refused inputs.
  for (const auto &[what, extra] :
       {std::pair{
          std::string("axis oblique in the model plane (C45)"),
          std::vector<std::string>{"Material/Symmetry=transversely isotropic",
                                   ti_material,
                                   "Material/Material axes=1, 1, 0"}},
        std::pair{
          std::string("axis out of the model plane"),
          std::vector<std::string>{"Material/Symmetry=transversely isotropic",
                                   ti_material,
                                   "Material/Material axes=0, 1, 1"}},
        std::pair{std::string("a stiffness factor"),
                  std::vector<std::string>{"Material/Stiffness factor=2"}}})
    {
      std::vector<std::string> arguments = {prm};
      for (const auto &s : settings)
        arguments.insert(arguments.end(), {"--set", s});
      for (const auto &s : extra)
        arguments.insert(arguments.end(), {"--set", s});
      arguments.insert(arguments.end(), {"--set", "Output directory=refused"});
      std::string  errors;
      const int    code  = tests::run_capture(arguments, errors);
      const auto   start = errors.find("Error:");
      const size_t end   = errors.find('\n', start);
      std::printf("%s: exit code %d\n  %s\n",
                  what.c_str(),
                  code,
                  start == std::string::npos ?
                    "(no message)" :
                    errors.substr(start, end - start).c_str());
    }
}
