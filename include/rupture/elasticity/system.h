#ifndef rupture_elasticity_system_h
#define rupture_elasticity_system_h

#include <rupture/operators/elastic_system.h>
#include <rupture/operators/node_coupling.h>
#include <rupture/time_integration/newmark.h>

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/function_parser.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/timer.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/la_parallel_vector.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <functional>
#include <memory>
#include <vector>

namespace rupture
{
  namespace Discretization
  {
    template <int dim>
    class Discretization;
  }
  namespace Fault
  {
    template <int dim>
    class Fault;
  }
  namespace Material
  {
    class ElasticMaterials;
  }
  namespace Scene
  {
    template <int dim>
    class BoundaryConditions;
  }
  namespace Operators
  {
    template <int dim>
    class ElasticOperator;
    template <int dim>
    class FaultZoneDamping;
    template <int dim>
    class Multigrid;
  } // namespace Operators
  namespace Solver
  {
    class LinearSolver;
  }
  namespace TimeIntegration
  {
    struct TimeState;
  }

  /**
   * The elastic body on its discretization: stiffness, mass, damping,
   * absorbing boundaries and loads, and the effective stiffness of the
   * implicit and quasi-static solves with its preconditioner.
   */
  namespace Elasticity
  {
    using namespace dealii;

    /**
     * The elastic system of the run (Operators::ElasticSystem), with one
     * vector type (Trilinos'): the stiffness matrix-free (deal.II's
     * MatrixFree with sum factorisation) or stored, the mass lumped or
     * consistent, Rayleigh damping, the fault zone's Kelvin-Voigt layer,
     * the absorbing boundaries' dashpots, gravity, boundary tractions and a
     * body force; the effective stiffness k K + m M + c C_absorbing stored
     * with its algebraic preconditioner, or matrix-free with the
     * block-Jacobi or geometric multigrid preconditioner. Only what the run
     * needs is built (a scene pays only for what it uses).
     *
     * setup() builds the operators of the current DoFs, assemble() their
     * matrices and constant loads; both run again after each change of
     * the mesh.
     */
    template <int dim>
    class System : public Operators::ElasticSystem
    {
    public:
      using VectorType   = TrilinosWrappers::MPI::Vector;
      using CellIterator = typename DoFHandler<dim>::active_cell_iterator;

      System(const Discretization::Discretization<dim> &discretization,
             const Material::ElasticMaterials          &materials,
             const Scene::BoundaryConditions<dim>      &boundary_conditions,
             const TimeIntegration::Parameters         &time_parameters,
             const TimeIntegration::TimeState          &state,
             Solver::LinearSolver                      &linear_solver,
             TimerOutput                               &timer,
             ConditionalOStream                        &pcout,
             const MPI_Comm                             communicator);
      ~System() override;

      /// Read <Discretization>'s <Mass matrix> and <Stiffness operator>,
      /// <Damping> and <Loads>; with @p test_mode, print no sizes of memory.
      void
      parse_parameters(ParameterHandler &prm, const bool test_mode);
      /// The explicit scheme always lumps the mass (after
      /// parse_parameters(), which reads <Mass matrix>).
      void
      use_lumped_mass_always()
      {
        use_lumped_mass = true;
      }
      /// The fault whose pairs the operators couple (none by default).
      void
      set_fault(Fault::Fault<dim> *fault)
      {
        this->fault = fault;
      }
      /// The scheme of the phase being run: a quasi-static phase has no
      /// damping; its solves always use multigrid if it is built.
      void
      set_scheme(const TimeIntegration::Scheme scheme)
      {
        this->scheme = scheme;
      }
      TimeIntegration::Scheme
      current_scheme() const
      {
        return scheme;
      }

      // --- set-up and assembly (system.cc, assembly.cc) ---
      /// The operators of the current DoFs: the matrices' patterns, the
      /// matrix-free operator, the diagonals, multigrid, the fault zone, the
      /// vectors of the constant loads and diagonal operators, and the near
      /// null space; the linear solver's preconditioner and factors of the
      /// old matrices are cleared.
      void
      setup();
      /// Assemble the stored matrices, the lumped mass, the absorbing
      /// dashpots and the constant loads (gravity, tractions).
      void
      assemble();
      /// Call @p action with the DoF indices, the stiffness matrix and (if
      /// @p with_mass) the consistent mass matrix of each locally owned
      /// cell. Cells for which @p selected is false are skipped (none if
      /// it is empty).
      void
      for_each_cell_matrix(
        const bool                                             with_mass,
        const std::function<void(const CellIterator &,
                                 const std::vector<types::global_dof_index> &,
                                 FullMatrix<double> &,
                                 const FullMatrix<double> &)> &action,
        const std::function<bool(const CellIterator &)> &selected = {}) const;
      /// The rigid-body modes at the locally owned DoFs: the near null
      /// space of the algebraic multigrid.
      std::vector<std::vector<double>>
      rigid_body_modes() const;

