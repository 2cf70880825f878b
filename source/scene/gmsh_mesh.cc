#include <rupture/scene/gmsh_mesh.h>

#include <deal.II/base/utilities.h>
#include <deal.II/grid/grid_in.h>
#include <deal.II/grid/tria.h>

#include <fstream>
#include <map>
#include <set>
#include <sstream>

namespace rupture
{
  namespace Scene
  {
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
      std::string version;
      int         file_type = -1;
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
        while (std::getline(body, section))
          {
            section = dealii::Utilities::trim(section);
            if (section != "$Nodes" && section != "$Elements")
              continue;
            std::string header;
            std::getline(body, header);
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
          }
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
