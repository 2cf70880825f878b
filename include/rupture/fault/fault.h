#ifndef rupture_fault_fault_h
#define rupture_fault_fault_h

#include <rupture/base/sparse_gather.h>
#include <rupture/fault/anisotropic_contact.h>
#include <rupture/fault/contact.h>
#include <rupture/fault/event_source.h>
#include <rupture/fault/node_state.h>
#include <rupture/friction/interface.h>
#include <rupture/operators/pair_blocks.h>

#include <deal.II/base/function_parser.h>
#include <deal.II/base/index_set.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <array>
#include <functional>
#include <iosfwd>
#include <map>
#include <memory>
#include <set>
#include <string>
#include <vector>

namespace rupture
{
  namespace Fault
  {
    /**
     * Summary of the fault after a step, over all ranks.
     */
    struct Statistics
    {
      unsigned int n_nodes            = 0;
      unsigned int n_slipping         = 0;
      unsigned int n_open             = 0;
      double       max_slip           = 0;
      double       max_slip_rate      = 0;
      double       slipping_area      = 0;
      double       seismic_moment     = 0;
      double       frictional_energy  = 0;
      bool         unstable_softening = false;
      /// The area where the rupture has passed (the slip rate exceeded
      /// 1 mm/s since the start of the dynamic phase; m^2, m in 2-D), and
      /// the mean slip over it (m).
      double ruptured_area = 0;
      double mean_slip     = 0;
      /// Area-weighted means of the normal traction (negative in
      /// compression) and of the magnitude of the shear traction (Pa).
      double mean_normal_traction = 0;
      double mean_shear_traction  = 0;
      /// The smallest and largest values over the fault of the friction
      /// law's state outputs (Friction::Interface::state_names()).
      std::vector<double> state_minimum;
      std::vector<double> state_maximum;
    };

    /**
     * A fault as a frictional contact interface that splits the
     * displacement field (see doc/design.md).
     *
     * The cells of the mesh are divided into a minus side (active FE index
     * 0) and a plus side (index 1), by a plane or by material ids. The faces
     * between the two sides form the interface. Where the interface lies in
     * the fault region, its nodes carry separate displacements on either
     * side (split node pairs) coupled by penalty contact with friction;
     * elsewhere the plus node is tied to the minus node (welded).
     *
     * Contact is evaluated at the nodes with their tributary area (the
     * paper's node-to-surface master-slave element on a matching mesh):
     * a vertex quadrature of the fault faces.
     */
    template <int dim>
    class Fault : public EventSource<dim>
    {
    public:
      using VectorType = TrilinosWrappers::MPI::Vector;

      /**
       * The values of one fault node, for output. The key identifies the
       * node (its minus-side DoF of component 0).
       */
      struct NodeRecord
      {
        types::global_dof_index key = 0;
        Point<dim>              location;
        Tensor<1, dim>          normal;
        /// Relative displacement u+ - u-, tangential part (m), since the
        /// start of the dynamic phase.
        Tensor<1, dim> slip;
        /// Its rate over the last step (m/s).
        Tensor<1, dim> slip_velocity;
        /// Traction on the minus side (Pa).
        Tensor<1, dim> traction;
        /// The frictional slip rate (m/s; ContactResponse::sliding, set
        /// with anisotropic friction).
        Tensor<1, dim> sliding;
        double         slip_path    = 0;
        double         friction     = 0;
        double         rupture_time = -1;
        int            status       = 0;
        /// The friction law's state fields (Friction::Interface::
        /// state_output()).
        std::vector<double> state_values;
      };

      static void
      declare_parameters(ParameterHandler &prm);

      /**
       * Read the "Fault" section. Returns nullptr if Model = none.
       */
      static std::unique_ptr<Fault<dim>>
      create(ParameterHandler &prm);

      /**
       * The side (0 = minus, 1 = plus) of a cell.
       */
      unsigned int
      side(const typename Triangulation<dim>::cell_iterator &cell) const;

      /**
       * Whether face @p f of @p cell (active or a parent) lies between the
       * two sides: its neighbour is on the other side (welded or not).
       */
      bool
      interface_face(const typename Triangulation<dim>::cell_iterator &cell,
                     const unsigned int                                f) const;

