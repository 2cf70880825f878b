// The boundary-integral method with the laws of the rate-and-state family
// other than `rate and state` (their state rates, Friction::
// RateStateFamily), on the single-element spring-slider of
// inputs/spring_slider.prm, each against the rate-and-state law it equals
// for a choice of its constants:
// - flash heating with a weakening rate V_w far above any slip rate is the
//   regularised slip law in psi = f0 + b ln(V0 theta / L) (its steady
//   state a ln(2 V0 / V sinh(f_LV / a)) is f0 - b ln(V / V0) to round-off);
// - two state variables with B2 = 0 and th2 = 0 are the slip law in the
//   additive state th1 = b ln(V0 theta / L), regularised or logarithmic;
// - Chester's law without activation enthalpies (Q_A = Q_B = 0) is the
//   regularised slip law in theta = ln(V0 theta / L), however its
//   temperature (advanced outside the integrator, warmed by the friction)
//   evolves;
// - the slowness law with cut-offs far away (Vinf = 1e20 m/s,
//   theta0 = 1e-20 s, V0 = V1 = 0) is the logarithmic aging law with
//   mu0 = f0 - a ln V0 + b ln(V0 / L) + a ln Vinf + b ln theta0.
// Each run ends after two events, and its SEAS station file holds numbers
// only (its state column is the law's first state output); the events' start
// times agree within 1e-4 of the first one's and the peak slip rates within
// 1e-3 (the integrators see different variables, so their steps differ).

#include <deal.II/base/mpi.h>

#include "../tests.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <sstream>
#include <string>
#include <vector>

namespace
{
  const double a = 0.01, b = 0.015, L = 1e-3, f0 = 0.6, V0 = 1e-6,
               theta = 1.2e6;

  std::string
  number(const double x)
  {
    char text[64];
    std::snprintf(text, sizeof(text), "%.17g", x);
    return text;
  }

  // Whether every data row of the station file has its five columns, all
  // numbers (the state column is the law's first state output: log10 theta,
  // psi, th1).
  bool
  station_finite(const std::string &file)
  {
    std::istringstream in(tests::read_file(file));
    std::string        line;
    unsigned int       rows = 0;
    while (std::getline(in, line))
      {
        if (line.empty() || line[0] == '#' || line[0] == 't')
          continue;
        std::istringstream  s(line);
        std::vector<double> row;
        std::string         word;
        while (s >> word)
          row.push_back(std::strtod(word.c_str(), nullptr));
        if (row.size() != 5)
          return false;
        for (const double v : row)
          if (!std::isfinite(v))
            return false;
        ++rows;
      }
    return rows > 0;
  }

  std::vector<std::vector<double>>
  events(const std::string &directory, std::vector<std::string> settings)
  {
    settings.push_back("Termination/Number of events=2");
    tests::run_in(directory,
                  {std::string(SOURCE_DIR) + "/inputs/spring_slider.prm"},
                  settings);
    std::printf("  %s: station rows all numbers: %s\n",
                directory.c_str(),
                station_finite(directory + "/slider.dat") ? "yes" : "no");
    return tests::read_csv(directory + "/events.csv");
  }

  void
  compare(const std::string                      &name,
          const std::vector<std::vector<double>> &law,
          const std::vector<std::vector<double>> &reference)
  {
    // 0-based columns: 1 start (s), 7 peak slip rate.
    bool same = law.size() == 2 && reference.size() == 2;
    for (unsigned int i = 0; same && i < 2; ++i)
      same = std::abs(law[i][1] - reference[i][1]) < 1e-4 * reference[0][1] &&
             std::abs(law[i][7] / reference[i][7] - 1) < 1e-3;
    std::printf("  %s: %zu events, as the reference's: %s\n",
                name.c_str(),
                law.size(),
                same ? "yes" : "no");
  }
} // namespace



int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const std::string                        fs = "Fault/Flash heating/";
  const std::string                        ts = "Fault/Two state variables/";
  const std::string                        ss = "Fault/Slowness law/";

  std::printf("The slip law, regularised\n");
  const auto slip = events("slip", {"Fault/Rate and state/Evolution law=slip"});
  std::printf("  reference: %zu events, the first at %.3g s\n",
              slip.size(),
              slip.empty() ? 0. : slip[0][1]);
  const double psi = f0 + b * std::log(V0 * theta / L);
  compare("flash heating, V_w = 1e10 m/s",
          events("flash",
                 {"Fault/Friction law=flash heating",
                  fs + "Direct effect=" + number(a),
                  fs + "Evolution effect=" + number(b),
                  fs + "Characteristic slip distance=" + number(L),
                  fs + "Weakening slip rate=1e10",
                  fs + "Initial state=" + number(psi)}),
          slip);
  const auto two_states = [&](const std::string &formulation) {
    return std::vector<std::string>{"Fault/Friction law=two state variables",
                                    ts + "Formulation=" + formulation,
                                    ts + "Static friction coefficient=" +
                                      number(f0),
                                    ts + "Direct effect=" + number(a),
                                    ts + "Evolution effect 1=" + number(b),
                                    ts + "Evolution effect 2=0",
                                    ts + "Slip distance 1=" + number(L),
                                    ts + "Reference slip rate=" + number(V0),
                                    ts + "Initial state 1=" + number(psi - f0),
                                    ts + "Initial state 2=0"};
  };
  compare("two state variables, B2 = 0",
          events("two", two_states("regularized")),
          slip);
  const std::string cs = "Fault/Chester/";
  compare("chester, Q_A = Q_B = 0",
          events("chester",
                 {"Fault/Friction law=chester",
                  cs + "Direct effect=" + number(a),
                  cs + "Evolution effect=" + number(b),
                  cs + "Characteristic slip distance=" + number(L),
                  cs + "Reference friction coefficient=" + number(f0),
                  cs + "Reference slip rate=" + number(V0),
                  cs + "Direct activation enthalpy=0",
                  cs + "Evolution activation enthalpy=0",
                  cs + "Initial state=" + number(std::log(V0 * theta / L))}),
          slip);

  std::printf("The slip law, logarithmic\n");
  const auto log_slip =
    events("log-slip",
           {"Fault/Rate and state/Evolution law=slip",
            "Fault/Rate and state/Formulation=logarithmic"});
  std::printf("  reference: %zu events\n", log_slip.size());
  compare("two state variables, B2 = 0",
          events("log-two", two_states("logarithmic")),
          log_slip);

  std::printf("The aging law, logarithmic\n");
  const auto aging =
    events("aging", {"Fault/Rate and state/Formulation=logarithmic"});
  std::printf("  reference: %zu events\n", aging.size());
  const double Vinf = 1e20, theta0 = 1e-20;
  const double mu0 = f0 - a * std::log(V0) + b * std::log(V0 / L) +
                     a * std::log(Vinf) + b * std::log(theta0);
  compare("slowness law, cut-offs far away",
          events("slowness",
                 {"Fault/Friction law=slowness law",
                  ss + "Static friction coefficient=" + number(mu0),
                  ss + "Direct effect=" + number(a),
                  ss + "Evolution effect=" + number(b),
                  ss + "Characteristic slip distance=" + number(L),
                  ss + "High-velocity cut-off=" + number(Vinf),
                  ss + "State cut-off=" + number(theta0),
                  ss + "Initial state=" + number(theta)}),
          aging);
  return 0;
}
