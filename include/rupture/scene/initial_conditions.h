#ifndef rupture_scene_initial_conditions_h
#define rupture_scene_initial_conditions_h

#include <deal.II/base/function_parser.h>
#include <deal.II/base/parameter_handler.h>

#include <memory>

namespace rupture
{
  namespace Scene
  {
    using namespace dealii;

    /**
     * The initial displacement and velocity of the body (<Initial
     * conditions>), functions of position (zero when empty). A fault's
     * initial slip velocity is the fault's, added by the caller.
     */
    template <int dim>
    struct InitialConditions
    {
      static void
      declare_parameters(ParameterHandler &prm);
      /// Read <Initial conditions> (an error names the entry).
      void
      parse_parameters(ParameterHandler &prm);

      std::unique_ptr<FunctionParser<dim>> displacement;
      std::unique_ptr<FunctionParser<dim>> velocity;
    };
  } // namespace Scene
} // namespace rupture

#endif
