#ifndef rupture_boundary_integral_antiplane_body_h
#define rupture_boundary_integral_antiplane_body_h

#include <rupture/boundary_integral/antiplane_finite_elements.h>

#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/grid/tria.h>
#include <deal.II/lac/sparse_direct.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/sparsity_pattern.h>
#include <deal.II/lac/vector.h>

#include <vector>

namespace rupture
{
  namespace BoundaryIntegral
  {
    /**
     * The meshed side x > 0 of the antiplane body of
     * AntiplaneFiniteElements (see there): the graded grid, FE_Q of the
     * settings' degree, the stiffness matrix A (C55 u,x v,x + C44 u,y v,y),
     * which unknowns are held (the fault, the far side x = width and the
     * bottom y = -height), the fault's nodes above W by depth with their
     * tributary lengths, and one sparse direct factorisation of A with
     * the held rows and columns cut to the diagonal: a solve with the held
     * values on the right-hand side gives the static field. What the
     * fault's stiffness (one solve per node) and the fully dynamic phases
     * (AntiplaneDynamics) share.
     */
    struct AntiplaneBody
    {
      /// Mesh, assemble and factorise; throws on settings out of range.
      explicit AntiplaneBody(const AntiplaneFiniteElements::Settings &settings);

      /**
       * The static field @p u for the values of the held unknowns in
       * @p u (all other entries are overwritten): A u = 0 at every free
       * unknown.
       */
      void
      solve_static(dealii::Vector<double> &u) const;

      /// Solve the reduced system in place (@p rhs: zero or the diagonal
      /// times the value at the held unknowns).
      void
      solve(dealii::Vector<double> &rhs) const
      {
        solver.solve(rhs);
      }

      const AntiplaneFiniteElements::Settings settings;
      /// The antiplane moduli (C44 = C55 for an isotropic body).
      double C55 = 0, C44 = 0;
      /// The fault's cell size above W, the box's width and height (m).
      double                        h = 0, width = 0, height = 0;
      dealii::Triangulation<2>      mesh;
      dealii::FE_Q<2>               fe;
      dealii::DoFHandler<2>         dofs;
      dealii::SparsityPattern       sparsity;
      dealii::SparseMatrix<double>  A;
      std::vector<dealii::Point<2>> support;
      std::vector<bool>             held;
      /// The fault's nodes above W, from the surface down: their unknowns,
      /// depths and tributary lengths.
      std::vector<dealii::types::global_dof_index> fault_dof;
      std::vector<double>                          node_depths, tributary;

    private:
      dealii::SparseMatrix<double>        reduced;
      mutable dealii::SparseDirectUMFPACK solver;
    };
  } // namespace BoundaryIntegral
} // namespace rupture

#endif
