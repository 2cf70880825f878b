#include <rupture/scene/gmsh_mesh.h>

#include <deal.II/base/geometry_info.h>
#include <deal.II/base/tensor.h>
#include <deal.II/base/utilities.h>
#include <deal.II/grid/grid_in.h>
#include <deal.II/grid/tria.h>

#include <array>
#include <cmath>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <vector>

namespace rupture
{
  namespace Scene
  {
    namespace
    {
      /**
       * Refuse cells of the mesh file (quadrilaterals in 2-D, hexahedra in
       * 3-D) that name a node twice or two nodes at one place: deal.II's
       * reader cannot build such a cell (it aborts or makes one of zero
       * size).
       */
      template <int dim>
      void
      check_cell_nodes(const std::string &file_name, const std::string &version)
      {
        const int          cell_type  = (dim == 2) ? 3 : 5;
        const unsigned int n_vertices = (dim == 2) ? 4 : 8;
        // The volume cells of the other dimension (hexahedra in a 2-D run,
        // quadrilaterals in a 3-D one) tell a mesh of the wrong dimension.
        const int  other_type = (dim == 2) ? 5 : 3;
        long       n_cells = 0, n_other = 0;
        const auto check_dimension = [&]() {
          AssertThrow(
            !((dim == 2 && n_other > 0) ||
              (dim == 3 && n_cells == 0 && n_other > 0)),
            ExcMessage(
              "The mesh file <" + file_name + "> holds " +
              (dim == 2 ? std::string("hexahedra (a 3-D mesh)") :
                          std::string("only quadrilaterals (a 2-D mesh, or "
                                      "the surface of a 3-D one)")) +
              ", but <Dimension> = " + std::to_string(dim) +
              ". Allowed: a mesh of quadrilaterals with <Dimension> = 2, or "
              "one of hexahedra with <Dimension> = 3."));
        };
        std::ifstream                         in(file_name);
        std::map<long, std::array<double, 3>> nodes;
        std::string                           line;
        const auto fail = [&](const long cell, const std::string &what) {
          AssertThrow(false,
                      ExcMessage("The mesh file <" + file_name +
                                 "> has a degenerate cell: element " +
                                 std::to_string(cell) + " " + what +
                                 ". Allowed: " +
                                 (dim == 2 ? std::string("quadrilaterals") :
                                             std::string("hexahedra")) +
                                 " with " + std::to_string(n_vertices) +
                                 " distinct nodes at distinct places."));
        };
        const auto check = [&](const long cell, const std::vector<long> &v) {
          for (unsigned int i = 0; i < v.size(); ++i)
            for (unsigned int j = i + 1; j < v.size(); ++j)
              {
                if (v[i] == v[j])
                  fail(cell, "names node " + std::to_string(v[i]) + " twice");
                const auto a = nodes.find(v[i]), b = nodes.find(v[j]);
                if (a != nodes.end() && b != nodes.end() &&
                    a->second == b->second)
                  fail(cell,
                       "has its nodes " + std::to_string(v[i]) + " and " +
                         std::to_string(v[j]) + " at the same place");
              }
        };
        while (std::getline(in, line))
          {
            line = dealii::Utilities::trim(line);
            if (line == "$Nodes")
              {
                if (version == "2.2")
                  {
                    long n = 0;
                    in >> n;
                    for (long i = 0; i < n && in; ++i)
                      {
                        long                  tag;
                        std::array<double, 3> x;
                        in >> tag >> x[0] >> x[1] >> x[2];
                        nodes[tag] = x;
                      }
                  }
                else
                  {
                    long blocks = 0, n = 0, min = 0, max = 0;
                    in >> blocks >> n >> min >> max;
                    for (long b = 0; b < blocks && in; ++b)
                      {
                        long entity_dim, entity, parametric, count;
                        in >> entity_dim >> entity >> parametric >> count;
                        std::vector<long> tags(count);
                        for (auto &t : tags)
                          in >> t;
                        for (const long t : tags)
                          {
                            std::array<double, 3> x;
                            in >> x[0] >> x[1] >> x[2];
                            nodes[t] = x;
                          }
                      }
                  }
              }
            else if (line == "$Elements")
              {
                std::vector<long> v;
                if (version == "2.2")
                  {
                    long n = 0;
                    in >> n;
                    std::getline(in, line);
                    for (long i = 0; i < n && std::getline(in, line); ++i)
                      {
                        std::istringstream words(line);
                        long               number, type, n_tags, tag;
                        words >> number >> type >> n_tags;
                        for (long t = 0; t < n_tags; ++t)
                          words >> tag;
                        n_other += (type == other_type);
                        if (type != cell_type)
                          continue;
                        ++n_cells;
                        v.assign(n_vertices, 0);
                        for (auto &node : v)
                          words >> node;
                        check(number, v);
                      }
                  }
                else
                  {
                    long blocks = 0, n = 0, min = 0, max = 0;
                    in >> blocks >> n >> min >> max;
                    for (long b = 0; b < blocks && in; ++b)
                      {
                        long entity_dim, entity, type, count;
                        in >> entity_dim >> entity >> type >> count;
                        std::getline(in, line);
                        if (type == other_type)
                          n_other += count;
                        if (type == cell_type)
                          n_cells += count;
                        for (long i = 0; i < count && std::getline(in, line);
                             ++i)
                          if (type == cell_type)
                            {
                              std::istringstream words(line);
                              long               number;
                              words >> number;
                              v.assign(n_vertices, 0);
                              for (auto &node : v)
                                words >> node;
                              check(number, v);
                            }
                      }
                  }
                check_dimension();
                return;
              }
          }
      }
    } // namespace



