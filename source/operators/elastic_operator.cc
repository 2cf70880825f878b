// Debian's deal.II is configured without SIMD (VectorizedArray of width
// one), which leaves the sum-factorisation kernels scalar. Where this file
// is compiled for a CPU with AVX (RUPTURE_SIMD, see CMakeLists.txt), it
// enables deal.II's own AVX VectorizedArray<double, 4> here, and
// instantiates the MatrixFree templates for it from deal.II's headers.
#include <deal.II/base/config.h>
#if defined(RUPTURE_SIMD) && defined(__AVX__) && \
  DEAL_II_VECTORIZATION_WIDTH_IN_BITS < 256
#  undef DEAL_II_VECTORIZATION_WIDTH_IN_BITS
#  define DEAL_II_VECTORIZATION_WIDTH_IN_BITS 256
#  undef DEAL_II_COMPILER_VECTORIZATION_LEVEL
#  define DEAL_II_COMPILER_VECTORIZATION_LEVEL 2
#  define RUPTURE_SIMD_INSTANTIATE
// deal.II's kernels for a degree known only at run time (MatrixFree's
// set-up, hanging nodes, faces) are instantiated here for the wide
// VectorizedArray: up to degree 4, the highest <Discretization/Polynomial
// degree> allows (deal.II's default: 6; a higher degree would take its
// generic path). This saves 30 % of this file's compile time and 0.85 GB
// of the compiler's memory (contrib/build-cost-per-degree,
// doc/performance.md).
#  define FE_EVAL_FACTORY_DEGREE_MAX 4
#endif

#include <rupture/operators/elastic_operator.h>

#include <deal.II/base/quadrature_lib.h>
#include <deal.II/matrix_free/fe_evaluation.h>
#include <deal.II/matrix_free/matrix_free.h>

#include <functional>
#include <map>
#ifdef RUPTURE_SIMD_INSTANTIATE
#  include <deal.II/matrix_free/dof_info.templates.h>
#  include <deal.II/matrix_free/evaluation_template_factory.templates.h>
#  include <deal.II/matrix_free/mapping_info.templates.h>
#  include <deal.II/matrix_free/matrix_free.templates.h>
#  include <deal.II/matrix_free/shape_info.templates.h>
// (deal.II 9.4 gives this file the include guard of the one above)
#  undef dealii_matrix_free_evaluation_template_factory_templates_h
#  include <deal.II/matrix_free/evaluation_template_face_factory.templates.h>
#  include <deal.II/matrix_free/evaluation_template_factory_hanging_nodes.templates.h>
#endif

namespace rupture
{
  namespace
  {
#ifdef RUPTURE_SIMD_INSTANTIATE
    constexpr std::size_t simd_width = 4;
#else
    constexpr std::size_t simd_width = 1;
#endif
  } // namespace

  namespace Operators
  {
    template <int dim>
    struct ElasticOperator<dim>::Implementation
    {
      using Number = VectorizedArray<double, simd_width>;
      using MF     = MatrixFree<dim, double, Number>;

      MF           matrix_free;
      unsigned int fe_degree = 1;
      /// Lame constants and density of each cell batch (one lane a cell).
      AlignedVector<Number> lambda, mu, density;
      /// With anisotropic materials: the stiffness tensors of the cell
      /// batches, used instead of lambda and mu in every cell. Batches
      /// with the same materials in their lanes share one (tensor[batch]
      /// indexes stiffness): a tensor per batch cost 88 B per DoF at Q1.
      bool                                           anisotropic = false;
      AlignedVector<SymmetricTensor<4, dim, Number>> stiffness;
      std::vector<unsigned int>                      tensor;
      /// Constants that vary in space, at each quadrature point of each
      /// cell batch (batch * n_q + q): Lame's constants and the density
      /// (ElasticMaterials::at()); with anisotropic materials, the factor
      /// of the batch's tensor (its lanes of materials whose isotropic
      /// constants are functions hold zero tensors and use lambda and mu
      /// instead, which are zero in the other lanes).
      bool                  varying = false;
      unsigned int          n_q     = 0;
      AlignedVector<Number> q_lambda, q_mu, q_density, q_scale;
      /// Where anisotropic constants are functions (their tensor's shape
      /// varies): the whole tensor at each quadrature point (factors
      /// included), used instead of the batch tensor and q_scale: its
      /// Voigt matrix's upper triangle (in 2-D of the in-plane rows 1, 2,
      /// 6), n_voigt numbers from (batch * n_q + q) * n_voigt; zero in the
      /// lanes of materials whose isotropic constants are functions.
      static constexpr unsigned int n_voigt   = (dim == 2 ? 6 : 21);
      bool                          q_tensors = false;
      AlignedVector<Number>         q_voigt;

