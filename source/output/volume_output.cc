#include <rupture/base/binary_io.h>
#include <rupture/base/lobatto_points.h>
#include <rupture/base/utilities.h>
#include <rupture/output/volume_output.h>
#include <rupture/output/vtu_file.h>

#include <deal.II/base/data_out_base.h>
#include <deal.II/base/geometry_info.h>
#include <deal.II/base/quadrature_lib.h>
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
                                                    "mpi_rank",
                                                    "level"};

      /**
       * What one finite element of the collection needs for the stress:
       * the physical component of each of its DoFs and the gradient of each
       * shape function at the centre of the reference cell. With a split
       * fault the element
       * carries the displacement on one side: its components i and i + dim
       * are the same physical component, and only one side has DoFs.
       */
      template <int dim>
      struct ElementTable
      {
        std::vector<unsigned int> component;
        /// The gradients of the shape functions at the centre of each
        /// sub-cell (index [sub-cell][shape function]).
        std::vector<std::vector<Tensor<1, dim>>> gradient;
        /// The gradients of the vertices' (Q1 geometry) shape functions
        /// there ([sub-cell][vertex]).
        std::vector<
          std::array<Tensor<1, dim>, GeometryInfo<dim>::vertices_per_cell>>
          vertex_gradient;
      };

      /**
       * The nodes of one element of the collection, in lexicographic
       * order: the local DoF of each displacement component at each node
       * and its unit support point, and the element's degree p (p^dim
       * sub-cells between the nodes).
       */
      template <int dim>
      struct NodeTable
      {
        unsigned int                               degree = 1;
        std::vector<std::array<unsigned int, dim>> node_dof;
        std::vector<Point<dim>>                    unit_point;
      };

      template <int dim>
      NodeTable<dim>
      node_table(const FiniteElement<dim> &fe)
      {
        NodeTable<dim> table;
        table.degree         = fe.degree;
        const unsigned int p = fe.degree;
        const unsigned int n = dealii::Utilities::fixed_power<dim>(p + 1);
        table.node_dof.resize(n);
        table.unit_point.resize(n);
        for (unsigned int i = 0; i < fe.n_dofs_per_cell(); ++i)
          {
            const auto [component, node] = fe.system_to_component_index(i);
            const auto       base = fe.component_to_base_index(component).first;
            const Point<dim> x =
              fe.base_element(base).get_unit_support_points()[node];
            unsigned int lex = 0;
            for (unsigned int d = dim; d-- > 0;)
              lex = lex * (p + 1) + LobattoPoints::nearest(p, x[d]);
            table.node_dof[lex][component % dim] = i;
            table.unit_point[lex]                = x;
          }
        return table;
      }

      /// The centre of sub-cell @p sub (lexicographic) of a cell of degree
      /// @p degree, in unit coordinates.
      template <int dim>
      Point<dim>
      sub_cell_centre(const unsigned int degree, unsigned int sub)
      {
        const std::vector<double> gl = LobattoPoints::points(degree);
        Point<dim>                centre;
        for (unsigned int d = 0; d < dim; ++d)
          {
            const unsigned int i = sub % degree;
            sub /= degree;
            centre[d] = 0.5 * (gl[i] + gl[i + 1]);
          }
        return centre;
      }

    } // namespace



    template <int dim>
    const std::vector<std::string> &
    VolumeOutput<dim>::available_fields()
    {
      return field_names;
    }



    template <int dim>
    void
    VolumeOutput<dim>::Settings::parse_parameters(ParameterHandler &prm)
    {
      cells_per_piece          = prm.get_integer("Cells per output piece");
      const std::string choice = prm.get("Compression");
      compression              = (choice == "none") ? Compression::none :
                                 (choice == "all")  ? Compression::all :
                                                      Compression::mesh;
      fields = dealii::Utilities::split_string_list(prm.get("Volume fields"));
    }



    template <int dim>
    VolumeOutput<dim>::VolumeOutput(Directory                        &directory,
                                    const Material::ElasticMaterials &materials,
                                    const Settings                   &settings,
                                    const MPI_Comm communicator)
      : directory(directory)
      , materials(materials)
      , compression(settings.compression)
      , cells_per_piece(settings.cells_per_piece)
      , communicator(communicator)
    {
      for (const auto &f : settings.fields)
        {
          const auto at = std::find(field_names.begin(), field_names.end(), f);
          AssertThrow(at != field_names.end(),
                      ExcMessage("<Output/Volume fields>: unknown field '" + f +
                                 "'."));
          write_field[at - field_names.begin()] = true;
        }
    }



    template <int dim>
    VolumeOutput<dim>::~VolumeOutput()
    {
      tria_listener.disconnect();
    }



    template <int dim>
    void
    VolumeOutput<dim>::build_pieces(
      const DoFHandler<dim>                             &dof_handler,
      const std::function<int(types::global_dof_index)> &local,
      const int                                          n_local)
    {
      constexpr unsigned int n_vertices = GeometryInfo<dim>::vertices_per_cell;
      pieces.clear();
      pieces_dof_handler = &dof_handler;
      pieces_n_dofs      = dof_handler.n_dofs();
      pieces_n_local     = n_local;
      tria_listener.disconnect();
      tria_listener =
        dof_handler.get_triangulation().signals.any_change.connect(
          [this]() { pieces.clear(); });

      // The nodes of each element, in lexicographic order.
      const auto                 &fes = dof_handler.get_fe_collection();
      std::vector<NodeTable<dim>> tables(fes.size());
      for (unsigned int f = 0; f < fes.size(); ++f)
        if (fes[f].n_dofs_per_cell() > 0)
          {
            AssertThrow(fes[f].n_dofs_per_vertex() == dim,
                        ExcMessage("Volume output: each vertex must carry the "
                                   "dim components of the displacement."));
            tables[f] = node_table(fes[f]);
          }

      // Points are shared by the cells of a piece: one point per node and
      // side of the fault (the key is the node's first DoF).
      const bool compress = (compression != Compression::none);
      const std::array<unsigned int, 8> vtk_order = {{0, 1, 3, 2, 4, 5, 7, 6}};
      std::vector<int>                  point_of(n_local, -1);
      std::vector<int>                  touched;
      std::vector<float>                points;
      std::vector<types::global_dof_index> dofs;
      const unsigned int                   my_rank =
        dealii::Utilities::MPI::this_mpi_process(communicator);
      const auto finish = [&]() {
        Piece                    &p = pieces.back();
        VtuFile                   encoder(0, 0, 0, 0, compress);
        std::vector<std::int32_t> offsets(p.cells.size());
        for (unsigned int c = 0; c < offsets.size(); ++c)
          offsets[c] = (c + 1) * n_vertices;
        const std::vector<std::uint8_t> types(p.cells.size(),
                                              dim == 3 ? 12 : 9);
        p.mesh = {encoder.add(VtuFile::Section::points, "Points", 3, points),
                  encoder.add(
                    VtuFile::Section::cells, "connectivity", 1, p.connectivity),
                  encoder.add(VtuFile::Section::cells, "offsets", 1, offsets),
                  encoder.add(VtuFile::Section::cells, "types", 1, types)};
        std::vector<std::int32_t> values(p.cells.size());
        if (write_field[3])
          {
            for (unsigned int c = 0; c < values.size(); ++c)
              values[c] = p.cells[c]->material_id();
            p.cell_fields.push_back(encoder.add(
              VtuFile::Section::cell_data, "material_id", 1, values));
          }
        if (write_field[4])
          {
            std::fill(values.begin(), values.end(), my_rank);
            p.cell_fields.push_back(
              encoder.add(VtuFile::Section::cell_data, "mpi_rank", 1, values));
          }
        if (write_field[5])
          {
            for (unsigned int c = 0; c < values.size(); ++c)
              values[c] = p.cells[c]->level();
            p.cell_fields.push_back(
              encoder.add(VtuFile::Section::cell_data, "level", 1, values));
          }
        for (const int i : touched)
          point_of[i] = -1;
        touched.clear();
        points.clear();
      };

      for (const auto &cell : dof_handler.active_cell_iterators())
        if (cell->is_locally_owned())
          {
            const unsigned int    f     = cell->active_fe_index();
            const NodeTable<dim> &table = tables[f];
            const unsigned int    p1    = table.degree + 1;
            const unsigned int    n_sub =
              dealii::Utilities::fixed_power<dim>(table.degree);
            // A piece takes whole cells, at least one.
            if (pieces.empty() ||
                (!pieces.back().cells.empty() &&
                 pieces.back().cells.size() + n_sub > cells_per_piece))
              {
                if (!pieces.empty())
                  finish();
                pieces.emplace_back();
              }
            Piece &p = pieces.back();
            dofs.resize(cell->get_fe().n_dofs_per_cell());
            cell->get_dof_indices(dofs);
            for (unsigned int sub = 0; sub < n_sub; ++sub)
              {
                p.cells.push_back(cell);
                p.sub_cell.push_back(sub);
                // The sub-cell's lowest node, lexicographic.
                unsigned int origin = 0;
                for (unsigned int d = 0, rest = sub, stride = 1; d < dim;
                     ++d, rest /= table.degree, stride *= p1)
                  origin += (rest % table.degree) * stride;
                for (unsigned int k = 0; k < n_vertices; ++k)
                  {
                    const unsigned int v    = vtk_order[k];
                    unsigned int       node = origin;
                    for (unsigned int d = 0, stride = 1; d < dim;
                         ++d, stride *= p1)
                      node += ((v >> d) & 1) * stride;
                    const int key = local(dofs[table.node_dof[node][0]]);
                    if (point_of[key] < 0)
                      {
                        point_of[key] = p.point_dofs.size();
                        touched.push_back(key);
                        std::array<int, dim> point_dofs;
                        for (unsigned int d = 0; d < dim; ++d)
                          point_dofs[d] = local(dofs[table.node_dof[node][d]]);
                        p.point_dofs.push_back(point_dofs);
                        Point<dim> x;
                        if (table.degree == 1)
                          x = cell->vertex(v);
                        else
                          for (const unsigned int w : cell->vertex_indices())
                            x += GeometryInfo<dim>::d_linear_shape_function(
                                   table.unit_point[node], w) *
                                 cell->vertex(w);
                        for (unsigned int d = 0; d < 3; ++d)
                          points.push_back(d < dim ? x[d] : 0.);
                      }
                    p.connectivity.push_back(point_of[key]);
                  }
              }
          }
      // A rank without cells writes one empty piece.
      if (pieces.empty())
        pieces.emplace_back();
      finish();
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
      const int first_lid = contiguous ? lid(first_owned) : 0;
      const std::function<int(types::global_dof_index)> local =
        [&](const types::global_dof_index i) {
          return (contiguous && i >= first_owned && i < end_owned) ?
                   first_lid + static_cast<int>(i - first_owned) :
                   lid(i);
        };

      if (pieces.empty() || pieces_dof_handler != &dof_handler ||
          pieces_n_dofs != dof_handler.n_dofs() ||
          pieces_n_local != map.NumMyElements())
        build_pieces(dof_handler, local, map.NumMyElements());

      // For the stress: the gradients at the centre of each sub-cell of
      // each element's shape functions and of the vertices' (Q1 geometry)
      // shape functions. A Q1 element's DoFs are the points'.
      Point<dim> centre;
      for (unsigned int d = 0; d < dim; ++d)
        centre[d] = 0.5;
      std::array<Tensor<1, dim>, n_vertices> vertex_gradient;
      for (unsigned int v = 0; v < n_vertices; ++v)
        vertex_gradient[v] =
          GeometryInfo<dim>::d_linear_shape_function_gradient(centre, v);
      const auto                    &fes = dof_handler.get_fe_collection();
      std::vector<ElementTable<dim>> tables(fes.size());
      bool                           all_q1 = true;
      for (unsigned int f = 0; f < fes.size(); ++f)
        {
          const FiniteElement<dim> &fe = fes[f];
          all_q1                       = all_q1 && (fe.n_dofs_per_cell() == 0 ||
                              fe.n_dofs_per_cell() == n_vertices * dim);
          if (fe.n_dofs_per_cell() == 0)
            continue;
          for (unsigned int i = 0; i < fe.n_dofs_per_cell(); ++i)
            tables[f].component.push_back(
              fe.system_to_component_index(i).first % dim);
          const unsigned int n_sub =
            dealii::Utilities::fixed_power<dim>(fe.degree);
          tables[f].gradient.resize(n_sub);
          tables[f].vertex_gradient.resize(n_sub);
          for (unsigned int sub = 0; sub < n_sub; ++sub)
            {
              const Point<dim> x = sub_cell_centre<dim>(fe.degree, sub);
              for (unsigned int i = 0; i < fe.n_dofs_per_cell(); ++i)
                tables[f].gradient[sub].push_back(fe.shape_grad(i, x));
              for (unsigned int v = 0; v < n_vertices; ++v)
                tables[f].vertex_gradient[sub][v] =
                  GeometryInfo<dim>::d_linear_shape_function_gradient(x, v);
            }
        }
      const std::array<unsigned int, 8> vtk_order = {{0, 1, 3, 2, 4, 5, 7, 6}};

      const unsigned int my_rank =
        dealii::Utilities::MPI::this_mpi_process(communicator);
      const unsigned int n_pieces      = pieces.size();
      unsigned int       pieces_so_far = 0;
      MPI_Scan(
        &n_pieces, &pieces_so_far, 1, MPI_UNSIGNED, MPI_SUM, communicator);
      const unsigned int first_piece = pieces_so_far - n_pieces;
      const unsigned int n_all_pieces =
        dealii::Utilities::MPI::sum(n_pieces, communicator);

      std::string step_name = std::to_string(step);
      step_name.insert(0, std::max<int>(0, 5 - int(step_name.size())), '0');
      const std::string pvtu       = file_prefix + "_" + step_name + ".pvtu";
      const auto        piece_name = [&](const unsigned int piece) {
        return file_prefix + "_" + step_name + "." + std::to_string(piece) +
               ".vtu";
      };

      const bool          compress       = (compression != Compression::none);
      const bool          deflate_fields = (compression == Compression::all);
      std::vector<double> point_u;
      std::vector<float>  values;
      std::vector<types::global_dof_index> dofs;
      for (unsigned int i = 0; i < n_pieces; ++i)
        {
          const Piece       &p        = pieces[i];
          const unsigned int n_points = p.point_dofs.size();
          VtuFile file(n_points, p.cells.size(), time, step, compress);
          for (const auto &array : p.mesh)
            file.add(array);

          // The displacement at the points, also the Q1 stress's input.
          point_u.assign(n_points * dim, 0.);
          for (unsigned int n = 0; n < n_points; ++n)
            for (unsigned int d = 0; d < dim; ++d)
              point_u[n * dim + d] = u_values[p.point_dofs[n][d]];
          const auto point_field =
            [&](const auto get) -> const std::vector<float> & {
            values.assign(3 * n_points, 0.f);
            for (unsigned int n = 0; n < n_points; ++n)
              for (unsigned int d = 0; d < dim; ++d)
                values[3 * n + d] = get(n, d);
            return values;
          };
          if (with_displacement)
            file.add(VtuFile::Section::point_data,
                     "displacement",
                     3,
                     point_field(
                       [&](const unsigned int n, const unsigned int d) {
                         return point_u[n * dim + d];
                       }),
                     deflate_fields);
          if (with_velocity)
            file.add(VtuFile::Section::point_data,
                     "velocity",
                     3,
                     point_field(
                       [&](const unsigned int n, const unsigned int d) {
                         return v_values[p.point_dofs[n][d]];
                       }),
                     deflate_fields);

          if (with_stress)
            {
              values.assign(9 * p.cells.size(), 0.f);
              for (unsigned int c = 0; c < p.cells.size(); ++c)
                {
                  const auto              &cell = p.cells[c];
                  const ElementTable<dim> &table =
                    tables[cell->active_fe_index()];
                  const unsigned int sub = p.sub_cell[c];
                  Tensor<2, dim>     jacobian, reference_gradient;
                  for (unsigned int v = 0; v < n_vertices; ++v)
                    jacobian +=
                      outer_product(Tensor<1, dim>(cell->vertex(v)),
                                    all_q1 ? vertex_gradient[v] :
                                             table.vertex_gradient[sub][v]);
                  if (all_q1)
                    for (unsigned int k = 0; k < n_vertices; ++k)
                      {
                        const unsigned int n =
                          p.connectivity[c * n_vertices + k];
                        for (unsigned int d = 0; d < dim; ++d)
                          reference_gradient[d] +=
                            point_u[n * dim + d] *
                            vertex_gradient[vtk_order[k]];
                      }
                  else
                    {
                      dofs.resize(table.component.size());
                      cell->get_dof_indices(dofs);
                      for (unsigned int j = 0; j < dofs.size(); ++j)
                        reference_gradient[table.component[j]] +=
                          u_values[local(dofs[j])] * table.gradient[sub][j];
                    }
                  const Tensor<2, dim> gradient =
                    reference_gradient * invert(jacobian);
                  // (Constants that vary in space: those at the cell's
                  // centre.)
                  const Material::ElasticConstants *constants =
                    &materials.get(cell->material_id());
                  Material::ElasticConstants at_centre;
                  if (materials.varies_in_space())
                    {
                      at_centre =
                        materials.at(cell->material_id(), cell->center());
                      constants = &at_centre;
                    }
                  const Material::ElasticConstants &m = *constants;
                  const Tensor<2, dim>              strain =
                    0.5 * (gradient + transpose(gradient));
                  Tensor<2, dim> stress =
                    m.isotropic() ?
                      Tensor<2, dim>(m.lambda * trace(strain) *
                                       unit_symmetric_tensor<dim>() +
                                     2 * m.mu * strain) :
                      Tensor<2, dim>(m.template stress<dim>(
                        SymmetricTensor<2, dim>(strain)));
                  for (unsigned int a = 0; a < dim; ++a)
                    for (unsigned int b = 0; b < dim; ++b)
                      values[9 * c + 3 * a + b] = stress[a][b];
                }
              file.add(VtuFile::Section::cell_data,
                       "stress",
                       9,
                       values,
                       deflate_fields);
            }
          for (const auto &array : p.cell_fields)
            file.add(array);

          directory.write("solution/" + piece_name(first_piece + i),
                          file.str());
          if (my_rank == 0 && i == 0)
            {
              std::vector<std::string> names;
              for (unsigned int k = 0; k < n_all_pieces; ++k)
                names.push_back(piece_name(k));
              directory.write("solution/" + pvtu, file.pvtu_record(names));
            }
        }
      records.emplace_back(time, "solution/" + pvtu);

      if (my_rank == 0)
        {
          std::ostringstream pvd;
          DataOutBase::write_pvd_record(pvd, records);
          directory.write(pvd_name, pvd.str());
        }
    }



    template <int dim>
    void
    VolumeOutput<dim>::start_series(const std::string &file_prefix,
                                    const std::string &pvd_name)
    {
      this->file_prefix = file_prefix;
      this->pvd_name    = pvd_name;
      records.clear();
    }



    template <int dim>
    void
    VolumeOutput<dim>::save(std::ostream &out) const
    {
      BinaryIO::write(out, records);
      BinaryIO::write(out, file_prefix);
      BinaryIO::write(out, pvd_name);
    }



    template <int dim>
    void
    VolumeOutput<dim>::load(std::istream &in)
    {
      BinaryIO::read(in, records);
      BinaryIO::read(in, file_prefix);
      BinaryIO::read(in, pvd_name);
    }



    template class VolumeOutput<2>;
    template class VolumeOutput<3>;
  } // namespace Output
} // namespace rupture
