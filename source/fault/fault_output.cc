#include <rupture/base/binary_io.h>
#include <rupture/base/utilities.h>
#include <rupture/fault/face_nodes.h>
#include <rupture/fault/fault_output.h>
#include <rupture/output/seas_format.h>
#include <rupture/output/series_header.h>

#include <deal.II/base/data_out_base.h>
#include <deal.II/base/mpi.h>

#include <boost/serialization/set.hpp>
#include <boost/serialization/string.hpp>
#include <boost/serialization/vector.hpp>

#include <algorithm>
#include <cmath>
#include <ctime>
#include <filesystem>
#include <iomanip>
#include <limits>
#include <sstream>

namespace rupture
{
  namespace Fault
  {
    template <int dim>
    void
    FaultOutput<dim>::declare_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Fault");
      prm.enter_subsection("Output");
      {
        prm.declare_entry(
          "Stations",
          "",
          Patterns::Anything(),
          "On-fault stations, written as time series in the SCEC format to "
          "<output>/<name>.dat: 'name: x, y[, z]' entries separated by ';', "
          "e.g. 'faultst075dp075: 7500, 0, -7500; faultst000dp075: 0, 0, "
          "-7500'. A station may lie anywhere on the fault (values are "
          "interpolated); one off the fault is an error.");
        prm.declare_entry(
          "Down-dip origin",
          "",
          Patterns::Anything(),
          "The height (last coordinate, m) at which the down-dip distances "
          "of the SCEC files (the station headers and rupture_time.dat) are "
          "zero; they grow down the fault, as the depth below it over the "
          "sine of the dip. Empty: the model's top (right for a free "
          "surface, as in TPV102). SCEC's whole-space benchmarks count from "
          "the fault's top edge: TPV3, TPV101 and TPV103 with the "
          "hypocentre at z = 0, 7.5 km below that edge, need 7500. 3-D only "
          "(2-D files have no down-dip distance).");
        prm.declare_entry(
          "Along-strike direction",
          "",
          Patterns::Anything(),
          "Unit vector of the along-strike (h) direction of the outputs, one "
          "number per dimension. Empty: the horizontal direction in the "
          "fault, n x e_z (in 2-D the fault's tangent with n x t > 0). The "
          "down-dip (v) direction is n x strike, turned to point down.");
        prm.declare_entry(
          "Station format",
          "SCEC",
          Patterns::Selection("SCEC|SEAS"),
          "The layout of the station files. 'SCEC': the dynamic-rupture "
          "benchmarks' (time, horizontal and vertical slip, slip rate and "
          "shear stress, then the normal stress and the law's state). "
          "'SEAS': the SCEC SEAS (earthquake cycle) benchmarks' 't slip "
          "slip_rate shear_stress state': the along-strike slip (m), the "
          "log10 of the magnitude of its rate (m/s; -300 where it is 0), "
          "the along-strike shear stress (MPa) and the log10 of the first "
          "state variable (0 for laws without a state).");
        prm.declare_entry(
          "Output interval",
          "",
          Patterns::Anything(),
          "Simulated time (s) between outputs of the fault surface "
          "(fault.pvd) and of the station and rupture-time files. Empty: "
          "the volume's <Output/Output interval>. 0 writes every step; a "
          "negative value writes the surface never and the tables at the "
          "end only. The fault's files scale with the fault, not with the "
          "mesh, so a large model can write its fault every step and its "
          "volume rarely.");
        EventCatalogue<dim>::declare_parameters(prm);
      }
      prm.leave_subsection();
      prm.leave_subsection();
    }



    template <int dim>
    void
    FaultOutput<dim>::parse_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Fault");
      prm.enter_subsection("Output");
      station_text  = prm.get("Stations");
      strike_text   = prm.get("Along-strike direction");
      origin_text   = dealii::Utilities::trim(prm.get("Down-dip origin"));
      interval_text = dealii::Utilities::trim(prm.get("Output interval"));
      seas_format   = (prm.get("Station format") == "SEAS");
      events.parse_parameters(prm);
      prm.leave_subsection();
      if (!interval_text.empty())
        surface_interval(0);
      prm.leave_subsection();

