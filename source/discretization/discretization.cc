// The degrees of freedom of the discretization and their constraints.

#include <rupture/base/utilities.h>
#include <rupture/discretization/discretization.h>
#include <rupture/fault/fault.h>
#include <rupture/scene/boundary_conditions.h>

#include <deal.II/base/quadrature.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_nothing.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/mapping_q1.h>
#include <deal.II/hp/fe_values.h>
#include <deal.II/hp/mapping_collection.h>
#include <deal.II/hp/q_collection.h>

namespace rupture
{
  namespace Discretization
  {
    template <int dim>
    Discretization<dim>::Discretization(const MPI_Comm communicator)
      : mpi_communicator(communicator)
      , mesh(communicator,
             typename Triangulation<dim>::MeshSmoothing(
               Triangulation<dim>::limit_level_difference_at_vertices))
    {}



    template <int dim>
    Discretization<dim>::~Discretization()
    {
      dofs.clear();
    }



    template <int dim>
    void
    Discretization<dim>::declare_parameters(ParameterHandler &prm)
    {
      prm.declare_entry("Initial global refinement",
                        "0",
                        Patterns::Integer(0, 12),
                        "Number of times each coarse cell of the scene is "
                        "refined (each halves the cell size).");
      prm.declare_entry(
        "Refinement region",
        "0",
        Patterns::Anything(),
        "Cells whose centre makes this function of position (x, y and, in "
        "3-D, z) positive are refined <Refinement region levels> more times "
        "after the global refinement, e.g. 'x < 1000 ? 1 : 0' or "
        "'abs(z) < 5000'. Neighbouring cells differ by at most one level; "
        "the hanging nodes between them are constrained. The fault is "
        "refined alike on both sides: where the region takes a cell next "
        "to the fault, the cell across the fault is refined with it. In "
        "3-D the fault may then be finer in some parts than in others: "
        "its nodes on the border of a finer part hang and follow the "
        "nodes around them (with either <Fault/Model>). The multigrid "
        "preconditioner needs this region off (0).");
      prm.declare_entry("Refinement region levels",
                        "0",
                        Patterns::Integer(0, 6),
                        "How many times the cells of <Refinement region> "
                        "are refined (each halves their size). 0 leaves the "
                        "mesh as the global refinement made it.");
      prm.declare_entry(
        "Fault cell weight",
        "1",
        Patterns::Double(1, 100),
        "The cost of a cell with a face on the fault, in cells without "
        "one, when the mesh is partitioned between MPI ranks (at the start "
        "and after every adaptation): the ranks then get equal sums of "
        "these weights instead of equal numbers of cells. Such a cell "
        "carries the fault's node pairs (their friction) and, with "
        "<Damping/Fault zone damping>, a share of a second stiffness "
        "product; contrib/partition-study measures it (doc/partition.md: "
        "about 4 for TPV3's Q2 cells with fault zone damping). 1 balances "
        "the numbers of cells; a single rank ignores it.");
      prm.declare_entry("Polynomial degree",
                        "1",
                        Patterns::Integer(1, 4),
                        "Degree p of the FE_Q displacement elements, 1 to "
                        "4: 1 is the paper's (bi/trilinear). The nodes of "
                        "degree p sit at the Gauss-Lobatto points of each "
                        "cell, so a cell of size h has nodes h/p apart on "
                        "average (the node spacing that the SCEC "
                        "benchmarks' resolution refers to), and the lumped "
                        "mass of the explicit scheme is the Gauss-Lobatto "
                        "one of spectral elements. The stable explicit "
                        "step is computed for the degree (at equal node "
                        "spacing it is 0.80, 0.67 and 0.56 times degree "
                        "1's at degrees 2, 3 and 4); <Time "
                        "integration/Courant fraction> is a fraction of it "
                        "at every degree.");
    }



    template <int dim>
    void
    Discretization<dim>::parse_parameters(ParameterHandler &prm)
    {
      global_refinements = prm.get_integer("Initial global refinement");
      region_refinements = prm.get_integer("Refinement region levels");
      region    = Utilities::parse_function<dim>(prm.get("Refinement region"),
                                              1,
                                              "Discretization/Refinement "
                                                 "region",
                                              dim == 2 ? "x,y" : "x,y,z");
      fe_degree = prm.get_integer("Polynomial degree");
      fault_cell_weight = prm.get_double("Fault cell weight");
    }



    template <int dim>
    void
    Discretization<dim>::set_fault(const Fault::Fault<dim> *fault)
    {
      this->fault = fault;
    }



    template <int dim>
    void
    Discretization<dim>::distribute_dofs()
    {
      // One displacement field per side: component s*dim + c is component
      // c on side s, and FE_Nothing gives the other side no DoFs on a cell.
      if (elements.size() == 0)
        {
          if (!fault)
            elements.push_back(FESystem<dim>(FE_Q<dim>(fe_degree), dim));
          else
            {
              elements.push_back(FESystem<dim>(
                FE_Q<dim>(fe_degree), dim, FE_Nothing<dim>(), dim));
              elements.push_back(FESystem<dim>(
                FE_Nothing<dim>(), dim, FE_Q<dim>(fe_degree), dim));
            }
        }
      // Ghosted copies exchange by the pattern of the old DoFs.
      ghosts.reset();
      dofs.reinit(mesh);
      if (fault)
        for (const auto &cell : dofs.active_cell_iterators())
          if (cell->is_locally_owned())
            cell->set_active_fe_index(fault->side(cell));
      dofs.distribute_dofs(elements);

      owned = dofs.locally_owned_dofs();
      DoFTools::extract_locally_relevant_dofs(dofs, relevant);
    }



