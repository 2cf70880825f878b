// Geometric multigrid for the implicit and quasi-static system without a
// stored matrix: levels, transfers, smoothers and the V-cycle.

#include <rupture/base/sparse_gather.h>
#include <rupture/base/utilities.h>
#include <rupture/operators/elastic_operator.h>
#include <rupture/operators/mesh_transfer.h>
#include <rupture/operators/multigrid.h>
#include <rupture/operators/pair_blocks.h>

#include <deal.II/base/partitioner.h>
#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/distributed/repartitioning_policy_tools.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/component_mask.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/mapping_q1.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/identity_matrix.h>
#include <deal.II/lac/solver_cg.h>
#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/solver_gmres.h>
#include <deal.II/multigrid/mg_transfer_global_coarsening.h>

#include <algorithm>
#include <map>
#include <sstream>

namespace rupture
{
  namespace Operators
  {
    namespace
    {
      using VectorType = LinearAlgebra::distributed::Vector<double>;

      /**
       * The degrees of the levels on the simulator's mesh, coarsest first:
       * the degree halved down to 1 (4, 2, 1 and 3, 1), the usual
       * p-coarsening before the mesh is coarsened.
       */
      std::vector<unsigned int>
      degree_sequence(const unsigned int degree)
      {
        std::vector<unsigned int> degrees{degree};
        while (degrees.back() > 1)
          degrees.push_back(degrees.back() / 2);
        std::reverse(degrees.begin(), degrees.end());
        return degrees;
      }



      /// The same elements as @p fes (each side's FE_Q and FE_Nothing) at
      /// another degree.
      template <int dim>
      hp::FECollection<dim>
      at_degree(const hp::FECollection<dim> &fes, const unsigned int degree)
      {
        hp::FECollection<dim> result;
        const FE_Q<dim>       q(degree);
        for (unsigned int s = 0; s < fes.size(); ++s)
          {
            std::vector<const FiniteElement<dim> *> bases;
            std::vector<unsigned int>               multiplicities;
            for (unsigned int b = 0; b < fes[s].n_base_elements(); ++b)
              {
                const FiniteElement<dim> &base = fes[s].base_element(b);
                bases.push_back(dynamic_cast<const FE_Q<dim> *>(&base) ? &q :
                                                                         &base);
                multiplicities.push_back(fes[s].element_multiplicity(b));
              }
            result.push_back(FESystem<dim>(bases, multiplicities));
          }
        return result;
      }



      /// A scalar FE_Q matrix (fine DoFs times coarse DoFs) on the
      /// components of the system elements' side.
      template <int dim>
      FullMatrix<double>
      on_components(const FiniteElement<dim> &fine,
                    const FiniteElement<dim> &coarse,
                    const FullMatrix<double> &scalar)
      {
        FullMatrix<double> p(fine.n_dofs_per_cell(), coarse.n_dofs_per_cell());
        for (unsigned int i = 0; i < p.m(); ++i)
          for (unsigned int j = 0; j < p.n(); ++j)
            {
              const auto ci = fine.system_to_component_index(i);
              const auto cj = coarse.system_to_component_index(j);
              if (ci.first == cj.first)
                p(i, j) = scalar(ci.second, cj.second);
            }
        return p;
      }
    } // namespace



    template <int dim>
    struct Multigrid<dim>::Implementation
    {
      struct Level
      {
        /// The polynomial degree of the level's elements.
        unsigned int                              degree = 1;
        std::shared_ptr<const Triangulation<dim>> triangulation;
        std::unique_ptr<DoFHandler<dim>>          own_dof_handler;
        const DoFHandler<dim>                    *dof_handler = nullptr;
        AffineConstraints<double>                 constraints;
        std::unique_ptr<ElasticOperator<dim>>     own_operator;
        const ElasticOperator<dim>               *op = nullptr;
        std::shared_ptr<const dealii::Utilities::MPI::Partitioner> relevant;
        PairBlocks<dim>                                            pair_blocks;
        VectorType                  free, diagonal_k, diagonal_m, diagonal;
        std::array<VectorType, dim> tangent;
        double                      lambda_max = 2;
        mutable VectorType          x, b, r, d, t, masked;
      };

