#include <rupture/base/utilities.h>
#include <rupture/output/volume_output.h>

#include <deal.II/base/data_out_base.h>
#include <deal.II/numerics/data_out.h>
#include <deal.II/numerics/data_postprocessor.h>

#include <algorithm>
#include <sstream>
#include <vector>

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
    VolumeOutput<dim>::VolumeOutput(Directory                        &directory,
                                    const Material::ElasticMaterials &materials,
                                    const unsigned int cells_per_piece,
                                    const MPI_Comm     communicator)
      : directory(directory)
      , materials(materials)
      , cells_per_piece(cells_per_piece)
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

      // The cells are written in pieces of at most cells_per_piece cells,
      // each from its own DataOut, so that the memory of a snapshot stays
      // bounded (one DataOut of the whole mesh took about 1 kB per DoF,
      // more than the whole run).
      // Pieces are numbered across the ranks; with one piece per rank the
      // files are those of DataOut::write_vtu_with_pvtu_record().
      // The owned cells of each piece, in order, and each cell's place.
      std::vector<std::vector<typename Triangulation<dim>::cell_iterator>>
                                pieces;
      std::vector<unsigned int> place(tria.n_active_cells(), 0);
      unsigned int              n_owned = 0;
      for (const auto &cell : tria.active_cell_iterators())
        if (cell->is_locally_owned())
          {
            if (n_owned % cells_per_piece == 0)
              pieces.emplace_back();
            place[cell->active_cell_index()] = pieces.back().size();
            pieces.back().push_back(cell);
            ++n_owned;
          }
      const unsigned int n_pieces =
        std::max(1u, (n_owned + cells_per_piece - 1) / cells_per_piece);
      unsigned int pieces_so_far = 0;
      MPI_Scan(
        &n_pieces, &pieces_so_far, 1, MPI_UNSIGNED, MPI_SUM, communicator);
      const unsigned int first_piece = pieces_so_far - n_pieces;
      const unsigned int n_all_pieces =
        dealii::Utilities::MPI::sum(n_pieces, communicator);

      std::string step_name = std::to_string(step);
      step_name.insert(0, std::max<int>(0, 5 - int(step_name.size())), '0');
      const std::string pvtu       = "solution_" + step_name + ".pvtu";
      const auto        piece_name = [&](const unsigned int piece) {
        return "solution_" + step_name + "." + std::to_string(piece) + ".vtu";
      };

      for (unsigned int piece = 0; piece < n_pieces; ++piece)
        {
          DataOut<dim> data_out;
          // Walks this piece's cells only (a filter would walk every cell
          // of every level for each piece).
          if (piece < pieces.size())
            {
              const auto &cells = pieces[piece];
              data_out.set_cell_selection(
                [&cells](const Triangulation<dim> &) { return cells[0]; },
                [&cells, &place](
                  const Triangulation<dim>                         &t,
                  const typename Triangulation<dim>::cell_iterator &cell) {
                  const unsigned int next =
                    place[cell->active_cell_index()] + 1;
                  return next < cells.size() ?
                           cells[next] :
                           typename Triangulation<dim>::cell_iterator(t.end());
                });
            }
          else
            // No owned cells: an empty piece.
            data_out.set_cell_selection(
              [](const Triangulation<dim> &t) { return t.end(); },
              [](const Triangulation<dim> &t,
                 const typename Triangulation<dim>::cell_iterator &) {
                return t.end();
              });
          data_out.attach_dof_handler(dof_handler);
          data_out.add_data_vector(displacement, displacement_out);
          data_out.add_data_vector(velocity, velocity_out);
          data_out.add_data_vector(material_id, "material_id");
          data_out.add_data_vector(rank, "mpi_rank");
          data_out.build_patches();

          DataOutBase::VtkFlags flags;
          flags.time  = time;
          flags.cycle = step;
          // deal.II 9.4 compresses best by default: several times slower
          // for files some 10 % smaller.
          flags.compression_level = DataOutBase::VtkFlags::best_speed;
          data_out.set_flags(flags);

          std::ostringstream vtu;
          data_out.write_vtu(vtu);
          directory.write("solution/" + piece_name(first_piece + piece),
                          vtu.str());
          if (my_rank == 0 && piece == 0)
            {
              std::vector<std::string> names;
              for (unsigned int i = 0; i < n_all_pieces; ++i)
                names.push_back(piece_name(i));
              std::ostringstream record;
              data_out.write_pvtu_record(record, names);
              directory.write("solution/" + pvtu, record.str());
            }
        }
      records.emplace_back(time, "solution/" + pvtu);

      if (dealii::Utilities::MPI::this_mpi_process(communicator) == 0)
        {
          std::ostringstream pvd;
          DataOutBase::write_pvd_record(pvd, records);
          directory.write("solution.pvd", pvd.str());
        }
    }



    template class VolumeOutput<2>;
    template class VolumeOutput<3>;
  } // namespace Output
} // namespace rupture
