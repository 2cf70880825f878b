#ifndef rupture_time_integration_dormand_prince_h
#define rupture_time_integration_dormand_prince_h

#include <functional>
#include <iosfwd>
#include <vector>

namespace rupture
{
  namespace TimeIntegration
  {
    /**
     * The embedded Runge-Kutta pair of Dormand and Prince (1980): a step of
     * fifth order with a fourth-order solution beside it whose difference
     * estimates the step's error. For a system of ordinary differential
     * equations dy/dt = f(t, y) that is not stiff, such as a fault's slip
     * and state under radiation damping (the boundary-integral method).
     *
     * The step controller: a step is accepted when its error is within
     * the tolerances in every component,
     *   |e_i| <= absolute_i + relative max(|y_i|, |y_i new|),
     * and the next step is dt 0.9 (error ratio)^(-1/5), at most
     * maximum_growth and at least 0.2 times this one, between the minimum
     * and maximum step; a rejected step is repeated with the smaller step.
     * The last stage of an accepted step is the first of the next (first
     * same as last), so a step costs six evaluations of f. The time is a
     * compensated sum of the steps, and the last step ends at t_end
     * exactly.
     */
    class DormandPrince
    {
    public:
      using Rhs = std::function<void(const double               t,
                                     const std::vector<double> &y,
                                     std::vector<double>       &rate)>;

      struct Settings
      {
        double              relative_tolerance = 1e-8;
        std::vector<double> absolute_tolerance;
        double              minimum_step   = 1e-6;
        double              maximum_step   = 3.15576e7;
        double              maximum_growth = 5;
      };

      DormandPrince(const Rhs &rhs, const Settings &settings);

      /**
       * One accepted step from (@p t, @p y), trying @p dt first and never
       * past @p t_end; on return @p t and @p y are at the step's end and
       * @p dt is the step proposed for the next one. Returns the length of
       * the step taken. Throws (naming the minimum) when the step would
       * have to fall below the minimum.
       */
      double
      advance(double              &t,
              std::vector<double> &y,
              double              &dt,
              const double         t_end);

      /// The solution was changed after the last accepted step (by a part
      /// of the equations advanced outside the pair): @p rate, the rates at
      /// the changed solution, is the first stage of the next step.
      void
      restart(const std::vector<double> &rate)
      {
        k[0]             = rate;
        have_first_stage = true;
      }

      /// The number of rejected steps so far.
      unsigned long
      rejected_steps() const
      {
        return n_rejected;
      }

      /// Write the first stage of the next step and the count of
      /// rejections (a checkpoint), so that a continued run takes the same
      /// steps to the last digit; and read them back.
      void
      save(std::ostream &out) const;
      void
      load(std::istream &in);

      /// The rates f(t, y) at the end of the last accepted step (the first
      /// stage of the next).
      const std::vector<double> &
      last_rate() const
      {
        return k[0];
      }

    private:
      Rhs                              rhs;
      Settings                         settings;
      std::vector<std::vector<double>> k;
      std::vector<double>              stage;
      bool                             have_first_stage = false;
      unsigned long                    n_rejected       = 0;
      /// What the compensated sum of the time still owes.
      double compensation = 0;
    };
  } // namespace TimeIntegration
} // namespace rupture

#endif