      /// The place of Voigt entry (I, J) in the upper triangle of an n x n
      /// matrix stored by rows (n = 3 in 2-D, 6 in 3-D; I, J from 0).
      static constexpr unsigned int
      packed(const unsigned int I, const unsigned int J)
      {
        constexpr unsigned int n = (dim == 2 ? 3 : 6);
        return I <= J ? I * n - I * (I - 1) / 2 + (J - I) :
                        J * n - J * (J - 1) / 2 + (I - J);
      }

      /// The stress of the strain @p eps by the packed Voigt matrix @p c.
      static SymmetricTensor<2, dim, Number>
      voigt_stress(const Number *c, const SymmetricTensor<2, dim, Number> &eps)
      {
        SymmetricTensor<2, dim, Number> sigma;
        if constexpr (dim == 2)
          {
            // Voigt 1, 2, 6 = xx, yy, xy with engineering shear.
            const Number g[3] = {eps[0][0], eps[1][1], 2. * eps[0][1]};
            Number       s[3];
            for (unsigned int I = 0; I < 3; ++I)
              {
                s[I] = c[packed(I, 0)] * g[0];
                for (unsigned int J = 1; J < 3; ++J)
                  s[I] += c[packed(I, J)] * g[J];
              }
            sigma[0][0] = s[0];
            sigma[1][1] = s[1];
            sigma[0][1] = s[2];
          }
        else
          {
            // Voigt 1-6 = xx, yy, zz, yz, xz, xy.
            const Number g[6] = {eps[0][0],
                                 eps[1][1],
                                 eps[2][2],
                                 2. * eps[1][2],
                                 2. * eps[0][2],
                                 2. * eps[0][1]};
            Number       s[6];
            for (unsigned int I = 0; I < 6; ++I)
              {
                s[I] = c[packed(I, 0)] * g[0];
                for (unsigned int J = 1; J < 6; ++J)
                  s[I] += c[packed(I, J)] * g[J];
              }
            sigma[0][0] = s[0];
            sigma[1][1] = s[1];
            sigma[2][2] = s[2];
            sigma[1][2] = s[3];
            sigma[0][2] = s[4];
            sigma[0][1] = s[5];
          }
        return sigma;
      }
      /// With anisotropic materials: whether a batch has lanes whose
      /// isotropic constants are functions.
      std::vector<bool> batch_has_functions;
      /// The factors of K and M in the product of the next cell loop.
      mutable double stiffness_factor = 1, mass_factor = 0;
      /// The Kelvin-Voigt zone: 1 in the lanes of its cells, 0 elsewhere,
      /// and whether a batch has any of them.
      AlignedVector<Number> zone_mask;
      std::vector<bool>     batch_in_zone;
      /// In the next cell loop, if not null: only the product eta K_zone
      /// of the zone's cells with this vector (vmult_zone()).
      mutable const VectorType *zone_src = nullptr;
      mutable double            zone_eta = 0;
      /// Whether the next cell loop zeroes dst first (not in vmult_zone()).
      mutable bool zero_dst = true;

