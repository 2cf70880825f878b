#ifndef rupture_discretization_discretization_h
#define rupture_discretization_discretization_h

#include <rupture/base/constraint_distributor.h>
#include <rupture/base/ghosted_vectors.h>
#include <rupture/time_integration/kinematics.h>

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/function_parser.h>
#include <deal.II/base/index_set.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/timer.h>
#include <deal.II/distributed/tria.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/hp/fe_collection.h>
#include <deal.II/lac/affine_constraints.h>

#include <array>
#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace rupture
{
  namespace Scene
  {
    template <int dim>
    class Interface;
    template <int dim>
    class BoundaryConditions;
  } // namespace Scene
  namespace Material
  {
    class ElasticMaterials;
  }
  namespace Fault
  {
    template <int dim>
    class Fault;
  }

  /**
   * The discretization of the model: the distributed mesh, the element, the
   * degrees of freedom and the constraints between them.
   */
  namespace Discretization
  {
    using namespace dealii;

    /**
     * Owns the distributed triangulation, the hp collection of elements
     * (one displacement field per side of the fault, FE_Nothing on the
     * other side), the DoF handler, its index sets, and the constraints of
     * hanging nodes, welded fault nodes and kinematic boundaries. Builds the
     * mesh (the scene's coarse mesh, global refinements, the static
     * refinement region) and sets the DoFs up again whenever the mesh has
     * changed; implements what a time integrator needs of it
     * (TimeIntegration::Kinematics).
     *
     * Component c of side s is component s*dim + c of the field.
     */
    template <int dim>
    class Discretization : public TimeIntegration::Kinematics
    {
    public:
      using VectorType   = TrilinosWrappers::MPI::Vector;
      using CellIterator = typename DoFHandler<dim>::active_cell_iterator;

      explicit Discretization(const MPI_Comm communicator);
      ~Discretization() override;

      /// Declare the mesh's and the element's entries of <Discretization>
      /// (the caller has entered the subsection).
      static void
      declare_parameters(ParameterHandler &prm);
      /// Read the mesh's and the element's entries of <Discretization>
      /// (the caller has entered the subsection).
      void
      parse_parameters(ParameterHandler &prm);

      /// The fault whose two sides the mesh refines alike and whose cells
      /// carry the field of their side (none: one field). Before the first
      /// distribute_dofs(), which builds the elements for it.
      void
      set_fault(const Fault::Fault<dim> *fault);

      // --- the mesh (mesh.cc) ---
      /**
       * Build the mesh: the scene's coarse mesh refined globally and in the
       * refinement region, or, with @p saved_mesh, the mesh a checkpoint
       * saved there (refined and partitioned as it was). The size is
       * checked against the memory of the run's nodes before anything
       * large is built, and every material id against @p materials.
       */
      void
      make_mesh(const Scene::Interface<dim>      &scene,
                const Material::ElasticMaterials &materials,
                const std::string                &saved_mesh,
                ConditionalOStream               &pcout);
      /// Flag the cells next to finer cells across the fault (refining them
      /// makes both sides of each fault face alike); whether any process
      /// flagged one. Collective.
      bool
      flag_fault_alike();
      /**
       * Refine and coarsen the mesh as flagged and carry @p fields (vectors
       * of the current DoFs, their hanging DoFs distributed) to the new
       * DoFs. The mesh's balance may leave a fault face with one side finer
       * than the other: up to @p max_alike_rounds more rounds refine those
       * cells (the fields carried through each). Then @p reflag (if given)
       * may flag the cells of the next level of the same adaptation and
       * say whether it flagged any: the fields go on through that mesh too
       * (an adaptation of several levels carries them as each cell's
       * values through meshes without DoFs: CellWiseFields). @p setup is
       * called once
       * the mesh is final, before the fields are interpolated to it: it
       * distributes the DoFs and sets up what depends on them (step-75's
       * setup_system()). Times its parts in @p timer ("Refinement: ...").
       * Collective.
       */
      void
      refine(std::vector<VectorType>     &fields,
             const unsigned int           max_alike_rounds,
             const std::function<bool()> &reflag,
             const std::function<void()> &setup,
             TimerOutput                 &timer);
      /// The meshes that refine() has made so far (each refinement pass,
      /// each round for the fault's sides and each repartition is one).
      unsigned int
      n_meshes_made() const
      {
        return meshes_made;
      }
      /**
       * The mesh's partition: for each rank, its number of locally owned
       * cells and of those with a face on the fault. Collective.
       */
      std::array<std::vector<double>, 2>
      partition() const;
      /// The largest of @p loads (one per rank) over their mean.
      static double
      largest_over_mean(const std::vector<double> &loads);
      /// largest_over_mean() of the ranks' loads in @p counts (of
      /// partition()), a cell on the fault counting @p weight cells.
      static double
      weighted_balance(const std::array<std::vector<double>, 2> &counts,
                       const double                              weight);
      /// <Fault cell weight>.
      double
      fault_weight() const
      {
        return fault_cell_weight;
      }
      /// Whether the partition weighs the fault's cells (a fault, a weight
      /// other than 1, more than one rank).
      bool
      weighted() const;
      /// The level a cell had before any adaptation: the scene's own
      /// levels, the global refinements and the refinement region's.
      unsigned int
      base_level(const typename Triangulation<dim>::cell_iterator &cell) const;

      // --- the DoFs (discretization.cc) ---
      /// Distribute the DoFs on the current mesh (each cell with its
      /// side's element) and find the locally owned and relevant ones.
      void
      distribute_dofs();
      /**
       * The constraints of the DoFs of distribute_dofs(): the hanging
       * nodes, then what @p add_interface adds before they are closed (the
       * fault's welded nodes), then the kinematic boundaries of
       * @p boundary_conditions (the first condition wins where boundaries
       * meet), which increment_constraints() holds besides.
       */
      void
      make_constraints(
        const std::function<void(AffineConstraints<double> &)> &add_interface,
        const Scene::BoundaryConditions<dim> &boundary_conditions);
      /**
       * Call @p action with the DoF indices of each cell for which
       * @p select is true and the support points of those DoFs (in the
       * cell's order, MappingQ1): the positions of the DoFs without a
       * global map of them.
       */
      void
      for_each_support_point(
        const std::function<bool(const CellIterator &)>            &select,
        const std::function<void(const CellIterator &,
                                 const std::vector<types::global_dof_index> &,
                                 const std::vector<Point<dim>> &)> &action)
        const;

      // --- vectors on the DoFs (vectors.cc) ---
      /**
       * A ghosted copy of @p v (locally owned entries) in slot @p slot (0
       * or 1), valid until the slot's next use or the next
       * distribute_dofs(). Two slots: the volume output needs displacement
       * and velocity together. The exchange pattern is built at the first
       * use after distribute_dofs(). Collective.
       */
      const VectorType &
      ghosted_copy(const unsigned int slot, const VectorType &v) const;
      /// "largest in component c at (x, y, z) m": where |v| is largest, or
      /// first not finite, over all processes (support points, MappingQ1).
      /// Collective.
      std::string
      locate_largest(const VectorType &v) const;

      /// Which displacement components a kinematic boundary holds at some
      /// DoF this process owns.
      std::array<bool, dim>
      held_components() const
      {
        std::array<bool, dim> held{};
        for (const auto &k : kinematic_dofs)
          held[k.component] = true;
        return held;
      }

      parallel::distributed::Triangulation<dim> &
      triangulation()
      {
        return mesh;
      }
      const parallel::distributed::Triangulation<dim> &
      triangulation() const
      {
        return mesh;
      }
      const DoFHandler<dim> &
      dof_handler() const
      {
        return dofs;
      }
      const hp::FECollection<dim> &
      fe_collection() const
      {
        return elements;
      }
      unsigned int
      degree() const
      {
        return fe_degree;
      }
      unsigned int
      n_global_refinements() const
      {
        return global_refinements;
      }
      /// The number of levels of the static refinement region.
      unsigned int
      n_region_refinements() const
      {
        return region_refinements;
      }
      const IndexSet &
      locally_owned_dofs() const
      {
        return owned;
      }
      const IndexSet &
      locally_relevant_dofs() const
      {
        return relevant;
      }

      // TimeIntegration::Kinematics
      const IndexSet &
      owned_dofs() const override
      {
        return owned;
      }
      MPI_Comm
      communicator() const override
      {
        return mpi_communicator;
      }
      const AffineConstraints<double> &
      hanging_constraints() const override
      {
        return hanging;
      }
      const AffineConstraints<double> &
      increment_constraints() const override
      {
        return increments;
      }
      void
      distribute_hanging(VectorType &v) const override;
      void
      set_kinematic_velocity(VectorType &v, const double t) const override;
      void
      impose_kinematic_motion(const VectorType &old_u,
                              VectorType       &u,
                              const double      t,
                              const double      dt) const override;

    private:
      /// The weight of @p cell in the partition (<Fault cell weight>);
      /// @p status says whether p4est is about to refine or coarsen it.
      unsigned int
      cell_weight(const typename Triangulation<dim>::cell_iterator &cell,
                  const typename Triangulation<dim>::CellStatus status) const;
      /// Refuse a mesh of @p n_coarse coarse cells (as @p source says)
      /// whose refined size cannot fit in the memory @p available (bytes)
      /// of the run's @p n_nodes nodes (0: unknown, no check).
      void
      check_mesh_size(const double       n_coarse,
                      const std::string &source,
                      const double       available,
                      const unsigned int n_nodes) const;
      /// After the refinement region's levels: refine the cells next to
      /// finer cells across the fault until both sides match.
      void
      refine_fault_alike();

      /// A locally owned kinematically constrained DoF with its velocity.
      struct KinematicDof
      {
        types::global_dof_index dof;
        unsigned int            component;
        Point<dim>              location;
        FunctionParser<dim>    *velocity;
      };
      /// Its velocity at time @p t.
      double
      kinematic_velocity(const KinematicDof &k, const double t) const;

      MPI_Comm     mpi_communicator;
      unsigned int fe_degree          = 1;
      unsigned int global_refinements = 0;
      /// <Refinement region> and its number of levels.
      std::unique_ptr<FunctionParser<dim>> region;
      unsigned int                         region_refinements = 0;
      /// <Fault cell weight>: a fault cell's share of the partition.
      double fault_cell_weight = 1;
      /// n_meshes_made().
      unsigned int meshes_made = 0;
      /// The level of the scene's cells as it builds them (a box of blocks
      /// refines its blocks itself): the base of base_level().
      unsigned int                              scene_levels = 0;
      const Fault::Fault<dim>                  *fault        = nullptr;
      parallel::distributed::Triangulation<dim> mesh;
      hp::FECollection<dim>                     elements;
      DoFHandler<dim>                           dofs;
      IndexSet                                  owned;
      IndexSet                                  relevant;
      /// Hanging nodes and welded fault nodes: for the physical operators.
      AffineConstraints<double> hanging;
      /// Those plus the homogeneous kinematic conditions: for increments.
      AffineConstraints<double> increments;
      /// Sets the tied DoFs of a vector.
      ConstraintDistributor     hanging_distributor;
      std::vector<KinematicDof> kinematic_dofs;
      /// The ghosted copies of ghosted_copy(), built at their first use
      /// after distribute_dofs().
      mutable std::unique_ptr<GhostedVectors> ghosts;
    };
  } // namespace Discretization
} // namespace rupture

#endif
