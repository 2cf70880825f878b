#include <rupture/adaptivity/wavefield_criterion.h>

#include <deal.II/base/mpi.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/fe_values_extractors.h>
#include <deal.II/hp/fe_values.h>
#include <deal.II/hp/q_collection.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <map>
#include <vector>

namespace rupture
{
  namespace Adaptivity
  {
    namespace
    {
      /// The gradients of the displacement-like field @p v of the cell
      /// that @p values was set up for (its side's component group).
      template <int dim>
      void
      gradients_of(const dealii::FEValuesBase<dim>             &values,
                   const dealii::TrilinosWrappers::MPI::Vector &v,
                   const unsigned int                           side,
                   std::vector<dealii::Tensor<2, dim>>         &out)
      {
        out.resize(values.n_quadrature_points);
        values[dealii::FEValuesExtractors::Vector(side * dim)]
          .get_function_gradients(v, out);
      }
    } // namespace



    template <int dim>
    WavefieldCriterion<dim>::WavefieldCriterion(
      const dealii::DoFHandler<dim>               &dofs,
      const dealii::TrilinosWrappers::MPI::Vector &velocity,
      const double                                 threshold,
      const double                                 band)
      : threshold(threshold)
      , degree(dofs.get_fe_collection().max_degree())
      , indicator(dofs.get_triangulation().n_active_cells())
    {
      using namespace dealii;
      const hp::FECollection<dim> &elements = dofs.get_fe_collection();
      hp::QCollection<dim - 1>     quadratures;
      for (unsigned int i = 0; i < elements.size(); ++i)
        quadratures.push_back(QGauss<dim - 1>(degree + 1));
      const UpdateFlags flags = update_gradients | update_normal_vectors |
                                update_quadrature_points | update_JxW_values;
      hp::FEFaceValues<dim> own_face(elements, quadratures, flags),
        other_face(elements, quadratures, flags);
      hp::FESubfaceValues<dim> own_subface(elements, quadratures, flags),
        other_subface(elements, quadratures, flags);
      std::vector<Tensor<2, dim>> own, other;
      // The cell's side of the fault, and its sums over its faces.
      unsigned int side     = 0;
      double       integral = 0, area = 0;

      // The jump's square integrated over one face (or subface) seen from
      // both cells, their quadrature points matched by place.
      const auto add_jump = [&](const FEValuesBase<dim> &a,
                                const FEValuesBase<dim> &b) {
        gradients_of(a, velocity, side, own);
        gradients_of(b, velocity, side, other);
        for (unsigned int q = 0; q < a.n_quadrature_points; ++q)
          {
            unsigned int nearest = 0;
            double       best    = std::numeric_limits<double>::max();
            for (unsigned int k = 0; k < b.n_quadrature_points; ++k)
              {
                const double d =
                  a.quadrature_point(q).distance_square(b.quadrature_point(k));
                if (d < best)
                  {
                    best    = d;
                    nearest = k;
                  }
              }
            const Tensor<1, dim> jump =
              (own[q] - other[nearest]) * a.normal_vector(q);
            integral += jump.norm_square() * a.JxW(q);
            area += a.JxW(q);
          }
      };

      double largest = 0;
      for (const auto &cell : dofs.active_cell_iterators())
        if (cell->is_locally_owned())
          {
            side     = cell->active_fe_index();
            integral = 0;
            area     = 0;
            for (const unsigned int f : cell->face_indices())
              {
                if (cell->at_boundary(f))
                  continue;
                const auto neighbor = cell->neighbor(f);
                if (neighbor->has_children())
                  {
                    // Finer neighbours: one subface each.
                    for (unsigned int s = 0; s < cell->face(f)->n_children();
                         ++s)
                      {
                        const auto child =
                          cell->neighbor_child_on_subface(f, s);
                        if (child->active_fe_index() != side)
                          continue;
                        own_subface.reinit(cell, f, s);
                        other_face.reinit(child, cell->neighbor_of_neighbor(f));
                        add_jump(own_subface.get_present_fe_values(),
                                 other_face.get_present_fe_values());
                      }
                    continue;
                  }
                if (neighbor->active_fe_index() != side)
                  continue;
                own_face.reinit(cell, f);
                if (cell->neighbor_is_coarser(f))
                  {
                    const auto [face, subface] =
                      cell->neighbor_of_coarser_neighbor(f);
                    other_subface.reinit(neighbor, face, subface);
                    add_jump(own_face.get_present_fe_values(),
                             other_subface.get_present_fe_values());
                  }
                else
                  {
                    other_face.reinit(neighbor, cell->neighbor_of_neighbor(f));
                    add_jump(own_face.get_present_fe_values(),
                             other_face.get_present_fe_values());
                  }
              }
            const double value = area > 0 ? std::sqrt(integral / area) : 0.;
            indicator[cell->active_cell_index()] = value;
            largest                              = std::max(largest, value);
          }
      const MPI_Comm communicator = dofs.get_triangulation().get_communicator();
      largest_indicator = dealii::Utilities::MPI::max(largest, communicator);
      if (band <= 0)
        return;

      // The band: the cells that hold a wave which needs their level (not
      // coarsened: the parent's estimate at least half the threshold) or a
      // finer one (above the threshold), with the level they need. A wave
      // in such a cell may be anywhere in it, so the distance counts from
      // its centre plus half its diameter (the largest such, for all of
      // them). The band crosses the processes' borders: each process gets
      // the waves of every process that lie in the box of its own cells'
      // vertices widened by the reach and half its largest cell, which
      // holds every point within the reach of one of its cells (not all
      // waves: their number grows with the mesh).
      std::vector<std::pair<Point<dim>, double>> mine;
      double                                     widest = 0, own_widest = 0;
      std::array<double, 2 * dim + 1>            box;
      for (unsigned int d = 0; d < dim; ++d)
        {
          box[d]       = std::numeric_limits<double>::max();
          box[dim + d] = -std::numeric_limits<double>::max();
        }
      box[2 * dim] = 0; // (1: the process owns cells)
      for (const auto &cell : dofs.active_cell_iterators())
        if (cell->is_locally_owned())
          {
            box[2 * dim] = 1;
            own_widest   = std::max(own_widest, cell->diameter());
            for (const unsigned int v : cell->vertex_indices())
              for (unsigned int d = 0; d < dim; ++d)
                {
                  box[d]       = std::min(box[d], cell->vertex(v)[d]);
                  box[dim + d] = std::max(box[dim + d], cell->vertex(v)[d]);
                }
            const double value = indicator[cell->active_cell_index()];
            if (std::ldexp(value, static_cast<int>(degree)) < 0.5 * threshold)
              continue;
            mine.emplace_back(cell->center(),
                              cell->level() + (value > threshold ? 1 : 0));
            widest = std::max(widest, cell->diameter());
          }
      reach = band + 0.5 * dealii::Utilities::MPI::max(widest, communicator);
      const double margin = reach + 0.5 * own_widest;
      for (unsigned int d = 0; d < dim; ++d)
        {
          box[d] -= margin;
          box[dim + d] += margin;
        }
      const std::vector<std::array<double, 2 *dim + 1>> boxes =
        dealii::Utilities::MPI::all_gather(communicator, box);
      std::map<unsigned int, std::vector<double>> out;
      for (const auto &w : mine)
        for (unsigned int r = 0; r < boxes.size(); ++r)
          {
            bool inside = boxes[r][2 * dim] > 0;
            for (unsigned int d = 0; d < dim && inside; ++d)
              inside =
                w.first[d] >= boxes[r][d] && w.first[d] <= boxes[r][dim + d];
            if (!inside)
              continue;
            std::vector<double> &flat = out[r];
            for (unsigned int d = 0; d < dim; ++d)
              flat.push_back(w.first[d]);
            flat.push_back(w.second);
          }
      std::vector<std::pair<Point<dim>, double>> waves;
      for (const auto &[rank, flat] :
           dealii::Utilities::MPI::some_to_some(communicator, out))
        for (std::size_t i = 0; i + dim < flat.size(); i += dim + 1)
          {
            Point<dim> p;
            for (unsigned int d = 0; d < dim; ++d)
              p[d] = flat[i + d];
            waves.emplace_back(p, flat[i + dim]);
          }
      // needing[l]: the centres of the cells that need level l or finer.
      unsigned int finest = 0;
      for (const auto &w : waves)
        finest = std::max(finest, static_cast<unsigned int>(w.second));
      std::vector<std::vector<Point<dim>>> points(waves.empty() ? 0 :
                                                                  finest + 1);
      for (const auto &w : waves)
        for (unsigned int l = 0; l <= static_cast<unsigned int>(w.second); ++l)
          points[l].push_back(w.first);
      for (const auto &p : points)
        needing.push_back(std::make_unique<PointCloud<dim>>(p));
    }



    template <int dim>
    WavefieldCriterion<dim>::~WavefieldCriterion() = default;



    template <int dim>
    Decision
    WavefieldCriterion<dim>::decide(
      const typename dealii::Triangulation<dim>::cell_iterator &cell,
      const unsigned int                                        base_level,
      const unsigned int finest_level) const
    {
      const double       value = indicator[cell->active_cell_index()];
      const unsigned int level = cell->level();
      // Within the band of a wave that needs level l: a point of the cell
      // within the reach of the centre of that wave's cell.
      const auto near = [&](const unsigned int l) {
        return l < needing.size() &&
               needing[l]->any_within(cell->center(),
                                      reach + 0.5 * cell->diameter());
      };
      if (level < finest_level && (value > threshold || near(level + 1)))
        return Decision::refine;
      if (level > base_level && !near(level) &&
          std::ldexp(value, static_cast<int>(degree)) < 0.5 * threshold)
        return Decision::coarsen;
      return Decision::keep;
    }



    template class WavefieldCriterion<2>;
    template class WavefieldCriterion<3>;
  } // namespace Adaptivity
} // namespace rupture
