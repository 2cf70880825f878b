#include <rupture/base/ghosted_vectors.h>

#include <Epetra_Import.h>

namespace rupture
{
  GhostedVectors::GhostedVectors(const IndexSet    &owned,
                                 const IndexSet    &relevant,
                                 const MPI_Comm     communicator,
                                 const unsigned int n_vectors)
  {
    vectors.emplace_back(owned, relevant, communicator);
    // The copies share the first one's (reference-counted) layout.
    for (unsigned int i = 1; i < n_vectors; ++i)
      vectors.push_back(vectors[0]);
    const TrilinosWrappers::MPI::Vector source(owned, communicator);
    importer =
      std::make_unique<Epetra_Import>(vectors[0].trilinos_vector().Map(),
                                      source.trilinos_vector().Map());
  }



  GhostedVectors::~GhostedVectors() = default;



  const TrilinosWrappers::MPI::Vector &
  GhostedVectors::copy(const unsigned int                   i,
                       const TrilinosWrappers::MPI::Vector &source)
  {
    AssertIndexRange(i, vectors.size());
    const int code =
      vectors[i].trilinos_vector().Import(source.trilinos_vector(),
                                          *importer,
                                          Insert);
    AssertThrow(code == 0, ExcTrilinosError(code));
    return vectors[i];
  }
} // namespace rupture
