#ifndef rupture_discretization_cell_wise_fields_h
#define rupture_discretization_cell_wise_fields_h

#include <deal.II/distributed/tria.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/hp/fe_collection.h>
#include <deal.II/lac/la_parallel_vector.h>

#include <vector>

namespace rupture
{
  namespace Discretization
  {
    using namespace dealii;

    /**
     * Finite-element fields carried through several meshes by their values
     * on each locally owned cell (its element's index and its DoF values,
     * one block per field), without DoFs on the meshes between: a refined
     * cell's children get the parent's polynomials (the element's
     * prolongation), a coarsened family's parent the children's interpolant
     * (the element's restriction, as deal.II's SolutionTransfer computes
     * it), and a cell that moves to another process takes its values with
     * it. The cells' elements are those of the DoF handler's collection,
     * which the DoF handler itself carries to the children.
     *
     * A cell keeps the fields up to the last one that is not zero on it
     * (the fault's state is zero away from the fault). A mesh whose cells
     * are only refined carries the fields exactly (their
     * values at a hanging node are then their own polynomial's); where a
     * family was coarsened next to finer cells the values at the hanging
     * nodes are set right only by that mesh's constraints, which the caller
     * distributes: on the final mesh, or, if a later mesh may refine the
     * coarse cell (the node would stop hanging with two values), on the
     * coarsened mesh's DoFs before going on (write(), distribute, and a new
     * CellWiseFields, as Discretization::refine() does).
     */
    template <int dim>
    class CellWiseFields
    {
    public:
      using Vector = LinearAlgebra::distributed::Vector<double>;

      /// The values of @p fields (with ghost entries) on the locally owned
      /// cells of @p dofs, whose elements are @p elements.
      CellWiseFields(const DoFHandler<dim>                     &dofs,
                     const hp::FECollection<dim>               &elements,
                     const std::vector<Vector *>               &fields,
                     parallel::distributed::Triangulation<dim> &mesh);

      /// Attach the values to the mesh before it is refined, coarsened or
      /// partitioned again (execute_coarsening_and_refinement() or
      /// repartition()).
      void
      attach();

      /// Take the values back on the new mesh.
      void
      unpack();

      /// Write the values into @p fields (each with the ghost entries of
      /// @p dofs, the DoFs of the final mesh): every DoF of a locally owned
      /// cell, ghost entries included.
      void
      write(const DoFHandler<dim>       &dofs,
            const std::vector<Vector *> &fields) const;

    private:
      using CellIterator = typename Triangulation<dim>::cell_iterator;

      /// The values of one cell: its element's index, then each field's
      /// DoF values up to the last field that is not zero on the cell (the
      /// others are zero).
      using Values = std::vector<double>;

      /// The element's index of @p v.
      static unsigned int
      element(const Values &v)
      {
        return static_cast<unsigned int>(v[0]);
      }

      /// Leave out the fields after the last one that is not zero.
      void
      trim(Values &v) const;

      /// A coarsened family's values on the parent.
      Values
      restricted(const CellIterator &parent) const;

      const hp::FECollection<dim>               &elements;
      parallel::distributed::Triangulation<dim> &mesh;
      const unsigned int                         n_fields;
      /// Per active cell (by its active index): its Values, empty for the
      /// cells of other processes.
      std::vector<Values> cells;
      unsigned int        handle = 0;
    };
  } // namespace Discretization
} // namespace rupture

#endif
