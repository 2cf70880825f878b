#ifndef rupture_fault_anisotropic_contact_h
#define rupture_fault_anisotropic_contact_h

#include <rupture/fault/contact.h>

namespace rupture
{
  namespace Fault
  {
    /**
     * The shape of an anisotropic friction set (the review paper's
     * section 5): the admissible shear tractions are
     *
     *   K = {tau in the fault plane : |A^-1 tau| <= S},
     *
     * an ellipse with A = a_1 e_1 e_1 + a_2 e_2 e_2, e_1 a direction in
     * the fault plane, e_2 = n x e_1 (3-D only), and S the strength of the
     * friction law (mu sigma_N + cohesion). The strength along e_i is a_i
     * S; a_1 = a_2 = 1 is isotropic friction. By the subdifferential
     * sliding rule the slip rate lies in the normal cone of K at the
     * traction, i.e. along A^-2 tau, and the slip the law sees is measured
     * in the dual norm |A slip|, so that the dissipation tau . slip rate
     * equals S |A slip rate| (the paper's eq. 5.2).
     */
    template <int dim>
    struct FrictionEllipse
    {
      /// The first principal direction (in model coordinates; projected
      /// onto the fault plane and normalised where used).
      Tensor<1, dim> direction;
      /// The factors of the strength along the first and second
      /// principal directions.
      double a1 = 1, a2 = 1;
    };

    /**
     * A^-1 @p v for the tangential part of @p v in the plane of normal
     * @p n (its normal part dropped): the coordinates in which the
     * ellipse of @p ellipse is the disc of radius S.
     */
    template <int dim>
    Tensor<1, dim>
    inverse_metric(const FrictionEllipse<dim> &ellipse,
                   const Tensor<1, dim>       &n,
                   const Tensor<1, dim>       &v);

    /**
     * Penalty contact with anisotropic friction at one fault point: the
     * return mapping of return_map() for the set K of @p ellipse. The
     * elastic trial traction is returned to K by the closest-point
     * projection in the metric of the tangential penalty, which makes the
     * sliding rule exact: tau = (I + c A^-2)^-1 tau_trial with the scalar
     * c >= 0 found from |A^-1 tau| = S(l) and the slip increment l =
     * |A delta u_p| = c |A^-1 tau| / p_t. The consistent tangent
     * dT/d(delta) follows from the linearisation of these equations (not
     * symmetric while sliding). The law is met at the step's end (first
     * order in time); with a_1 = a_2 = 1 the result is return_map()'s
     * without @p old_shear_traction, to round-off.
     */
    template <int dim>
    ContactResponse<dim>
    anisotropic_return_map(const Tensor<1, dim>       &delta,
                           const Tensor<1, dim>       &normal,
                           const Tensor<1, dim>       &initial_traction,
                           const double                normal_penalty,
                           const double                tangential_penalty,
                           const Tensor<1, dim>       &old_plastic_slip,
                           const Friction::State      &old_state,
                           const Friction::Interface  &law,
                           const Point<3>             &x,
                           const double                dt,
                           const FrictionEllipse<dim> &ellipse);
  } // namespace Fault
} // namespace rupture

#endif