      MPI_Comm                            communicator;
      Description                         description;
      std::vector<std::unique_ptr<Level>> levels;
      std::vector<MeshTransfer<dim>>      transfers;
      /// The elements of each degree below the simulator's.
      std::map<unsigned int, hp::FECollection<dim>> collections;
      /// The prolongation matrices of the transfers (see MeshTransfer):
      /// [0] between meshes, at the coarse levels' degree; [k] from the
      /// (k-1)-th to the k-th degree on the simulator's mesh.
      std::vector<std::vector<std::vector<FullMatrix<double>>>> prolongation;
      double               stiffness_factor  = 1;
      double               mass_factor       = 0;
      mutable unsigned int coarse_iterations = 0;
      mutable unsigned int n_coarse_solves   = 0;

      void
      setup_level(Level &level, const bool finest);

      /// dst = A_l src.
      void
      apply(const unsigned int l, VectorType &dst, const VectorType &src) const;

      /// dst = P_l^-1 src (pair-block Jacobi).
      void
      precondition(const unsigned int l,
                   VectorType        &dst,
                   const VectorType  &src) const;

      /// Chebyshev smoothing of A_l x = b, from x = 0 if @p from_zero.
      void
      smooth(const unsigned int l, const bool from_zero) const;

      void
      vcycle(const unsigned int l) const;
    };



    template <int dim>
    Multigrid<dim>::Multigrid()
      : impl(std::make_unique<Implementation>())
    {}



    template <int dim>
    Multigrid<dim>::~Multigrid() = default;



    template <int dim>
    void
    Multigrid<dim>::Implementation::setup_level(Level &level, const bool finest)
    {
      const DoFHandler<dim> &dh = *level.dof_handler;
      IndexSet               relevant_dofs;
      DoFTools::extract_locally_relevant_dofs(dh, relevant_dofs);
      const IndexSet &owned = dh.locally_owned_dofs();
      level.relevant =
        std::make_shared<dealii::Utilities::MPI::Partitioner>(owned,
                                                              relevant_dofs,
                                                              communicator);

      // Hanging nodes and the fault's welding, as on the fine mesh; the
      // pairs of the fine mesh are those of the simulator's fault (its
      // constraints are given).
      AffineConstraints<double>  scratch;
      AffineConstraints<double> &constraints =
        finest ? scratch : level.constraints;
      constraints.reinit(relevant_dofs);
      if (!finest)
        DoFTools::make_hanging_node_constraints(dh, constraints);
      std::vector<PairDofs> pairs;
      if (description.interface)
        pairs = description.interface(dh, constraints);
      constraints.close();
      level.pair_blocks.reinit(pairs, owned, communicator);

      if (!finest)
        {
          level.own_operator = std::make_unique<ElasticOperator<dim>>();
          level.own_operator->reinit(MappingQ1<dim>(),
                                     dh,
                                     level.constraints,
                                     *description.materials,
                                     level.degree);
          level.op = level.own_operator.get();
        }
      for (VectorType *v : {&level.free,
                            &level.x,
                            &level.b,
                            &level.r,
                            &level.d,
                            &level.t,
                            &level.masked,
                            &level.diagonal})
        level.op->initialize_dof_vector(*v);
      for (auto &v : level.tangent)
        level.op->initialize_dof_vector(v);
      level.op->compute_diagonals(level.diagonal_k, level.diagonal_m);

      // Free DoFs: neither constrained nor on a kinematic boundary.
      const AffineConstraints<double> &c =
        finest ? *description.constraints : level.constraints;
      IndexSet           fixed(dh.n_dofs());
      const unsigned int n_components = dh.get_fe_collection().n_components();
      for (const auto &[id, components] : description.kinematic_boundaries)
        {
          ComponentMask mask(n_components, false);
          for (unsigned int k = 0; k < n_components; ++k)
            mask.set(k, components[k % dim]);
          fixed.add_indices(DoFTools::extract_boundary_dofs(dh, mask, {id}));
        }
      unsigned int i = 0;
      for (const auto dof : owned)
        level.free.local_element(i++) =
          (c.is_constrained(dof) || fixed.is_element(dof)) ? 0. : 1.;
    }



