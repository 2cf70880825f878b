#include <rupture/simulator/simulator.h>

#include <deal.II/base/utilities.h>

#include <iomanip>

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
    const types::global_dof_index          n_dofs = dof_handler.n_dofs();
    dealii::Utilities::System::MemoryStats stats;
    dealii::Utilities::System::get_memory_stats(stats);
    const double peak     = 1024. * stats.VmHWM;
    const double peak_max = dealii::Utilities::MPI::max(peak, communicator);
    const double peak_sum = dealii::Utilities::MPI::sum(peak, communicator);
    pcout << std::defaultfloat << std::setprecision(4)
          << "   Time loop: " << step << " steps of " << n_dofs << " DoFs in "
          << time_loop_seconds << " s on " << n_ranks << " rank(s): "
          << (step > 0 ?
                1e9 * time_loop_seconds * n_ranks / (double(n_dofs) * step) :
                0.)
          << " ns per DoF-step per core\n"
          << "   Peak memory: " << peak_max / 1048576.
          << " MB on the largest rank, " << peak_sum / 1048576.
          << " MB on all ranks, " << peak_sum / double(n_dofs)
          << " B per DoF\n";
    if (!memory_by_stage.empty())
      {
        // Growth of the resident memory over the set-up stages, then up to
        // the peak: where the bytes per DoF go.
        pcout << "   Memory per DoF by stage (resident, all ranks):";
        double previous = 0;
        for (const auto &[stage, bytes] : memory_by_stage)
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
    memory_by_stage.emplace_back(
      stage, dealii::Utilities::MPI::sum(1024. * stats.VmRSS, communicator));
  }



  template class Simulator<2>;
  template class Simulator<3>;
} // namespace rupture