      /**
       * Whether @p cell (active or a parent) has a face on the fault: an
       * interface face with the fault region nonzero at its centre. For the
       * weights of the mesh's partition.
       */
      bool
      on_fault(const typename Triangulation<dim>::cell_iterator &cell) const;

      /**
       * After the DoFs are distributed: find the split node pairs and the
       * welded ones, add the welding constraints u+ = u- to
       * @p constraints (not yet closed), and compute the nodes' areas and
       * normals. @p shear_across gives, for a material at a point, its
       * shear stiffness across a plane of normal n and its density (the
       * pairs' shear_modulus and, with <Radiation damping> = auto, their
       * radiation damping).
       *
       * The first set-up starts every pair from the initial state (the
       * initial traction, the friction law's initial state). A set-up
       * after it (on a new mesh, or the same one again) keeps the committed
       * state of every pair at a location where this process had a pair
       * before (LocationIndex); the others start from the initial state
       * and are counted by n_new_pairs().
       */
      void
      setup(const DoFHandler<dim>     &dof_handler,
            const IndexSet            &locally_owned_dofs,
            const IndexSet            &locally_relevant_dofs,
            AffineConstraints<double> &constraints,
            const std::function<std::array<double, 2>(types::material_id,
                                                      const Tensor<1, dim> &,
                                                      const Point<dim> &)>
                          &shear_across,
            const MPI_Comm communicator);

      /**
       * The interface of another DoFHandler on a mesh with the same sides
       * (a coarser level of the multigrid preconditioner): adds its welding
       * constraints to @p constraints and returns its split pairs (minus,
       * plus DoFs) whose minus DoF of component 0 is locally owned.
       */
      std::vector<std::pair<std::array<types::global_dof_index, dim>,
                            std::array<types::global_dof_index, dim>>>
      level_interface(const DoFHandler<dim>     &dof_handler,
                      AffineConstraints<double> &constraints) const;

      /**
       * The minus DoFs of each locally owned pair and its contact block:
       * area times the tangent of the last assemble(), for the multigrid
       * preconditioner.
       */
      std::vector<
        std::pair<std::array<types::global_dof_index, dim>, Tensor<2, dim>>>
      pair_tangents() const;

      /**
       * Add the coupling between the two nodes of each pair (for a pair on
       * hanging nodes, between the nodes they follow by @p constraints).
       */
      void
      add_sparsity(DynamicSparsityPattern          &dsp,
                   const AffineConstraints<double> &constraints) const;

      /**
       * The (minus, plus) DoF pairs of the locally owned split nodes, one
       * per component, for the linear solver (LinearSolver::set_fault_pairs).
       */
      std::vector<std::pair<types::global_dof_index, types::global_dof_index>>
      dof_pairs() const;

      /**
       * Return-map every pair for the displacement @p u (with ghost
       * entries), add the contact forces to @p force, and, if @p tangent is
       * given, add @p sign times the contact tangent to it. The states stay
       * trial states until commit().
       */
      void
      assemble(const VectorType                &u,
               const double                     dt,
               const AffineConstraints<double> &force_constraints,
               VectorType                      &force,
               const AffineConstraints<double> &tangent_constraints,
               TrilinosWrappers::SparseMatrix  *tangent,
               const double                     sign = 1);

      /**
       * While @p on, assemble() holds every pair that is closed in place:
       * it sticks on its penalty springs from its accepted plastic slip,
       * whatever its strength (no friction law, no forced slip), and opens
       * under tension as always. A balance of the body at a fixed time
       * (after a mesh change), not a step.
       */
      void
      hold(const bool on)
      {
        held = on;
      }

      /**
       * After a balance with hold(): each pair's accepted slip becomes the
       * slip of the last assemble()'s displacement (its plastic slip and
       * friction state stay: the balance slid nothing), so that the next
       * step's slip rate does not count the balance's correction.
       */
      void
      accept_held_slip()
      {
        for (auto &pair : pairs)
          pair.slip = pair.trial_slip;
      }

      /**
       * Add the contact forces of the pairs' tractions of the last
       * assemble() (or of the state carried to a new mesh) to @p force,
       * without return-mapping again.
       */
      void
      add_contact_force(const AffineConstraints<double> &constraints,
                        VectorType                      &force) const;