      // Operators::ElasticSystem
      void
      apply_stiffness(const VectorType &x, VectorType &y) const override;
      const double *
      apply_stiffness_in_place(const VectorType &x) const override;
      void
      apply_mass(const VectorType &x, VectorType &y) const override;
      void
      damping_force(const VectorType &v, VectorType &y) const override;
      void
      absorbing_force(const VectorType &v, VectorType &y) const override;
      void
      set_effective_stiffness(const double stiffness_factor,
                              const double mass_factor,
                              const double absorbing_factor) override;
      const VectorType &
      load(const double t) override;
      void
      assemble_load(const double t, VectorType &f) const override;
      const VectorType &
      lumped_mass() const override
      {
        return lumped_mass_vector;
      }
      const VectorType *
      absorbing_damping() const override
      {
        return has_absorbing() ? &absorbing_vector : nullptr;
      }

      const Operators::NodeCoupling *
      absorbing_coupling() const override
      {
        return (has_absorbing() && !absorbing_blocks.empty()) ?
                 &absorbing_blocks :
                 nullptr;
      }
      double
      rayleigh_alpha() const override
      {
        return alpha;
      }
      double
      rayleigh_beta() const override
      {
        return beta;
      }
      double
      fault_zone_viscosity() const override;
      void
      add_fault_zone_force(const double      factor,
                           const VectorType &v,
                           VectorType       &y) const override;

      // --- what the nonlinear solve and the initial state need ---
      /// a = M^-1 r at the free DoFs, 0 at the others (lumped, or a CG
      /// solve with the consistent mass).
      void
      solve_mass(const VectorType &r, VectorType &a) const;
      /// y = A x for the effective stiffness A of
      /// set_effective_stiffness() plus the fault's contact tangent,
      /// matrix-free, with the identity in the rows of DoFs that the
      /// increment constraints constrain (x is read as zero there
      /// otherwise).
      void
      apply_system(const VectorType &x, VectorType &y) const;
      /// z = P^-1 r for the preconditioner of apply_system(): multigrid
      /// when use_multigrid_now(), else block Jacobi.
      void
      precondition_system(const VectorType &r, VectorType &z) const;
      /// Whether the solves of the current step use the multigrid
      /// preconditioner (quasi-static steps always, dynamic ones if
      /// <Solver/Multigrid in dynamic steps>), or block Jacobi.
      bool
      use_multigrid_now() const;
      /// y = stiffness_factor K x + mass_factor M x with the matrix-free
      /// operator (M the consistent mass).
      void
      apply_elastic(const VectorType &x,
                    VectorType       &y,
                    const double      stiffness_factor,
                    const double      mass_factor) const;
      /// The stored effective stiffness (empty with the matrix-free
      /// solver), to which the fault adds its contact tangent.
      TrilinosWrappers::SparseMatrix &
      effective_matrix()
      {
        return system_matrix;
      }
      /// Its diagonal (without the contact) with the matrix-free solver.
      const VectorType &
      effective_diagonal() const
      {
        return system_diagonal;
      }
      /// The factors k, m, c of set_effective_stiffness().
      struct Factors
      {
        double stiffness = 1, mass = 0, absorbing = 0;
      };
      const Factors &
      effective_factors() const
      {
        return system_factors;
      }
      /// The largest diagonal entry of the effective stiffness (without
      /// the contact): Newton's displacement scale for its round-off floor.
      double
      max_effective_diagonal() const
      {
        return max_system_diagonal;
      }
      /// 1 at free DoFs, 0 at constrained ones (matrix-free solver).
      const VectorType &
      free_dof_mask() const
      {
        return free_dofs;
      }
      /// The rigid-body modes of a run with a stored system matrix.
      const std::vector<std::vector<double>> &
      near_null_space() const
      {
        return null_space;
      }
      /// The geometric multigrid preconditioner, if built.
      Operators::Multigrid<dim> *
      multigrid_preconditioner() const
      {
        return multigrid.get();
      }
      bool
      has_absorbing() const;
      /// Name each owned DoF's siblings (the other components of its node)
      /// to absorbing_blocks, at cells with an absorbing face.
      void
      set_absorbing_siblings();
      bool
      has_body_force() const
      {
        return body_force_given;
      }
      bool
      uses_lumped_mass() const
      {
        return use_lumped_mass;
      }
      /// Whether the fault zone's Kelvin-Voigt layer is built, and its
      /// fraction eta / dt.
      double
      fault_zone_fraction_in_use() const
      {
        return fault_zone ? fault_zone_fraction : 0.;
      }

