// The boundary-integral method (Method = boundary integral) with a single
// element (inputs/spring_slider.prm) is a quasi-dynamic spring-slider of
// stiffness k = 4 mu / (3 pi W): its cycles against the accurate
// integration of the slider's equations (tests/spring_slider_reference.h).
// The method integrates (slip, ln theta) with its own Dormand-Prince pair
// and finds the slip rate from the friction balance point by point; the
// reference integrates (ln V, ln theta). Checked: the same events, the
// period and the peak slip rate within 1e-4 (an error tolerance of 1e-9
// per step), the event catalogue's start times and peak slip rates as the
// slider's within 1e-4 and its slips within 1e-3 (the catalogue's slip is
// from step to step, the slider's between the interpolated crossings of
// 1 mm/s: 7e-4 apart), the whole fault (W = 400 m) ruptured and
// the moment mu W slip, and the SEAS station file's last row at the
// end time with the slider's slip. With <Termination/Number of events> = 2
// the run ends after the second event.

#include <deal.II/base/mpi.h>

#include "../spring_slider_reference.h"
#include "../tests.h"

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  if (dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) != 0)
    std::freopen("/dev/null", "w", stdout);
  const double yr = 3.15576e7, end = 2.9e8, mu = 1e10, W = 400;
  const double k = 4 * mu / (3 * M_PI * W);
  const slider_reference::Slider slider{k,
                                        1e7,
                                        0.01,
                                        0.015,
                                        1e-3,
                                        0.6,
                                        1e-6,
                                        1e-9,
                                        4.62e6,
                                        6345387.768569107,
                                        1.2e6};
  std::vector<double>            t, V, D;
  slider.integrate(
    {slider.initial_log_rate(), std::log(slider.theta0)}, end, t, V, D);
  const auto reference = slider_reference::find_events(t, V);
  const auto exact     = slider_reference::cycle(reference);

  const int code =
    tests::run_in("bi",
                  {std::string(SOURCE_DIR) + "/inputs/spring_slider.prm"},
                  {});
  std::printf("exit code %d\n", code);
  // 0-based columns: step, time, time step, maximum slip rate, rejected.
  const auto          rows = tests::read_statistics("bi/statistics.dat");
  std::vector<double> bi_t, bi_V;
  for (const auto &r : rows)
    {
      bi_t.push_back(r[1]);
      bi_V.push_back(r[3]);
    }
  const auto events = slider_reference::find_events(bi_t, bi_V);
  const auto bi     = slider_reference::cycle(events);
  slider_reference::print_events(reference, events, "BI");
  std::printf("  same number of events (%zu): %s\n",
              reference.start.size(),
              events.start.size() == reference.start.size() ? "yes" : "no");
  std::printf("  period within 1e-4: %s\n",
              std::abs(bi[0] / exact[0] - 1) < 1e-4 ? "yes" : "no");
  std::printf("  peak slip rate within 1e-4: %s\n",
              std::abs(bi[1] / exact[1] - 1) < 1e-4 ? "yes" : "no");

  // Each event's slip from the slider: between the crossings of 1 mm/s.
  const std::vector<double> slips = slider_reference::event_slips(t, V, D);
  // 0-based columns (2-D): number, start (s), start (years), end (s),
  // duration (s), hypocentre x and y, peak slip rate, moment (N/m),
  // ruptured length, mean slip, largest slip, complete.
  const auto catalogue     = tests::read_csv("bi/events.csv");
  bool       as_the_slider = catalogue.size() == reference.start.size() &&
                       slips.size() == catalogue.size();
  for (unsigned int i = 0; as_the_slider && i < catalogue.size(); ++i)
    {
      const auto &r = catalogue[i];
      as_the_slider = r.size() == 13 && r[12] == 1 &&
                      std::abs(r[1] - reference.start[i]) < 1e-4 * exact[0] &&
                      std::abs(r[7] / reference.peak[i] - 1) < 1e-4 &&
                      std::abs(r[10] / slips[i] - 1) < 1e-3 && r[9] == W &&
                      r[5] == 0 && r[6] == -W / 2 &&
                      std::abs(r[8] / (mu * W * r[10]) - 1) < 1e-9;
    }
  std::printf("  catalogue: %zu events, start, peak slip rate and slip as the "
              "slider's within 1e-4 (slip 1e-3), ruptured length W, moment "
              "mu W slip: "
              "%s\n",
              catalogue.size(),
              as_the_slider ? "yes" : "no");

  // The station (SEAS: t, slip, log10 slip rate, shear stress, log10
  // theta): its last row at the end time, with the slider's slip.
  const auto station = tests::read_statistics("bi/slider.dat");
  const bool at_end  = !station.empty() && station.back()[0] == end &&
                      std::abs(station.back()[1] / D.back() - 1) < 1e-4 &&
                      std::abs(station.back()[2] - std::log10(V.back())) < 1e-3;
  std::printf("  station: last row at the end time with the slider's slip "
              "and slip rate: %s\n",
              at_end ? "yes" : "no");

  // <Termination/Number of events> = 2: the run ends after the second
  // event, whose row is the full run's.
  tests::run_in("two",
                {std::string(SOURCE_DIR) + "/inputs/spring_slider.prm"},
                {"Termination/Number of events=2"});
  const auto two     = tests::read_csv("two/events.csv");
  const auto summary = tests::read_file("two/summary.json");
  std::printf("  ended after 2 events, as the full run's rows, before the end "
              "time: %s\n",
              two.size() == 2 && catalogue.size() >= 2 &&
                  two[1] == catalogue[1] &&
                  summary.find("\"ended early\"") != std::string::npos ?
                "yes" :
                "no");

  // <Fault/Radiation damping> = auto: half the shear impedance, sqrt(rho
  // mu) / 2 = 2.5e6 Pa s/m for rho = 2500 kg/m^3 and mu = 1e10 Pa.
  for (const std::string eta : {"auto", "2.5e6"})
    tests::run_in("eta-" + eta,
                  {std::string(SOURCE_DIR) + "/inputs/spring_slider.prm"},
                  {"Termination/Number of events=2",
                   "Fault/Radiation damping=" + eta});
  std::printf("  radiation damping 'auto' is the run with sqrt(rho mu) / 2 = "
              "2.5e6 Pa s/m: %s\n",
              tests::read_file("eta-auto/events.csv") ==
                    tests::read_file("eta-2.5e6/events.csv") &&
                  !tests::read_file("eta-auto/events.csv").empty() ?
                "yes" :
                "no");
  return 0;
}