      /**
       * Newton safeguard of penalty contact. For each pair that slips in the
       * last assemble(), follow its tangential trial traction along the
       * Newton update @p increment (with ghost entries). If the full update
       * would carry it from slip straight across the stick region into slip
       * again (typically reversing the slip direction, the overshoot of a
       * node coming to rest), add to @p correction the change of the pair's
       * tangential jump that stops the update 5 % of the chord into the
       * stick region. Returns the number of such pairs over all ranks.
       */
      unsigned int
      limit_stick_crossings(const VectorType                &increment,
                            const AffineConstraints<double> &constraints,
                            VectorType                      &correction) const;

      /**
       * True for the traction-at-split-node method of the explicit scheme,
       * false for penalty contact.
       */
      bool
      uses_split_nodes() const
      {
        return split_node_method;
      }
      /// Whether <Fault/Anisotropic friction> makes the friction set an
      /// ellipse that is not a disc.
      bool
      has_anisotropic_friction() const
      {
        return anisotropic_friction;
      }

      /// <Fault/Radiation damping> (Pa s/m; 0: none; -1: 'auto', half the
      /// shear impedance across the fault at each pair,
      /// PairData::radiation_damping).
      double
      radiation_damping_coefficient() const
      {
        return radiation_damping;
      }

      /**
       * <Fault/Initial slip velocity>: the velocity of the plus side
       * relative to the minus side at t = 0 (zero by default).
       */
      const Tensor<1, dim> &
      initial_slip_velocity_of_sides() const
      {
        return initial_slip_velocity;
      }

      /**
       * The traction-at-split-node method (Day et al. 2005) for the
       * explicit scheme. Given the predicted displacement @p u at the end of
       * the step, the predicted velocity @p v (v + (1 - gamma) dt a), the
       * residual force @p residual without the fault (all without ghost
       * entries: the pairs' values are exchanged alone) and the inverse of
       * the diagonal (lumped) mass
       * @p inverse_mass, compute for each pair the traction that keeps its
       * two nodes together over the next step, open it under tension or
       * limit its shear part by the friction strength, and add the fault's
       * internal forces (as in assemble()) to @p force, on the owners of
       * the DoFs (no compress() is needed). With gamma = 1/2 the
       * slip rate of the half step that follows is what the traction
       * controls, as in central differences. The states stay trial states
       * until commit().
       */
      void
      assemble_split_node(const VectorType &u,
                          const VectorType &v,
                          const VectorType &residual,
                          const VectorType &inverse_mass,
                          const double      dt,
                          const double      gamma,
                          VectorType       &force);

      /**
       * The entries of a vector's locally owned array (indices into it,
       * increasing) that assemble_split_node() reads or adds to on this
       * rank; the force it adds is zero everywhere else.
       */
      std::vector<unsigned int>
      split_node_entries() const
      {
        return pair_dofs.owned_entries();
      }

      /**
       * Accept the trial states of the last assemble() as the new state.
       */
      void
      commit(const double dt, const double time);

      /**
       * The records of the locally owned nodes (all, or those whose keys
       * are in @p keys), gathered on rank 0 (empty elsewhere).
       */
      std::vector<NodeRecord>
      gather(const std::set<types::global_dof_index> *keys = nullptr) const;

      /**
       * The fault faces as lists of the keys of all their nodes
       * (lexicographic, see FaceNodes: the corners first and last),
       * gathered on rank 0.
       */
      std::vector<std::vector<types::global_dof_index>>
      gather_faces() const;

      /// The friction law (for the names of its state fields).
      const Friction::Interface &
      friction() const
      {
        return *friction_law;
      }

      /// A point of the fault plane (for output coordinates).
      const Point<dim> &
      reference_point() const
      {
        return plane_point;
      }

      /**
       * A number that changes when a pair changes between stick, slip and
       * open in the last assemble(), summed over ranks.
       */
      unsigned long
      status_signature() const;

      /**
       * Set the time (s) at the end of the step about to be solved.
       */
      void
      set_time(const double time);

      /**
       * Tell the friction law that the dynamic phase starts now. Slip,
       * seismic moment and rupture times are counted from here on.
       */
      void
      start_dynamic_phase(const double time);

      /**
       * During a loading phase friction does not weaken: bonded zones hold
       * up to their static strength.
       */
      void
      start_loading_phase();

      /**
       * A run continued from a checkpoint in the dynamic phase that started
       * at @p time: friction weakens and forced slip acts again, without
       * the resets of start_dynamic_phase().
       */
      void
      continue_dynamic_phase(const double time);