    template <int dim>
    void
    Multigrid<dim>::Implementation::apply(const unsigned int l,
                                          VectorType        &dst,
                                          const VectorType  &src) const
    {
      const Level       &level = *levels[l];
      const unsigned int n     = src.locally_owned_size();
      // (Raw arrays of the owned entries: the V-cycle's loops stay fast in
      // the Debug build.)
      const double *free = level.free.begin(), *s = src.begin();
      double       *masked = level.masked.begin();
      for (unsigned int i = 0; i < n; ++i)
        masked[i] = s[i] * free[i];
      level.op->vmult(dst, level.masked, stiffness_factor, mass_factor);
      level.pair_blocks.apply(level.masked.begin(), dst.begin());
      double *d = dst.begin();
      for (unsigned int i = 0; i < n; ++i)
        if (free[i] == 0)
          d[i] = s[i];
    }



    template <int dim>
    void
    Multigrid<dim>::Implementation::precondition(const unsigned int l,
                                                 VectorType        &dst,
                                                 const VectorType  &src) const
    {
      const Level       &level = *levels[l];
      const unsigned int n     = src.locally_owned_size();
      const double      *free  = level.free.begin(),
                   *diagonal = level.diagonal.begin(), *s = src.begin();
      double *t = dst.begin();
      for (unsigned int i = 0; i < n; ++i)
        {
          const double d = diagonal[i];
          t[i]           = (free[i] != 0 && d > 0) ? s[i] / d : s[i];
        }
      level.pair_blocks.precondition(src.begin(), dst.begin());
    }



    template <int dim>
    void
    Multigrid<dim>::Implementation::smooth(const unsigned int l,
                                           const bool         from_zero) const
    {
      const Level &level = *levels[l];
      // Chebyshev iteration on the upper part of the spectrum of P^-1 A.
      const double upper = 1.2 * level.lambda_max;
      const double lower = upper / 15.;
      const double theta = (upper + lower) / 2, delta = (upper - lower) / 2;
      const double sigma = theta / delta;
      double       rho   = 1 / sigma;
      if (from_zero)
        {
          level.x = 0;
          level.r = level.b;
        }
      else
        {
          apply(l, level.t, level.x);
          level.r = level.b;
          level.r -= level.t;
        }
      precondition(l, level.d, level.r);
      level.d *= 1 / theta;
      for (unsigned int k = 0; k < description.smoothing_degree; ++k)
        {
          level.x += level.d;
          if (k + 1 == description.smoothing_degree)
            break;
          apply(l, level.t, level.d);
          level.r -= level.t;
          const double rho_next = 1 / (2 * sigma - rho);
          precondition(l, level.t, level.r);
          level.d.sadd(rho_next * rho, 2 * rho_next / delta, level.t);
          rho = rho_next;
        }
    }



    namespace
    {
      /// deal.II's solvers call vmult() on the operator and preconditioner.
      struct LevelFunction
      {
        std::function<void(VectorType &, const VectorType &)> function;
        void
        vmult(VectorType &dst, const VectorType &src) const
        {
          function(dst, src);
        }
      };
    } // namespace



    template <int dim>
    void
    Multigrid<dim>::Implementation::vcycle(const unsigned int l) const
    {
      const Level &level = *levels[l];
      if (l == 0)
        {
          const LevelFunction a{
            [this](VectorType &d, const VectorType &s) { apply(0, d, s); }};
          const LevelFunction p{[this](VectorType &d, const VectorType &s) {
            precondition(0, d, s);
          }};
          // A loose coarse solve: the outer Krylov method is flexible,
          // and the coarse mesh is the V-cycle's most expensive part
          // (the Northeast-Japan model at 10 km: 1e-1 takes 25 GMRES
          // iterations per coarse solve, 1e-8 250, with 20 against 18
          // outer iterations per linear solve).
          ReductionControl        control(10000, 1e-300, 1e-1);
          SolverGMRES<VectorType> gmres(
            control,
            typename SolverGMRES<VectorType>::AdditionalData(50, true));
          level.x = 0;
          try
            {
              gmres.solve(a, level.x, level.b, p);
            }
          catch (const SolverControl::NoConvergence &)
            {
              // A preconditioner needs no exact coarse solve.
            }
          coarse_iterations += control.last_step();
          ++n_coarse_solves;
          return;
        }
      const Level &coarse = *levels[l - 1];
      smooth(l, true);
      apply(l, level.t, level.x);
      level.r = level.b;
      level.r -= level.t;
      transfers[l - 1].restrict(level.r, coarse.b);
      for (unsigned int i = 0; i < coarse.b.locally_owned_size(); ++i)
        coarse.b.begin()[i] *= coarse.free.begin()[i];
      vcycle(l - 1);
      transfers[l - 1].prolongate(coarse.x, level.t);
      for (unsigned int i = 0; i < level.t.locally_owned_size(); ++i)
        level.t.begin()[i] *= level.free.begin()[i];
      level.x += level.t;
      smooth(l, false);
    }



