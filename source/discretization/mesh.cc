// The mesh of the discretization: the scene's coarse mesh, its global
// refinements and the static refinement region, both sides of the fault
// alike.

#include <rupture/discretization/discretization.h>
#include <rupture/fault/fault.h>
#include <rupture/material/elastic_material.h>
#include <rupture/scene/scene.h>

#include <deal.II/base/utilities.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iomanip>
#include <limits>
#include <sstream>

namespace rupture
{
  namespace Discretization
  {
    namespace
    {
      /**
       * The memory of the nodes this run has (the sum of MemTotal over the
       * nodes), or 0 if unknown.
       */
      double
      memory_of_nodes(const MPI_Comm communicator, unsigned int &n_nodes)
      {
        MPI_Comm node;
        MPI_Comm_split_type(
          communicator, MPI_COMM_TYPE_SHARED, 0, MPI_INFO_NULL, &node);
        const bool first = dealii::Utilities::MPI::this_mpi_process(node) == 0;
        MPI_Comm_free(&node);
        double mine = 0;
        if (first)
          {
            std::ifstream in("/proc/meminfo");
            std::string   key;
            double        kilobytes = 0;
            while (in >> key >> kilobytes)
              {
                if (key == "MemTotal:")
                  {
                    mine = kilobytes * 1024;
                    break;
                  }
                in.ignore(256, '\n');
              }
          }
        n_nodes = dealii::Utilities::MPI::sum(first ? 1u : 0u, communicator);
        return dealii::Utilities::MPI::sum(mine, communicator);
      }
    } // namespace



    template <int dim>
    void
    Discretization<dim>::check_mesh_size(const double       n_coarse,
                                         const std::string &source,
                                         const double       available,
                                         const unsigned int n_nodes) const
    {
      // A lower bound of what a cell costs with everything the run builds
      // on it (about 1.6 kB for Q1 and 6.5 kB for Q2 hexahedra, measured):
      // a mesh that needs more than the nodes have cannot be set up.
      const double bytes_per_cell = 1000;
      const double n_cells =
        n_coarse * std::pow(2., dim * double(global_refinements));
      if (available > 0 && n_cells * bytes_per_cell > available)
        {
          std::ostringstream message;
          message << std::setprecision(3) << "The mesh would have about "
                  << n_cells << " cells (" << source << " " << n_coarse
                  << " coarse cells, refined "
                  << "<Discretization/Initial global refinement> = "
                  << global_refinements << " times), which needs at least "
                  << n_cells * bytes_per_cell / 1e9 << " GB, more than the "
                  << available / 1e9 << " GB of memory of the " << n_nodes
                  << " node(s) this run has. Allowed: a mesh that fits, at "
                     "1 kB per cell or more; give fewer cells or less "
                     "refinement, or run on more nodes.";
          AssertThrow(false, ExcMessage(message.str()));
        }
    }



    template <int dim>
    bool
    Discretization<dim>::flag_fault_alike()
    {
      if (!fault)
        return false;
      bool flagged = false;
      for (const auto &cell : mesh.active_cell_iterators())
        if (cell->is_locally_owned())
          for (const auto f : cell->face_indices())
            if (!cell->at_boundary(f) && cell->neighbor(f)->has_children())
              for (unsigned int c = 0; c < cell->face(f)->n_children(); ++c)
                {
                  const auto child = cell->neighbor_child_on_subface(f, c);
                  if (fault->side(child) != fault->side(cell) &&
                      !cell->refine_flag_set())
                    {
                      cell->clear_coarsen_flag();
                      cell->set_refine_flag();
                      flagged = true;
                    }
                }
      return dealii::Utilities::MPI::max(flagged ? 1 : 0, mpi_communicator) !=
             0;
    }



    template <int dim>
    void
    Discretization<dim>::refine_fault_alike()
    {
      // The mesh's 2:1 balance may refine a cell on one side of the fault
      // only: refine its neighbour across until both sides match.
      for (unsigned int pass = 0; pass < 2 * region_refinements + 2; ++pass)
        {
          if (!flag_fault_alike())
            return;
          mesh.execute_coarsening_and_refinement();
        }
    }



    template <int dim>
    bool
    Discretization<dim>::weighted() const
    {
      return fault && fault_cell_weight != 1 &&
             dealii::Utilities::MPI::n_mpi_processes(mpi_communicator) > 1;
    }



