#ifndef rupture_scene_boundary_conditions_h
#define rupture_scene_boundary_conditions_h

#include <deal.II/base/function_parser.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/tensor.h>
#include <deal.II/base/types.h>

#include <array>
#include <map>
#include <memory>
#include <string>
#include <vector>

namespace rupture
{
  using namespace dealii;

  namespace Scene
  {
    /**
     * Boundary conditions, each attached to a named boundary of the scene.
     *
     * Kinematic conditions constrain the displacement increment of a step:
     * "fixed" and "roller" keep chosen components at their current value
     * (normally zero), "prescribed velocity" moves all components at a
     * velocity given as a function of position and time (plate motion).
     * Tractions and absorbing (Lysmer-Kuhlemeyer) dashpots are natural
     * conditions; a boundary with none of these is traction free.
     */
    template <int dim>
    class BoundaryConditions
    {
    public:
      struct Kinematic
      {
        std::string        name;
        types::boundary_id id;
        /// Which components are constrained.
        std::array<bool, dim> components;
        /// Velocity of the constrained components (m/s) as a function of
        /// position and time; null for fixed and roller boundaries.
        std::shared_ptr<FunctionParser<dim>> velocity;
      };

      static void
      declare_parameters(ParameterHandler &prm);

      /**
       * Read the section, checking every boundary name against
       * @p boundary_names, the names the scene provides.
       */
      void
      parse_parameters(
        ParameterHandler                                &prm,
        const std::map<std::string, types::boundary_id> &boundary_names);

      std::vector<Kinematic>                                     kinematic;
      std::vector<std::pair<types::boundary_id, Tensor<1, dim>>> tractions;
      std::vector<types::boundary_id>                            absorbing;
    };
  } // namespace Scene
} // namespace rupture

#endif