    template <int dim>
    void
    GmshMesh<dim>::declare_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Scene");
      prm.enter_subsection("Gmsh");
      {
        prm.declare_entry(
          "Mesh file",
          "",
          Patterns::Anything(),
          "Path of the Gmsh .msh file (ASCII, format 2.2 or 4.1), relative "
          "to the directory the program is started in. Cells must be "
          "hexahedra (quadrilaterals in 2-D). The physical tags of cells, in "
          "ascending order, become material ids 0, 1, 2, ...; named physical groups of boundary faces become the "
          "boundary names used by <Boundary conditions>.");
      }
      prm.leave_subsection();
      prm.leave_subsection();
    }



    template <int dim>
    void
    GmshMesh<dim>::parse_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Scene");
      prm.enter_subsection("Gmsh");
      file_name = prm.get("Mesh file");
      prm.leave_subsection();
      prm.leave_subsection();

      AssertThrow(!file_name.empty(),
                  ExcMessage("<Scene/Gmsh/Mesh file> is empty; give the path "
                             "of a .msh file."));
      std::ifstream in(file_name);
      AssertThrow(in.good(),
                  ExcMessage("The mesh file <" + file_name +
                             "> given in <Scene/Gmsh/Mesh file> is missing "
                             "or unreadable."));

      std::string line;
      while (std::getline(in, line) && dealii::Utilities::trim(line).empty())
        ;
      AssertThrow(dealii::Utilities::trim(line) == "$MeshFormat",
                  ExcMessage("The file <" + file_name +
                             "> given in <Scene/Gmsh/Mesh file> is not a "
                             "Gmsh .msh file: it does not begin with "
                             "$MeshFormat. Allowed are ASCII .msh files of "
                             "format 2.2 or 4.1."));

