#include <rupture/adaptivity/fault_refinement.h>
#include <rupture/output/statistics_columns.h>
#include <rupture/simulator/simulator.h>

#include <deal.II/base/utilities.h>

#include <cmath>
#include <iomanip>
#include <sstream>

namespace rupture
{
  template <int dim>
  void
  Simulator<dim>::print_performance_summary() const
  {
    // The cost per unknown and step, and the memory per unknown: the
    // figures doc/performance.md compares with other codes.
    const unsigned int n_ranks =
      dealii::Utilities::MPI::n_mpi_processes(communicator);
    const types::global_dof_index n_dofs =
      discretization.dof_handler().n_dofs();
    dealii::Utilities::System::MemoryStats stats;
    dealii::Utilities::System::get_memory_stats(stats);
    const double peak     = 1024. * stats.VmHWM;
    const double peak_max = dealii::Utilities::MPI::max(peak, communicator);
    const double peak_sum = dealii::Utilities::MPI::sum(peak, communicator);
    pcout << std::defaultfloat << std::setprecision(4)
          << "   Time loop: " << state.step << " steps of " << n_dofs
          << " DoFs in " << cost.time_loop_seconds << " s on " << n_ranks
          << " rank(s): "
          << (state.step > 0 ?
                1e9 * cost.time_loop_seconds * n_ranks /
                  (mesh_refinement.enabled() ? cost.dof_steps :
                                               double(n_dofs) * state.step) :
                0.)
          << " ns per DoF-step per core\n";
    if (n_ranks > 1)
      {
        // Largest rank over the mean: of the cells, of those on the fault,
        // and of the weights the partition balanced.
        const auto   counts = discretization.partition();
        const double w      = discretization.fault_weight();
        using D             = Discretization::Discretization<dim>;
        pcout << "   Partition of the last mesh, largest rank over the mean: "
              << std::setprecision(3) << "cells "
              << D::largest_over_mean(counts[0]);
        if (fault)
          pcout << ", cells on the fault " << D::largest_over_mean(counts[1])
                << ", weighted (<Discretization/Fault cell weight> = " << w
                << ") " << D::weighted_balance(counts, w);
        pcout << "\n" << std::setprecision(4);
      }
    if (mesh_refinement.enabled())
      pcout << "   Mesh refinement: " << fault_refinement->n_adaptations()
            << " adaptations (" << discretization.n_meshes_made()
            << " new meshes) in " << fault_refinement->seconds()
            << " s (with those before the first step, if made), "
            << cost.peak_dofs << " DoFs at the peak, " << cost.dof_steps
            << " DoF-steps\n";
    if (balance_report.adaptations + balance_report.failures > 0)
      pcout << "   Balance after adaptation: " << balance_report.adaptations
            << " new meshes balanced in " << balance_report.iterations
            << " Newton iterations, " << balance_report.failures
            << " not balanced (the solve failed)\n";
    pcout << "   Peak memory: " << peak_max / 1048576.
          << " MB on the largest rank, " << peak_sum / 1048576.
          << " MB on all ranks, " << peak_sum / double(n_dofs)
          << " B per DoF\n";
    if (!cost.memory_by_stage.empty())
      {
        // Growth of the resident memory over the set-up stages, then up to
        // the peak: where the bytes per DoF go.
        pcout << "   Memory per DoF by stage (resident, all ranks):";
        double previous = 0;
        for (const auto &[stage, bytes] : cost.memory_by_stage)
          {
            pcout << " " << stage << " +"
                  << std::max(bytes - previous, 0.) / double(n_dofs) << " B,";
            previous = bytes;
          }
        pcout << " to the peak +"
              << std::max(peak_sum - previous, 0.) / double(n_dofs) << " B\n";
      }
  }



  template <int dim>
  void
  Simulator<dim>::record_memory(const std::string &stage)
  {
    dealii::Utilities::System::MemoryStats stats;
    dealii::Utilities::System::get_memory_stats(stats);
    cost.memory_by_stage.emplace_back(
      stage, dealii::Utilities::MPI::sum(1024. * stats.VmRSS, communicator));
  }



  namespace
  {
    /// @p text as a JSON string.
    std::string
    json_string(const std::string &text)
    {
      std::ostringstream s;
      s << '"';
      for (const char c : text)
        if (c == '"' || c == '\\')
          s << '\\' << c;
        else if (c == '\n')
          s << "\\n";
        else if (static_cast<unsigned char>(c) < 0x20)
          s << ' ';
        else
          s << c;
      s << '"';
      return s.str();
    }

    /// @p x as a JSON number (null if not finite).
    std::string
    json_number(const double x)
    {
      if (!std::isfinite(x))
        return "null";
      std::ostringstream s;
      s << std::setprecision(10) << x;
      return s.str();
    }
  } // namespace



  template <int dim>
  Termination::Sample
  Simulator<dim>::termination_sample(const std::vector<double> &row) const
  {
    Termination::Sample s;
    s.time            = state.clock.phase_time;
    const auto column = [&](const char *name) {
      return row[statistics.index(name)];
    };
    s.kinetic_energy = column(Output::Columns::kinetic_energy);
    if (fault)
      {
        s.slipping_area       = column(Output::Columns::slipping_area);
        s.max_slip            = column(Output::Columns::max_slip);
        s.max_slip_rate       = column(Output::Columns::max_slip_rate);
        s.seismic_moment      = column(Output::Columns::seismic_moment);
        s.mean_shear_traction = column(Output::Columns::mean_shear_traction);
        s.events              = fault_output->n_events();
      }
    if (termination.uses_wall_clock())
      {
        // Rank 0's clock, so that all ranks stop at the same step.
        double seconds = MPI_Wtime() - cost.wall_time_start;
        MPI_Bcast(&seconds, 1, MPI_DOUBLE, 0, communicator);
        s.wall_seconds = seconds;
      }
    return s;
  }



