#ifndef rupture_fault_contact_h
#define rupture_fault_contact_h

#include <rupture/friction/interface.h>

#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>

namespace rupture
{
  namespace Fault
  {
    /**
     * The state of a fault point after the return mapping.
     */
    enum class ContactStatus
    {
      stick,
      slip,
      open
    };

    /**
     * What the return mapping computes at one fault point.
     */
    template <int dim>
    struct ContactResponse
    {
      /// Total traction (Pa) exerted by the plus side on the minus side,
      /// T = sigma n with n pointing from minus to plus. Compression is
      /// T.n < 0.
      Tensor<1, dim> traction;
      /// The tangential elastic trial traction (Pa), T_0 + p_t (delta -
      /// old plastic slip) projected on the fault plane, before the return
      /// mapping (zero where the point is open or its slip is imposed).
      Tensor<1, dim> trial_traction;
      /// The consistent tangent dT/d(delta) (Pa/m); nonsymmetric when
      /// slipping (the paper's D^ep, eq. 11).
      Tensor<2, dim> tangent;
      ContactStatus  status = ContactStatus::stick;
      /// Length of the plastic slip increment of the step (m).
      double slip_increment = 0;
      /// Accumulated plastic (frictional) slip vector after the step (m).
      Tensor<1, dim> plastic_slip;
      /// The frictional slip rate of the step as a vector (m/s): the plastic
      /// slip increment of penalty contact over dt, the slip rate over the
      /// next step that a split node's traction lets through. Set with
      /// anisotropic friction (the sliding rule's direction), else zero.
      Tensor<1, dim> sliding;
      /// Friction coefficient in effect.
      double friction = 0;
      /// Its derivative with respect to the slip increment (1/m): negative
      /// while the point weakens.
      double friction_derivative = 0;
      /// True if slip weakening is steeper than the tangential penalty where
      /// the point starts to slip: its traction then drops to the residual
      /// strength within the step (snap-back), a jump in the response that
      /// Newton's method handles poorly.
      bool unstable_softening = false;
    };

    /**
     * Penalty contact with Coulomb friction at one fault point, by the
     * return mapping of the GeoFEM paper (section 3.2).
     *
     * @p delta is the relative displacement u+ - u- (m), @p normal the unit
     * normal from the minus to the plus side, @p initial_traction the
     * traction (Pa) of the initial stress that the displacement field does
     * not carry (zero when the stress comes from a loading step). The
     * normal penalty p_n (Pa/m) resists interpenetration, and the fault
     * opens with zero traction under tension. The tangential penalty p_t
     * (Pa/m) gives the elastic trial traction, which is returned to the
     * friction strength mu |T_n| + cohesion when it exceeds it, with mu
     * from @p law as a function of the slip increment of the step. The
     * tangent is derived consistently with that mapping, so Newton's method
     * converges quadratically. With @p radiation_damping eta (Pa s/m) the
     * strength has the quasi-dynamic term eta l / dt added (the radiation
     * damping of Rice (1993), the SEAS benchmarks' -eta V), which the
     * tangent includes. Given the shear traction @p old_shear_traction at
     * the step's start, a law of the slip rate is met at the middle of
     * the step (the mean traction against the strength at the mean slip
     * rate, the state evolved over half the step: second order in time);
     * without it at the step's end (first order).
     */
    template <int dim>
    ContactResponse<dim>
    return_map(const Tensor<1, dim>      &delta,
               const Tensor<1, dim>      &normal,
               const Tensor<1, dim>      &initial_traction,
               const double               normal_penalty,
               const double               tangential_penalty,
               const Tensor<1, dim>      &old_plastic_slip,
               const Friction::State     &old_state,
               const Friction::Interface &law,
               const Point<3>            &x,
               const double               dt,
               const double               radiation_damping  = 0,
               const Tensor<1, dim>      *old_shear_traction = nullptr);

    /**
     * Penalty contact at a point whose slip is imposed (the forced-slip
     * trigger): the normal response as in return_map(), and a tangential
     * traction T_0,t + p_t (delta_t - @p imposed_slip) with no friction
     * limit, which pulls the slip to the imposed value. The status is slip
     * while the imposed slip changes.
     */
    template <int dim>
    ContactResponse<dim>
    forced_slip_response(const Tensor<1, dim> &delta,
                         const Tensor<1, dim> &normal,
                         const Tensor<1, dim> &initial_traction,
                         const double          normal_penalty,
                         const double          tangential_penalty,
                         const Tensor<1, dim> &old_plastic_slip,
                         const Tensor<1, dim> &imposed_slip);
  } // namespace Fault
} // namespace rupture

#endif
