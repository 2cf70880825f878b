// The volume snapshots (Output::VolumeOutput, Output::VtuFile), read back
// byte by byte as VTK reads them: 2-D and 3-D, Q1 to Q4 (a cell of degree
// p written as p^dim sub-cells between its nodes), a distorted mesh, the
// fault's hp split (one FESystem per side, FE_Nothing for the other) with a
// jump of the displacement across the interface, each of the three
// compression modes, and pieces of at most 7 VTK cells (whole mesh cells,
// at least one). The displacement is linear (A x, plus a constant c on the
// far side of the split), so every point must carry exactly that value,
// every cell the stress C : sym(A) (on even cycles in transversely
// isotropic rock with an oblique axis, C from its rotated Voigt matrix),
// and the points of a piece must be shared by its cells: one point per
// node and side of the split.

#include <rupture/material/elastic_material.h>
#include <rupture/output/directory.h>
#include <rupture/output/volume_output.h>

#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/distributed/tria.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_nothing.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/hp/fe_collection.h>
#include <deal.II/lac/trilinos_vector.h>

#include "../tests.h"
#include <zlib.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <iostream>
#include <map>
#include <regex>
#include <set>

using namespace dealii;

namespace
{
  /**
   * The arrays of one .vtu file, decoded.
   */
  struct Piece
  {
    std::uint64_t                              n_points = 0, n_cells = 0;
    std::map<std::string, std::vector<double>> arrays;
  };

  Piece
  read_piece(const std::string &file)
  {
    const std::string text = tests::read_file(file);
    Piece             piece;
    std::smatch       m;
    std::regex_search(
      text,
      m,
      std::regex("NumberOfPoints=\"([0-9]+)\" NumberOfCells=\"([0-9]+)\""));
    piece.n_points = std::stoull(m[1]);
    piece.n_cells  = std::stoull(m[2]);
    const bool compressed =
      text.find("vtkZLibDataCompressor") != std::string::npos;
    const auto       appended   = text.find("<AppendedData encoding=\"raw\">");
    const auto       data_start = text.find('_', appended) + 1;
    const std::regex array(
      "<DataArray type=\"([A-Za-z0-9]+)\" Name=\"([a-z_A-Z]+)\" "
      "NumberOfComponents=\"[0-9]+\" format=\"appended\" offset=\"([0-9]+)\"/>");
    for (auto it =
           std::sregex_iterator(text.begin(), text.begin() + appended, array);
         it != std::sregex_iterator();
         ++it)
      {
        const std::string type = (*it)[1];
        const std::string name = (*it)[2];
        const char       *at = text.data() + data_start + std::stoull((*it)[3]);
        std::vector<char> bytes;
        std::uint64_t     header[3];
        std::memcpy(header, at, sizeof(header));
        if (!compressed)
          bytes.assign(at + 8, at + 8 + header[0]);
        else if (header[0] == 1)
          {
            std::uint64_t compressed_size;
            std::memcpy(&compressed_size, at + 24, 8);
            bytes.resize(header[1]);
            uLongf size = bytes.size();
            uncompress(reinterpret_cast<Bytef *>(bytes.data()),
                       &size,
                       reinterpret_cast<const Bytef *>(at + 32),
                       compressed_size);
          }
        std::vector<double> &values = piece.arrays[name];
        const auto           add    = [&](auto zero) {
          using T = decltype(zero);
          for (std::size_t i = 0; i < bytes.size() / sizeof(T); ++i)
            {
              T v;
              std::memcpy(&v, bytes.data() + i * sizeof(T), sizeof(T));
              values.push_back(v);
            }
        };
        if (type == "Float32")
          add(float());
        else if (type == "Int32")
          add(std::int32_t());
        else
          add(std::uint8_t());
      }
    return piece;
  }



  template <int dim>
  void
  check(const unsigned int degree,
        const bool         split,
        const std::string &compression,
        const unsigned int cycle)
  {
    const MPI_Comm                            comm = MPI_COMM_WORLD;
    parallel::distributed::Triangulation<dim> tria(comm);
    GridGenerator::subdivided_hyper_cube(tria, 4, 0, 1);
    // General hexahedra: a smooth deformation that keeps x = 1/2.
    GridTools::transform(
      [](const Point<dim> &p) {
        Point<dim> q = p;
        for (unsigned int d = 1; d < dim; ++d)
          q[d] += 0.1 * std::sin(3 * p[0]) * p[d] * (1 - p[d]);
        return q;
      },
      tria);

    hp::FECollection<dim> fe;
    if (split)
      {
        fe.push_back(
          FESystem<dim>(FE_Q<dim>(degree), dim, FE_Nothing<dim>(), dim));
        fe.push_back(
          FESystem<dim>(FE_Nothing<dim>(), dim, FE_Q<dim>(degree), dim));
      }
    else
      fe.push_back(FESystem<dim>(FE_Q<dim>(degree), dim));
    DoFHandler<dim> dof_handler(tria);
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned() && split && cell->center()[0] > 0.5)
        cell->set_active_fe_index(1);
    dof_handler.distribute_dofs(fe);
    const IndexSet owned = dof_handler.locally_owned_dofs();
    IndexSet       relevant;
    DoFTools::extract_locally_relevant_dofs(dof_handler, relevant);

