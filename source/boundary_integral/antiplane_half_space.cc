// The stiffness of the antiplane half-space fault (the dual method's
// traction from slip).

#include <rupture/boundary_integral/antiplane_half_space.h>
#include <rupture/boundary_integral/text.h>

#include <deal.II/base/exceptions.h>

#include <cmath>
#include <iomanip>
#include <sstream>
#include <string>

namespace rupture
{
  namespace BoundaryIntegral
  {
    AntiplaneHalfSpace::AntiplaneHalfSpace(const double depth,
                                           const double element_size,
                                           const double shear_modulus,
                                           const double moment_modulus)
      : n(0)
      , h(0)
      , mu(shear_modulus)
      , moment_mu(moment_modulus > 0 ? moment_modulus : shear_modulus)
    {
      using dealii::ExcMessage;
      AssertThrow(std::isfinite(depth) && depth > 0,
                  ExcMessage("<Boundary integral/Fault depth> is " +
                             number(depth) + ", but it must be > 0 (m)."));
      AssertThrow(std::isfinite(element_size) && element_size > 0 &&
                    element_size <= depth,
                  ExcMessage("<Boundary integral/Element size> is " +
                             number(element_size) +
                             ", but it must be > 0 and at most <Fault "
                             "depth> (m)."));
      const double elements = std::ceil(depth / element_size - 1e-9);
      AssertThrow(elements <= 20000,
                  ExcMessage("<Boundary integral/Element size> of " +
                             number(element_size) + " m cuts the fault into " +
                             number(elements) +
                             " elements; the dense stiffness allows at most "
                             "20000 (3.2 GB). Give a larger element size."));
      AssertThrow(std::isfinite(mu) && mu > 0,
                  ExcMessage("The shear modulus (density times the S-wave "
                             "speed squared, <Material>) must be > 0."));
      n = static_cast<unsigned int>(elements);
      h = depth / n;
    }



    double
    AntiplaneHalfSpace::stiffness(const unsigned int i,
                                  const unsigned int j) const
    {
      const double z  = centre(i);
      const double d1 = j * h, d2 = (j + 1) * h;
      return mu / (2 * M_PI) *
             (1 / (z - d2) - 1 / (z - d1) + 1 / (z + d1) - 1 / (z + d2));
    }



    std::vector<double>
    AntiplaneHalfSpace::rows(const unsigned int begin,
                             const unsigned int end) const
    {
      std::vector<double> k;
      k.reserve(std::size_t(end - begin) * n);
      for (unsigned int i = begin; i < end; ++i)
        for (unsigned int j = 0; j < n; ++j)
          k.push_back(stiffness(i, j));
      return k;
    }



    std::string
    AntiplaneHalfSpace::description() const
    {
      std::ostringstream s;
      s << std::setprecision(6) << "antiplane half-space, " << n
        << " elements of " << h << " m down to " << n * h / 1e3 << " km";
      return s.str();
    }
  } // namespace BoundaryIntegral
} // namespace rupture