    template <int dim>
    void
    Multigrid<dim>::reinit(const Description &description,
                           const MPI_Comm     communicator)
    {
      Implementation &m = *impl;
      m.communicator    = communicator;
      m.description     = description;
      m.levels.clear();
      m.transfers.clear();

      // The degrees on the simulator's mesh; every coarser mesh has the
      // lowest.
      const hp::FECollection<dim>    &fes = *description.fe_collection;
      const std::vector<unsigned int> degrees =
        degree_sequence(description.fe_degree);
      m.collections.clear();
      for (const unsigned int d : degrees)
        if (d != description.fe_degree)
          m.collections.emplace(d, at_degree(fes, d));
      const auto collection =
        [&](const unsigned int d) -> const hp::FECollection<dim> & {
        return d == description.fe_degree ? fes : m.collections.at(d);
      };

      // The prolongation of each side's element between meshes: FE_Q's on
      // the side's own components, for each child, and the identity where
      // a cell stays; between degrees, FE_Q's interpolation.
      const unsigned int n_children = GeometryInfo<dim>::max_children_per_cell;
      m.prolongation.assign(degrees.size(), {});
      {
        const hp::FECollection<dim> &low = collection(degrees.front());
        const FE_Q<dim>              q(degrees.front());
        for (unsigned int s = 0; s < low.size(); ++s)
          {
            m.prolongation[0].emplace_back();
            for (unsigned int c = 0; c < n_children; ++c)
              m.prolongation[0][s].push_back(
                on_components(low[s], low[s], q.get_prolongation_matrix(c)));
            IdentityMatrix identity(low[s].n_dofs_per_cell());
            m.prolongation[0][s].emplace_back(identity);
          }
      }
      for (unsigned int k = 1; k < degrees.size(); ++k)
        {
          const hp::FECollection<dim> &fine   = collection(degrees[k]);
          const hp::FECollection<dim> &coarse = collection(degrees[k - 1]);
          const FE_Q<dim>              qf(degrees[k]), qc(degrees[k - 1]);
          FullMatrix<double>           interpolation(qf.n_dofs_per_cell(),
                                           qc.n_dofs_per_cell());
          qf.get_interpolation_matrix(qc, interpolation);
          for (unsigned int s = 0; s < fes.size(); ++s)
            {
              // Only a cell that stays: the mesh is the same.
              m.prolongation[k].emplace_back(n_children + 1);
              m.prolongation[k][s][n_children] =
                on_components(fine[s], coarse[s], interpolation);
            }
        }

      const auto triangulations =
        MGTransferGlobalCoarseningTools::create_geometric_coarsening_sequence(
          *description.triangulation,
          RepartitioningPolicyTools::FirstChildPolicy<dim>(
            *description.triangulation));
      const unsigned int n_meshes = triangulations.size();
      const unsigned int n_levels = n_meshes + degrees.size() - 1;
      // A coarse cell takes the material of its first child: scenes may set
      // the materials of the active cells only.
      for (unsigned int l = n_meshes - 1; l > 0; --l)
        {
          const Triangulation<dim> &finer = (l + 1 == n_meshes) ?
                                              *description.triangulation :
                                              *triangulations[l];
          for (const auto &cell :
               triangulations[l - 1]->active_cell_iterators())
            if (cell->is_locally_owned())
              {
                auto fine_cell = finer.create_cell_iterator(cell->id());
                if (fine_cell->has_children())
                  fine_cell = fine_cell->child(0);
                cell->set_material_id(fine_cell->material_id());
              }
        }
      // Constants that vary in space are evaluated on the coarser meshes'
      // cells too, over the region of all their children: allowed there?
      // The run's own mesh is checked at its own degree's points: the
      // levels of lower degree on it, and the coarser meshes, evaluate them
      // elsewhere.
      const auto check = [&](const Triangulation<dim> &mesh,
                             const unsigned int        degree,
                             const std::string        &which) {
        try
          {
            description.materials->check_on_mesh(mesh, degree, communicator);
          }
        catch (const ExceptionBase &error)
          {
            AssertThrow(false,
                        ExcMessage(
                          "The geometric multigrid's " + which +
                          " evaluates the constants where they are not "
                          "allowed: " +
                          Utilities::message_of(error) +
                          " Allowed: functions of position that are valid "
                          "over each material's whole region, or "
                          "<Solver/Preconditioner> = AMG or block Jacobi "
                          "(the run's own mesh and degree only)."));
          }
      };
      if (description.materials->varies_in_space())
        {
          for (unsigned int l = 0; l + 1 < n_meshes; ++l)
            check(*triangulations[l],
                  degrees.front(),
                  "coarser mesh " + std::to_string(l) + " (of " +
                    std::to_string(n_meshes - 1) +
                    "; its cells span their children's region, its "
                    "quadrature points lie between the run's own)");
          for (unsigned int k = 0; k + 1 < degrees.size(); ++k)
            check(*description.triangulation,
                  degrees[k],
                  "level of degree " + std::to_string(degrees[k]) +
                    " on the run's mesh (its quadrature points lie "
                    "between those of the run's degree)");
        }
      // The meshes at the lowest degree, then the simulator's mesh at each
      // higher degree.
      for (unsigned int l = 0; l < n_levels; ++l)
        {
          auto       level = std::make_unique<typename Implementation::Level>();
          const bool finest = (l + 1 == n_levels);
          level->degree     = degrees[l < n_meshes ? 0 : l - n_meshes + 1];
          if (finest)
            {
              level->dof_handler = description.dof_handler;
              level->op          = description.fine_operator;
            }
          else
            {
              const Triangulation<dim> *triangulation =
                description.triangulation;
              if (l + 1 < n_meshes)
                {
                  level->triangulation = triangulations[l];
                  triangulation        = level->triangulation.get();
                }
              level->own_dof_handler =
                std::make_unique<DoFHandler<dim>>(*triangulation);
              if (description.set_sides)
                description.set_sides(*level->own_dof_handler);
              level->own_dof_handler->distribute_dofs(
                collection(level->degree));
              level->dof_handler = level->own_dof_handler.get();
            }
          m.setup_level(*level, finest);
          m.levels.push_back(std::move(level));
        }
      m.transfers.resize(n_levels - 1);
      for (unsigned int l = 1; l < n_levels; ++l)
        m.transfers[l - 1].reinit(
          *m.levels[l - 1]->dof_handler,
          m.levels[l - 1]->relevant,
          m.levels[l - 1]->constraints,
          *m.levels[l]->dof_handler,
          m.levels[l]->relevant,
          m.prolongation[l < n_meshes ? 0 : l - n_meshes + 1]);
    }



