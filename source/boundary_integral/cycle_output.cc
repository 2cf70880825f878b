// The series of a boundary-integral cycle run, appended as they grow.

#include <rupture/base/binary_io.h>
#include <rupture/boundary_integral/cycle_output.h>
#include <rupture/boundary_integral/text.h>
#include <rupture/output/directory.h>
#include <rupture/output/seas_format.h>

#include <deal.II/base/exceptions.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <iomanip>
#include <sstream>

namespace rupture
{
  namespace BoundaryIntegral
  {
    double
    station_distance(const std::string &name,
                     const Point<2>    &point,
                     const double       dip,
                     const double       extent)
    {
      if (dip == 90)
        {
          AssertThrow(std::abs(point[0]) < 1e-6 && point[1] <= 0 &&
                        -point[1] <= extent,
                      dealii::ExcMessage(
                        "The station <" + name +
                        "> of <Fault/Output/Stations> is not on the fault: "
                        "with <Method> = boundary integral the fault is x = "
                        "0 between the depths 0 and <Fault depth> (y from "
                        "0 down to -W), e.g. 'bp1_st050: 0, -5000'."));
          return -point[1];
        }
      // (On a dipping fault: the point's projection on the fault's line,
      // at most a metre from it.)
      const double angle = dip * M_PI / 180;
      const double distance =
                     point[0] * std::cos(angle) - point[1] * std::sin(angle),
                   off     = std::abs(point[0] * std::sin(angle) +
                                  point[1] * std::cos(angle));
      const double nearest = std::clamp(distance, 0., extent);
      AssertThrow(off < 1 && distance >= -1 && distance <= extent + 1,
                  dealii::ExcMessage(
                    "The station <" + name +
                    "> of <Fault/Output/Stations> is not on the fault: "
                    "with <Method> = boundary integral and <Dip> = " +
                    number(dip) +
                    " the fault runs from (0, 0) down to the distance "
                    "<Fault depth> along the dip, through (d cos(dip), "
                    "-d sin(dip)) at the distance d (within a metre; the "
                    "nearest point of it is (" +
                    number(nearest * std::cos(angle)) + ", " +
                    number(-nearest * std::sin(angle)) + "))."));
      return nearest;
    }



    CycleOutput::CycleOutput(
      const Stiffness                                     &geometry,
      const std::vector<std::pair<std::string, Point<2>>> &points,
      const Sampling                                      &sampling,
      const bool                                           test_mode,
      const MPI_Comm                                       communicator,
      const std::vector<std::pair<std::string, Point<2>>> &surface_points,
      const double                                         plate_rate)
      : geometry(geometry)
      , normal_stress(geometry.changes_normal_stress())
      , sampling(sampling)
      , test_mode(test_mode)
      , root(dealii::Utilities::MPI::this_mpi_process(communicator) == 0)
      , stations(points.size())
      , surface_stations(surface_points.size())
      , plate_rate(plate_rate)
    {
      AssertThrow(surface_points.size() == geometry.n_surface_points(),
                  dealii::ExcInternalError());
      for (unsigned int k = 0; k < surface_points.size(); ++k)
        {
          surface_stations[k].name    = surface_points[k].first;
          surface_stations[k].depth   = surface_points[k].second[0];
          surface_stations[k].element = k;
        }
      const unsigned int n = geometry.size();
      for (unsigned int k = 0; k < points.size(); ++k)
        {
          const auto &[name, point] = points[k];
          const double distance =
            station_distance(name, point, geometry.dip(), geometry.extent());
          Station &s = stations[k];
          s.name     = name;
          s.depth    = distance;
          // Between the element above the station and the one below
          // (the first or the last element's value above or below them).
          s.element = 0;
          s.weight  = 0;
          if (n > 1)
            {
              while (s.element + 2 < n &&
                     geometry.depth(s.element + 1) <= s.depth)
                ++s.element;
              const double above = geometry.depth(s.element),
                           below = geometry.depth(s.element + 1);
              s.weight =
                std::clamp((s.depth - above) / (below - above), 0., 1.);
            }
        }
    }



