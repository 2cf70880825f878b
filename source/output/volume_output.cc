#include <rupture/base/utilities.h>
#include <rupture/output/volume_output.h>
#include <rupture/output/vtu_file.h>

#include <deal.II/base/data_out_base.h>
#include <deal.II/base/geometry_info.h>
#include <deal.II/fe/fe.h>
#include <deal.II/lac/trilinos_index_access.h>

#include <Epetra_MultiVector.h>

#include <algorithm>
#include <array>
#include <sstream>

namespace rupture
{
  namespace Output
  {
    namespace
    {
      const std::vector<std::string> field_names = {"displacement",
                                                    "velocity",
                                                    "stress",
                                                    "material_id",
                                                    "mpi_rank"};

      /**
       * What one finite element of the collection needs for the output:
       * the physical component of each of its DoFs, the gradient of each
       * shape function at the centre of the reference cell, and the DoF of
       * each component at each vertex. With a split fault the element
       * carries the displacement on one side: its components i and i + dim
       * are the same physical component, and only one side has DoFs.
       */
      template <int dim>
      struct ElementTable
      {
        std::vector<unsigned int>   component;
        std::vector<Tensor<1, dim>> gradient;
        std::array<std::array<unsigned int, dim>,
                   GeometryInfo<dim>::vertices_per_cell>
          vertex_dof;
      };

      /**
       * The pieces' arrays, filled cell by cell.
       */
      struct PieceArrays
      {
        std::vector<float>        points, displacement, velocity, stress;
        std::vector<std::int32_t> connectivity, offsets, material_id, rank;
        std::vector<std::uint8_t> types;
        /// The local (Epetra) indices whose point number was set.
        std::vector<int> touched;

        void
        clear()
        {
          for (auto *v : {&points, &displacement, &velocity, &stress})
            v->clear();
          for (auto *v : {&connectivity, &offsets, &material_id, &rank})
            v->clear();
          types.clear();
          touched.clear();
        }
      };
    } // namespace



    template <int dim>
    const std::vector<std::string> &
    VolumeOutput<dim>::available_fields()
    {
      return field_names;
    }



    template <int dim>
    VolumeOutput<dim>::VolumeOutput(Directory                        &directory,
                                    const Material::ElasticMaterials &materials,
                                    const std::vector<std::string>   &fields,
                                    const Compression  compression,
                                    const unsigned int cells_per_piece,
                                    const MPI_Comm     communicator)
      : directory(directory)
      , materials(materials)
      , compression(compression)
      , cells_per_piece(cells_per_piece)
      , communicator(communicator)
    {
      for (const auto &f : fields)
        {
          const auto at = std::find(field_names.begin(), field_names.end(), f);
          AssertThrow(at != field_names.end(),
                      ExcMessage("<Output/Volume fields>: unknown field '" + f +
                                 "'."));
          write_field[at - field_names.begin()] = true;
        }
    }