      // The version line: "version file-type data-size". deal.II reads
      // ASCII 2.2 and 4.1; a file whose header and body disagree once
      // corrupted the reader's memory, so the body's section headers are
      // checked against the version below.
      std::getline(in, line);
      int file_type = -1;
      {
        std::istringstream words(line);
        words >> version >> file_type;
      }
      AssertThrow((version == "2.2" || version == "4.1") && file_type == 0,
                  ExcMessage("The mesh file <" + file_name +
                             "> given in <Scene/Gmsh/Mesh file> has the "
                             "format line '" +
                             dealii::Utilities::trim(line) +
                             "'. Allowed are ASCII files (file type 0) of "
                             "format 2.2 or 4.1: save the mesh with Gmsh's "
                             "'Version 2 ASCII' or 'Version 4 ASCII' option."));
      {
        // In 2.2 $Nodes and $Elements start with one count; in 4.1 with
        // four numbers (blocks, count, smallest and largest tag).
        const unsigned int expected = (version == "2.2") ? 1 : 4;
        std::ifstream      body(file_name);
        std::string        section;
        unsigned int       line_number = 0, n_nodes_sections = 0,
                     n_elements_sections = 0;
        while (std::getline(body, section))
          {
            ++line_number;
            section = dealii::Utilities::trim(section);
            if (section != "$Nodes" && section != "$Elements")
              continue;
            ++(section == "$Nodes" ? n_nodes_sections : n_elements_sections);
            std::string header;
            std::getline(body, header);
            ++line_number;
            std::istringstream words(header);
            std::string        word;
            unsigned int       n_words = 0;
            bool               numbers = true;
            while (words >> word)
              {
                ++n_words;
                numbers = numbers && word.find_first_not_of("0123456789") ==
                                       std::string::npos;
              }
            AssertThrow(
              n_words == expected && numbers,
              ExcMessage(
                "The mesh file <" + file_name + "> says it has format " +
                version + ", but its " + section + " section starts with '" +
                dealii::Utilities::trim(header) + "', which is not " +
                (expected == 1 ? std::string("one count (format 2.2)") :
                                 std::string("four numbers (format "
                                             "4.1)")) +
                ". Save the mesh again with Gmsh, or fix "
                "the $MeshFormat line."));
            // In 2.2 every node is a line "tag x y z": a broken body is
            // named here, with its line, instead of by what follows from
            // it (a mesh without boundaries or cells).
            if (version == "2.2" && section == "$Nodes")
              {
                const unsigned long n = std::stoul(header);
                for (unsigned long k = 0; k < n; ++k)
                  {
                    std::string node;
                    const bool  read =
                      static_cast<bool>(std::getline(body, node));
                    ++line_number;
                    std::istringstream numbers(node);
                    long               tag = 0;
                    double             x = 0, y = 0, z = 0;
                    std::string        rest;
                    AssertThrow(
                      read && (numbers >> tag >> x >> y >> z) &&
                        !(numbers >> rest),
                      ExcMessage(
                        "Line " + std::to_string(line_number) +
                        " of the mesh file <" + file_name + "> " +
                        (read ? "is '" + dealii::Utilities::trim(node) + "'" :
                                std::string("is missing")) +
                        ", but its $Nodes section announces " +
                        std::to_string(n) +
                        " nodes, each a line 'tag x y z' of "
                        "numbers. The file is damaged: save the "
                        "mesh again with Gmsh."));
                  }
              }
          }
        AssertThrow(n_nodes_sections == 1 && n_elements_sections == 1,
                    ExcMessage(
                      "The mesh file <" + file_name + "> has " +
                      std::to_string(n_nodes_sections) + " $Nodes and " +
                      std::to_string(n_elements_sections) +
                      " $Elements sections after its $MeshFormat header; a "
                      "Gmsh mesh has one of each (the file is damaged or "
                      "not a mesh: save it again with Gmsh)."));
      }