    void
    CycleOutput::open_file(std::ofstream      &file,
                           const std::string  &path,
                           const bool          continuing,
                           const std::uint64_t length)
    {
      if (continuing)
        {
          std::error_code error;
          const auto      size = std::filesystem::file_size(path, error);
          AssertThrow(!error && size >= length,
                      dealii::ExcMessage(
                        "The continued run finds <" + path + "> " +
                        (error ? "missing" :
                                 "shorter than the checkpoint's " +
                                   std::to_string(length) + " bytes") +
                        ". The output directory must hold the files of the "
                        "run that wrote the checkpoint."));
          std::filesystem::resize_file(path, length, error);
          AssertThrow(!error,
                      dealii::ExcMessage(
                        "The continued run cannot cut <" + path +
                        "> back to the checkpoint's " + std::to_string(length) +
                        " bytes: " + error.message() +
                        ". The output directory must hold the files of the "
                        "run that wrote the checkpoint."));
          file.open(path, std::ios::app);
        }
      else
        file.open(path);
      AssertThrow(file.good(),
                  dealii::ExcMessage("Cannot write <" + path + ">."));
    }



    void
    CycleOutput::open(Output::Directory &directory, const bool continuing)
    {
      if (!root)
        return;
      const bool with_profiles =
        sampling.profile_between > 0 || sampling.profile_during > 0;
      AssertThrow(!continuing || lengths.size() == 2 + stations.size() +
                                                     surface_stations.size(),
                  dealii::ExcMessage("The checkpoint has another number of "
                                     "stations than <Fault/Output/Stations> "
                                     "gives."));
      statistics_path = directory.record("statistics.dat");
      open_file(statistics,
                statistics_path,
                continuing,
                continuing ? lengths[0] : 0);
      statistics << std::scientific << std::setprecision(10);
      if (!continuing)
        statistics << "# rupture, boundary-integral method: one row per "
                      "sampled step\n"
                   << "# 1: Step\n# 2: Time (s)\n# 3: Time step (s)\n"
                   << "# 4: Maximum slip rate (m/s)\n"
                   << "# 5: Rejected steps (so far)\n";
      if (with_profiles)
        {
          profiles_path = directory.record("slip_profiles.dat");
          open_file(profiles,
                    profiles_path,
                    continuing,
                    continuing ? lengths[1] : 0);
          profiles << std::scientific << std::setprecision(7);
          if (!continuing)
            {
              if (geometry.dip() == 90)
                profiles << "# Slip profiles: the first row holds 0, 0 and "
                            "the depths (m) of the elements (their centres, "
                            "or the fault's nodes with finite elements); "
                            "each further row t (s), the log10 of the "
                            "largest slip rate (m/s), and the slip (m) at "
                            "those depths.\n0 0";
              else
                profiles << "# Slip profiles: the first row holds 0, 0 and "
                            "the distances (m) of the fault's nodes down the "
                            "fault (dipping at "
                         << geometry.dip()
                         << " degrees); each further row t (s), the log10 "
                            "of the largest slip rate (m/s), and the slip "
                            "(m) at those distances.\n0 0";
              for (unsigned int i = 0; i < geometry.size(); ++i)
                profiles << " " << geometry.depth(i);
              profiles << "\n";
            }
        }
      for (unsigned int k = 0; k < stations.size(); ++k)
        {
          Station &s = stations[k];
          s.path     = directory.record(s.name + ".dat");
          open_file(s.file,
                    s.path,
                    continuing,
                    continuing ? lengths[2 + k] : 0);
          if (!continuing)
            s.file << Output::seas_station_header(
              "on fault, " + number(s.depth / 1e3) +
                (geometry.dip() == 90 ? " km depth" : " km down-dip"),
              test_mode,
              normal_stress,
              state_name);
        }
      for (unsigned int k = 0; k < surface_stations.size(); ++k)
        {
          Station &s = surface_stations[k];
          s.path     = directory.record(s.name + ".dat");
          open_file(s.file,
                    s.path,
                    continuing,
                    continuing ? lengths[2 + stations.size() + k] : 0);
          if (!continuing)
            s.file << Output::seas_surface_header(
              "on surface, x = " + number(s.depth / 1e3) + " km", test_mode);
        }
    }