      stations.clear();
      for (const auto &[name, location] :
           Utilities::parse_named_points<dim>(station_text,
                                              "Fault/Output/Stations"))
        {
          Station s;
          s.name     = name;
          s.location = location;
          stations.push_back(std::move(s));
        }
    }



    template <int dim>
    double
    FaultOutput<dim>::surface_interval(const double volume_interval) const
    {
      if (interval_text.empty())
        return volume_interval;
      std::vector<double> values;
      try
        {
          values = Utilities::parse_doubles(interval_text,
                                            "Fault/Output/Output interval");
        }
      catch (const ExceptionBase &)
        {
          // Not a number: the message below says what is allowed.
        }
      AssertThrow(values.size() == 1 && std::isfinite(values[0]),
                  ExcMessage("<Fault/Output/Output interval> must be empty "
                             "(the volume's output interval) or one finite "
                             "number of seconds (0: every step, negative: "
                             "never), but is <" +
                             interval_text + ">."));
      return values[0];
    }



    template <int dim>
    void
    FaultOutput<dim>::setup(const Fault<dim> &fault,
                            const MPI_Comm    comm,
                            const double      surface)
    {
      communicator  = comm;
      this->surface = surface;
      if (!origin_text.empty())
        {
          const std::vector<double> z =
            Utilities::parse_doubles(origin_text,
                                     "Fault/Output/Down-dip origin");
          AssertThrow(z.size() == 1,
                      ExcMessage("<Fault/Output/Down-dip origin> takes one "
                                 "number (a height in m), or nothing for the "
                                 "model's top, but was given <" +
                                 origin_text + ">."));
          this->surface = z[0];
        }
      origin = fault.reference_point();
      // A new set-up (a changed mesh) locates the stations anew.
      station_keys.clear();
      for (auto &s : stations)
        {
          s.nodes.clear();
          s.weights.clear();
        }
      const auto all  = fault.gather();
      faces           = fault.gather_faces();
      const bool root = dealii::Utilities::MPI::this_mpi_process(comm) == 0;

      // Rank 0 does the work; an error there (a malformed entry, a station
      // off the fault) is raised on every rank together.
      std::string error;
      if (root)
        try
          {
            Tensor<1, dim>                                n;
            std::map<types::global_dof_index, Point<dim>> location;
            for (const auto &r : all)
              {
                n += r.normal;
                location[r.key] = r.location;
              }
            if (n.norm() > 0)
              n /= n.norm();
            if (!strike_text.empty())
              {
                strike = Utilities::parse_vector<dim>(
                  strike_text, "Fault/Output/Along-strike direction");
                AssertThrow(strike.norm() > 0,
                            ExcMessage("<Fault/Output/Along-strike direction> "
                                       "must not be zero."));
                strike /= strike.norm();
              }
            else if (dim == 2)
              {
                strike[0] = n[1];
                strike[1] = -n[0];
              }
            else
              {
                Tensor<1, dim> ez;
                ez[dim - 1] = 1;
                strike      = cross_product_3d(n, ez);
                if (strike.norm() < 1e-8)
                  {
                    strike    = Tensor<1, dim>();
                    strike[0] = 1;
                  }
                strike /= strike.norm();
              }
            if (dim == 3)
              {
                dip = cross_product_3d(n, strike);
                if (dip[dim - 1] > 0)
                  dip = -dip;
              }

            // Locate each station in a fault face.
            for (auto &s : stations)
              {
                double best = std::numeric_limits<double>::max();
                for (const auto &face : faces)
                  {
                    bool present = true;
                    for (const auto key : face)
                      present = present && location.count(key);
                    if (!present)
                      continue; // a face whose border nodes are welded
                    const unsigned int degree =
                      FaceNodes::degree<dim>(face.size());
                    std::vector<Point<dim>> v;
                    for (const unsigned int c : FaceNodes::corners<dim>(degree))
                      v.push_back(location[face[c]]);
                    double diameter = 0;
                    for (const auto &p : v)
                      diameter = std::max(diameter, p.distance(v[0]));
                    const auto xi = FaceNodes::coordinates<dim>(v, s.location);
                    const Point<dim> x       = FaceNodes::point<dim>(v, xi);
                    const double     tol     = 1e-6 * diameter;
                    double           outside = 0;
                    for (const double c : xi)
                      outside = std::max({outside, -c, c - 1});
                    const double distance =
                      x.distance(s.location) + outside * diameter;
                    best = std::min(best, distance);
                    if (distance <= tol)
                      {
                        s.nodes   = face;
                        s.weights = FaceNodes::weights<dim>(degree, xi);
                        break;
                      }
                  }
                if (s.nodes.empty())
                  {
                    std::ostringstream m;
                    m << "The station <" << s.name << "> at (" << s.location
                      << ") given in <Fault/Output/Stations> is not on the "
                         "fault (its distance to the fault's faces is "
                      << best
                      << " m). Stations must lie on the part of the interface "
                         "that <Fault/Fault region> makes a fault, in a face "
                         "none of whose nodes is on the fault's edge (those "
                         "nodes are welded; at a higher degree or in coarser "
                         "cells such faces reach farther in).";
                    error = m.str();
                    break;
                  }
                station_keys.insert(s.nodes.begin(), s.nodes.end());
              }
          }
        catch (const ExceptionBase &e)
          {
            error = Utilities::message_of(e);
          }
      error = dealii::Utilities::MPI::broadcast(comm, error, 0);
      AssertThrow(error.empty(), ExcMessage(error));
      station_keys = dealii::Utilities::MPI::broadcast(comm, station_keys, 0);
    }



    template <int dim>
    double
    FaultOutput<dim>::strike_component(const Tensor<1, dim> &v) const
    {
      return v * strike;
    }



    template <int dim>
    double
    FaultOutput<dim>::dip_component(const Tensor<1, dim> &v) const
    {
      return (dim == 3) ? v * dip : 0.;
    }



    template <int dim>
    double
    FaultOutput<dim>::rake_of(const Tensor<1, dim> &v) const
    {
      const double h = strike_component(v), d = dip_component(v);
      return (h == 0 && d == 0) ? 0. : std::atan2(-d, h) * 180 / numbers::PI;
    }



    template <int dim>
    double
    FaultOutput<dim>::down_dip_distance(const Point<dim> &x) const
    {
      if (dim != 3)
        return 0;
      // dip points down: -dip_z is the sine of the dip angle.
      const double sine = -dip[dim - 1];
      return (sine > 1e-6) ? (surface - x[dim - 1]) / sine :
                             dip_component(x - origin);
    }



    template <int dim>
    void
    FaultOutput<dim>::start_loading_phase()
    {
      file_prefix = "loading";
      pvd_name    = "fault-loading.pvd";
      records.clear();
    }



    template <int dim>
    void
    FaultOutput<dim>::start_dynamic_phase()
    {
      for (auto &s : stations)
        s.rows.clear();
      file_prefix = "fault";
      pvd_name    = "fault.pvd";
      records.clear();
    }



    template <int dim>
    void
    FaultOutput<dim>::keep_series_in(Output::Directory &directory)
    {
      for (auto &s : stations)
        s.rows.keep_in_file(directory.record(".station-" + s.name + ".rows"));
    }



    template <int dim>
    void
    FaultOutput<dim>::record(Fault<dim> &fault, const double time)
    {
      events.record(fault, time);
      if (stations.empty())
        return;
      const auto records = fault.gather(&station_keys);
      if (dealii::Utilities::MPI::this_mpi_process(communicator) != 0)
        return;
      std::map<types::global_dof_index, const typename Fault<dim>::NodeRecord *>
        by_key;
      for (const auto &r : records)
        by_key[r.key] = &r;
      for (auto &s : stations)
        {
          Tensor<1, dim>      slip, rate, traction, sliding, n;
          double              normal = 0;
          std::vector<double> state;
          for (unsigned int k = 0; k < s.nodes.size(); ++k)
            {
              const auto &r = *by_key.at(s.nodes[k]);
              slip += s.weights[k] * r.slip;
              rate += s.weights[k] * r.slip_velocity;
              traction += s.weights[k] * r.traction;
              sliding += s.weights[k] * r.sliding;
              n += s.weights[k] * r.normal;
              normal += s.weights[k] * (r.traction * r.normal);
              state.resize(r.state_values.size());
              for (unsigned int i = 0; i < state.size(); ++i)
                state[i] += s.weights[k] * r.state_values[i];
            }
          std::vector<double> row = {time,
                                     strike_component(slip),
                                     strike_component(rate),
                                     strike_component(traction) / 1e6,
                                     dip_component(slip),
                                     dip_component(rate),
                                     dip_component(traction) / 1e6};
          // Laws with state: the SCEC rate-and-state columns, the normal
          // stress and the state variables.
          if (!state.empty())
            {
              row.push_back(normal / 1e6);
              row.insert(row.end(), state.begin(), state.end());
            }
          // With anisotropic friction in 3-D, the directions (rake_of())
          // of the slip, of the frictional slip rate and of the shear
          // traction, and the angle between the last two (write_tables()
          // puts them into a file of their own).
          if (dim == 3 && fault.has_anisotropic_friction())
            {
              n /= n.norm();
              const Tensor<1, dim> shear = traction - (traction * n) * n;
              const double         norms = sliding.norm() * shear.norm();
              row.push_back(rake_of(slip));
              row.push_back(rake_of(sliding));
              row.push_back(rake_of(shear));
              row.push_back(
                (norms > 0) ?
                  std::acos(std::clamp((sliding * shear) / norms, -1., 1.)) *
                    180 / numbers::PI :
                  0.);
            }
          s.rows.append(row);
        }
    }



    template <int dim>
    void
    FaultOutput<dim>::write_surface(const Fault<dim>  &fault,
                                    Output::Directory &directory,
                                    const double       time,
                                    const unsigned int step)
    {
      const auto records = fault.gather();
      if (dealii::Utilities::MPI::this_mpi_process(communicator) != 0)
        return;
      std::map<types::global_dof_index, unsigned int> index;
      for (unsigned int i = 0; i < records.size(); ++i)
        index[records[i].key] = i;
      // Each face as sub-cells between its nodes (one cell at degree 1),
      // where all its nodes are fault nodes.
      std::vector<std::vector<unsigned int>> cells;
      for (const auto &face : faces)
        {
          bool present = true;
          for (const auto key : face)
            present = present && index.count(key);
          if (!present)
            continue;
          for (const auto &sub :
               FaceNodes::sub_cells<dim>(FaceNodes::degree<dim>(face.size())))
            {
              std::vector<unsigned int> c;
              for (const unsigned int k : sub)
                c.push_back(index[face[k]]);
              cells.push_back(c);
            }
        }

      std::ostringstream out;
      out << std::setprecision(10);
      out << "<?xml version=\"1.0\"?>\n"
          << "<VTKFile type=\"UnstructuredGrid\" version=\"0.1\" "
             "byte_order=\"LittleEndian\">\n<UnstructuredGrid>\n"
          << "<FieldData><DataArray type=\"Float64\" Name=\"TIME\" "
             "NumberOfTuples=\"1\" format=\"ascii\">"
          << time << "</DataArray></FieldData>\n"
          << "<Piece NumberOfPoints=\"" << records.size()
          << "\" NumberOfCells=\"" << cells.size() << "\">\n"
          << "<Points><DataArray type=\"Float64\" NumberOfComponents=\"3\" "
             "format=\"ascii\">\n";
      const auto vector3 = [&](const Tensor<1, dim> &v) {
        for (unsigned int d = 0; d < 3; ++d)
          out << (d < dim ? v[d] : 0.) << ' ';
        out << '\n';
      };
      for (const auto &r : records)
        vector3(r.location);
      out
        << "</DataArray></Points>\n<Cells>\n"
        << "<DataArray type=\"Int32\" Name=\"connectivity\" format=\"ascii\">\n";
      for (const auto &c : cells)
        {
          for (const auto i : c)
            out << i << ' ';
          out << '\n';
        }
      out << "</DataArray>\n<DataArray type=\"Int32\" Name=\"offsets\" "
             "format=\"ascii\">\n";
      for (unsigned int i = 0; i < cells.size(); ++i)
        out << (i + 1) * GeometryInfo<dim>::vertices_per_face << ' ';
      out << "\n</DataArray>\n<DataArray type=\"UInt8\" Name=\"types\" "
             "format=\"ascii\">\n";
      for (unsigned int i = 0; i < cells.size(); ++i)
        out << (dim == 3 ? 9 : 3) << ' ';
      out << "\n</DataArray>\n</Cells>\n<PointData>\n";
      const auto vector_field = [&](const std::string &name, auto get) {
        out << "<DataArray type=\"Float64\" Name=\"" << name
            << "\" NumberOfComponents=\"3\" format=\"ascii\">\n";
        for (const auto &r : records)
          vector3(get(r));
        out << "</DataArray>\n";
      };
      const auto scalar_field = [&](const std::string &name, auto get) {
        out << "<DataArray type=\"Float64\" Name=\"" << name
            << "\" format=\"ascii\">\n";
        for (const auto &r : records)
          out << get(r) << '\n';
        out << "</DataArray>\n";
      };
      using R = typename Fault<dim>::NodeRecord;
      vector_field("slip", [](const R &r) { return r.slip; });
      vector_field("slip_velocity", [](const R &r) { return r.slip_velocity; });
      scalar_field("slip_rate",
                   [](const R &r) { return r.slip_velocity.norm(); });
      scalar_field("slip_path", [](const R &r) { return r.slip_path; });
      // The slip's direction in the fault plane (degrees from strike,
      // positive up-dip: the rake of Aki and Richards; in 2-D 0 or 180),
      // and the angle between the slip rate and the shear traction
      // (degrees; 0 for isotropic friction, where slip follows the
      // traction; anisotropic friction turns the slip towards the weaker
      // direction). Both 0 where there is no slip (rate).
      scalar_field("rake", [this](const R &r) { return rake_of(r.slip); });
      scalar_field("slip_traction_angle", [](const R &r) {
        const Tensor<1, dim> shear =
          r.traction - (r.traction * r.normal) * r.normal;
        const double norms = shear.norm() * r.slip_velocity.norm();
        if (!(norms > 0))
          return 0.;
        return std::acos(
                 std::clamp((shear * r.slip_velocity) / norms, -1., 1.)) *
               180 / numbers::PI;
      });
      // With anisotropic friction, the frictional slip rate of the step
      // (along the ellipse's normal at the traction: the sliding rule).
      if (fault.has_anisotropic_friction())
        vector_field("frictional_slip_rate",
                     [](const R &r) { return r.sliding; });
      scalar_field("friction_coefficient",
                   [](const R &r) { return r.friction; });
      scalar_field("normal_traction",
                   [](const R &r) { return r.traction * r.normal; });
      vector_field("shear_traction", [](const R &r) {
        return Tensor<1, dim>(r.traction - (r.traction * r.normal) * r.normal);
      });
      scalar_field("state", [](const R &r) { return r.status; });
      scalar_field("rupture_time", [](const R &r) {
        return r.rupture_time < 0 ? 1e9 : r.rupture_time;
      });
      // The friction law's state variables (e.g. log10_theta).
      const std::vector<std::string> state_names =
        fault.friction().state_names();
      for (unsigned int i = 0; i < state_names.size(); ++i)
        scalar_field(state_names[i], [i](const R &r) {
          return (i < r.state_values.size()) ? r.state_values[i] : 0.;
        });
      out << "</PointData>\n</Piece>\n</UnstructuredGrid>\n</VTKFile>\n";

      std::ostringstream name;
      name << "fault/" << file_prefix << "_" << std::setw(5)
           << std::setfill('0') << step << ".vtu";
      directory.write(name.str(), out.str());
      this->records.emplace_back(time, name.str());
      std::ostringstream pvd;
      DataOutBase::write_pvd_record(pvd, this->records);
      directory.write(pvd_name, pvd.str());
    }



    template <int dim>
    void
    FaultOutput<dim>::write_tables(const Fault<dim>  &fault,
                                   Output::Directory &directory,
                                   const double       time_step,
                                   const bool         test_mode) const
    {
      events.write(fault, directory);
      const auto records = fault.gather();
      if (dealii::Utilities::MPI::this_mpi_process(communicator) != 0)
        return;
      const auto        state_names = fault.friction().state_names();
      const std::string first_state_name =
        state_names.empty() ? std::string() : state_names[0];
      for (const auto &s : stations)
        {
          if (seas_format)
            {
              directory.write(s.name + ".dat",
                              seas_station(s, first_state_name, test_mode));
              continue;
            }
          std::ostringstream   out;
          const Tensor<1, dim> r = s.location - origin;
          out << "# problem = rupture station output\n"
              << "# author = rupture\n";
          if (!test_mode)
            {
              const std::time_t now = std::time(nullptr);
              out << "# date = " << std::put_time(std::gmtime(&now), "%Y/%m/%d")
                  << "\n";
            }
          // One pass over the rows (kept on disk): their text, and their
          // times for the header.
          std::vector<double> times;
          std::ostringstream  body;
          body << std::scientific << std::setprecision(7);
          // (The SCEC columns; those after them, with anisotropic
          // friction, go to <name>-rake.dat.)
          const unsigned int n_scec =
            7 + (state_names.empty() ? 0 : 1 + state_names.size());
          std::ostringstream rake;
          rake << std::scientific << std::setprecision(7);
          s.rows.for_each([&](const std::vector<double> &row) {
            times.push_back(row[0]);
            for (unsigned int c = 0; c < row.size() && c < n_scec; ++c)
              body << (c ? " " : "") << row[c];
            body << "\n";
            if (row.size() > n_scec)
              {
                rake << row[0];
                for (unsigned int c = n_scec; c < row.size(); ++c)
                  rake << " " << row[c];
                rake << "\n";
              }
          });
          if (!rake.str().empty())
            directory.write(
              s.name + "-rake.dat",
              "# problem = rupture station directions (anisotropic "
              "friction)\n# location = " +
                std::to_string(strike_component(r) / 1e3) +
                " km along strike, " +
                std::to_string(down_dip_distance(s.location) / 1e3) +
                " km down-dip\n# Directions in degrees from the "
                "along-strike direction, positive up-dip (0 where the "
                "vector vanishes)\n# Column #1 = Time (s)\n# Column #2 = "
                "rake of the slip\n# Column #3 = direction of the "
                "frictional slip rate\n# Column #4 = direction of the shear "
                "traction\n# Column #5 = angle between the frictional slip "
                "rate and the shear traction\nt rake slip-rate-direction "
                "traction-direction slip-traction-angle\n" +
                rake.str());
          out << "# code = rupture\n# code_version = 0.1\n"
              << Output::time_step_lines(times, time_step)
              << "# num_time_steps = " << s.rows.size() << "\n"
              << "# location = " << strike_component(r) / 1e3
              << " km along strike, " << down_dip_distance(s.location) / 1e3
              << " km down-dip\n"
              << "# Column #1 = Time (s)\n"
              << "# Column #2 = horizontal slip (m)\n"
              << "# Column #3 = horizontal slip rate (m/s)\n"
              << "# Column #4 = horizontal shear stress (MPa)\n"
              << "# Column #5 = vertical slip (m)\n"
              << "# Column #6 = vertical slip rate (m/s)\n"
              << "# Column #7 = vertical shear stress (MPa)\n";
          // The SCEC rate-and-state format adds the normal stress and the
          // state (log10 theta as "log-theta", or psi).
          std::string header =
            "t h-slip h-slip-rate h-shear-stress v-slip v-slip-rate "
            "v-shear-stress";
          if (!state_names.empty())
            {
              out << "# Column #8 = normal stress (MPa, negative in "
                     "compression)\n";
              header += " n-stress";
              for (unsigned int i = 0; i < state_names.size(); ++i)
                {
                  std::string name = state_names[i];
                  if (name == "log10_theta")
                    name = "log-theta";
                  std::replace(name.begin(), name.end(), '_', '-');
                  out << "# Column #" << 9 + i << " = " << state_names[i]
                      << "\n";
                  header += " " + name;
                }
            }
          out << header << "\n" << body.str();
          directory.write(s.name + ".dat", out.str());
        }

      std::ostringstream out;
      out << "# problem = rupture rupture-time contours\n# author = rupture\n"
          << "# code = rupture\n# code_version = 0.1\n"
          << "# Column #1 = Distance along strike (m)\n"
          << "# Column #2 = Distance down-dip (m)\n"
          << "# Column #3 = Rupture time (s); 1.0E+09 where the fault did "
             "not rupture\n"
          << "j k t\n"
          << std::scientific << std::setprecision(7);
      for (const auto &rec : records)
        {
          const Tensor<1, dim> r = rec.location - origin;
          out << strike_component(r) << " " << down_dip_distance(rec.location)
              << " " << (rec.rupture_time < 0 ? 1e9 : rec.rupture_time) << "\n";
        }
      directory.write("rupture_time.dat", out.str());
    }



    template <int dim>
    std::string
    FaultOutput<dim>::seas_station(const Station     &s,
                                   const std::string &state_name,
                                   const bool         test_mode) const
    {
      const bool           has_state = !state_name.empty();
      const Tensor<1, dim> r         = s.location - origin;
      std::ostringstream   location;
      location << "on fault, " << strike_component(r) / 1e3
               << " km along strike, " << down_dip_distance(s.location) / 1e3
               << " km down-dip";
      std::string out =
        Output::seas_station_header(location.str(),
                                    test_mode,
                                    false,
                                    has_state ? state_name : "log10_theta");
      // A row of the station: t, h-slip, h-slip-rate, h-shear-stress,
      // v-..., then with a state the normal stress and the state outputs
      // (log10 theta first; without a state the columns after the SCEC
      // ones are anisotropic friction's directions).
      s.rows.for_each([&](const std::vector<double> &row) {
        out +=
          Output::seas_station_row(row[0],
                                   row[1],
                                   row[2],
                                   row[3],
                                   has_state && row.size() > 8 ? row[8] : 0.);
      });
      return out;
    }



    template <int dim>
    void
    FaultOutput<dim>::save(std::ostream &out) const
    {
      BinaryIO::write(out, records);
      BinaryIO::write(out, file_prefix);
      BinaryIO::write(out, pvd_name);
      BinaryIO::write(out, static_cast<std::uint64_t>(stations.size()));
      for (const auto &s : stations)
        s.rows.save(out);
      // (Only with a catalogue: the checkpoints of runs without one are as
      // they were.)
      if (events.enabled())
        events.save(out);
    }



    template <int dim>
    void
    FaultOutput<dim>::load(std::istream &in)
    {
      BinaryIO::read(in, records);
      BinaryIO::read(in, file_prefix);
      BinaryIO::read(in, pvd_name);
      AssertThrow(BinaryIO::read_size(in) == stations.size(),
                  ExcMessage("The checkpoint has another number of fault "
                             "stations than <Fault/Output/Stations> gives."));
      for (auto &s : stations)
        s.rows.load(in);
      if (events.enabled())
        events.load(in);
    }



    template class FaultOutput<2>;
    template class FaultOutput<3>;
  } // namespace Fault
} // namespace rupture