    private:
      void
      setup_matrix_free_stiffness();
      void
      setup_multigrid();
      /// Mark the cells of <Damping/Fault zone damping> and assemble their
      /// stiffness (nothing without a fault or with the fraction 0).
      void
      setup_fault_zone_damping();
      /// stiffness_factor K x + mass_factor M x, left in the operator's
      /// destination vector (the owned entries, valid until its next
      /// product).
      const double *
      apply_elastic_in_place(const VectorType &x,
                             const double      stiffness_factor,
                             const double      mass_factor) const;

      const Discretization::Discretization<dim> &discretization;
      const Material::ElasticMaterials          &materials;
      const Scene::BoundaryConditions<dim>      &boundary_conditions;
      const TimeIntegration::Parameters         &time_parameters;
      const TimeIntegration::TimeState          &state;
      Solver::LinearSolver                      &linear_solver;
      TimerOutput                               &timer;
      ConditionalOStream                        &pcout;
      MPI_Comm                                   communicator;
      Fault::Fault<dim>                         *fault     = nullptr;
      bool                                       test_mode = false;
      TimeIntegration::Scheme                    scheme =
        TimeIntegration::Scheme::implicit_newmark;

      // Parameters.
      bool   use_lumped_mass       = false;
      bool   stiffness_matrix_free = true;
      double alpha                 = 0;
      double beta                  = 0;
      /// <Damping/Fault zone damping>: eta / dt of the cells at the fault.
      double                               fault_zone_fraction = 0;
      double                               gravity             = 0;
      std::unique_ptr<FunctionParser<dim>> body_force;
      bool                                 body_force_given = false;

      /// The matrix-free stiffness operator, if used, and the vectors that
      /// carry its argument and result.
      std::unique_ptr<Operators::ElasticOperator<dim>>   elastic_operator;
      mutable LinearAlgebra::distributed::Vector<double> operator_src;
      mutable LinearAlgebra::distributed::Vector<double> operator_dst;
      /// The geometric multigrid preconditioner (<Solver/Preconditioner> =
      /// multigrid).
      std::unique_ptr<Operators::Multigrid<dim>> multigrid;
      /// The cells of the fault zone and their stiffness (null without
      /// the zone).
      std::unique_ptr<Operators::FaultZoneDamping<dim>> fault_zone;

      // Only what the scheme needs is built.
      TrilinosWrappers::SparseMatrix   stiffness_matrix;
      TrilinosWrappers::SparseMatrix   mass_matrix;
      TrilinosWrappers::SparseMatrix   system_matrix;
      std::vector<std::vector<double>> null_space;
      VectorType                       lumped_mass_vector;
      VectorType                       absorbing_vector;
      /// The absorbing dashpots' coupling of a node's components (the
      /// off-diagonal part of sqrt(rho Gamma(n)); empty on faces normal to
      /// an axis of the material's symmetry).
      Operators::NodeCoupling absorbing_blocks;
      Factors                 system_factors;
      /// Without a stored system matrix (Solver::LinearSolver::
      /// matrix_free()): the diagonals of K and of the consistent M, that
      /// of the effective stiffness, and 1 at free DoFs, 0 at those the
      /// increment constraints constrain.
      VectorType stiffness_diagonal, consistent_mass_diagonal, system_diagonal,
        free_dofs;
      /// Work vector of apply_system().
      mutable VectorType system_work;
      /// The load of the step if it varies (load()).
      VectorType step_load;
      VectorType constant_load;
      /// The largest diagonal entry of the effective system (without the
      /// contact), set where the system is assembled.
      double max_system_diagonal = 0;
    };
  } // namespace Elasticity
} // namespace rupture

#endif
