// The fault's stiffness from a finite-element model of the antiplane body:
// one factorisation, one solve per fault node.

#include <rupture/boundary_integral/antiplane_body.h>
#include <rupture/boundary_integral/antiplane_finite_elements.h>

#include <deal.II/base/mpi.h>

#include <iomanip>
#include <sstream>

namespace rupture
{
  namespace BoundaryIntegral
  {
    using namespace dealii;

    AntiplaneFiniteElements::AntiplaneFiniteElements(
      const Settings &settings,
      const MPI_Comm  communicator)
      : settings(settings)
      , body_(std::make_shared<const AntiplaneBody>(settings))
    {
      const AntiplaneBody &body    = *body_;
      n_cells                      = body.mesh.n_active_cells();
      n_dofs                       = body.dofs.n_dofs();
      node_depths                  = body.node_depths;
      tributary                    = body.tributary;
      const auto        &A         = body.A;
      const auto        &held      = body.held;
      const auto        &fault_dof = body.fault_dof;
      const unsigned int N         = fault_dof.size();

      // This rank's columns.
      const unsigned int rank = dealii::Utilities::MPI::this_mpi_process(
                           communicator),
                         ranks = dealii::Utilities::MPI::n_mpi_processes(
                           communicator);
      const unsigned int first = std::size_t(N) * rank / ranks,
                         last  = std::size_t(N) * (rank + 1) / ranks;
      std::vector<double> columns;
      columns.reserve(std::size_t(last - first) * N);
      // The right-hand side -A u_j of u_j = 1/2 at node j is nonzero only
      // in column j of A (its row, A being symmetric), and only the
      // fault's rows of A u are needed: no product with the whole matrix.
      Vector<double> u(n_dofs);
      for (unsigned int j = first; j < last; ++j)
        {
          const types::global_dof_index dof = fault_dof[j];
          u                                 = 0;
          for (auto entry = A.begin(dof); entry != A.end(dof); ++entry)
            if (!held[entry->column()])
              u[entry->column()] = -0.5 * entry->value();
          body.solve(u);
          u[dof] = 0.5;
          for (unsigned int i = 0; i < N; ++i)
            {
              double reaction = 0;
              for (auto entry = A.begin(fault_dof[i]);
                   entry != A.end(fault_dof[i]);
                   ++entry)
                reaction += entry->value() * u[entry->column()];
              columns.push_back(-reaction / tributary[i]);
            }
        }
      // All columns on every rank, stored by rows.
      const std::vector<std::vector<double>> parts =
        dealii::Utilities::MPI::all_gather(communicator, columns);
      matrix.assign(std::size_t(N) * N, 0.);
      unsigned int j = 0;
      for (const auto &part : parts)
        for (std::size_t c = 0; c < part.size() / N; ++c, ++j)
          for (unsigned int i = 0; i < N; ++i)
            matrix[std::size_t(i) * N + j] = part[c * N + i];
      if (!settings.keep_body)
        body_.reset();
    }



    std::vector<double>
    AntiplaneFiniteElements::rows(const unsigned int begin,
                                  const unsigned int end) const
    {
      const std::size_t N = size();
      return std::vector<double>(matrix.begin() + begin * N,
                                 matrix.begin() + end * N);
    }



    std::string
    AntiplaneFiniteElements::description() const
    {
      std::ostringstream s;
      s << std::setprecision(6) << "antiplane finite elements (Q"
        << settings.degree << ", " << n_cells << " cells, " << n_dofs
        << " unknowns on a " << settings.domain_size / 1e3 << " km box), "
        << size() << " fault nodes " << settings.fault_depth / size()
        << " m apart" << (settings.degree > 2 ? " on average" : "")
        << " down to " << settings.fault_depth / 1e3 << " km";
      return s.str();
    }
  } // namespace BoundaryIntegral
} // namespace rupture