      /**
       * For checkpoints: save() writes this rank's node pairs (their
       * committed state, keyed by location) and the fault's clock; load()
       * reads the files that all ranks of the checkpointed run wrote and
       * gives each of its own pairs the state saved at its location, so a
       * run may continue on another number of ranks. Throws if a pair has
       * no saved state (the mesh or the fault differ).
       */
      void
      save(std::ostream &out) const;
      void
      load(const std::vector<std::string> &files);

      /**
       * Refuse a traction perturbation time function that is not finite at
       * some time of the first @p duration seconds of the dynamic phase
       * (sampled at 1001 times), before the run starts.
       */
      void
      check_time_functions(const double duration) const;

      /**
       * The number of nodes (over all ranks) that slipped in the last
       * assemble() where friction can still weaken: a bonded zone reaching
       * its strength.
       */
      unsigned int
      n_weakening() const;

      /**
       * The number of fault nodes (over all ranks) that slipped in the last
       * assemble() while still weakening, with a softening stiffness
       * (-mu' |T_n| p_t / (p_t + mu' |T_n|) times the node's area, the slip
       * direction's part of the contact tangent) larger than the stiffness
       * that holds the node along its slip direction: the two sides'
       * entries of @p effective_diagonal (the diagonal of the stiffness
       * plus the Newmark mass and damping terms, without the contact; an
       * owned vector) in series. Collective.
       * There the global tangent is indefinite, which makes Newton's method
       * fail; a shorter time step stiffens the inertia term as 1/dt^2.
       */
      unsigned int
      n_steeper_than_body(const VectorType &effective_diagonal) const;

      /**
       * y += T x for the contact tangent T of the last assemble() (the
       * pairs' blocks, as assemble() adds them to a matrix), for Krylov
       * solvers that store no matrix. @p x and @p y are owned vectors; the
       * pairs' entries are exchanged alone, no compress() is needed. x must
       * be zero at constrained DoFs. Collective.
       */
      void
      apply_tangent(const VectorType &x, VectorType &y) const;

      /**
       * The fault part of a block-Jacobi preconditioner of the effective
       * stiffness A + T, set up for the contact tangent T of the last
       * assemble(): inverts each pair's 2 dim x 2 dim block diag(A) +
       * T_pair, which the stiff penalty dominates, and keeps the inverses
       * for precondition_pairs(). @p diagonal is diag(A); @p free is 1 at
       * free DoFs and 0 at constrained ones, whose rows and columns are the
       * identity. Owned vectors. Collective.
       */
      void
      prepare_pair_preconditioner(const VectorType &diagonal,
                                  const VectorType &free);

      /**
       * Applies the fault part of the block-Jacobi preconditioner: @p z
       * holds the point-Jacobi solution r / diag(A) (and r at constrained
       * DoFs); at each pair's 2 dim DoFs it is replaced by the solution of
       * the pair's block, with the inverses of the last
       * prepare_pair_preconditioner(). Collective.
       */
      void
      precondition_pairs(const VectorType &r, VectorType &z) const;

      /**
       * True if no pair slipped in the last assemble().
       */
      bool
      all_stuck() const;

      Statistics
      statistics() const;

      /**
       * The shortest time over which a pair's friction state evolves, over
       * all ranks: the smallest L / V of the not hanging pairs, with the
       * law's slip scale L (Friction::Interface::slip_scale()) and the slip
       * rate V of the last accepted step. Infinite where no pair slips or
       * the law has no state. Collective.
       */
      double
      state_evolution_time() const;

      /**
       * The largest frictional slip rate over all ranks (the rate that
       * rupture times are measured on: plastic with penalty contact) and
       * the location of a pair that has it. Collective.
       */
      std::pair<double, Point<dim>>
      fastest_pair() const override;

      /**
       * An earthquake starts: each pair keeps its slip and rate as the
       * event's start (EventCatalogue).
       */
      void
      start_event() override;

      /**
       * After each step of an event: each pair's peak slip rate.
       */
      void
      track_event() override;

      /**
       * The event's sums since start_event(), pairs counted as ruptured
       * where their peak slip rate reached @p threshold. Collective.
       */
      EventSummary<dim>
      event_summary(const double threshold) const override;

