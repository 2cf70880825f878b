#ifndef rupture_time_integration_implicit_newmark_h
#define rupture_time_integration_implicit_newmark_h

#include <rupture/time_integration/interface.h>

namespace rupture
{
  namespace TimeIntegration
  {
    /**
     * Implicit Newmark (the paper's eqs. 12-15): each step solves the
     * effective static problem K + a0 M + a1 C for the new displacement,
     * with Newton's method when a penalty fault makes it nonlinear (the
     * paper's Fig. 6). A step whose Newton iteration fails is cut in
     * half, recursively, up to <Solver/Maximum step cuts> times; after a
     * cut the following steps start from the sub-step size that converged
     * and double it again after two steps without a cut.
     */
    template <int dim>
    class ImplicitNewmark : public Interface<dim>
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
      /// The static balance f - M a - C v - K u - F_contact = 0 solved for
      /// u at the present time, with a and v as carried, every closed
      /// fault pair stuck on its springs (its plastic slip and friction
      /// state kept, its accepted slip then that of the balanced
      /// displacement) and the prescribed DoFs kept.
      unsigned int
      balance_displacement() override;

      void
      save_scheme(BinaryIO::Records &records) const override;
      void
      load_scheme(const BinaryIO::Records &records) override;

    private:
      /// Build the effective stiffness for steps of @p h.
      void
      set_time_step(const double h);
      /// One Newmark step of the state's time step, ending at its time.
      void
      substep();

      /// Steps are taken as 2^substep_depth sub-steps: raised after a step
      /// cut, lowered again after two steps without one.
      unsigned int substep_depth     = 0;
      unsigned int steps_without_cut = 0;
    };
  } // namespace TimeIntegration
} // namespace rupture

#endif
