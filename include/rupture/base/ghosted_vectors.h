#ifndef rupture_base_ghosted_vectors_h
#define rupture_base_ghosted_vectors_h

#include <deal.II/base/index_set.h>
#include <deal.II/base/mpi.h>
#include <deal.II/lac/trilinos_vector.h>

#include <memory>
#include <vector>

class Epetra_Import;

namespace rupture
{
  using namespace dealii;

  /**
   * A few ghosted copies (locally relevant entries) of distributed Trilinos
   * vectors, with the exchange pattern built once. A plain assignment to a
   * ghosted vector builds the pattern anew each time, which costs as much
   * as some hundred vector operations on a large mesh.
   */
  class GhostedVectors
  {
  public:
    /**
     * @p n_vectors copies with the locally @p owned and the locally
     * @p relevant entries. Collective.
     */
    GhostedVectors(const IndexSet    &owned,
                   const IndexSet    &relevant,
                   const MPI_Comm     communicator,
                   const unsigned int n_vectors);

    ~GhostedVectors();

    /**
     * Copy @p source (owned entries only) into copy @p i and update its
     * ghost entries. Collective.
     */
    const TrilinosWrappers::MPI::Vector &
    copy(const unsigned int i, const TrilinosWrappers::MPI::Vector &source);

  private:
    std::vector<TrilinosWrappers::MPI::Vector> vectors;
    std::unique_ptr<Epetra_Import>             importer;
  };
} // namespace rupture

#endif