    template <int dim>
    void
    Multigrid<dim>::set_operator(
      const double                                  stiffness_factor,
      const double                                  mass_factor,
      const std::vector<std::pair<std::array<types::global_dof_index, dim>,
                                  Tensor<2, dim>>> &pair_tangents)
    {
      Implementation &m           = *impl;
      m.stiffness_factor          = stiffness_factor;
      m.mass_factor               = mass_factor;
      const unsigned int n_levels = m.levels.size();

      // The fine pairs' blocks, restricted level by level.
      auto &fine = *m.levels.back();
      for (auto &v : fine.tangent)
        v = 0;
      for (const auto &[minus, tangent] : pair_tangents)
        for (unsigned int c = 0; c < dim; ++c)
          for (unsigned int d = 0; d < dim; ++d)
            fine.tangent[d].local_element(
              fine.tangent[d].get_partitioner()->global_to_local(minus[c])) =
              tangent[c][d];
      for (unsigned int l = n_levels - 1; l > 0; --l)
        for (unsigned int d = 0; d < dim; ++d)
          m.transfers[l - 1].restrict(m.levels[l]->tangent[d],
                                      m.levels[l - 1]->tangent[d]);

      for (unsigned int l = 0; l < n_levels; ++l)
        {
          auto                       &level = *m.levels[l];
          auto                       &pb    = level.pair_blocks;
          std::vector<Tensor<2, dim>> blocks(pb.pairs().size());
          std::vector<double>         values;
          for (unsigned int d = 0; d < dim; ++d)
            {
              pb.gather().gather(level.tangent[d].begin(), values);
              for (unsigned int k = 0; k < pb.pairs().size(); ++k)
                for (unsigned int c = 0; c < dim; ++c)
                  blocks[k][c][d] = values[2 * dim * k + c];
            }
          level.diagonal.equ(stiffness_factor, level.diagonal_k);
          if (mass_factor != 0)
            level.diagonal.add(mass_factor, level.diagonal_m);

          if (l > 0)
            {
              // The largest eigenvalue of P^-1 A, from a few CG (Lanczos)
              // iterations, with the symmetric positive semi-definite part
              // of the pairs' blocks (slipping and softening pairs are
              // neither).
              pb.blocks.resize(blocks.size());
              for (unsigned int k = 0; k < blocks.size(); ++k)
                {
                  const auto eigen =
                    eigenvectors(symmetrize(blocks[k]),
                                 SymmetricTensorEigenvectorMethod::jacobi);
                  pb.blocks[k] = Tensor<2, dim>();
                  for (const auto &[value, vector] : eigen)
                    if (value > 0)
                      pb.blocks[k] += value * outer_product(vector, vector);
                }
              pb.prepare(level.diagonal.begin(), level.free.begin());
              const auto &partitioner = level.b.get_partitioner();
              for (unsigned int i = 0; i < level.b.locally_owned_size(); ++i)
                level.b.local_element(i) =
                  level.free.local_element(i) *
                  (1. + 0.1 * (partitioner->local_to_global(i) % 11));
              const LevelFunction a{
                [&m, l](VectorType &d, const VectorType &s) {
                  m.apply(l, d, s);
                }};
              const LevelFunction p{
                [&m, l](VectorType &d, const VectorType &s) {
                  m.precondition(l, d, s);
                }};
              IterationNumberControl control(12, 1e-300);
              SolverCG<VectorType>   cg(control);
              double                 lambda = 0;
              cg.connect_eigenvalues_slot(
                [&lambda](const std::vector<double> &eigenvalues) {
                  if (!eigenvalues.empty())
                    lambda =
                      *std::max_element(eigenvalues.begin(), eigenvalues.end());
                });
              level.x = 0;
              try
                {
                  cg.solve(a, level.x, level.b, p);
                }
              catch (const SolverControl::NoConvergence &)
                {}
              level.lambda_max = (lambda > 0 ? lambda : 2.);
            }

          // Smoothing and the coarse solve use the pairs' own tangent,
          // nonsymmetric where they slip: the slip modes of slipping pairs
          // are what a symmetric version misses most.
          pb.blocks = blocks;
          pb.prepare(level.diagonal.begin(), level.free.begin());
        }
    }