      /// The fault's communicator.
      MPI_Comm
      mpi_communicator() const override
      {
        return communicator;
      }

      /**
       * The locations of the locally owned pairs that slip faster than
       * @p rate, or whose rupture (NodeState::rupture_time) is less than
       * @p memory before @p time (both since the start of the dynamic
       * phase; @p memory < 0: any rupture): where a mesh that follows the
       * rupture is refined. With @p overstressed also the pairs whose
       * traction exceeds the strength of a law that does not depend on the
       * slip rate (the last assemble() says so): before the first step,
       * the nucleation patch that slips from it.
       */
      std::vector<Point<dim>>
      active_locations(const double rate,
                       const double time,
                       const double memory,
                       const bool   overstressed = false) const;

      /**
       * The locally owned, not hanging pairs' locations and their friction
       * law's process-zone width (Friction::Interface::process_zone_width())
       * with the pair's shear modulus and its compressive normal traction
       * of the last assemble() (the initial traction before the first):
       * where a mesh refines to resolve the zone. Pairs of an infinite
       * width (nothing weakens there, or no pressure) are left out.
       */
      std::vector<std::pair<Point<dim>, double>>
      process_zone_widths() const;

      unsigned int
      n_split_nodes() const;

      unsigned int
      n_welded_nodes() const;

      /**
       * The state of the locally owned pairs as finite element fields of
       * the DoFHandler of the last set-up (entries at both DoFs of every
       * pair, zero elsewhere; without ghost entries), for
       * parallel::distributed::SolutionTransfer to carry to a refined,
       * coarsened or repartitioned mesh. After the new set-up,
       * interpolate_new_pairs() reads the transferred fields.
       */
      std::vector<VectorType>
      state_fields(const IndexSet &locally_owned_dofs) const;

      /**
       * Give every new pair of the last set-up (n_new_pairs()) the state
       * in @p fields, the fields of state_fields() transferred to the new
       * mesh: along the fault faces, the old nodes' values interpolated
       * (the state variables that the friction law says span decades in
       * their logarithm), divided by the interpolated weight of the pairs
       * (so that welded nodes next to the fault region do not count). The
       * rupture time is not interpolated: a node that existed before keeps
       * its own, a node between old ones gets NodeState::unknown_time if
       * the rupture had reached an old neighbour. Returns the number of
       * new pairs with no old pair near (they keep the initial state), over
       * all processes.
       */
      unsigned int
      interpolate_new_pairs(const std::vector<VectorType> &fields);

      /**
       * The pairs of the last set-up that had no pair at their location
       * before it, over all processes (all of them at the first set-up:
       * 0 is returned then).
       */
      unsigned int
      n_new_pairs() const
      {
        return n_global_new;
      }

      /**
       * Whether a cell with the DoFs @p cell_dofs has a node of the fault
       * region (a split or penalty node pair, not a welded one) among its
       * nodes: the cells that touch the fault, also by an edge or a
       * vertex. Known for the locally owned and ghost cells (from
       * setup()).
       */
      bool
      touches_fault_region(
        const std::vector<types::global_dof_index> &cell_dofs) const;

      /**
       * The l2 norm of the nodal forces A T_0 of the initial traction on
       * both sides of every pair (from setup()): a force scale of a
       * prestressed fault at rest, where the residual alone is tiny.
       */
      double
      initial_force_norm() const
      {
        return initial_force_scale;
      }

    private:
      /// A node pair: its topology, the parameters at its location, its
      /// committed state (node_state.h) and the trial state of the last
      /// assemble().
      struct NodePair : PairTopology<dim>, PairData<dim>, NodeState<dim>
      {
        // Trial state of the last assemble().
        ContactResponse<dim> trial;
        Tensor<1, dim>       trial_slip;
        /// The time-centred split-node update of a law of the slip rate:
        /// the state evolved to the time of the step's traction (over the
        /// slip of the step before), and the slip velocity there, which
        /// commit() takes.
        Friction::State trial_state;
        Tensor<1, dim>  trial_slip_velocity;
      };

      Point<3>
      to_3d(const Point<dim> &p) const;

      /**
       * The distance below which two locations of fault nodes are the same
       * node (LocationIndex): a millionth of the smallest node spacing of
       * the pairs @p of on all processes.
       */
      double
      location_tolerance(const std::vector<NodePair> &of) const;