  template <int dim>
  void
  Simulator<dim>::write_summary(const std::string &status,
                                const std::string &message)
  {
    // A failure may be one rank's alone: then no collective call, and rank
    // 0 writes what it knows.
    const bool collective = (status != "failed");
    const bool root =
      dealii::Utilities::MPI::this_mpi_process(communicator) == 0;
    const unsigned int n_ranks =
      dealii::Utilities::MPI::n_mpi_processes(communicator);
    std::ostringstream out;
    const std::string  end = (status == "finished" || status == "ended early") ?
                               Termination::name(outcome.reason) :
                               status;
    out << "{\n"
        << "  \"status\": " << json_string(status) << ",\n"
        << "  \"end\": " << json_string(end) << ",\n"
        << "  \"message\": " << json_string(message) << ",\n"
        << "  \"dimension\": " << dim << ",\n"
        << "  \"ranks\": " << n_ranks << ",\n"
        << "  \"dofs\": " << discretization.dof_handler().n_dofs() << ",\n"
        << "  \"steps\": " << state.step << ",\n"
        << "  \"time loop wall time\": "
        << json_number(test_mode ? 0. : cost.time_loop_seconds) << ",\n";
    if (collective)
      {
        // The last mesh's cells and fault cells on each rank.
        const auto counts = discretization.partition();
        const auto list   = [](const std::vector<double> &x) {
          std::ostringstream s;
          for (unsigned int r = 0; r < x.size(); ++r)
            s << (r > 0 ? ", " : "") << static_cast<unsigned long long>(x[r]);
          return "[" + s.str() + "]";
        };
        out << "  \"partition\": {\"fault cell weight\": "
            << json_number(discretization.fault_weight())
            << ", \"cells per rank\": " << list(counts[0])
            << ", \"fault cells per rank\": " << list(counts[1]) << "},\n";
      }
    if (mesh_refinement.enabled())
      out << "  \"mesh adaptations\": " << fault_refinement->n_adaptations()
          << ",\n"
          << "  \"meshes made\": " << discretization.n_meshes_made() << ",\n"
          << "  \"peak dofs\": " << json_number(cost.peak_dofs) << ",\n"
          << "  \"dof-steps\": " << json_number(cost.dof_steps) << ",\n"
          << "  \"adaptation wall time\": "
          << json_number(test_mode ? 0. : fault_refinement->seconds()) << ",\n"
          << "  \"balanced adaptations\": " << balance_report.adaptations
          << ",\n"
          << "  \"balance iterations\": " << balance_report.iterations << ",\n"
          << "  \"balances failed\": " << balance_report.failures << ",\n";
    // What the stability studies read: the explicit scheme's stable step
    // (null where none was computed), the last step, the steps cut in half.
    out << "  \"stable time step\": "
        << (stable_time_step > 0 ? json_number(stable_time_step) : "null")
        << ",\n"
        << "  \"time step\": " << json_number(state.time_step) << ",\n"
        << "  \"step cuts\": " << newton.status().total_step_cuts << ",\n";
    if (status == "finished" || status == "ended early")
      {
        const EnergyVerdict verdict = energy_verdict();
        out << "  \"energy balance\": {\"error\": "
            << json_number(verdict.error)
            << ", \"scale\": " << json_number(verdict.scale)
            << ", \"tolerance\": " << json_number(verdict.tolerance)
            << ", \"within\": " << (verdict.within() ? "true" : "false")
            << "},\n";
      }
    out << "  \"time\": " << json_number(state.clock.phase_time) << ",\n"
        << "  \"time since the start of the run\": " << json_number(state.time)
        << ",\n"
        << "  \"wall time\": "
        << json_number(test_mode ? 0. : MPI_Wtime() - cost.wall_time_start);
    if (collective)
      {
        dealii::Utilities::System::MemoryStats stats;
        dealii::Utilities::System::get_memory_stats(stats);
        const double peak = 1024. * stats.VmHWM;
        out << ",\n  \"peak memory, largest rank (B)\": "
            << json_number(test_mode ?
                             0. :
                             dealii::Utilities::MPI::max(peak, communicator))
            << ",\n  \"peak memory, all ranks (B)\": "
            << json_number(test_mode ?
                             0. :
                             dealii::Utilities::MPI::sum(peak, communicator));
        if (fault)
          {
            const Fault::Statistics f = fault->statistics();
            out << ",\n  \"fault\": {\n"
                << "    \"seismic moment\": " << json_number(f.seismic_moment)
                << ",\n"
                << "    \"moment magnitude\": "
                << ((dim == 3 && f.seismic_moment > 0) ?
                      json_number(2. / 3. *
                                  (std::log10(f.seismic_moment) - 9.1)) :
                      "null")
                << ",\n"
                << "    \"ruptured area\": " << json_number(f.ruptured_area)
                << ",\n"
                << "    \"mean slip\": " << json_number(f.mean_slip) << ",\n"
                << "    \"max slip\": " << json_number(f.max_slip) << ",\n"
                << "    \"peak slip rate\": "
                << json_number(outcome.peak_slip_rate) << ",\n"
                << "    \"nodes\": " << f.n_nodes << "\n  }";
          }
      }
    out << "\n}\n";
    if (root)
      output_directory->write("summary.json", out.str());
  }



  template class Simulator<2>;
  template class Simulator<3>;
} // namespace rupture