    template <int dim>
    void
    Multigrid<dim>::vmult(const double *r, double *z, const double *free) const
    {
      const Implementation &m    = *impl;
      const auto           &fine = *m.levels.back();
      const unsigned int    n    = fine.b.locally_owned_size();
      for (unsigned int i = 0; i < n; ++i)
        fine.b.local_element(i) = (free[i] != 0 ? r[i] : 0.);
      m.vcycle(m.levels.size() - 1);
      for (unsigned int i = 0; i < n; ++i)
        z[i] = (free[i] != 0 ? fine.x.local_element(i) : r[i]);
    }



    template <int dim>
    unsigned int
    Multigrid<dim>::n_levels() const
    {
      return impl->levels.size();
    }



    template <int dim>
    std::string
    Multigrid<dim>::summary() const
    {
      std::ostringstream s;
      s << impl->levels.size() << " levels of";
      for (const auto &level : impl->levels)
        s << " " << level->dof_handler->n_dofs();
      s << " DoFs";
      if (impl->levels.back()->degree > 1)
        {
          s << " (degrees";
          for (const auto &level : impl->levels)
            s << " " << level->degree;
          s << ")";
        }
      if (impl->n_coarse_solves > 0)
        s << ", " << impl->coarse_iterations / impl->n_coarse_solves
          << " GMRES iterations per coarse solve";
      return s.str();
    }



    template <int dim>
    std::size_t
    Multigrid<dim>::memory_consumption() const
    {
      std::size_t bytes = 0;
      for (const auto &level : impl->levels)
        {
          if (level->own_operator)
            bytes += level->own_operator->memory_consumption() +
                     level->own_dof_handler->memory_consumption() +
                     level->constraints.memory_consumption();
          bytes += (12 + dim) * level->free.memory_consumption();
        }
      for (const auto &t : impl->transfers)
        bytes += t.memory_consumption();
      return bytes;
    }
  } // namespace Operators
} // namespace rupture


template class rupture::Operators::Multigrid<2>;
template class rupture::Operators::Multigrid<3>;