      /// The split-node method's tractions of the hanging pairs: those of
      /// the pairs they follow, interpolated as the displacements are.
      void
      interpolate_hanging_tractions();

      /// The number of values state_fields() holds per pair.
      unsigned int
      n_transfer_values() const;

      /// The length scale of location_mark(): a thousandth of the fault's
      /// extent.
      double
      transfer_length() const;

      /// A smooth function of the location that no interpolation between
      /// other nodes reproduces: tells the nodes that existed before from
      /// new ones after a transfer.
      static double
      location_mark(const Point<dim> &x, const double length);

      /**
       * Give @p to, a pair of a new set-up at the location of @p from, the
       * committed and the trial state of @p from.
       */
      static void
      carry_state(const NodePair &from, NodePair &to);

      /// The interface of a DoFHandler: split and welded nodes (keyed by
      /// their minus DoF of component 0), fault faces.
      struct Interface
      {
        std::map<types::global_dof_index, NodePair> fault_nodes;
        std::map<types::global_dof_index, NodePair> welded_nodes;
        std::set<std::pair<typename DoFHandler<dim>::active_cell_iterator,
                           unsigned int>>
                                                          fault_faces;
        std::vector<std::vector<types::global_dof_index>> owned_faces;
        unsigned int                                      n_interface_faces = 0;
      };

      /**
       * Find the interface of @p dof_handler, weld the nodes outside the
       * fault region (adding u+ = u- to @p constraints) and check that the
       * fault lies on mesh faces without hanging nodes.
       */
      void
      find_interface(const DoFHandler<dim>     &dof_handler,
                     AffineConstraints<double> &constraints,
                     Interface                 &result) const;

      /// Add the internal force of the trial traction of @p pair.
      void
      add_internal_force(const NodePair                  &pair,
                         const AffineConstraints<double> &constraints,
                         VectorType                      &force) const;

      /**
       * The pair's contact tangent as a 2 dim x 2 dim block on (minus,
       * plus) DoFs, [D, -D; -D, D] with D = factor * area * tangent.
       */
      static void
      pair_tangent_block(const NodePair     &pair,
                         const double        factor,
                         FullMatrix<double> &block);

      /// The imposed slip vector of a forced pair at the current time plus
      /// @p delay.
      Tensor<1, dim>
      imposed_slip(const NodePair &pair, const double delay) const;

      /**
       * The split-node traction of a pair under a friction law of the slip
       * rate: slip rate and traction solved together (see the .cc file).
       * Sets the friction, slip increment and status of @p r.
       */
      Tensor<1, dim>
      rate_dependent_traction(const NodePair       &pair,
                              const Point<3>       &x,
                              const Tensor<1, dim> &stick_traction,
                              const double          tn,
                              const Tensor<1, dim> &inverse_sum,
                              const double          c,
                              const double          dt,
                              ContactResponse<dim> &r) const;

      /**
       * The time-centred split-node traction of a pair under a friction
       * law of the slip rate (second order in time; see the .cc file).
       * Evolves the pair's state to the time of the traction into
       * pair.trial_state, sets pair.trial_slip_velocity and the friction,
       * slip increment and status of @p r.
       */
      Tensor<1, dim>
      centred_rate_traction(NodePair             &pair,
                            const Point<3>       &x,
                            const Tensor<1, dim> &stick_traction,
                            const double          tn,
                            const Tensor<1, dim> &inverse_sum,
                            const double          c,
                            const double          dt,
                            const Tensor<1, dim> &slip,
                            ContactResponse<dim> &r) const;

      /**
       * The split-node traction of a pair with anisotropic friction, for
       * every law: the stick traction's shear part projected onto the
       * friction ellipse in the pair's impedance (the slip over the next
       * step along the ellipse's normal at the traction), the strength of
       * the law as rate_dependent_traction() (@p centred false) or
       * centred_rate_traction() (@p centred true) has it, or a slip law's
       * strength. Sets what those set.
       */
      Tensor<1, dim>
      anisotropic_split_traction(NodePair             &pair,
                                 const Point<3>       &x,
                                 const Tensor<1, dim> &stick_traction,
                                 const double          tn,
                                 const Tensor<1, dim> &inverse_sum,
                                 const double          c,
                                 const double          dt,
                                 const Tensor<1, dim> &slip,
                                 const bool            centred,
                                 ContactResponse<dim> &r) const;

