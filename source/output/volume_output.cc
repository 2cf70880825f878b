#include <rupture/base/utilities.h>
#include <rupture/output/volume_output.h>

#include <deal.II/base/data_out_base.h>
#include <deal.II/numerics/data_out.h>
#include <deal.II/numerics/data_postprocessor.h>

#include <sstream>

namespace rupture
{
  namespace Output
  {
    namespace
    {
      /**
       * Sums the sides of a (possibly split) displacement-like field and,
       * optionally, computes the stress from its gradient.
       */
      template <int dim>
      class FieldPostprocessor : public DataPostprocessor<dim>
      {
      public:
        FieldPostprocessor(const std::string                &name,
                           const bool                        with_stress,
                           const Material::ElasticMaterials *materials)
          : name(name)
          , with_stress(with_stress)
          , materials(materials)
        {}

        void
        evaluate_vector_field(
          const DataPostprocessorInputs::Vector<dim> &inputs,
          std::vector<Vector<double>>                &computed) const override
        {
          const unsigned int n_q     = inputs.solution_values.size();
          const unsigned int n_sides = inputs.solution_values[0].size() / dim;
          const auto         cell    = inputs.template get_cell<dim>();
          const auto        &m       = materials->get(cell->material_id());
          for (unsigned int q = 0; q < n_q; ++q)
            {
              Tensor<2, dim> grad;
              for (unsigned int d = 0; d < dim; ++d)
                {
                  double value = 0;
                  for (unsigned int s = 0; s < n_sides; ++s)
                    {
                      value += inputs.solution_values[q][s * dim + d];
                      if (with_stress)
                        grad[d] += inputs.solution_gradients[q][s * dim + d];
                    }
                  computed[q][d] = value;
                }
              if (with_stress)
                {
                  const Tensor<2, dim> strain = 0.5 * (grad + transpose(grad));
                  const Tensor<2, dim> stress =
                    m.lambda * trace(strain) * unit_symmetric_tensor<dim>() +
                    2 * m.mu * strain;
                  for (unsigned int i = 0; i < dim; ++i)
                    for (unsigned int j = 0; j < dim; ++j)
                      computed[q][dim + i * dim + j] = stress[i][j];
                }
            }
        }

        std::vector<std::string>
        get_names() const override
        {
          std::vector<std::string> names(dim, name);
          if (with_stress)
            for (unsigned int i = 0; i < dim * dim; ++i)
              names.emplace_back("stress");
          return names;
        }

        std::vector<DataComponentInterpretation::DataComponentInterpretation>
        get_data_component_interpretation() const override
        {
          std::vector<DataComponentInterpretation::DataComponentInterpretation>
            result(dim,
                   DataComponentInterpretation::component_is_part_of_vector);
          if (with_stress)
            for (unsigned int i = 0; i < dim * dim; ++i)
              result.push_back(
                DataComponentInterpretation::component_is_part_of_tensor);
          return result;
        }

        UpdateFlags
        get_needed_update_flags() const override
        {
          return with_stress ? (update_values | update_gradients) :
                               update_values;
        }

      private:
        const std::string                 name;
        const bool                        with_stress;
        const Material::ElasticMaterials *materials;
      };
    } // namespace



    template <int dim>
    VolumeOutput<dim>::VolumeOutput(const std::string &output_directory,
                                    const Material::ElasticMaterials &materials,
                                    const MPI_Comm communicator)
      : directory(output_directory)
      , materials(materials)
      , communicator(communicator)
    {}



    template <int dim>
    void
    VolumeOutput<dim>::write(const DoFHandler<dim>               &dof_handler,
                             const TrilinosWrappers::MPI::Vector &displacement,
                             const TrilinosWrappers::MPI::Vector &velocity,
                             const double                         time,
                             const unsigned int                   step)
    {
      FieldPostprocessor<dim> displacement_out("displacement",
                                               true,
                                               &materials);
      FieldPostprocessor<dim> velocity_out("velocity", false, &materials);

      const auto        &tria = dof_handler.get_triangulation();
      Vector<float>      material_id(tria.n_active_cells());
      Vector<float>      rank(tria.n_active_cells());
      const unsigned int my_rank =
        dealii::Utilities::MPI::this_mpi_process(communicator);
      for (const auto &cell : dof_handler.active_cell_iterators())
        if (cell->is_locally_owned())
          {
            material_id(cell->active_cell_index()) = cell->material_id();
            rank(cell->active_cell_index())        = my_rank;
          }

      DataOut<dim> data_out;
      data_out.attach_dof_handler(dof_handler);
      data_out.add_data_vector(displacement, displacement_out);
      data_out.add_data_vector(velocity, velocity_out);
      data_out.add_data_vector(material_id, "material_id");
      data_out.add_data_vector(rank, "mpi_rank");
      data_out.build_patches();

      DataOutBase::VtkFlags flags;
      flags.time  = time;
      flags.cycle = step;
      data_out.set_flags(flags);

      const std::string pvtu = data_out.write_vtu_with_pvtu_record(
        directory + "/solution/", "solution", step, communicator, 5, 0);
      records.emplace_back(time, "solution/" + pvtu);

      if (dealii::Utilities::MPI::this_mpi_process(communicator) == 0)
        {
          std::ostringstream pvd;
          DataOutBase::write_pvd_record(pvd, records);
          Utilities::write_file_atomically(directory + "/solution.pvd",
                                           pvd.str());
        }
    }



    template class VolumeOutput<2>;
    template class VolumeOutput<3>;
  } // namespace Output
} // namespace rupture
