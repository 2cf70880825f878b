// Anisotropic elastic constants (Material::ElasticMaterials with
// <Material/Symmetry>): the Voigt matrices of each class, the rotation to
// the model's frame, the Christoffel phase speeds against closed forms of a
// transversely isotropic medium (along, across and oblique to the axis),
// the extreme speeds over all directions against a fine search, the 2-D
// plane-strain part, the shear stiffness across a plane and the boundary
// impedance; isotropic constants given as a general tensor agree with the
// isotropic formulas. Then every refused input and its message.

#include <rupture/material/elastic_material.h>

#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>

#include <cmath>
#include <iomanip>
#include <iostream>
#include <string>

using namespace dealii;
using namespace rupture::Material;

namespace
{
  ElasticMaterials
  parse(const std::string &entries, const unsigned int dim = 3)
  {
    ParameterHandler prm;
    ElasticMaterials::declare_parameters(prm);
    prm.parse_input_from_string("subsection Material\n" + entries + "end\n");
    ElasticMaterials materials;
    materials.parse_parameters(prm, dim);
    return materials;
  }



  void
  refuse(const std::string &label,
         const std::string &entries,
         const unsigned int dim = 3)
  {
    try
      {
        parse(entries, dim);
        std::cout << label << ": accepted (WRONG)" << std::endl;
      }
    catch (const std::exception &e)
      {
        // The message alone, without deal.II's frame and stack trace.
        std::string text = e.what();
        const auto  msg  = text.find("Additional information:");
        if (msg != std::string::npos)
          text = text.substr(msg + 24);
        const auto stack = text.find("Stacktrace");
        if (stack != std::string::npos)
          text = text.substr(0, stack);
        while (!text.empty() && (text.back() == '\n' || text.back() == ' ' ||
                                 text.back() == '-'))
          text.pop_back();
        std::cout << label << ": refused:" << text << std::endl;
      }
  }



  bool
  close(const double a, const double b, const double tolerance = 1e-10)
  {
    return std::abs(a - b) <= tolerance * std::max(std::abs(a), std::abs(b));
  }
} // namespace



