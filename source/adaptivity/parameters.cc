#include <rupture/adaptivity/parameters.h>

#include <deal.II/base/exceptions.h>
#include <deal.II/base/utilities.h>

namespace rupture
{
  namespace Adaptivity
  {
    void
    Parameters::declare_parameters(dealii::ParameterHandler &prm)
    {
      using namespace dealii;
      prm.enter_subsection("Mesh refinement");
      {
        prm.declare_entry(
          "Criteria",
          "",
          Patterns::List(Patterns::Selection("rupture front")),
          "What the mesh follows during the run; empty: the mesh stays as "
          "set up. \"rupture front\": the cells at the fault (on both sides) "
          "are refined <Levels> more times where a fault node slips faster "
          "than <Slip rate threshold> and in a band ahead of it as wide as "
          "a P wave travels in <Interval> steps (plus <Extra band>), so that "
          "the refinement reaches a node before the front does; they are "
          "coarsened again, never below the base mesh, where no node is "
          "active within twice that band (a node is active while it slips "
          "or for <Coarsening delay> after its rupture). The fields, the "
          "fault's state and the outputs' series carry over; the time step "
          "of the explicit scheme follows the stable step of the new mesh. "
          "Multigrid preconditioners are refused on such meshes.");
        prm.declare_entry("Interval",
                          "10",
                          Patterns::Integer(1),
                          "Time steps between two adaptations of the mesh.");
        prm.declare_entry("Levels",
                          "1",
                          Patterns::Integer(1, 8),
                          "How many times the cells at the rupture front are "
                          "refined beyond the base mesh (<Discretization/"
                          "Initial global refinement> and <Refinement "
                          "region levels>); each level halves the cell "
                          "size.");
        prm.declare_entry("Slip rate threshold",
                          "1e-3",
                          Patterns::Double(0),
                          "A fault node that slips faster than this (m/s) is "
                          "active: the front's cells are refined around it.");
        prm.declare_entry(
          "Coarsening delay",
          "-1",
          Patterns::Double(),
          "A node stays active for this time (s) after its rupture even "
          "when it slips slower than the threshold; negative: for ever, so "
          "that the ruptured part of the fault keeps its fine cells.");
        prm.declare_entry("Extra band",
                          "0",
                          Patterns::Double(0),
                          "Distance (m) added to the band ahead of the "
                          "front that is refined.");
      }
      prm.leave_subsection();
    }



    void
    Parameters::parse_parameters(dealii::ParameterHandler &prm)
    {
      prm.enter_subsection("Mesh refinement");
      const std::vector<std::string> criteria =
        dealii::Utilities::split_string_list(prm.get("Criteria"));
      follow_front = false;
      for (const auto &c : criteria)
        if (c == "rupture front")
          follow_front = true;
      interval            = prm.get_integer("Interval");
      levels              = prm.get_integer("Levels");
      slip_rate_threshold = prm.get_double("Slip rate threshold");
      coarsening_delay    = prm.get_double("Coarsening delay");
      extra_band          = prm.get_double("Extra band");
      prm.leave_subsection();
    }
  } // namespace Adaptivity
} // namespace rupture