      // $PhysicalNames: "n" then lines "dimension tag \"name\"".
      boundary_names.clear();
      while (std::getline(in, line))
        if (dealii::Utilities::trim(line) == "$PhysicalNames")
          {
            unsigned int n = 0;
            in >> n;
            for (unsigned int i = 0; i < n; ++i)
              {
                int         group_dim = 0, tag = 0;
                std::string name;
                in >> group_dim >> tag;
                std::getline(in, name);
                name = dealii::Utilities::trim(name);
                if (name.size() >= 2 && name.front() == '"' &&
                    name.back() == '"')
                  name = name.substr(1, name.size() - 2);
                AssertThrow(in,
                            ExcMessage("The $PhysicalNames section of <" +
                                       file_name + "> is malformed."));
                if (group_dim == dim - 1)
                  {
                    AssertThrow(tag >= 0 && tag < 255,
                                ExcMessage("The physical tag " +
                                           std::to_string(tag) + " of <" +
                                           name + "> in <" + file_name +
                                           "> is not in the allowed range "
                                           "0..254 for boundary ids."));
                    boundary_names[name] = tag;
                  }
              }
            break;
          }
      // The cells (their dimension, repeated or coincident nodes), before
      // the boundary names are checked against them and before deal.II's
      // reader sees them.
      check_cell_nodes<dim>(file_name, version);
    }



    template <int dim>
    void
    GmshMesh<dim>::create_coarse_mesh(
      parallel::distributed::Triangulation<dim> &triangulation) const
    {
      Triangulation<dim> serial;
      GridIn<dim>        grid_in;
      grid_in.attach_triangulation(serial);
      std::ifstream in(file_name);
      try
        {
          grid_in.read_msh(in);
        }
      catch (const ExceptionBase &e)
        {
          std::ostringstream message;
          e.print_info(message);
          AssertThrow(false,
                      ExcMessage("The mesh file <" + file_name +
                                 "> could not be read as a Gmsh mesh of " +
                                 (dim == 3 ? std::string("hexahedra") :
                                             std::string("quadrilaterals")) +
                                 ": " + message.str()));
        }
      AssertThrow(serial.n_active_cells() > 0,
                  ExcMessage("The mesh file <" + file_name +
                             "> contains no cells."));
      AssertThrow(serial.all_reference_cells_are_hyper_cube(),
                  ExcMessage("The mesh file <" + file_name +
                             "> contains cells that are not hexahedra "
                             "(quadrilaterals in 2-D); only those are "
                             "allowed."));
      // Every cell must map the unit cell one to one: a positive Jacobian
      // determinant at each of its corners (repeated nodes make it zero, a
      // twisted 'bow-tie' cell negative at some corners). Such a cell would
      // give infinite or NaN stresses only once the run has started.
      unsigned int number = 0;
      for (const auto &cell : serial.active_cell_iterators())
        {
          ++number;
          const double size = std::pow(cell->diameter(), dim);
          for (const unsigned int v : cell->vertex_indices())
            {
              const Point<dim> corner = GeometryInfo<dim>::unit_cell_vertex(v);
              Tensor<2, dim>   jacobian;
              for (const unsigned int w : cell->vertex_indices())
                jacobian += outer_product(
                  Tensor<1, dim>(cell->vertex(w)),
                  GeometryInfo<dim>::d_linear_shape_function_gradient(corner,
                                                                      w));
              const double det = determinant(jacobian);
              if (!(det > 1e-12 * size))
                {
                  std::ostringstream message;
                  message << "The mesh file <" << file_name
                          << "> has a degenerate or twisted cell: cell "
                          << number << " (physical tag "
                          << int(cell->material_id()) << ", centre "
                          << cell->center()
                          << ") has a Jacobian determinant of " << det
                          << " at its node " << cell->vertex(v)
                          << " (nodes repeated, crossing edges or a wrong "
                             "node order). Allowed: cells whose corners all "
                             "turn the same way, with a positive Jacobian "
                             "at each of them.";
                  AssertThrow(false, ExcMessage(message.str()));
                }
            }
        }

      // Physical tags of cells, in ascending order, become material ids
      // 0, 1, 2, ...: the order of the lists in the Material section.
      std::set<types::material_id> tags;
      for (const auto &cell : serial.active_cell_iterators())
        tags.insert(cell->material_id());
      std::map<types::material_id, types::material_id> id_of_tag;
      for (const auto tag : tags)
        id_of_tag.emplace(tag, id_of_tag.size());
      for (const auto &cell : serial.active_cell_iterators())
        cell->set_material_id(id_of_tag[cell->material_id()]);

      triangulation.copy_triangulation(serial);
    }



    template <int dim>
    std::map<std::string, types::boundary_id>
    GmshMesh<dim>::get_boundary_names() const
    {
      return boundary_names;
    }

    RUPTURE_REGISTER_SCENE(GmshMesh,
                           "gmsh",
                           "a hexahedral mesh read from a Gmsh .msh file, with "
                           "physical tags for materials and named physical "
                           "groups for boundaries.")

  } // namespace Scene
} // namespace rupture


template class rupture::Scene::GmshMesh<2>;
template class rupture::Scene::GmshMesh<3>;