    template <int dim>
    void
    Discretization<dim>::make_constraints(
      const std::function<void(AffineConstraints<double> &)> &add_interface,
      const Scene::BoundaryConditions<dim> &boundary_conditions)
    {
      hanging.clear();
      hanging.reinit(relevant);
      DoFTools::make_hanging_node_constraints(dofs, hanging);
      if (add_interface)
        add_interface(hanging);
      hanging.close();
      hanging_distributor.reinit(hanging, owned, mpi_communicator);

      // Kinematic boundary conditions: collect the constrained DoFs of each
      // named boundary (first condition wins where boundaries meet).
      increments.clear();
      increments.reinit(relevant);
      kinematic_dofs.clear();
      for (const auto &bc : boundary_conditions.kinematic)
        for_each_support_point(
          [&](const CellIterator &cell) {
            if (cell->is_artificial())
              return false;
            for (const auto f : cell->face_indices())
              if (cell->face(f)->at_boundary() &&
                  cell->face(f)->boundary_id() == bc.id)
                return true;
            return false;
          },
          [&](const CellIterator                         &cell,
              const std::vector<types::global_dof_index> &cell_dofs,
              const std::vector<Point<dim>>              &points) {
            const auto &fe = cell->get_fe();
            for (const auto f : cell->face_indices())
              if (cell->face(f)->at_boundary() &&
                  cell->face(f)->boundary_id() == bc.id)
                for (unsigned int i = 0; i < cell_dofs.size(); ++i)
                  {
                    if (!fe.has_support_on_face(i, f))
                      continue;
                    const unsigned int c =
                      fe.system_to_component_index(i).first % dim;
                    const auto dof = cell_dofs[i];
                    if (!bc.components[c] || increments.is_constrained(dof) ||
                        hanging.is_constrained(dof))
                      continue;
                    increments.add_line(dof);
                    if (owned.is_element(dof))
                      kinematic_dofs.push_back(
                        {dof, c, points[i], bc.velocity.get()});
                  }
          });
      increments.merge(
        hanging,
        AffineConstraints<double>::MergeConflictBehavior::left_object_wins);
      increments.close();
    }



    template <int dim>
    void
    Discretization<dim>::for_each_support_point(
      const std::function<bool(const CellIterator &)>            &select,
      const std::function<void(const CellIterator &,
                               const std::vector<types::global_dof_index> &,
                               const std::vector<Point<dim>> &)> &action) const
    {
      // A quadrature whose points are the unit support points of each
      // element: its mapped points are the support points of the cell's
      // DoFs.
      hp::QCollection<dim> support_quadrature;
      for (unsigned int i = 0; i < elements.size(); ++i)
        support_quadrature.push_back(
          Quadrature<dim>(elements[i].get_unit_support_points()));
      const hp::MappingCollection<dim>     mapping{MappingQ1<dim>()};
      hp::FEValues<dim>                    fe_values(mapping,
                                  elements,
                                  support_quadrature,
                                  update_quadrature_points);
      std::vector<types::global_dof_index> cell_dofs;
      for (const auto &cell : dofs.active_cell_iterators())
        if (select(cell))
          {
            fe_values.reinit(cell);
            cell_dofs.resize(cell->get_fe().n_dofs_per_cell());
            cell->get_dof_indices(cell_dofs);
            action(cell,
                   cell_dofs,
                   fe_values.get_present_fe_values().get_quadrature_points());
          }
    }



    template <int dim>
    void
    Discretization<dim>::distribute_hanging(VectorType &v) const
    {
      hanging_distributor.distribute(v.trilinos_vector()[0]);
    }



    template <int dim>
    double
    Discretization<dim>::kinematic_velocity(const KinematicDof &k,
                                            const double        t) const
    {
      if (!k.velocity)
        return 0;
      k.velocity->set_time(t);
      return k.velocity->value(k.location, k.component);
    }



    template <int dim>
    void
    Discretization<dim>::set_kinematic_velocity(VectorType  &v,
                                                const double t) const
    {
      for (const auto &k : kinematic_dofs)
        v(k.dof) = kinematic_velocity(k, t);
      v.compress(VectorOperation::insert);
    }



    template <int dim>
    void
    Discretization<dim>::impose_kinematic_motion(const VectorType &old_u,
                                                 VectorType       &u,
                                                 const double      t,
                                                 const double      dt) const
    {
      for (const auto &k : kinematic_dofs)
        u(k.dof) = old_u(k.dof) + kinematic_velocity(k, t - 0.5 * dt) * dt;
      u.compress(VectorOperation::insert);
    }



    template class Discretization<2>;
    template class Discretization<3>;
  } // namespace Discretization
} // namespace rupture
