#ifndef rupture_fault_anisotropic_contact_h
#define rupture_fault_anisotropic_contact_h

#include <rupture/fault/contact.h>

#include <array>
#include <functional>

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
     * The friction ellipse at a fault point of normal @p n: its principal
     * directions e_i in the fault plane, the factors a_i and b_i =
     * 1 / a_i^2, and the norms it defines.
     */
    template <int dim>
    struct EllipseFrame
    {
      EllipseFrame(const FrictionEllipse<dim> &ellipse,
                   const Tensor<1, dim>       &n);

      /// The number of directions in the fault plane.
      static constexpr unsigned int n_directions = dim - 1;

      /// The components of @p v along the principal directions.
      std::array<double, 2>
      components(const Tensor<1, dim> &v) const;

      /// The vector with principal components @p c.
      Tensor<1, dim>
      vector(const std::array<double, 2> &c) const;

      /// |A^-1 v|: the measure of a shear traction that the strength
      /// bounds (the Euclidean norm for a disc).
      double
      strength_norm(const Tensor<1, dim> &v) const;

      /// |A v|: the measure of a slip (rate) that the law sees.
      double
      dual_norm(const Tensor<1, dim> &v) const;

      /// A^-1 @p v (its tangential part): the coordinates in which the
      /// ellipse is the disc of radius S.
      Tensor<1, dim>
      inverse_metric(const Tensor<1, dim> &v) const;

      /// A^-2 @p v: the direction of the sliding rule at traction @p v.
      Tensor<1, dim>
      sliding_direction(const Tensor<1, dim> &v) const;

      std::array<Tensor<1, dim>, dim - 1> e;
      std::array<double, 2>               a = {{1, 1}}, b = {{1, 1}};
    };

    /**
     * The strength S(l) of a slip l (the dual norm of the step's slip
     * increment), with its derivatives dS/dl and dS/d pressure.
     */
    using StrengthOfSlip =
      std::function<double(double l, double &dS_dl, double &dS_dp)>;

    /**
     * The closest-point projection of a shear traction @p trial onto the
     * friction set K = {|A^-1 tau| <= S(l)} in the metric of a stiffness
     * k (Pa/m: the tangential penalty, or a split node's impedance over
     * dt): tau = trial - k du with the slip increment du along the normal
     * of K at tau, du = c A^-2 tau / k, so tau = (I + c A^-2)^-1 trial,
     * and l = |A du| = c |A^-1 tau| / k. The caller has checked that
     * |A^-1 trial| exceeds S(0).
     */
    struct EllipseProjection
    {
      /// The multiplier c >= 0 (dimensionless).
      double c = 0;
      /// The principal components of tau.
      std::array<double, 2> tau = {{0, 0}};
      /// |A^-1 tau| and the slip l.
      double N = 0, l = 0;
      /// d(|A^-1 tau| - S(l))/dc at the root: negative where the root is
      /// unique (the law weakens slower than k allows).
      double slope = 0;
    };

    template <int dim>
    EllipseProjection
    project_onto_ellipse(const EllipseFrame<dim> &frame,
                         const Tensor<1, dim>    &trial,
                         const double             k,
                         const StrengthOfSlip    &strength);

    /**
     * Penalty contact with anisotropic friction at one fault point: the
     * return mapping of return_map() for the set K of @p ellipse. The
     * elastic trial traction is returned to K by the closest-point
     * projection in the metric of the tangential penalty, which makes the
     * sliding rule exact (project_onto_ellipse()), with the slip increment
     * l = |A du_p| the law sees. The consistent tangent dT/d(delta)
     * follows from the linearisation of these equations (not symmetric
     * while sliding).
     *
     * Radiation damping eta acts on the slip rate as a vector (the
     * traction is that of friction plus eta du_p / dt), so the projection
     * runs in the stiffness p_t + eta / dt. Given the shear traction
     * @p old_shear_traction at the step's start, a law of the slip rate is
     * met at the middle of the step: the mean traction (T_n + tau) / 2,
     * less the damping, lies on the set of the strength at the step's
     * mean slip rate with the state evolved over half the step, and the
     * slip increment along its normal there (the implicit midpoint rule;
     * a projection of (T_n + trial) / 2 in the stiffness p_t / 2 + eta /
     * dt). Otherwise the law is met at the step's end (first order). With
     * a_1 = a_2 = 1 the result is return_map()'s to round-off, except that
     * centred the old traction enters as a vector where return_map() takes
     * its part along the trial (the same where the two are parallel).
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
                           const FrictionEllipse<dim> &ellipse,
                           const double                radiation_damping = 0,
                           const Tensor<1, dim> *old_shear_traction = nullptr);
  } // namespace Fault
} // namespace rupture

#endif