    template <int dim>
    unsigned int
    Discretization<dim>::cell_weight(
      const typename Triangulation<dim>::cell_iterator &cell,
      const typename Triangulation<dim>::CellStatus     status) const
    {
      // 1000 for a cell without a fault face (deal.II's own unit). The
      // children of a refined fault cell are weighed alike, on average:
      // half of them have a face on the fault. (deal.II 9.4 asks with the
      // parent for each child: CELL_REFINE for the first, CELL_INVALID for
      // the others.)
      const double unit = 1000;
      if (!fault->on_fault(cell))
        return unit;
      const bool child = status == Triangulation<dim>::CELL_REFINE ||
                         status == Triangulation<dim>::CELL_INVALID;
      const double extra = (child ? 0.5 : 1.) * (fault_cell_weight - 1);
      return static_cast<unsigned int>(std::lround(unit * (1 + extra)));
    }



    template <int dim>
    std::array<std::vector<double>, 2>
    Discretization<dim>::partition() const
    {
      // locally owned cells, and those with a face on the fault
      std::array<double, 2> mine = {{0, 0}};
      for (const auto &cell : mesh.active_cell_iterators())
        if (cell->is_locally_owned())
          {
            mine[0] += 1;
            mine[1] += (fault && fault->on_fault(cell)) ? 1 : 0;
          }
      const auto all =
        dealii::Utilities::MPI::all_gather(mpi_communicator, mine);
      std::array<std::vector<double>, 2> result;
      for (const auto &rank : all)
        for (unsigned int k = 0; k < 2; ++k)
          result[k].push_back(rank[k]);
      return result;
    }



    template <int dim>
    double
    Discretization<dim>::largest_over_mean(const std::vector<double> &loads)
    {
      double sum = 0, most = 0;
      for (const double x : loads)
        {
          sum += x;
          most = std::max(most, x);
        }
      return sum > 0 ? most * loads.size() / sum : 1.;
    }



    template <int dim>
    double
    Discretization<dim>::weighted_balance(
      const std::array<std::vector<double>, 2> &counts,
      const double                              weight)
    {
      std::vector<double> load(counts[0].size());
      for (unsigned int r = 0; r < load.size(); ++r)
        load[r] = counts[0][r] + (weight - 1) * counts[1][r];
      return largest_over_mean(load);
    }



    template <int dim>
    unsigned int
    Discretization<dim>::base_level(
      const typename Triangulation<dim>::cell_iterator &cell) const
    {
      // As make_mesh() refines: the scene's own levels and the global
      // refinements, then one level more for each ancestor (or the cell
      // itself) whose centre lies in the static refinement region, up to
      // its number of levels.
      unsigned int level = scene_levels + global_refinements;
      for (unsigned int k = 0; k < region_refinements; ++k)
        {
          if (level > static_cast<unsigned int>(cell->level()))
            break;
          auto ancestor = cell;
          while (static_cast<unsigned int>(ancestor->level()) > level)
            ancestor = ancestor->parent();
          if (!(region->value(ancestor->center()) > 0))
            break;
          ++level;
        }
      return level;
    }



