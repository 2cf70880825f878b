// Fields carried through meshes by their values on each cell (no DoFs on
// the meshes between the first and the last).

#include <rupture/discretization/cell_wise_fields.h>

#include <deal.II/base/exceptions.h>
#include <deal.II/lac/vector.h>

#include <algorithm>
#include <cstring>

namespace rupture
{
  namespace Discretization
  {
    template <int dim>
    CellWiseFields<dim>::CellWiseFields(
      const DoFHandler<dim>                     &dofs,
      const hp::FECollection<dim>               &elements,
      const std::vector<Vector *>               &fields,
      parallel::distributed::Triangulation<dim> &mesh)
      : elements(elements)
      , mesh(mesh)
      , n_fields(fields.size())
      , cells(mesh.n_active_cells())
    {
      dealii::Vector<double> local;
      for (const auto &cell : dofs.active_cell_iterators())
        if (cell->is_locally_owned())
          {
            const unsigned int n = cell->get_fe().n_dofs_per_cell();
            Values            &v = cells[cell->active_cell_index()];
            v.resize(1 + n_fields * n);
            v[0] = cell->active_fe_index();
            local.reinit(n);
            for (unsigned int k = 0; k < n_fields; ++k)
              {
                cell->get_dof_values(*fields[k], local);
                std::copy(local.begin(), local.end(), v.begin() + 1 + k * n);
              }
            trim(v);
          }
    }



    template <int dim>
    void
    CellWiseFields<dim>::trim(Values &v) const
    {
      // The fields after the last one that is not zero on the cell (the
      // fault's state away from the fault, the motion where no wave has
      // arrived) are left out.
      const unsigned int n = elements[element(v)].n_dofs_per_cell();
      unsigned int       m = (v.size() - 1) / std::max(n, 1u);
      while (m > 0 && std::all_of(v.begin() + 1 + (m - 1) * n,
                                  v.begin() + 1 + m * n,
                                  [](const double x) { return x == 0.; }))
        --m;
      v.resize(1 + m * n);
    }



    template <int dim>
    typename CellWiseFields<dim>::Values
    CellWiseFields<dim>::restricted(const CellIterator &parent) const
    {
      // As DoFCellAccessor::get_interpolated_dof_values(): each child's
      // restriction adds to the additive shape functions and sets the
      // others where it is not zero. (A child's missing fields are zero.)
      const Values      &first = cells[parent->child(0)->active_cell_index()];
      const auto        &fe    = elements[element(first)];
      const unsigned int n     = fe.n_dofs_per_cell();
      Values             out(1 + n_fields * n, 0.);
      out[0] = first[0];
      dealii::Vector<double> in(n), restricted(n);
      for (unsigned int c = 0; c < parent->n_children(); ++c)
        {
          const Values &child = cells[parent->child(c)->active_cell_index()];
          const auto   &matrix =
            fe.get_restriction_matrix(c, parent->refinement_case());
          for (unsigned int k = 0; k < (child.size() - 1) / std::max(n, 1u);
               ++k)
            {
              const auto from = child.begin() + 1 + k * n;
              std::copy(from, from + n, in.begin());
              matrix.vmult(restricted, in);
              double *to = out.data() + 1 + k * n;
              for (unsigned int i = 0; i < n; ++i)
                if (fe.restriction_is_additive(i))
                  to[i] += restricted[i];
                else if (restricted[i] != 0.)
                  to[i] = restricted[i];
            }
        }
      trim(out);
      return out;
    }



    template <int dim>
    void
    CellWiseFields<dim>::attach()
    {
      using Status = typename Triangulation<dim>::CellStatus;
      handle       = mesh.register_data_attach(
        [this](const CellIterator &cell, const Status status) {
          // Each cell is packed once, by itself or by its parent: its
          // values go as they are packed (the memory of the mesh's buffer
          // is then mostly theirs).
          Values v;
          if (status == Triangulation<dim>::CELL_COARSEN)
            {
              v = restricted(cell);
              for (unsigned int c = 0; c < cell->n_children(); ++c)
                Values().swap(cells[cell->child(c)->active_cell_index()]);
            }
          else
            v.swap(cells[cell->active_cell_index()]);
          const char *bytes = reinterpret_cast<const char *>(v.data());
          return std::vector<char>(bytes, bytes + v.size() * sizeof(double));
        },
        true);
    }



    template <int dim>
    void
    CellWiseFields<dim>::unpack()
    {
      using Status = typename Triangulation<dim>::CellStatus;
      cells.assign(mesh.n_active_cells(), Values());
      mesh.notify_ready_to_unpack(
        handle,
        [this](const CellIterator &cell,
               const Status        status,
               const boost::iterator_range<std::vector<char>::const_iterator>
                 &data) {
          Values v(data.size() / sizeof(double));
          std::memcpy(v.data(), &*data.begin(), v.size() * sizeof(double));
          if (status != Triangulation<dim>::CELL_REFINE)
            {
              cells[cell->active_cell_index()] = std::move(v);
              return;
            }
          // The children get the parent's polynomials.
          const auto            &fe = elements[element(v)];
          const unsigned int     n  = fe.n_dofs_per_cell();
          const unsigned int     m  = (v.size() - 1) / std::max(n, 1u);
          dealii::Vector<double> in(n), out(n);
          for (unsigned int c = 0; c < cell->n_children(); ++c)
            {
              const auto &matrix =
                fe.get_prolongation_matrix(c, cell->refinement_case());
              Values child(v.size());
              child[0] = v[0];
              for (unsigned int k = 0; k < m; ++k)
                {
                  const auto from = v.begin() + 1 + k * n;
                  std::copy(from, from + n, in.begin());
                  matrix.vmult(out, in);
                  std::copy(out.begin(), out.end(), child.begin() + 1 + k * n);
                }
              cells[cell->child(c)->active_cell_index()] = std::move(child);
            }
        });
    }



    template <int dim>
    void
    CellWiseFields<dim>::write(const DoFHandler<dim>       &dofs,
                               const std::vector<Vector *> &fields) const
    {
      // The fields start at zero; a cell writes only the fields it kept
      // (those it left out are zero on it).
      dealii::Vector<double> local;
      for (auto *f : fields)
        *f = 0.;
      for (const auto &cell : dofs.active_cell_iterators())
        if (cell->is_locally_owned())
          {
            const Values      &v = cells[cell->active_cell_index()];
            const unsigned int n = cell->get_fe().n_dofs_per_cell();
            Assert(!v.empty() && element(v) == cell->active_fe_index(),
                   ExcInternalError());
            local.reinit(n);
            for (unsigned int k = 0; k < (v.size() - 1) / std::max(n, 1u); ++k)
              {
                const auto from = v.begin() + 1 + k * n;
                std::copy(from, from + n, local.begin());
                cell->set_dof_values(local, *fields[k]);
              }
          }
    }



    template class CellWiseFields<2>;
    template class CellWiseFields<3>;
  } // namespace Discretization
} // namespace rupture