      /**
       * The quadrature-point operation of stiffness_factor K +
       * mass_factor M on the values (if @p with_mass) and gradients held
       * by @p phi.
       */
      template <class Evaluation>
      void
      quadrature_operation(Evaluation        &phi,
                           const unsigned int cell,
                           const double       k_factor,
                           const double       m_factor) const
      {
        const Number l = k_factor * lambda[cell];
        const Number m = k_factor * mu[cell];
        const Number r = m_factor * density[cell];
        if (varying)
          {
            varying_quadrature_operation(phi, cell, k_factor, m_factor);
            return;
          }
        for (const unsigned int q : phi.quadrature_point_indices())
          {
            if (k_factor != 0 && anisotropic)
              phi.submit_symmetric_gradient(Number(k_factor) *
                                              (stiffness[tensor[cell]] *
                                               phi.get_symmetric_gradient(q)),
                                            q);
            else if (k_factor != 0)
              {
                SymmetricTensor<2, dim, Number> eps =
                  phi.get_symmetric_gradient(q);
                const Number trace = trace_of(eps);
                eps *= 2. * m;
                for (unsigned int d = 0; d < dim; ++d)
                  eps[d][d] += l * trace;
                phi.submit_symmetric_gradient(eps, q);
              }
            if (m_factor != 0)
              phi.submit_value(r * phi.get_value(q), q);
          }
      }

      /// quadrature_operation() with the factors of varying constants.
      template <class Evaluation>
      void
      varying_quadrature_operation(Evaluation        &phi,
                                   const unsigned int cell,
                                   const double       k_factor,
                                   const double       m_factor) const
      {
        const Number k(k_factor);
        for (const unsigned int q : phi.quadrature_point_indices())
          {
            const unsigned int i = cell * n_q + q;
            if (k_factor != 0)
              {
                const SymmetricTensor<2, dim, Number> eps =
                  phi.get_symmetric_gradient(q);
                SymmetricTensor<2, dim, Number> sigma;
                if (!anisotropic || batch_has_functions[cell])
                  {
                    const Number trace = trace_of(eps);
                    sigma              = (2. * k * q_mu[i]) * eps;
                    for (unsigned int d = 0; d < dim; ++d)
                      sigma[d][d] += k * q_lambda[i] * trace;
                  }
                if (q_tensors)
                  sigma += k * voigt_stress(&q_voigt[i * n_voigt], eps);
                else if (anisotropic)
                  sigma += (k * q_scale[i]) * (stiffness[tensor[cell]] * eps);
                phi.submit_symmetric_gradient(sigma, q);
              }
            if (m_factor != 0)
              phi.submit_value(Number(m_factor) * q_density[i] *
                                 phi.get_value(q),
                               q);
          }
      }

      static EvaluationFlags::EvaluationFlags
      flags(const double k_factor, const double m_factor)
      {
        return (k_factor != 0 ? EvaluationFlags::gradients :
                                EvaluationFlags::nothing) |
               (m_factor != 0 ? EvaluationFlags::values :
                                EvaluationFlags::nothing);
      }

      /**
       * K src on the cells of @p range: all of one active FE index, that
       * is one side of the fault, whose displacement starts at component
       * side * dim.
       */
      template <int degree>
      void
      local_apply(const MF                                    &data,
                  VectorType                                  &dst,
                  const VectorType                            &src,
                  const std::pair<unsigned int, unsigned int> &range) const
      {
        const unsigned int side = data.get_cell_active_fe_index(range);
        constexpr int      n_q  = (degree < 0 ? 0 : degree + 1);
        FEEvaluation<dim, degree, n_q, dim, double, Number> phi(
          data, range, 0, 0, side * dim);
        const auto evaluation_flags = flags(stiffness_factor, mass_factor);
        for (unsigned int cell = range.first; cell < range.second; ++cell)
          {
            // vmult_zone(): eta K_c v on the zone's cells only.
            if (zone_src && !batch_in_zone[cell])
              continue;
            phi.reinit(cell);
            phi.read_dof_values(src);
            if (zone_src)
              {
                const Number f = zone_eta * zone_mask[cell];
                Number      *x = phi.begin_dof_values();
                for (unsigned int i = 0; i < phi.dofs_per_cell; ++i)
                  x[i] *= f;
              }
            phi.evaluate(evaluation_flags);
            quadrature_operation(phi, cell, stiffness_factor, mass_factor);
            phi.integrate(evaluation_flags);
            phi.distribute_local_to_global(dst);
          }
      }