    template <int dim>
    void
    Discretization<dim>::make_mesh(const Scene::Interface<dim>      &scene,
                                   const Material::ElasticMaterials &materials,
                                   const std::string                &saved_mesh,
                                   ConditionalOStream               &pcout)
    {
      // The size is checked before anything large is built: from the
      // scene's own count if it has one, else from the coarse mesh.
      unsigned int n_nodes   = 0;
      const double available = memory_of_nodes(mpi_communicator, n_nodes);
      if (scene.n_coarse_cells() > 0)
        check_mesh_size(scene.n_coarse_cells(),
                        "the scene's <Number of cells> give",
                        available,
                        n_nodes);
      // Every partition from here on (the scene's own refinements, the
      // global ones, the region's, each adaptation) weighs the fault's
      // cells; a loaded checkpoint keeps the partition it was saved with
      // on as many ranks.
      if (weighted())
        mesh.signals.weight.connect(
          [this](const typename Triangulation<dim>::cell_iterator &cell,
                 const typename Triangulation<dim>::CellStatus     status) {
            return cell_weight(cell, status);
          });
      scene.create_coarse_mesh(mesh);
      // A scene may refine its coarse blocks itself (a box's tree levels):
      // the levels a mesh that follows the rupture never coarsens.
      {
        unsigned int level = std::numeric_limits<unsigned int>::max();
        for (const auto &cell : mesh.active_cell_iterators())
          if (cell->is_locally_owned())
            level = std::min<unsigned int>(level, cell->level());
        scene_levels = dealii::Utilities::MPI::min(level, mpi_communicator);
      }
      check_mesh_size(mesh.n_global_active_cells(),
                      "the scene's coarse mesh has",
                      available,
                      n_nodes);
      for (const auto &cell : mesh.active_cell_iterators())
        materials.check_material_id(cell->material_id());
      // Children take their parent's material wherever p4est refines a
      // coarse cell again (cells moved between processes, a loaded
      // checkpoint): a scene's parent cells carry their children's.
      // (Each process holds only the refinement near its own cells: the
      // verdict is taken together.)
      std::string mixed;
      for (const auto &cell : mesh.cell_iterators())
        if (mixed.empty() && cell->has_children())
          for (const auto &child : cell->child_iterators())
            if (child->material_id() != cell->material_id() && mixed.empty())
              {
                std::ostringstream where;
                where << "the scene's cell at (" << cell->center()
                      << ") on level " << cell->level() << " has material id "
                      << cell->material_id() << " and a child with "
                      << child->material_id();
                mixed = where.str();
              }
      if (dealii::Utilities::MPI::max(mixed.empty() ? 0 : 1,
                                      mpi_communicator) != 0)
        AssertThrow(false,
                    ExcMessage("Internal error: " +
                               (mixed.empty() ? std::string("on another "
                                                            "process, ") :
                                                mixed + "; ") +
                               "a scene must give its parent cells their "
                               "children's material."));
      // A continued run takes the checkpoint's refined mesh (and its
      // partition onto this run's ranks), with the fields attached.
      const bool saved = !saved_mesh.empty();
      if (saved)
        mesh.load(saved_mesh);
      else
        mesh.refine_global(global_refinements);
      for (unsigned int level = 0; level < (saved ? 0 : region_refinements);
           ++level)
        {
          std::string bad_centre;
          for (const auto &cell : mesh.active_cell_iterators())
            if (cell->is_locally_owned())
              {
                const double value = region->value(cell->center());
                if (!std::isfinite(value) && bad_centre.empty())
                  {
                    std::ostringstream where;
                    where << "(" << cell->center() << ")";
                    bad_centre = where.str();
                  }
                if (value > 0)
                  cell->set_refine_flag();
                // Both cells of a fault face are refined alike: where the
                // region covers one, the other is flagged too (evaluated
                // here, where that cell may be another process's).
                if (fault && !cell->refine_flag_set())
                  for (const auto f : cell->face_indices())
                    if (fault->interface_face(cell, f) &&
                        !cell->neighbor(f)->has_children() &&
                        region->value(cell->neighbor(f)->center()) > 0)
                      cell->set_refine_flag();
              }
          // Every process stops, not only the one that found the value.
          AssertThrow(dealii::Utilities::MPI::max(bad_centre.empty() ? 0 : 1,
                                                  mpi_communicator) == 0,
                      ExcMessage(
                        "<Discretization/Refinement region> is not a "
                        "finite number at the cell centre " +
                        (bad_centre.empty() ?
                           std::string("of a cell of another process") :
                           bad_centre) +
                        ". Allowed are expressions that are finite "
                        "everywhere in the model."));
          mesh.execute_coarsening_and_refinement();
          if (fault)
            refine_fault_alike();
        }

      // The refinements above weighed the children of a fault cell alike
      // (see refine()): once more with each cell's own weight.
      if (weighted() && !saved)
        mesh.repartition();

      std::vector<double> cells_per_material(materials.n_materials(), 0.);
      for (const auto &cell : mesh.active_cell_iterators())
        if (cell->is_locally_owned())
          cells_per_material[cell->material_id()] += 1;
      MPI_Allreduce(MPI_IN_PLACE,
                    cells_per_material.data(),
                    cells_per_material.size(),
                    MPI_DOUBLE,
                    MPI_SUM,
                    mpi_communicator);
      pcout << "   Mesh: " << mesh.n_global_active_cells()
            << " cells (per material id:";
      for (const double n : cells_per_material)
        pcout << " " << static_cast<unsigned long>(n);
      pcout << ")\n" << materials.summary();
    }



    template class Discretization<2>;
    template class Discretization<3>;
  } // namespace Discretization
} // namespace rupture