      /// The length of a pair's slip @p v that the friction law sees: |A v|
      /// with anisotropic friction, else |v|.
      double
      slip_measure(const NodePair &pair, const Tensor<1, dim> &v) const;

      /// The measure of a shear traction @p t that the strength bounds:
      /// |A^-1 t| with anisotropic friction, else |t|.
      double
      traction_measure(const NodePair &pair, const Tensor<1, dim> &t) const;

      MPI_Comm communicator;

      // Parameters.
      bool split_node_method = false;
      /// <Fault/Split-node friction time>: true for the time-centred
      /// update of laws of the slip rate, false for the former one (the
      /// friction of the slip rate over the next step, first order).
      bool centred_split_node = true;
      /// <Penalty friction time> = centred.
      bool centred_penalty = false;
      /// <Fault/Radiation damping> eta (Pa s/m) of the penalty return map.
      double radiation_damping = 0;
      /// <Fault/Anisotropic friction>: the friction set's ellipse, and
      /// whether it is not a disc.
      FrictionEllipse<dim>                 friction_ellipse;
      bool                                 anisotropic_friction = false;
      bool                                 side_by_plane        = true;
      Point<dim>                           plane_point;
      Tensor<1, dim>                       plane_normal;
      std::vector<types::material_id>      plus_materials;
      std::unique_ptr<FunctionParser<dim>> region;
      std::unique_ptr<FunctionParser<dim>> normal_penalty;
      std::unique_ptr<FunctionParser<dim>> tangential_penalty;
      std::unique_ptr<FunctionParser<dim>> initial_traction;
      Tensor<1, dim>                       initial_slip_velocity;
      /// Fault/Traction perturbation: null without one.
      std::unique_ptr<FunctionParser<dim>> traction_perturbation;
      std::unique_ptr<FunctionParser<1>>   perturbation_time_function;
      std::unique_ptr<Friction::Interface> friction_law;
      std::unique_ptr<FunctionParser<dim>> forced_region;
      std::unique_ptr<FunctionParser<dim>> forced_slip;
      Tensor<1, dim>                       forced_direction;
      /// Forced slip acts in the dynamic phase (from its start) only.
      bool forced_slip_active = true;
      /// hold(): every closed pair sticks (no friction, no forced slip).
      bool   held          = false;
      double dynamic_start = 0;
      double current_time  = 0;

      // Locally owned pairs (owned by the owner of the minus DoF of
      // component 0).
      std::vector<NodePair> pairs;
      /// The DoFs of the pairs (minus then plus components, pair by pair)
      /// in the vectors of the split-node method, and the values read from
      /// or added to them.
      SparseGather                pair_dofs;
      mutable std::vector<double> pair_values[4];
      /// The pairs' contact blocks (area times the tangent of the last
      /// assemble()): the matrix-free tangent and its block Jacobi.
      Operators::PairBlocks<dim> contact_blocks;
      /// Fault faces of locally owned cells, as the keys of their nodes
      /// (lexicographic, see FaceNodes).
      std::vector<std::vector<types::global_dof_index>> owned_faces;
      /// The DoFs of component 0 of both sides of every pair of the fault
      /// region that this rank sees (owned and ghost cells).
      std::set<types::global_dof_index> region_node_dofs;
      double                            initial_force_scale = 0;
      unsigned int                      n_global_split      = 0;
      unsigned int                      n_global_welded     = 0;
      /// Pairs of the last set-up without a pair at their location before
      /// it (all but the first set-up), over all processes.
      unsigned int n_global_new = 0;
      /// True if some pair lies on hanging nodes (on any process).
      bool any_hanging = false;
      /// The split-node method's hanging pairs: component c of the
      /// traction change of pair k takes weight times the value that
      /// hanging_gather reads from traction_change at the same place.
      struct HangingSource
      {
        unsigned int pair;
        unsigned int component;
        double       weight;
      };
      std::vector<HangingSource> hanging_sources;
      SparseGather               hanging_gather;
      VectorType                 traction_change;

      /// The indices in pairs of the new pairs of the last set-up.
      std::vector<unsigned int> new_pair_indices;
      /// True after the first set-up.
      bool   set_up            = false;
      double frictional_energy = 0;
    };
  } // namespace Fault
} // namespace rupture

#endif