      /**
       * The cells' diagonal entries of K (into @p dst) and of M (into
       * @p mass_diagonal): the operator applied to each unit vector of the
       * cell in turn.
       */
      template <int degree>
      void
      local_diagonals(const MF   &data,
                      VectorType &dst,
                      VectorType &mass_diagonal,
                      const std::pair<unsigned int, unsigned int> &range,
                      const bool zone = false) const
      {
        const unsigned int side = data.get_cell_active_fe_index(range);
        constexpr int      n_q  = (degree < 0 ? 0 : degree + 1);
        FEEvaluation<dim, degree, n_q, dim, double, Number> phi(
          data, range, 0, 0, side * dim);
        const unsigned int    n = phi.dofs_per_cell;
        AlignedVector<Number> k_diagonal(n), m_diagonal(n);
        for (unsigned int cell = range.first; cell < range.second; ++cell)
          {
            // (With @p zone: the stiffness diagonal of the zone's cells.)
            if (zone && !batch_in_zone[cell])
              continue;
            phi.reinit(cell);
            for (unsigned int pass = 0; pass < (zone ? 1 : 2); ++pass)
              {
                const double           k_factor = (pass == 0 ? 1 : 0);
                const double           m_factor = 1 - k_factor;
                const auto             f        = flags(k_factor, m_factor);
                AlignedVector<Number> &diagonal =
                  (pass == 0 ? k_diagonal : m_diagonal);
                for (unsigned int i = 0; i < n; ++i)
                  {
                    for (unsigned int j = 0; j < n; ++j)
                      phi.begin_dof_values()[j] = Number(i == j ? 1. : 0.);
                    phi.evaluate(f);
                    quadrature_operation(phi, cell, k_factor, m_factor);
                    phi.integrate(f);
                    diagonal[i] = phi.begin_dof_values()[i];
                  }
              }
            for (unsigned int i = 0; i < n; ++i)
              phi.begin_dof_values()[i] =
                zone ? zone_mask[cell] * k_diagonal[i] : k_diagonal[i];
            phi.distribute_local_to_global(dst);
            if (zone)
              continue;
            for (unsigned int i = 0; i < n; ++i)
              phi.begin_dof_values()[i] = m_diagonal[i];
            phi.distribute_local_to_global(mass_diagonal);
          }
      }

      /**
       * The cell loop of local_diagonals() at the operator's degree: the
       * diagonal of K into @p stiffness (compressed) and of M into
       * @p mass (not compressed), or with @p zone the zone's stiffness
       * diagonal alone.
       */
      void
      diagonals(VectorType &stiffness, VectorType &mass, const bool zone) const
      {
        using Range = std::pair<unsigned int, unsigned int>;
        const std::function<
          void(const MF &, VectorType &, const VectorType &, const Range &)>
          local = [&](const MF   &data,
                      VectorType &dst,
                      const VectorType &,
                      const Range &range) {
            switch (fe_degree)
              {
                case 1:
                  local_diagonals<1>(data, dst, mass, range, zone);
                  break;
                case 2:
                  local_diagonals<2>(data, dst, mass, range, zone);
                  break;
                case 3:
                  local_diagonals<3>(data, dst, mass, range, zone);
                  break;
                case 4:
                  local_diagonals<4>(data, dst, mass, range, zone);
                  break;
                default:
                  local_diagonals<-1>(data, dst, mass, range, zone);
              }
          };
        VectorType unused; // (the loop's source vector, not read)
        matrix_free.initialize_dof_vector(unused);
        matrix_free.cell_loop(local, stiffness, unused, true);
      }

      static Number
      trace_of(const SymmetricTensor<2, dim, Number> &t)
      {
        Number s = t[0][0];
        for (unsigned int d = 1; d < dim; ++d)
          s += t[d][d];
        return s;
      }
    };



    template <int dim>
    ElasticOperator<dim>::ElasticOperator()
      : impl(std::make_unique<Implementation>())
    {}



    template <int dim>
    ElasticOperator<dim>::~ElasticOperator() = default;