int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  std::cout << std::setprecision(6);

  // A transversely isotropic shale-like medium (Pa, kg/m^3), axis along z.
  const double rho = 2500, c11 = 6.0e10, c33 = 4.0e10, c13 = 1.5e10,
               c44 = 1.2e10, c66 = 2.0e10;
  const std::string ti_constants =
    "C11 = 6.0e10, C33 = 4.0e10, C13 = 1.5e10, C44 = 1.2e10, C66 = 2.0e10";
  {
    const ElasticMaterials  m = parse("  set Density = 2500\n"
                                      "  set Symmetry = transversely isotropic\n"
                                      "  set Stiffness = " +
                                     ti_constants + "\n");
    const ElasticConstants &c = m.get(0);
    std::cout << m.summary();
    // Closed forms at an angle theta from the axis.
    bool all = true;
    for (const double degrees : {0., 30., 45., 60., 90.})
      {
        const double theta = degrees * M_PI / 180;
        const double s = std::sin(theta), co = std::cos(theta);
        Tensor<1, 3> n;
        n[0]           = s;
        n[2]           = co;
        const double a = (c11 - c44) * s * s - (c33 - c44) * co * co;
        const double root =
          std::sqrt(a * a + 4 * std::pow((c13 + c44) * s * co, 2));
        const double qp =
          std::sqrt((c11 * s * s + c33 * co * co + c44 + root) / (2 * rho));
        const double qsv =
          std::sqrt((c11 * s * s + c33 * co * co + c44 - root) / (2 * rho));
        const double sh     = std::sqrt((c66 * s * s + c44 * co * co) / rho);
        const auto   v      = phase_speeds(c.voigt, rho, n);
        const double sv_min = std::min(qsv, sh), sv_max = std::max(qsv, sh);
        const bool   ok =
          close(v[0], qp) && close(v[1], sv_max) && close(v[2], sv_min);
        all = all && ok;
        std::cout << "  theta " << degrees << ": qP " << v[0]
                  << " (closed form " << qp << "), shear " << v[1] << ", "
                  << v[2] << " (closed forms " << sv_max << ", " << sv_min
                  << ")" << std::endl;
      }
    std::cout << "TI speeds equal the closed forms to 1e-10: "
              << (all ? "yes" : "no") << std::endl;

    // The extremes over all directions against a search every 0.1 degree
    // in the x-z plane (the medium is symmetric about z).
    double slow = 1e300, fast = 0;
    for (int i = 0; i <= 900; ++i)
      {
        const double theta = i * 0.1 * M_PI / 180;
        Tensor<1, 3> n;
        n[0]         = std::sin(theta);
        n[2]         = std::cos(theta);
        const auto v = phase_speeds(c.voigt, rho, n);
        slow         = std::min(slow, v[2]);
        fast         = std::max(fast, v[0]);
      }
    const SpeedRange r = c.wave_speeds<3>();
    std::cout << "3-D extremes " << r.slowest << ", " << r.fastest
              << " m/s; fine search " << slow << ", " << fast
              << "; within 1e-5: "
              << (close(r.slowest, slow, 1e-5) && close(r.fastest, fast, 1e-5) ?
                    "yes" :
                    "no")
              << std::endl;

    // Normal along the axis: shear stiffness C44; impedance
    // rho (vs, vs, vp) with vs = sqrt(C44/rho), vp = sqrt(C33/rho).
    Tensor<1, 3> z;
    z[2]                           = 1;
    const SymmetricTensor<2, 3> zi = c.boundary_impedance<3>(z);
    std::cout << "across the plane normal to the axis: shear modulus "
              << c.shear_modulus_across<3>(z) << " (C44 " << c44
              << "), impedance " << zi[0][0] << " " << zi[1][1] << " "
              << zi[2][2] << ", off the diagonal below 1e-12 of it: "
              << (std::abs(zi[0][1]) + std::abs(zi[0][2]) + std::abs(zi[1][2]) <
                      1e-12 * zi.norm() ?
                    "yes" :
                    "no")
              << " (expected " << std::sqrt(rho * c44) << " "
              << std::sqrt(rho * c44) << " " << std::sqrt(rho * c33) << ")"
              << std::endl;
    Tensor<1, 3> x;
    x[0] = 1;
    std::cout << "across the plane normal to x: shear modulus "
              << c.shear_modulus_across<3>(x) << " (mean of C66 and C44 "
              << 0.5 * (c66 + c44) << ")" << std::endl;

    // A boundary oblique to the axis: Z = sqrt(rho Gamma(n)) is a full
    // matrix, Z Z = rho Gamma, and Z p = rho c p for each plane wave that
    // leaves along n (c its phase speed, p its polarization).
    for (const double degrees : {30., 70.})
      {
        const double theta = degrees * M_PI / 180;
        Tensor<1, 3> n;
        n[0]                            = std::sin(theta);
        n[1]                            = 0.3;
        n[2]                            = std::cos(theta);
        n                               = n / n.norm();
        const SymmetricTensor<2, 3> zn  = c.boundary_impedance<3>(n);
        const SymmetricTensor<2, 3> g   = christoffel_matrix(c.voigt, n);
        const double                off = std::abs(zn[0][2]) / zn[0][0];
        const double                root =
          (Tensor<2, 3>(zn) * Tensor<2, 3>(zn) - Tensor<2, 3>(rho * g)).norm() /
          (rho * g).norm();
        const auto speeds = phase_speeds(c.voigt, rho, n);
        const auto pairs  = eigenvectors(g);
        double     worst  = 0;
        for (unsigned int k = 0; k < 3; ++k)
          worst = std::max(
            worst,
            (zn * pairs[k].second - rho * speeds[k] * pairs[k].second).norm() /
              (rho * speeds[k]));
        std::cout << "oblique boundary, " << degrees
                  << " degrees from the axis: |Z_xz| / Z_xx = " << off
                  << " (nonzero: " << (off > 1e-3 ? "yes" : "no")
                  << "), Z Z = rho Gamma within 1e-12: "
                  << (root < 1e-12 ? "yes" : "no")
                  << ", Z p = rho c p for qP, qS1, qS2 within 1e-12: "
                  << (worst < 1e-12 ? "yes" : "no") << std::endl;
      }
  }

  // The same medium with its axis along x (three numbers), and along x
  // given by the material's 1- and 2-axes (six numbers): speeds along x
  // are those along the axis above; the Kelvin eigenvalues do not change.
  for (const std::string axes : {"1, 0, 0", "0, 1, 0, 0, 0, 1"})
    {
      const ElasticMaterials m =
        parse("  set Density = 2500\n"
              "  set Symmetry = transversely isotropic\n"
              "  set Stiffness = " +
              ti_constants +
              "\n"
              "  set Material axes = " +
              axes + "\n");
      Tensor<1, 3> x;
      x[0]         = 1;
      const auto v = phase_speeds(m.get(0).voigt, rho, x);
      std::cout << "axis along x (" << axes << "): along x " << v[0] << ", "
                << v[1] << ", " << v[2] << " m/s (expected "
                << std::sqrt(c33 / rho) << ", " << std::sqrt(c44 / rho) << ", "
                << std::sqrt(c44 / rho) << ")" << std::endl;
    }

  // A rotation about an oblique axis: the Kelvin eigenvalues (invariants)
  // stay, and the speeds along a rotated direction are those along the
  // original one.
  {
    const ElasticMaterials m =
      parse("  set Density = 2500\n"
            "  set Symmetry = orthotropic\n"
            "  set Stiffness = C11 = 7e10, C22 = 5e10, C33 = 4e10, C12 = "
            "1.2e10, C13 = 1.1e10, C23 = 1.3e10, C44 = 1.4e10, C55 = 1.6e10, "
            "C66 = 1.9e10\n");
    const ElasticMaterials rotated =
      parse("  set Density = 2500\n"
            "  set Symmetry = orthotropic\n"
            "  set Stiffness = C11 = 7e10, C22 = 5e10, C33 = 4e10, C12 = "
            "1.2e10, C13 = 1.1e10, C23 = 1.3e10, C44 = 1.4e10, C55 = 1.6e10, "
            "C66 = 1.9e10\n"
            "  set Material axes = 2, 1, 2, -1, 2, 0\n");
    // The material's axes in model coordinates, as parse_axes builds them.
    Tensor<1, 3> a1, a2;
    a1[0]                 = 2. / 3;
    a1[1]                 = 1. / 3;
    a1[2]                 = 2. / 3;
    a2[0]                 = -1 / std::sqrt(5.);
    a2[1]                 = 2 / std::sqrt(5.);
    const Tensor<1, 3> a3 = cross_product_3d(a1, a2);
    Tensor<1, 3>       n;
    n[0] = 0.3;
    n[1] = -0.5;
    n[2] = 0.81;
    n /= n.norm();
    // n in the material's frame is (n.a1, n.a2, n.a3) in the model's.
    const Tensor<1, 3> model_n = n[0] * a1 + n[1] * a2 + n[2] * a3;
    const auto         v0      = phase_speeds(m.get(0).voigt, rho, n);
    const auto         v1   = phase_speeds(rotated.get(0).voigt, rho, model_n);
    const auto         e0   = kelvin_eigenvalues(m.get(0).voigt);
    const auto         e1   = kelvin_eigenvalues(rotated.get(0).voigt);
    bool               same = true;
    for (unsigned int i = 0; i < 3; ++i)
      same = same && close(v0[i], v1[i], 1e-12);
    for (unsigned int i = 0; i < 6; ++i)
      same = same && close(e0[i], e1[i], 1e-12);
    std::cout << "orthotropic, rotated: speeds " << v1[0] << ", " << v1[1]
              << ", " << v1[2]
              << " m/s; speeds and Kelvin eigenvalues invariant to 1e-12: "
              << (same ? "yes" : "no") << "; model plane a mirror plane: "
              << (model_plane_is_mirror_plane(rotated.get(0).voigt) ? "yes" :
                                                                      "no")
              << std::endl;
  }

  // Isotropic constants given as a general tensor: the same stiffness,
  // stress, speeds, impedance and shear stiffness as the isotropic
  // material (2-D and 3-D).
  {
    const double lambda = 2670. * (6000. * 6000 - 2 * 3464. * 3464),
                 mu     = 2670. * 3464. * 3464;
    std::ostringstream general;
    general << std::setprecision(17);
    for (unsigned int I = 0; I < 6; ++I)
      for (unsigned int J = I; J < 6; ++J)
        {
          const double value = (I < 3 && J < 3) ?
                                 lambda + (I == J ? 2 * mu : 0.) :
                                 (I == J ? mu : 0.);
          general << (I + J > 0 ? ", " : "") << "C" << I + 1 << J + 1 << " = "
                  << value;
        }
    for (const unsigned int dim : {2u, 3u})
      {
        const ElasticMaterials  m   = parse("  set Names = isotropic, general\n"
                                            "  set Density = 2670\n"
                                            "  set P-wave speed = 6000\n"
                                            "  set S-wave speed = 3464\n"
                                            "  set Symmetry = isotropic, general\n"
                                            "  set Stiffness = ; " +
                                           general.str() + "\n",
                                         dim);
        const ElasticConstants &iso = m.get(0), &gen = m.get(1);
        bool                    same = true;
        Tensor<1, 3>            n;
        n[0] = 0.6;
        n[1] = 0.8;
        if (dim == 3)
          {
            SymmetricTensor<2, 3> eps;
            eps[0][0]     = 1e-4;
            eps[0][1]     = 3e-5;
            eps[1][2]     = -2e-5;
            eps[2][2]     = 5e-5;
            const auto s0 = iso.stress<3>(eps), s1 = gen.stress<3>(eps);
            same            = same && (s0 - s1).norm() <= 1e-12 * s0.norm();
            Tensor<1, 3> n3 = n;
            same =
              same &&
              (iso.boundary_impedance<3>(n3) - gen.boundary_impedance<3>(n3))
                  .norm() <= 1e-9 * iso.boundary_impedance<3>(n3).norm();
            same = same && close(iso.shear_modulus_across<3>(n3),
                                 gen.shear_modulus_across<3>(n3),
                                 1e-12);
          }
        else
          {
            SymmetricTensor<2, 2> eps;
            eps[0][0]     = 1e-4;
            eps[0][1]     = 3e-5;
            eps[1][1]     = -2e-5;
            const auto s0 = iso.stress<2>(eps), s1 = gen.stress<2>(eps);
            same = same && (s0 - s1).norm() <= 1e-12 * s0.norm();
            Tensor<1, 2> n2;
            n2[0] = n[0];
            n2[1] = n[1];
            same =
              same &&
              (iso.boundary_impedance<2>(n2) - gen.boundary_impedance<2>(n2))
                  .norm() <= 1e-9 * iso.boundary_impedance<2>(n2).norm();
            same = same && close(iso.shear_modulus_across<2>(n2),
                                 gen.shear_modulus_across<2>(n2),
                                 1e-12);
          }
        const SpeedRange r =
          (dim == 2 ? gen.wave_speeds<2>() : gen.wave_speeds<3>());
        same =
          same && close(r.fastest, 6000, 1e-9) && close(r.slowest, 3464, 1e-9);
        std::cout << dim << "-D: isotropic constants as a general tensor "
                  << "give the isotropic stress, impedance, shear stiffness "
                     "and speeds: "
                  << (same ? "yes" : "no") << std::endl;
      }
  }

  // A TI medium in 2-D with its axis in the model plane: the model plane
  // is a mirror plane; in-plane speeds along the axis.
  {
    const ElasticMaterials m = parse("  set Density = 2500\n"
                                     "  set Symmetry = transversely isotropic\n"
                                     "  set Stiffness = " +
                                       ti_constants +
                                       "\n"
                                       "  set Material axes = 1, 1, 0\n",
                                     2);
    std::cout << "2-D, axis (1, 1, 0): " << m.summary();
  }

  // Refused inputs.
  const std::string ti = "  set Symmetry = transversely isotropic\n";
  refuse("unknown class", "  set Symmetry = cubic\n");
  refuse("stiffness of an isotropic material",
         "  set Stiffness = " + ti_constants + "\n");
  refuse("missing constant", ti + "  set Stiffness = C11 = 6e10, C33 = 4e10\n");
  refuse("constant of another class",
         ti + "  set Stiffness = " + ti_constants + ", C22 = 1e10\n");
  refuse("not a number",
         ti + "  set Stiffness = C11 = six, C33 = 4e10, C13 "
              "= 1.5e10, C44 = 1.2e10, C66 = 2e10\n");
  refuse("item without a value", ti + "  set Stiffness = C11\n");
  refuse("not positive definite",
         ti + "  set Stiffness = C11 = 6e10, C33 = 4e10, C13 = 5e10, C44 = "
              "1.2e10, C66 = 2e10\n");
  refuse("nearly singular",
         ti + "  set Stiffness = C11 = 6e10, C33 = 4e10, C13 = 1.5e10, C44 "
              "= 1e-2, C66 = 2e10\n");
  refuse("fields per material",
         "  set Names = a, b, c\n" + ti + "  set Stiffness = " + ti_constants +
           "; " + ti_constants + "\n");
  refuse("axes not orthogonal",
         ti + "  set Stiffness = " + ti_constants +
           "\n  set Material axes = 1, 0, 0, 1, 1, 0\n");
  refuse("axis zero",
         ti + "  set Stiffness = " + ti_constants +
           "\n  set Material axes = 0, 0, 0\n");
  refuse("three numbers for an orthotropic material",
         "  set Symmetry = orthotropic\n  set Stiffness = C11 = 7e10, C22 = "
         "5e10, C33 = 4e10, C12 = 1.2e10, C13 = 1.1e10, C23 = 1.3e10, C44 = "
         "1.4e10, C55 = 1.6e10, C66 = 1.9e10\n  set Material axes = 0, 0, 1\n");
  refuse("four numbers",
         ti + "  set Stiffness = " + ti_constants +
           "\n  set Material axes = 0, 0, 1, 0\n");
  refuse("2-D, axis oblique to the model plane",
         ti + "  set Stiffness = " + ti_constants +
           "\n  set Material axes = 1, 0, 1\n",
         2);
  refuse("speeds above the speed of light",
         "  set Density = 1e-3\n" + ti +
           "  set Stiffness = C11 = 6e19, C33 "
           "= 4e19, C13 = 1.5e19, C44 = 1.2e19, "
           "C66 = 2e19\n");
}
