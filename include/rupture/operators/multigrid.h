#ifndef rupture_operators_multigrid_h
#define rupture_operators_multigrid_h

#include <rupture/material/elastic_material.h>
#include <rupture/operators/elastic_operator.h>

#include <deal.II/base/tensor.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/grid/tria.h>
#include <deal.II/hp/fe_collection.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/la_parallel_vector.h>

#include <array>
#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace rupture
{
  namespace Operators
  {
    using namespace dealii;

    /**
     * A geometric multigrid V-cycle for the effective stiffness
     * stiffness_factor K + mass_factor M + T of implicit and quasi-static
     * steps (T the fault's contact tangent), that stores no matrix on any
     * level (see doc/design.md, "Geometric multigrid").
     *
     * The levels are the meshes of the p4est hierarchy, coarsened globally
     * from the simulator's mesh (deal.II's global-coarsening sequence, each
     * coarse cell on the rank of its first child), at degree 1, and above
     * them the simulator's mesh at the degrees between 1 and its own, each
     * half the next (p-coarsening: 4, 2, 1 or 3, 1). Each level has its own
     * hp DoFHandler with the fault's sides, so that the split of the
     * displacement field and the fault's welding are re-discretised on
     * every level, and its own matrix-free ElasticOperator. The transfer
     * between levels is the FE_Q prolongation (between meshes) or
     * interpolation (between degrees), cell by cell, on the side's own
     * components (deal.II 9.4's transfers do not take the FE_Nothing
     * split); restriction is its transpose.
     *
     * The fault's contact tangent on a coarser level is the restriction of
     * the finer one (the Galerkin product P^T T P lumped to the pairs), so
     * the pairs that stick, slip or open on the fine mesh do so on every
     * level; it is symmetrised, so that every level operator is symmetric.
     * Smoothing is Chebyshev iteration around the pair-block Jacobi of the
     * block-Jacobi preconditioner; the coarsest level is solved by GMRES
     * with the same block Jacobi to a loose tolerance (the V-cycle is
     * therefore not exactly linear: use it in flexible Krylov methods).
     */
    template <int dim>
    class Multigrid
    {
    public:
      using VectorType = LinearAlgebra::distributed::Vector<double>;

      /// The (minus, plus) DoFs of a split node pair, one per component.
      using PairDofs = std::pair<std::array<types::global_dof_index, dim>,
                                 std::array<types::global_dof_index, dim>>;

      /**
       * What the levels are built from.
       */
      struct Description
      {
        /// The simulator's mesh, DoFs, their constraints (hanging nodes and
        /// welding) and its operator: the finest level.
        const Triangulation<dim>         *triangulation = nullptr;
        const DoFHandler<dim>            *dof_handler   = nullptr;
        const AffineConstraints<double>  *constraints   = nullptr;
        const ElasticOperator<dim>       *fine_operator = nullptr;
        const hp::FECollection<dim>      *fe_collection = nullptr;
        unsigned int                      fe_degree     = 1;
        const Material::ElasticMaterials *materials     = nullptr;
        /// Set the active FE index (fault side) of the locally owned cells.
        std::function<void(DoFHandler<dim> &)> set_sides;
        /**
         * Add the fault's welding constraints of a level's DoFHandler to
         * the constraints and return its split pairs (those whose minus DoF
         * of component 0 is locally owned).
         */
        std::function<std::vector<PairDofs>(const DoFHandler<dim> &,
                                            AffineConstraints<double> &)>
          interface;
        /// The boundaries whose displacement increment is prescribed, with
        /// the components that are.
        std::vector<std::pair<types::boundary_id, std::array<bool, dim>>>
          kinematic_boundaries;
        /// Chebyshev degree of the smoother.
        unsigned int smoothing_degree = 4;
      };

      Multigrid();
      ~Multigrid();

      /**
       * Build the levels for the simulator's current mesh. Collective.
       */
      void
      reinit(const Description &description, const MPI_Comm communicator);

      /**
       * Set the operator of the next solves: the factors of K and of the
       * consistent M, and the contact tangent of the fine level's pairs:
       * the minus DoFs of each locally owned pair and its block D (area
       * times the tangent, so that the pair contributes [D, -D; -D, D]).
       * Sets up the smoothers (an eigenvalue estimate on each level).
       * Collective.
       */
      void
      set_operator(
        const double                                  stiffness_factor,
        const double                                  mass_factor,
        const std::vector<std::pair<std::array<types::global_dof_index, dim>,
                                    Tensor<2, dim>>> &pair_tangents);

      /**
       * One V-cycle: z = B r on the owned arrays of vectors with the fine
       * mesh's locally owned DoFs. @p free_dofs is 1 at free DoFs and 0 at
       * constrained ones, where z = r (the identity rows of the system).
       */
      void
      vmult(const double *r, double *z, const double *free_dofs) const;

      /// Number of levels.
      unsigned int
      n_levels() const;

      /// DoFs and iterations of the coarse solves, for the screen.
      std::string
      summary() const;

      /// Memory of the levels (bytes, this rank).
      std::size_t
      memory_consumption() const;

    private:
      struct Implementation;
      std::unique_ptr<Implementation> impl;
    };
  } // namespace Operators
} // namespace rupture

#endif
