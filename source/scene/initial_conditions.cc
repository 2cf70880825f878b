#include <rupture/base/utilities.h>
#include <rupture/scene/initial_conditions.h>

namespace rupture
{
  namespace Scene
  {
    template <int dim>
    void
    InitialConditions<dim>::declare_parameters(ParameterHandler &prm)
    {
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
    }



    template <int dim>
    void
    InitialConditions<dim>::parse_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Initial conditions");
      displacement =
        Utilities::parse_function<dim>(prm.get("Displacement"),
                                       dim,
                                       "Initial conditions/Displacement");
      velocity = Utilities::parse_function<dim>(prm.get("Velocity"),
                                                dim,
                                                "Initial conditions/Velocity");
      prm.leave_subsection();
    }



    template struct InitialConditions<2>;
    template struct InitialConditions<3>;
  } // namespace Scene
} // namespace rupture
