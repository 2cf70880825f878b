#ifndef rupture_time_integration_quasi_static_h
#define rupture_time_integration_quasi_static_h

#include <rupture/time_integration/interface.h>

namespace rupture
{
  namespace TimeIntegration
  {
    /**
     * Quasi-static steps without inertia: K u + F_contact(u) = f at each
     * time (the paper's loading phase), solved with Newton's method when a
     * penalty fault is present. The velocity written is the rate of the
     * loading, (u - u_old)/dt. A step whose Newton iteration fails is
     * cut in half, recursively (<Solver/Maximum step cuts>).
     */
    template <int dim>
    class QuasiStatic : public Interface<dim>
    {
    public:
      using typename Interface<dim>::VectorType;
      using Interface<dim>::Interface;

      Scheme
      scheme() const override;
      void
      prepare() override;
      void
      step() override;

    private:
      /// One step of the state's time step, ending at its time.
      void
      substep();
    };
  } // namespace TimeIntegration
} // namespace rupture

#endif
