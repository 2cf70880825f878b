#include <rupture/time_integration/central_difference.h>
#include <rupture/time_integration/implicit_newmark.h>
#include <rupture/time_integration/quasi_static.h>

namespace rupture
{
  namespace TimeIntegration
  {
    template <int dim>
    std::unique_ptr<Interface<dim>>
    create(const Scheme scheme, Simulator<dim> &simulator)
    {
      switch (scheme)
        {
          case Scheme::implicit_newmark:
            return std::make_unique<ImplicitNewmark<dim>>(simulator);
          case Scheme::explicit_central_difference:
            return std::make_unique<CentralDifference<dim>>(simulator);
          case Scheme::quasi_static:
            return std::make_unique<QuasiStatic<dim>>(simulator);
        }
      return nullptr;
    }



    template std::unique_ptr<Interface<2>>
    create(const Scheme, Simulator<2> &);
    template std::unique_ptr<Interface<3>>
    create(const Scheme, Simulator<3> &);
  } // namespace TimeIntegration
} // namespace rupture