    template <int dim>
    void
    ElasticOperator<dim>::reinit(const Mapping<dim>               &mapping,
                                 const DoFHandler<dim>            &dof_handler,
                                 const AffineConstraints<double>  &constraints,
                                 const Material::ElasticMaterials &materials,
                                 const unsigned int                fe_degree)
    {
      impl                 = std::make_unique<Implementation>();
      impl->fe_degree      = fe_degree;
      using AdditionalData = typename Implementation::MF::AdditionalData;
      AdditionalData data;
      data.tasks_parallel_scheme = AdditionalData::none;
      data.mapping_update_flags  = update_gradients | update_JxW_values;
      impl->varying              = materials.varies_in_space();
      impl->matrix_free.reinit(
        mapping, dof_handler, constraints, QGauss<1>(fe_degree + 1), data);

      const unsigned int n_batches = impl->matrix_free.n_cell_batches();
      impl->lambda.resize(n_batches);
      impl->mu.resize(n_batches);
      impl->density.resize(n_batches);
      impl->anisotropic = materials.any_anisotropic();
      if (impl->anisotropic)
        impl->tensor.resize(n_batches);
      std::map<std::vector<types::material_id>, unsigned int> patterns;
      for (unsigned int b = 0; b < n_batches; ++b)
        {
          std::vector<types::material_id> lanes;
          for (unsigned int v = 0;
               v < impl->matrix_free.n_active_entries_per_cell_batch(b);
               ++v)
            {
              const auto &m = materials.get(
                impl->matrix_free.get_cell_iterator(b, v)->material_id());
              impl->lambda[b][v]  = m.lambda;
              impl->mu[b][v]      = m.mu;
              impl->density[b][v] = m.density;
              lanes.push_back(
                impl->matrix_free.get_cell_iterator(b, v)->material_id());
            }
          if (!impl->anisotropic)
            continue;
          const auto [it, added] =
            patterns.emplace(lanes, impl->stiffness.size());
          impl->tensor[b] = it->second;
          if (added)
            {
              impl->stiffness.push_back(
                SymmetricTensor<4, dim, typename Implementation::Number>());
              for (unsigned int v = 0; v < lanes.size(); ++v)
                {
                  // (Zero for materials whose isotropic constants are
                  // functions: their lanes use q_lambda, q_mu.)
                  const SymmetricTensor<4, dim> c =
                    materials.given_as_functions(lanes[v]) ?
                      SymmetricTensor<4, dim>() :
                      materials.get(lanes[v]).template stiffness<dim>();
                  for (unsigned int i = 0; i < dim; ++i)
                    for (unsigned int j = i; j < dim; ++j)
                      for (unsigned int k = 0; k < dim; ++k)
                        for (unsigned int l = k; l < dim; ++l)
                          impl->stiffness.back()[i][j][k][l][v] = c[i][j][k][l];
                }
            }
        }
      if (impl->varying)
        {
          // The factors at the quadrature points of every cell (checked to
          // be positive by ElasticMaterials::check_on_mesh()).
          // (In the tensor-product order of QGauss<dim>, as the cell
          // loops' quadrature points.)
          const QGauss<dim> gauss(fe_degree + 1);
          impl->n_q = gauss.size();
          // (Lame's constants only where some lanes need them, the
          // tensor's factor only with anisotropic materials.)
          const typename Implementation::Number zero(0.);
          const std::size_t n_values = n_batches * impl->n_q;
          impl->q_density.resize(n_values, zero);
          if (!impl->anisotropic || materials.has_functions())
            {
              impl->q_lambda.resize(n_values, zero);
              impl->q_mu.resize(n_values, zero);
            }
          impl->q_tensors = materials.has_tensor_functions();
          if (impl->q_tensors)
            impl->q_voigt.resize(n_values * Implementation::n_voigt, zero);
          else if (impl->anisotropic)
            impl->q_scale.resize(n_values, zero);
          impl->batch_has_functions.assign(n_batches, false);
          for (unsigned int b = 0; b < n_batches; ++b)
            for (unsigned int v = 0;
                 v < impl->matrix_free.n_active_entries_per_cell_batch(b);
                 ++v)
              {
                const auto cell = impl->matrix_free.get_cell_iterator(b, v);
                const types::material_id id = cell->material_id();
                // (Isotropic constants given as functions.)
                const bool function = materials.given_as_functions(id);
                if (function)
                  impl->batch_has_functions[b] = true;
                for (unsigned int q = 0; q < impl->n_q; ++q)
                  {
                    const Point<dim> p =
                      mapping.transform_unit_to_real_cell(cell, gauss.point(q));
                    const Material::ElasticConstants m = materials.at(id, p);
                    const unsigned int               i = b * impl->n_q + q;
                    impl->q_density[i][v]              = m.density;
                    if (impl->q_tensors && !function)
                      {
                        // (In 2-D the in-plane rows 1, 2, 6.)
                        const unsigned int  rows[6]  = {0, 1, 2, 3, 4, 5};
                        const unsigned int  plane[3] = {0, 1, 5};
                        const unsigned int  n        = (dim == 2 ? 3 : 6);
                        const unsigned int *r = (dim == 2 ? plane : rows);
                        for (unsigned int a = 0; a < n; ++a)
                          for (unsigned int b = a; b < n; ++b)
                            impl->q_voigt[i * Implementation::n_voigt +
                                          Implementation::packed(a, b)][v] =
                              m.voigt[r[a]][r[b]];
                      }
                    else if (impl->anisotropic && !function)
                      impl->q_scale[i][v] =
                        materials.reference_ratios(id, p)[0];
                    else
                      {
                        impl->q_lambda[i][v] = m.lambda;
                        impl->q_mu[i][v]     = m.mu;
                      }
                  }
              }
        }
    }