    // u = A x (+ c on side 1), v = B x; each DoF's value is set from the
    // location of its support point.
    Tensor<2, dim> a, b;
    Tensor<1, dim> c;
    for (unsigned int i = 0; i < dim; ++i)
      {
        c[i] = 0.5 + i;
        for (unsigned int j = 0; j < dim; ++j)
          {
            a[i][j] = 1e-3 * (1 + i + 2 * j);
            b[i][j] = 0.1 * (i == j ? 2 : 1) - 0.05 * j;
          }
      }
    TrilinosWrappers::MPI::Vector        u(owned, comm), v(owned, comm);
    std::vector<types::global_dof_index> dofs;
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          const auto &f = cell->get_fe();
          dofs.resize(f.n_dofs_per_cell());
          cell->get_dof_indices(dofs);
          const auto &support = f.get_unit_support_points();
          for (unsigned int i = 0; i < dofs.size(); ++i)
            if (owned.is_element(dofs[i]))
              {
                // The support points of this mesh's (Q1-mapped) cells.
                Point<dim> x;
                for (unsigned int k = 0;
                     k < GeometryInfo<dim>::vertices_per_cell;
                     ++k)
                  x +=
                    GeometryInfo<dim>::d_linear_shape_function(support[i], k) *
                    cell->vertex(k);
                const unsigned int comp = f.system_to_component_index(i).first;
                const unsigned int d    = comp % dim;
                u[dofs[i]] = (a * x)[d] + (comp >= dim ? c[d] : 0.);
                v[dofs[i]] = (b * x)[d];
              }
        }
    u.compress(VectorOperation::insert);
    v.compress(VectorOperation::insert);
    TrilinosWrappers::MPI::Vector u_ghost(owned, relevant, comm),
      v_ghost(owned, relevant, comm);
    u_ghost = u;
    v_ghost = v;

    // Even cycles: transversely isotropic rock with an oblique axis (in
    // the model plane in 2-D, which keeps it a mirror plane), whose stress
    // is computed here from the rotated Voigt matrix.
    const bool        anisotropic = (cycle % 2 == 0);
    const std::string axes        = (dim == 2) ? "1, 2, 0" : "1, 2, 3";
    ParameterHandler  prm;
    rupture::Material::ElasticMaterials::declare_parameters(prm);
    prm.parse_input_from_string(
      "subsection Material\n"
      "  set Names = rock\n"
      "  set Density = 2700\n"
      "  set P-wave speed = 6000\n"
      "  set S-wave speed = 3464\n" +
      (anisotropic ? "  set Symmetry = transversely isotropic\n"
                     "  set Stiffness = C11 = 1.2e11, C33 = 0.8e11, C13 = "
                     "3.2e10, C44 = 2.4e10, C66 = 3.6e10\n"
                     "  set Material axes = " +
                       axes + "\n" :
                     std::string()) +
      "end\n");
    rupture::Material::ElasticMaterials materials;
    materials.parse_parameters(prm, dim);
    const auto          &m      = materials.get(0);
    const Tensor<2, dim> strain = 0.5 * (a + transpose(a));
    Tensor<2, dim>       stress =
      m.lambda * trace(strain) * unit_symmetric_tensor<dim>() +
      2 * m.mu * strain;
    if (anisotropic)
      {
        // sigma_I = C_IJ e_J, Voigt order 11, 22, 33, 23, 13, 12 with
        // engineering shear strains.
        const unsigned int row[6] = {0, 1, 2, 1, 0, 0},
                           col[6] = {0, 1, 2, 2, 2, 1};
        double e[6]               = {0, 0, 0, 0, 0, 0};
        for (unsigned int J = 0; J < 6; ++J)
          if (row[J] < dim && col[J] < dim)
            e[J] = (J < 3 ? 1. : 2.) * strain[row[J]][col[J]];
        stress = 0;
        for (unsigned int I = 0; I < 6; ++I)
          if (row[I] < dim && col[I] < dim)
            {
              double value = 0;
              for (unsigned int J = 0; J < 6; ++J)
                value += m.voigt[I][J] * e[J];
              stress[row[I]][col[I]] = stress[col[I]][row[I]] = value;
            }
      }

    using Output = rupture::Output::VolumeOutput<dim>;
    const typename Output::Compression mode =
      compression == "none" ? Output::Compression::none :
      compression == "all"  ? Output::Compression::all :
                              Output::Compression::mesh;
    const std::string          name = "results-" + std::to_string(cycle);
    rupture::Output::Directory directory(name, comm);
    directory.open();
    typename Output::Settings settings;
    settings.fields          = Output::available_fields();
    settings.compression     = mode;
    settings.cells_per_piece = 7;
    Output output(directory, materials, settings, comm);
    output.write(dof_handler, u_ghost, v_ghost, 0.25, cycle);
    MPI_Barrier(comm);
    if (Utilities::MPI::this_mpi_process(comm) != 0)
      return;

    // Read all pieces listed in the record.
    std::string step = std::to_string(cycle);
    step.insert(0, 5 - step.size(), '0');
    const std::string pvtu =
      tests::read_file(name + "/solution/solution_" + step + ".pvtu");
    const std::regex source("Source=\"([^\"]+)\"");
    unsigned int     n_pieces = 0, n_points = 0, n_cells = 0, max_cells = 0;
    double           u_error = 0, v_error = 0, s_error = 0, s_scale = 0;
    bool             topology_ok = true;
    std::set<std::vector<double>> distinct; // (x, side) over all pieces
    for (auto it = std::sregex_iterator(pvtu.begin(), pvtu.end(), source);
         it != std::sregex_iterator();
         ++it, ++n_pieces)
      {
        const Piece p = read_piece(name + "/solution/" + (*it)[1].str());
        n_points += p.n_points;
        n_cells += p.n_cells;
        max_cells          = std::max<unsigned int>(max_cells, p.n_cells);
        const auto &points = p.arrays.at("Points");
        const auto &conn   = p.arrays.at("connectivity");
        topology_ok =
          topology_ok && points.size() == 3 * p.n_points &&
          conn.size() == p.n_cells * GeometryInfo<dim>::vertices_per_cell &&
          p.arrays.at("types").size() == p.n_cells;
        // Each point's value against the field at its location; the side
        // is told by the jump c.
        std::vector<bool> used(p.n_points, false);
        for (const double i : conn)
          used[static_cast<unsigned int>(i)] = true;
        for (unsigned int n = 0; n < p.n_points; ++n)
          {
            Point<dim> x;
            for (unsigned int d = 0; d < dim; ++d)
              x[d] = points[3 * n + d];
            const Tensor<1, dim> ax = a * x, bx = b * x;
            double               e0 = 0, e1 = 0, ev = 0;
            for (unsigned int d = 0; d < dim; ++d)
              {
                const double value = p.arrays.at("displacement")[3 * n + d];
                e0                 = std::max(e0, std::abs(value - ax[d]));
                e1 = std::max(e1, std::abs(value - ax[d] - c[d]));
                ev = std::max(ev,
                              std::abs(p.arrays.at("velocity")[3 * n + d] -
                                       bx[d]));
              }
            u_error = std::max(u_error, std::min(e0, e1));
            v_error = std::max(v_error, ev);
            // Every point is used by a cell; 2-D fields have z = 0.
            topology_ok =
              topology_ok && used[n] &&
              (dim == 3 || (p.arrays.at("displacement")[3 * n + 2] == 0 &&
                            points[3 * n + 2] == 0));
            distinct.insert({std::round(x[0] * 1e5),
                             std::round(x[1] * 1e5),
                             dim == 3 ? std::round(x[2] * 1e5) : 0.,
                             e1 < e0 ? 1. : 0.});
          }
        for (unsigned int k = 0; k < p.n_cells; ++k)
          for (unsigned int i = 0; i < dim; ++i)
            for (unsigned int j = 0; j < dim; ++j)
              {
                s_error =
                  std::max(s_error,
                           std::abs(p.arrays.at("stress")[9 * k + 3 * i + j] -
                                    stress[i][j]));
                s_scale = std::max(s_scale, std::abs(stress[i][j]));
              }
      }
    // Points shared within a piece: at most the (vertex, side) pairs of its
    // cells; over all pieces, the distinct (vertex, side) pairs are those
    // of the mesh.
    const unsigned int n_vertices_1d = 4 * degree + 1;
    const unsigned int n_mesh_points =
      std::pow(n_vertices_1d, dim) +
      (split ? std::pow(n_vertices_1d, dim - 1) : 0);
    std::printf("%dd Q%u%s, compression %s: %u cells in %u pieces (at most %u "
                "cells each), %u points written, %zu distinct (mesh: %u)\n",
                dim,
                degree,
                split ? " split" : "",
                compression.c_str(),
                n_cells,
                n_pieces,
                max_cells,
                n_points,
                distinct.size(),
                n_mesh_points);
    std::printf("  topology consistent: %s\n", topology_ok ? "yes" : "no");
    if (anisotropic)
      std::printf("  rock: transversely isotropic, axis (%s)\n", axes.c_str());
    std::printf("  displacement, velocity and stress exact to float precision: "
                "%s %s %s\n",
                u_error < 1e-6 ? "yes" : "no",
                v_error < 1e-6 ? "yes" : "no",
                s_error < 1e-6 * s_scale ? "yes" : "no");
  }
} // namespace



int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  if (Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) != 0)
    std::freopen("/dev/null", "w", stdout);
  check<2>(1, false, "mesh", 1);
  check<2>(1, true, "none", 2);
  check<2>(2, true, "all", 3);
  check<3>(1, true, "mesh", 4);
  check<3>(2, false, "none", 5);
  check<3>(1, false, "all", 6);
  check<2>(4, true, "mesh", 7);
  check<3>(3, true, "all", 8);
}