    void
    CycleOutput::record(const double             t,
                        const unsigned long      step,
                        const double             dt,
                        const unsigned long      rejected,
                        const QuasiDynamicFault &fault,
                        const bool               force)
    {
      const double vmax = fault.max_slip_rate();
      const double change =
        std::abs(std::log10(std::max(vmax, 1e-300)) -
                 std::log10(std::max(last_row_rate, 1e-300)));
      if ((force || sampling.rate_change == 0 ||
           change >= sampling.rate_change ||
           t - last_row_time >= sampling.interval) &&
          rows_step != long(step))
        {
          rows_step     = step;
          last_row_rate = vmax;
          last_row_time = t;
          if (root)
            {
              statistics << step << " " << std::setprecision(15) << t << " "
                         << std::setprecision(10) << dt << " " << vmax << " "
                         << rejected << "\n";
              for (auto &s : stations)
                {
                  const unsigned int i = s.element;
                  const unsigned int j =
                    std::min<unsigned int>(i + 1, fault.size() - 1);
                  const auto mix = [&](const double a, const double b) {
                    return (1 - s.weight) * a + s.weight * b;
                  };
                  s.file << Output::seas_station_row(
                    t,
                    mix(fault.slip(i), fault.slip(j)),
                    mix(fault.slip_rate(i), fault.slip_rate(j)),
                    mix(fault.shear_stress(i), fault.shear_stress(j)) / 1e6,
                    mix(fault.state(i), fault.state(j)),
                    fault.normal_stress_changes() ?
                      mix(fault.normal_stress(i), fault.normal_stress(j)) /
                        1e6 :
                      std::nan(""));
                }
              if (!surface_stations.empty())
                {
                  // The displacement from the slip relative to the plate's,
                  // the velocity from the slip rate relative to it.
                  const unsigned int                 n = fault.size();
                  std::vector<std::array<double, 2>> u, v;
                  relative.resize(n);
                  for (unsigned int i = 0; i < n; ++i)
                    relative[i] = fault.slip(i) - plate_rate * t;
                  for (unsigned int k = 0; k < surface_stations.size(); ++k)
                    u.push_back(
                      geometry.surface_motion(k, relative, plate_rate * t));
                  for (unsigned int i = 0; i < n; ++i)
                    relative[i] = fault.signed_slip_rate(i) - plate_rate;
                  for (unsigned int k = 0; k < surface_stations.size(); ++k)
                    v.push_back(
                      geometry.surface_motion(k, relative, plate_rate));
                  for (unsigned int k = 0; k < surface_stations.size(); ++k)
                    surface_stations[k].file
                      << Output::seas_surface_row(t, u[k], v[k]);
                }
            }
        }
      const double interval = vmax >= sampling.event_rate ?
                                sampling.profile_during :
                                sampling.profile_between;
      if (root && profiles.is_open() &&
          (force || (interval > 0 && t - last_profile >= interval)) &&
          profile_step != long(step))
        {
          profile_step = step;
          last_profile = t;
          profiles << std::setprecision(15) << t << std::setprecision(7) << " "
                   << std::log10(std::max(vmax, 1e-300));
          for (unsigned int i = 0; i < fault.size(); ++i)
            profiles << " " << fault.slip(i);
          profiles << "\n";
        }
    }



    void
    CycleOutput::save(std::ostream &out)
    {
      std::vector<double> state = {last_row_rate,
                                   last_row_time,
                                   last_profile,
                                   double(rows_step),
                                   double(profile_step)};
      // The files' lengths (rank 0's; 0 elsewhere).
      const auto length = [](std::ofstream     &file,
                             const std::string &path) -> double {
        if (!file.is_open())
          return 0;
        file.flush();
        return double(std::filesystem::file_size(path));
      };
      state.push_back(length(statistics, statistics_path));
      state.push_back(length(profiles, profiles_path));
      for (auto &s : stations)
        state.push_back(length(s.file, s.path));
      for (auto &s : surface_stations)
        state.push_back(length(s.file, s.path));
      BinaryIO::write(out, state);
    }



    void
    CycleOutput::load(std::istream &in)
    {
      std::vector<double> state;
      BinaryIO::read(in, state);
      AssertThrow(state.size() == 7 + stations.size() + surface_stations.size(),
                  dealii::ExcMessage(
                    "The checkpoint has another number of stations than "
                    "<Fault/Output/Stations> gives."));
      last_row_rate = state[0];
      last_row_time = state[1];
      last_profile  = state[2];
      rows_step     = long(state[3]);
      profile_step  = long(state[4]);
      lengths.clear();
      for (unsigned int k = 5; k < state.size(); ++k)
        lengths.push_back(static_cast<std::uint64_t>(state[k]));
    }
  } // namespace BoundaryIntegral
} // namespace rupture