    template <int dim>
    void
    ElasticOperator<dim>::initialize_dof_vector(VectorType &v) const
    {
      impl->matrix_free.initialize_dof_vector(v);
    }



    template <int dim>
    void
    ElasticOperator<dim>::vmult(VectorType &dst, const VectorType &src) const
    {
      vmult(dst, src, 1., 0.);
    }



    template <int dim>
    void
    ElasticOperator<dim>::set_zone(
      const std::function<
        bool(const typename DoFHandler<dim>::active_cell_iterator &)> &in_zone)
    {
      Implementation    &i         = *impl;
      const unsigned int n_batches = i.matrix_free.n_cell_batches();
      i.zone_mask.resize(n_batches);
      i.batch_in_zone.assign(n_batches, false);
      for (unsigned int b = 0; b < n_batches; ++b)
        {
          i.zone_mask[b] = 0.;
          for (unsigned int v = 0;
               v < i.matrix_free.n_active_entries_per_cell_batch(b);
               ++v)
            if (in_zone(i.matrix_free.get_cell_iterator(b, v)))
              {
                i.zone_mask[b][v]  = 1.;
                i.batch_in_zone[b] = true;
              }
        }
    }



    template <int dim>
    void
    ElasticOperator<dim>::vmult_zone(VectorType       &dst,
                                     const VectorType &v,
                                     const double      eta) const
    {
      Assert(impl->batch_in_zone.size() == impl->matrix_free.n_cell_batches(),
             ExcMessage("set_zone() was not called"));
      impl->zone_src = &v;
      impl->zone_eta = eta;
      impl->zero_dst = false;
      vmult(dst, v, 1., 0.);
      impl->zone_src = nullptr;
      impl->zero_dst = true;
    }



    template <int dim>
    void
    ElasticOperator<dim>::vmult(VectorType       &dst,
                                const VectorType &src,
                                const double      stiffness_factor,
                                const double      mass_factor) const
    {
      const Implementation &i = *impl;
      i.stiffness_factor      = stiffness_factor;
      i.mass_factor           = mass_factor;
      switch (i.fe_degree)
        {
          case 1:
            i.matrix_free.cell_loop(&Implementation::template local_apply<1>,
                                    &i,
                                    dst,
                                    src,
                                    i.zero_dst);
            break;
          case 2:
            i.matrix_free.cell_loop(&Implementation::template local_apply<2>,
                                    &i,
                                    dst,
                                    src,
                                    i.zero_dst);
            break;
          case 3:
            i.matrix_free.cell_loop(&Implementation::template local_apply<3>,
                                    &i,
                                    dst,
                                    src,
                                    i.zero_dst);
            break;
          case 4:
            i.matrix_free.cell_loop(&Implementation::template local_apply<4>,
                                    &i,
                                    dst,
                                    src,
                                    i.zero_dst);
            break;
          default:
            i.matrix_free.cell_loop(&Implementation::template local_apply<-1>,
                                    &i,
                                    dst,
                                    src,
                                    i.zero_dst);
        }
    }



