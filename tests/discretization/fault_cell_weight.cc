// <Discretization/Fault cell weight>: the partition of the mesh between
// ranks weighs the cells with a face on the fault. A box 4 x 1 km split by
// a fault at y = 250 m over x < 2 km (welded beyond), two global
// refinements, in 2-D and 3-D, with weights 1 and 5:
// - Fault::on_fault() finds the cells of the fault faces, on both sides
//   and only where the fault region is (the count is the same for every
//   partition);
// - with weight 1 the ranks get equal numbers of cells; with weight 5
//   equal sums of weights (a cell on the fault counting 5), which
//   Discretization::partition() reports for each rank and which, on more
//   than one rank, the unweighted partition does not balance;
// - the same after the fault's cells are refined once and coarsened back
//   by Discretization::refine(), as during a run (with a weight, its last
//   round partitions the final mesh again with each cell's own weight).

#include <rupture/discretization/discretization.h>
#include <rupture/fault/fault.h>
#include <rupture/material/elastic_material.h>
#include <rupture/scene/scene.h>

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/timer.h>
#include <deal.II/base/utilities.h>

#include <cstdio>
#include <string>
#include <vector>

using namespace dealii;
using rupture::Discretization::Discretization;

namespace
{
  const char *
  yes(const bool b)
  {
    return b ? "yes" : "no";
  }



  /// Largest over mean of cells, of fault cells, and of the load that
  /// counts a fault cell @p w times; the number of fault cells.
  template <int dim>
  std::vector<double>
  balance(const Discretization<dim> &discretization, const double w)
  {
    const auto counts  = discretization.partition();
    double     n_fault = 0;
    for (const double n : counts[1])
      n_fault += n;
    return {Discretization<dim>::largest_over_mean(counts[0]),
            Discretization<dim>::largest_over_mean(counts[1]),
            Discretization<dim>::weighted_balance(counts, w),
            n_fault};
  }



  template <int dim>
  std::vector<std::vector<double>>
  run(const double weight)
  {
    ParameterHandler prm;
    rupture::Scene::declare_parameters(prm);
    rupture::Material::ElasticMaterials::declare_parameters(prm);
    rupture::Fault::Fault<dim>::declare_parameters(prm);
    prm.enter_subsection("Discretization");
    Discretization<dim>::declare_parameters(prm);
    prm.leave_subsection();
    prm.parse_input_from_string(
      "subsection Scene\n"
      "  set Model = box\n"
      "  subsection Box\n"
      "    set Lower corner = " +
      std::string(dim == 2 ? "0, 0" : "0, 0, 0") +
      "\n"
      "    set Upper corner = " +
      std::string(dim == 2 ? "4000, 1000" : "4000, 1000, 1000") +
      "\n"
      "    set Number of cells = " +
      std::string(dim == 2 ? "16, 4" : "8, 4, 2") +
      "\n"
      "  end\n"
      "end\n"
      "subsection Fault\n"
      "  set Model = traction at split nodes\n"
      "  set Plane point = " +
      std::string(dim == 2 ? "0, 250" : "0, 250, 0") +
      "\n"
      "  set Plane normal = " +
      std::string(dim == 2 ? "0, 1" : "0, 1, 0") +
      "\n"
      "  set Fault region = x < 2000 ? 1 : 0\n"
      "end\n"
      "subsection Discretization\n"
      "  set Initial global refinement = 2\n"
      "  set Fault cell weight = " +
      std::to_string(weight) +
      "\n"
      "end\n");
    const auto scene = rupture::Scene::create<dim>(prm);
    rupture::Material::ElasticMaterials materials;
    materials.parse_parameters(prm);
    const auto          fault = rupture::Fault::Fault<dim>::create(prm);
    Discretization<dim> discretization(MPI_COMM_WORLD);
    prm.enter_subsection("Discretization");
    discretization.parse_parameters(prm);
    prm.leave_subsection();
    discretization.set_fault(fault.get());
    ConditionalOStream silent(std::cout, false);
    discretization.make_mesh(*scene, materials, "", silent);

    std::vector<std::vector<double>> result;
    result.push_back(balance(discretization, 5.));
    // Adapted as during a run: Discretization::refine() with a field.
    discretization.distribute_dofs();
    TimerOutput                                           timer(MPI_COMM_SELF,
                      silent,
                      TimerOutput::never,
                      TimerOutput::wall_times);
    std::vector<typename Discretization<dim>::VectorType> fields(1);
    const auto adapt = [&](const bool refine) {
      fields[0].reinit(discretization.locally_owned_dofs(), MPI_COMM_WORLD);
      for (const auto &cell :
           discretization.triangulation().active_cell_iterators())
        if (cell->is_locally_owned())
          {
            if (refine && fault->on_fault(cell))
              cell->set_refine_flag();
            if (!refine && cell->level() > 2)
              cell->set_coarsen_flag();
          }
      discretization.refine(
        fields, 2, {}, [&]() { discretization.distribute_dofs(); }, timer);
      result.push_back(balance(discretization, 5.));
    };
    adapt(true);
    adapt(false);
    return result;
  }



  template <int dim>
  void
  check()
  {
    const auto  plain    = run<dim>(1);
    const auto  weighted = run<dim>(5);
    const bool  serial   = Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD) == 1;
    const char *stage[]  = {"made", "fault refined", "coarsened back"};
    if (Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
      for (unsigned int k = 0; k < 3; ++k)
        {
          const auto &p = plain[k], &w = weighted[k];
          std::printf("%d-D, mesh %s: %g cells on the fault with either "
                      "weight; largest rank over the mean, weight 1: cells "
                      "%.3f, fault cells %.3f, load 5:1 %.3f; weight 5: cells "
                      "%.3f, fault cells %.3f, load 5:1 %.3f\n",
                      dim,
                      stage[k],
                      p[3],
                      p[0],
                      p[1],
                      p[2],
                      w[0],
                      w[1],
                      w[2]);
          // Weight 1 balances cells, weight 5 the load; on several ranks
          // the plain partition leaves the load less even than the weighted.
          std::printf("   same fault cells: %s, weight 1 balances cells: %s, "
                      "weight 5 balances the load: %s, better than weight 1: "
                      "%s\n",
                      yes(p[3] == w[3]),
                      yes(p[0] <= 1.02),
                      yes(w[2] <= 1.05),
                      yes(serial ? w[2] == 1 : w[2] + 0.1 < p[2]));
        }
  }
} // namespace



int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  check<2>();
  check<3>();
}