    template <int dim>
    void
    VolumeOutput<dim>::write(const DoFHandler<dim>               &dof_handler,
                             const TrilinosWrappers::MPI::Vector &displacement,
                             const TrilinosWrappers::MPI::Vector &velocity,
                             const double                         time,
                             const unsigned int                   step)
    {
      constexpr unsigned int n_vertices = GeometryInfo<dim>::vertices_per_cell;
      const bool             with_displacement = write_field[0];
      const bool             with_velocity     = write_field[1];
      const bool             with_stress       = write_field[2];
      const bool             with_material_id  = write_field[3];
      const bool             with_rank         = write_field[4];

      // The tables of each element of the collection.
      Point<dim> centre;
      for (unsigned int d = 0; d < dim; ++d)
        centre[d] = 0.5;
      const auto                    &fes = dof_handler.get_fe_collection();
      std::vector<ElementTable<dim>> tables(fes.size());
      for (unsigned int f = 0; f < fes.size(); ++f)
        {
          const FiniteElement<dim> &fe = fes[f];
          if (fe.n_dofs_per_cell() == 0)
            continue;
          AssertThrow(fe.n_dofs_per_vertex() == dim,
                      ExcMessage("Volume output: each vertex must carry the "
                                 "dim components of the displacement."));
          for (unsigned int i = 0; i < fe.n_dofs_per_cell(); ++i)
            {
              const unsigned int c =
                fe.system_to_component_index(i).first % dim;
              tables[f].component.push_back(c);
              tables[f].gradient.push_back(fe.shape_grad(i, centre));
              if (i < n_vertices * dim)
                tables[f].vertex_dof[i / dim][c] = i;
            }
        }
      // The gradients of the vertices' (Q1 mapping) shape functions at the
      // centre: the Jacobian there.
      std::array<Tensor<1, dim>, n_vertices> vertex_gradient;
      for (unsigned int v = 0; v < n_vertices; ++v)
        vertex_gradient[v] =
          GeometryInfo<dim>::d_linear_shape_function_gradient(centre, v);

      // Values are read through the vectors' local (ghosted) layout.
      const Epetra_BlockMap &map = displacement.trilinos_vector().Map();
      AssertThrow(map.SameAs(velocity.trilinos_vector().Map()),
                  ExcInternalError());
      const double *u_values = displacement.trilinos_vector()[0];
      const double *v_values = velocity.trilinos_vector()[0];
      // The locally owned DoFs are one contiguous range, and so are their
      // local indices (the layout is sorted by global index): those are
      // found by an offset, only the ghosts by the map's search.
      const IndexSet owned = displacement.locally_owned_elements();
      const types::global_dof_index first_owned =
        owned.n_elements() > 0 ? owned.nth_index_in_set(0) : 0;
      const types::global_dof_index end_owned =
        first_owned + owned.n_elements();
      const auto lid = [&map](const types::global_dof_index i) {
        return map.LID(static_cast<TrilinosWrappers::types::int_type>(i));
      };
      const bool contiguous = owned.is_contiguous() && owned.n_elements() > 0 &&
                              lid(end_owned - 1) - lid(first_owned) ==
                                static_cast<int>(owned.n_elements()) - 1;
      const int  first_lid = contiguous ? lid(first_owned) : 0;
      const auto local     = [&](const types::global_dof_index i) {
        return (contiguous && i >= first_owned && i < end_owned) ?
                     first_lid + static_cast<int>(i - first_owned) :
                     lid(i);
      };
      // The point of each local DoF in the current piece, or -1.
      std::vector<int> point_of(map.NumMyElements(), -1);

      const auto        &tria = dof_handler.get_triangulation();
      const unsigned int my_rank =
        dealii::Utilities::MPI::this_mpi_process(communicator);
      unsigned int n_owned = 0;
      for (const auto &cell : tria.active_cell_iterators())
        if (cell->is_locally_owned())
          ++n_owned;
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

      // Each rank writes its cells in pieces of at most cells_per_piece
      // cells, so that the memory of a snapshot stays bounded. Points are
      // shared by the cells of a piece: one point per vertex and side of
      // the fault (the key is the vertex's first DoF). The stress is a cell
      // field, at the centre of each cell.
      PieceArrays  a;
      unsigned int piece = 0;
      const auto   flush = [&]() {
        const std::uint64_t n_points       = a.points.size() / 3;
        const std::uint64_t n_cells        = a.types.size();
        const bool          deflate_fields = (compression == Compression::all);
        VtuFile             file(
          n_points, n_cells, time, step, compression != Compression::none);
        file.add(VtuFile::Section::points, "Points", 3, a.points);
        file.add(VtuFile::Section::cells, "connectivity", 1, a.connectivity);
        file.add(VtuFile::Section::cells, "offsets", 1, a.offsets);
        file.add(VtuFile::Section::cells, "types", 1, a.types);
        if (with_displacement)
          file.add(VtuFile::Section::point_data,
                   "displacement",
                   3,
                   a.displacement,
                   deflate_fields);
        if (with_velocity)
          file.add(VtuFile::Section::point_data,
                   "velocity",
                   3,
                   a.velocity,
                   deflate_fields);
        if (with_stress)
          file.add(
            VtuFile::Section::cell_data, "stress", 9, a.stress, deflate_fields);
        if (with_material_id)
          file.add(VtuFile::Section::cell_data,
                   "material_id",
                   1,
                   a.material_id);
        if (with_rank)
          file.add(VtuFile::Section::cell_data, "mpi_rank", 1, a.rank);
        directory.write("solution/" + piece_name(first_piece + piece),
                        file.str());
        if (my_rank == 0 && piece == 0)
          {
            std::vector<std::string> names;
            for (unsigned int i = 0; i < n_all_pieces; ++i)
              names.push_back(piece_name(i));
            directory.write("solution/" + pvtu, file.pvtu_record(names));
          }
        for (const int i : a.touched)
          point_of[i] = -1;
        a.clear();
        ++piece;
      };

      // deal.II's lexicographic vertex order to VTK's.
      const std::array<unsigned int, 8> vtk_order = {{0, 1, 3, 2, 4, 5, 7, 6}};
      std::vector<types::global_dof_index> dofs;
      std::vector<int>                     lids;
      unsigned int                         n_in_piece = 0;
      for (const auto &cell : dof_handler.active_cell_iterators())
        if (cell->is_locally_owned())
          {
            const unsigned int       f     = cell->active_fe_index();
            const ElementTable<dim> &table = tables[f];
            dofs.resize(table.component.size());
            cell->get_dof_indices(dofs);
            lids.resize(dofs.size());
            for (unsigned int i = 0; i < dofs.size(); ++i)
              lids[i] = local(dofs[i]);

            for (unsigned int k = 0; k < n_vertices; ++k)
              {
                const unsigned int v   = vtk_order[k];
                const int          key = lids[table.vertex_dof[v][0]];
                if (point_of[key] < 0)
                  {
                    point_of[key] = a.points.size() / 3;
                    a.touched.push_back(key);
                    const Point<dim> &x = cell->vertex(v);
                    for (unsigned int d = 0; d < 3; ++d)
                      {
                        a.points.push_back(d < dim ? x[d] : 0.);
                        const int l =
                          d < dim ? lids[table.vertex_dof[v][d]] : -1;
                        if (with_displacement)
                          a.displacement.push_back(l < 0 ? 0. : u_values[l]);
                        if (with_velocity)
                          a.velocity.push_back(l < 0 ? 0. : v_values[l]);
                      }
                  }
                a.connectivity.push_back(point_of[key]);
              }
            a.offsets.push_back(a.connectivity.size());
            a.types.push_back(dim == 3 ? 12 : 9);

            if (with_stress)
              {
                Tensor<2, dim> jacobian, reference_gradient;
                for (unsigned int v = 0; v < n_vertices; ++v)
                  jacobian += outer_product(Tensor<1, dim>(cell->vertex(v)),
                                            vertex_gradient[v]);
                for (unsigned int i = 0; i < dofs.size(); ++i)
                  reference_gradient[table.component[i]] +=
                    u_values[lids[i]] * table.gradient[i];
                const Tensor<2, dim> gradient =
                  reference_gradient * invert(jacobian);
                const auto          &m = materials.get(cell->material_id());
                const Tensor<2, dim> strain =
                  0.5 * (gradient + transpose(gradient));
                const Tensor<2, dim> stress =
                  m.lambda * trace(strain) * unit_symmetric_tensor<dim>() +
                  2 * m.mu * strain;
                for (unsigned int i = 0; i < 3; ++i)
                  for (unsigned int j = 0; j < 3; ++j)
                    a.stress.push_back(i < dim && j < dim ? stress[i][j] : 0.);
              }
            if (with_material_id)
              a.material_id.push_back(cell->material_id());
            if (with_rank)
              a.rank.push_back(my_rank);

            if (++n_in_piece == cells_per_piece)
              {
                flush();
                n_in_piece = 0;
              }
          }
      // The last, partial piece, or the empty piece of a rank without
      // cells.
      if (n_in_piece > 0 || piece == 0)
        flush();
      AssertThrow(piece == n_pieces, ExcInternalError());
      records.emplace_back(time, "solution/" + pvtu);

      if (my_rank == 0)
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
