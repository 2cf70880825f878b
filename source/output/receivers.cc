#include <rupture/base/binary_io.h>
#include <rupture/base/utilities.h>
#include <rupture/output/receivers.h>
#include <rupture/output/series_header.h>

#include <deal.II/base/exceptions.h>
#include <deal.II/fe/mapping_q1.h>
#include <deal.II/grid/grid_tools.h>

#include <iomanip>
#include <sstream>

namespace rupture
{
  namespace Output
  {
    template <int dim>
    Receivers<dim>::Receivers(const std::string &specification,
                              const MPI_Comm     communicator)
      : communicator(communicator)
    {
      for (const auto &[name, location] :
           Utilities::parse_named_points<dim>(specification,
                                              "Output/Receivers"))
        {
          Receiver r;
          r.name     = name;
          r.location = location;
          receivers.push_back(std::move(r));
        }
    }



    template <int dim>
    void
    Receivers<dim>::setup(const DoFHandler<dim> &dof_handler,
                          const IndexSet        &locally_owned_dofs)
    {
      const unsigned int rank =
        dealii::Utilities::MPI::this_mpi_process(communicator);
      const unsigned int n_ranks =
        dealii::Utilities::MPI::n_mpi_processes(communicator);
      if (receivers.empty())
        return;
      IndexSet needed(locally_owned_dofs.size());
      for (auto &r : receivers)
        {
          r.dofs.clear();
          r.weights.clear();
          r.components.clear();
          r.owned = false;
          typename DoFHandler<dim>::active_cell_iterator cell;
          Point<dim>                                     unit;
          bool                                           found = false;
          try
            {
              const auto hit =
                GridTools::find_active_cell_around_point(MappingQ1<dim>(),
                                                         dof_handler,
                                                         r.location);
              cell  = hit.first;
              unit  = hit.second;
              found = cell.state() == IteratorState::valid &&
                      cell->is_locally_owned();
            }
          catch (...)
            {
              found = false;
            }
          // A point on a cell boundary may be found by several ranks: the
          // lowest one records it.
          const unsigned int owner =
            dealii::Utilities::MPI::min(found ? rank : n_ranks, communicator);
          if (owner == n_ranks)
            {
              std::ostringstream m;
              m << "The receiver <" << r.name << "> at (" << r.location
                << ") given in <Output/Receivers> is not inside the mesh.";
              AssertThrow(false, ExcMessage(m.str()));
            }
          if (owner != rank)
            continue;
          r.owned                                 = true;
          const auto                          &fe = cell->get_fe();
          std::vector<types::global_dof_index> cell_dofs(fe.n_dofs_per_cell());
          cell->get_dof_indices(cell_dofs);
          for (unsigned int i = 0; i < cell_dofs.size(); ++i)
            {
              r.dofs.push_back(cell_dofs[i]);
              r.weights.push_back(fe.shape_value(i, unit));
              r.components.push_back(fe.system_to_component_index(i).first %
                                     dim);
              needed.add_index(cell_dofs[i]);
            }
        }
      needed.add_indices(locally_owned_dofs);
      ghosted.reinit(locally_owned_dofs, needed, communicator);
    }



    template <int dim>
    void
    Receivers<dim>::record(const TrilinosWrappers::MPI::Vector &displacement,
                           const TrilinosWrappers::MPI::Vector &velocity,
                           const double                         time)
    {
      if (receivers.empty())
        return;
      std::vector<double> values(receivers.size() * 2 * dim, 0.);
      for (unsigned int field = 0; field < 2; ++field)
        {
          ghosted = (field == 0 ? displacement : velocity);
          for (unsigned int k = 0; k < receivers.size(); ++k)
            if (receivers[k].owned)
              for (unsigned int i = 0; i < receivers[k].dofs.size(); ++i)
                values[(2 * k + field) * dim + receivers[k].components[i]] +=
                  receivers[k].weights[i] * ghosted(receivers[k].dofs[i]);
        }
      const int ierr = MPI_Allreduce(MPI_IN_PLACE,
                                     values.data(),
                                     static_cast<int>(values.size()),
                                     MPI_DOUBLE,
                                     MPI_SUM,
                                     communicator);
      AssertThrowMPI(ierr);
      if (dealii::Utilities::MPI::this_mpi_process(communicator) != 0)
        return;
      for (unsigned int k = 0; k < receivers.size(); ++k)
        {
          std::vector<double> row(1 + 2 * dim);
          row[0] = time;
          for (unsigned int c = 0; c < dim; ++c)
            {
              row[1 + 2 * c] = values[(2 * k) * dim + c];
              row[2 + 2 * c] = values[(2 * k + 1) * dim + c];
            }
          receivers[k].rows.append(row);
        }
    }



    template <int dim>
    void
    Receivers<dim>::write(Directory &directory, const double time_step) const
    {
      if (dealii::Utilities::MPI::this_mpi_process(communicator) != 0)
        return;
      const char *axis[3] = {"x", "y", "z"};
      for (const auto &r : receivers)
        {
          std::ostringstream out;
          // One pass over the rows (kept on disk): their text, and their
          // times for the header.
          std::vector<double> times;
          std::ostringstream  body;
          body << std::setprecision(9) << std::scientific;
          r.rows.for_each([&](const std::vector<double> &row) {
            times.push_back(row[0]);
            for (unsigned int i = 0; i < row.size(); ++i)
              body << (i ? " " : "") << row[i];
            body << "\n";
          });
          out << "# problem = rupture receiver (off-fault station) output\n"
              << "# author = rupture\n# code = rupture\n"
              << "# code_version = 0.1\n"
              << time_step_lines(times, time_step)
              << "# num_time_steps = " << r.rows.size() << "\n"
              << "# location = " << r.location
              << " (m, global coordinates)\n# Column #1 = Time (s)\n";
          for (unsigned int c = 0; c < dim; ++c)
            out << "# Column #" << 2 + 2 * c << " = " << axis[c]
                << " displacement (m)\n# Column #" << 3 + 2 * c << " = "
                << axis[c] << " velocity (m/s)\n";
          out << "t";
          for (unsigned int c = 0; c < dim; ++c)
            out << " " << axis[c] << "-disp " << axis[c] << "-vel";
          out << "\n" << body.str();
          directory.write(r.name + ".dat", out.str());
        }
    }



    template <int dim>
    void
    Receivers<dim>::save(std::ostream &out) const
    {
      BinaryIO::write(out, static_cast<std::uint64_t>(receivers.size()));
      for (const auto &r : receivers)
        r.rows.save(out);
    }



    template <int dim>
    void
    Receivers<dim>::load(std::istream &in)
    {
      AssertThrow(BinaryIO::read_size(in) == receivers.size(),
                  ExcMessage("The checkpoint has another number of "
                             "receivers than <Output/Receivers> gives."));
      for (auto &r : receivers)
        {
          r.rows.load(in);
          AssertThrow(r.rows.empty() || r.rows.last().size() == 1 + 2 * dim,
                      ExcMessage("A receiver row of the checkpoint has "
                                 "the wrong length."));
        }
    }



    template class Receivers<2>;
    template class Receivers<3>;
  } // namespace Output
} // namespace rupture
