#include <rupture/adaptivity/parameters.h>

#include <deal.II/base/exceptions.h>
#include <deal.II/base/utilities.h>

#include <cmath>

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
          Patterns::List(
            Patterns::Selection("rupture front|process zone|wavefield")),
          "What the mesh follows during the run; empty: the mesh stays as "
          "set up. \"rupture front\": the cells at the fault (on both sides) "
          "are refined <Levels> more times where a fault node slips faster "
          "than <Slip rate threshold> and in a band ahead of it as wide as "
          "a P wave travels until the next adaptation (plus <Extra band>), "
          "so that the refinement reaches a node before the front does; "
          "they are coarsened again, never below the base mesh, where no "
          "node is active within twice that band (a node is active while "
          "it slips or for <Coarsening delay> after its rupture). \"process "
          "zone\": the fault's cells are refined, at most <Levels> times, "
          "until <Nodes per process zone> node spacings (cell size over the "
          "polynomial degree) fit into the friction law's estimate of the "
          "process (cohesive) zone at rest, (9 pi/32) mu d/(Delta p) with "
          "the law's slip scale d (slip-weakening distance, state distance "
          "L), its strength drop Delta per unit pressure (mu_s - mu_d, b) "
          "and the fault pressure p; cells finer than needed are coarsened. "
          "Both together: the front's band is refined only as deep as the "
          "process zone needs. \"wavefield\": cells anywhere are refined, "
          "at most <Wavefield levels> times, where the waves are resolved "
          "less well than <Wavefield threshold> asks (a Kelly-type "
          "indicator of the velocity that leaves out the fault's faces), "
          "and coarsened where the waves have left; in dynamic phases only, "
          "and the only criterion that needs no fault. "
          "With several criteria a cell is refined if one asks for it and "
          "coarsened only if all allow it. The fields, the fault's state "
          "and the "
          "outputs' series carry over; the time step of the explicit scheme "
          "follows the stable step of the new mesh. Multigrid "
          "preconditioners are refused on such meshes.");
        prm.declare_entry("Interval",
                          "10",
                          Patterns::Integer(1),
                          "Time steps between two adaptations of the mesh "
                          "(unless <Time interval> is set).");
        prm.declare_entry("Time interval",
                          "0",
                          Patterns::Double(0),
                          "Time (s) between two adaptations of the mesh: "
                          "the mesh is adapted after the step that crosses "
                          "a multiple of it (steps of any length). 0: every "
                          "<Interval> steps.");
        prm.declare_entry("Nodes per process zone",
                          "3",
                          Patterns::Double(0.1),
                          "Criterion \"process zone\": how many node "
                          "spacings the process zone at rest must span. The "
                          "zone shrinks as a front accelerates, so the "
                          "moving front has fewer nodes in it.");
        prm.declare_entry(
          "Maximum degrees of freedom",
          "0",
          Patterns::Double(0),
          "A budget: a level of refinement whose estimated degrees of "
          "freedom (the present ones times the ratio of the cell counts) "
          "would exceed it is not made, and the run says so; coarsening goes "
          "on. 0: no limit. It must not be below the base mesh's.");
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
        prm.declare_entry(
          "Wavefield threshold",
          "1e-3",
          Patterns::Double(0),
          "Criterion \"wavefield\": a cell is refined where the jump of the "
          "velocity's normal derivative across its inner faces (root mean "
          "square over them, in 1/s: a jump in strain rate; the faces "
          "between the fault plane's sides left out) exceeds this, and "
          "coarsened (cells at the fault: by the fault's criteria only) "
          "where its parent's (estimated as 2^degree times its own) is below "
          "half of it. The log gives the largest value at each adaptation, "
          "for choosing it: a fraction of the strain rates that matter.");
        prm.declare_entry("Wavefield levels",
                          "1",
                          Patterns::Integer(1, 8),
                          "Criterion \"wavefield\": how many times a cell is "
                          "refined at most beyond the base mesh.");
        prm.declare_entry(
          "Wavefield band",
          "true",
          Patterns::Bool(),
          "Criterion \"wavefield\": also refine (and keep from coarsening) "
          "the cells within the distance a P wave travels until the next "
          "adaptation of a cell above <Wavefield threshold>, so that the "
          "cells are fine before the waves reach them. Without it a wave "
          "runs into coarse cells for up to <Interval> steps before they "
          "are refined, and what those cells cannot carry stays behind as "
          "grid-scale waves that hardly move and keep the cells refined "
          "(doc/manual.md, section 3.1).");
        prm.declare_entry("Extra band",
                          "0",
                          Patterns::Double(0),
                          "Distance (m) added to the band ahead of the "
                          "front that is refined.");
        prm.declare_entry(
          "Graded band",
          "false",
          Patterns::Bool(),
          "With \"rupture front\" and <Levels> above 1: the cells ahead of "
          "the band are refined in rings, one level less per band's width "
          "(a cell <Levels> - k levels above its base mesh is refined where "
          "a node is active within k bands), so that the front, which "
          "travels at most a band between two adaptations, finds every cell "
          "at most one level short and each adaptation makes one new mesh "
          "instead of one per level. false: the band's cells go to the "
          "finest level at once and the cells beyond it stay as they are.");
        prm.declare_entry(
          "Balance after adaptation",
          "true",
          Patterns::Bool(),
          "In the implicit dynamic phase of a run with a loading phase: "
          "after each adaptation, move the displacement into the new mesh's "
          "static balance with the carried velocity and acceleration (a "
          "Newton solve at the present time; the prescribed boundary "
          "values stay, every closed fault pair sticks on its penalty "
          "springs, keeping its plastic slip and friction state, and its "
          "accepted slip follows the balanced displacement; also when a "
          "checkpoint is continued with --refine). The loaded body's "
          "stresses were those of the coarser mesh, and out of balance on "
          "the new nodes; without it the imbalance acts on them as a "
          "sudden force (in the Northeast-Japan model it opened the "
          "fault and the run ran away, doc/manual.md 3.1). The energy the "
          "balance changes counts with the mesh's (statistics column "
          "'Energy added by mesh changes'). Other schemes: no effect (a "
          "quasi-static step balances anyway; the explicit scheme has no "
          "solve to do it with).");
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
      process_zone = false;
      wavefield    = false;
      for (const auto &c : criteria)
        if (c == "rupture front")
          follow_front = true;
        else if (c == "process zone")
          process_zone = true;
        else if (c == "wavefield")
          wavefield = true;
      interval            = prm.get_integer("Interval");
      time_interval       = prm.get_double("Time interval");
      nodes_per_zone      = prm.get_double("Nodes per process zone");
      max_dofs            = prm.get_double("Maximum degrees of freedom");
      levels              = prm.get_integer("Levels");
      slip_rate_threshold = prm.get_double("Slip rate threshold");
      coarsening_delay    = prm.get_double("Coarsening delay");
      extra_band          = prm.get_double("Extra band");
      graded_band         = prm.get_bool("Graded band");
      balance             = prm.get_bool("Balance after adaptation");
      wavefield_threshold = prm.get_double("Wavefield threshold");
      wavefield_levels    = prm.get_integer("Wavefield levels");
      wavefield_band      = prm.get_bool("Wavefield band");
      prm.leave_subsection();
    }



    bool
    Parameters::due(const unsigned int step,
                    const double       phase_time,
                    const double       time_step) const
    {
      if (time_interval > 0)
        return std::floor(phase_time / time_interval) >
               std::floor((phase_time - time_step) / time_interval);
      return step % interval == 0;
    }
  } // namespace Adaptivity
} // namespace rupture