    template <int dim>
    void
    ElasticOperator<dim>::compute_diagonals(VectorType &stiffness_diagonal,
                                            VectorType &mass_diagonal) const
    {
      initialize_dof_vector(stiffness_diagonal);
      initialize_dof_vector(mass_diagonal);
      impl->diagonals(stiffness_diagonal, mass_diagonal, false);
      mass_diagonal.compress(VectorOperation::add);
    }



    template <int dim>
    void
    ElasticOperator<dim>::compute_zone_diagonal(VectorType &diagonal) const
    {
      initialize_dof_vector(diagonal);
      VectorType unused; // (no mass diagonal)
      initialize_dof_vector(unused);
      impl->diagonals(diagonal, unused, true);
    }



    template <int dim>
    unsigned long
    ElasticOperator<dim>::n_dofs() const
    {
      return impl->matrix_free.get_dof_handler().n_dofs();
    }



    template <int dim>
    std::size_t
    ElasticOperator<dim>::memory_consumption() const
    {
      return impl->matrix_free.memory_consumption() +
             impl->lambda.memory_consumption() + impl->mu.memory_consumption() +
             impl->stiffness.memory_consumption() +
             impl->q_lambda.memory_consumption() +
             impl->q_mu.memory_consumption() +
             impl->q_density.memory_consumption() +
             impl->q_scale.memory_consumption() +
             impl->q_voigt.memory_consumption();
    }



    template <int dim>
    std::string
    ElasticOperator<dim>::layout_summary() const
    {
      const auto        &mf          = impl->matrix_free;
      const unsigned int n           = mf.n_cell_batches();
      unsigned int       geometry[4] = {0, 0, 0, 0};
      for (unsigned int b = 0; b < n; ++b)
        ++geometry[std::min<unsigned int>(
          mf.get_mapping_info().get_cell_type(b), 3)];
      using Storage =
        internal::MatrixFreeFunctions::DoFInfo::IndexStorageVariants;
      const auto  &variants = mf.get_dof_info(0).index_storage_variants[2];
      unsigned int indexed  = 0;
      for (unsigned int b = 0; b < std::min<std::size_t>(n, variants.size());
           ++b)
        if (variants[b] == Storage::full || variants[b] == Storage::interleaved)
          ++indexed;
      return std::to_string(n) +
             " cell batches: " + std::to_string(geometry[0]) + " Cartesian, " +
             std::to_string(geometry[1]) + " affine, " +
             std::to_string(geometry[2] + geometry[3]) + " general; " +
             std::to_string(n - indexed) + " with contiguous DoFs, " +
             std::to_string(indexed) + " indexed";
    }



    template class ElasticOperator<2>;
    template class ElasticOperator<3>;
  } // namespace Operators
} // namespace rupture

#ifdef RUPTURE_SIMD_INSTANTIATE
// The parts of deal.II's MatrixFree that are only compiled into libdeal_II
// for its own (scalar) VectorizedArray; instantiated here for the wide one.
namespace dealii
{
  namespace internal
  {
    template struct FEFaceEvaluationFactory<2, VectorizedArray<double, 4>>;
    template struct FEFaceEvaluationFactory<3, VectorizedArray<double, 4>>;
    template struct FEEvaluationHangingNodesFactory<2,
                                                    double,
                                                    VectorizedArray<double, 4>>;
    template struct FEEvaluationHangingNodesFactory<3,
                                                    double,
                                                    VectorizedArray<double, 4>>;
  } // namespace internal
} // namespace dealii
#endif
