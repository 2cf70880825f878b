// The boundary-integral method's parameters.

#include <rupture/base/utilities.h>
#include <rupture/boundary_integral/cycle_output.h>
#include <rupture/boundary_integral/settings.h>
#include <rupture/boundary_integral/simulation.h>
#include <rupture/boundary_integral/stiffness.h>
#include <rupture/boundary_integral/text.h>
#include <rupture/fault/radiation_damping.h>
#include <rupture/material/anisotropic_input.h>

#include <deal.II/base/function_parser.h>

#include <cmath>
#include <cstdlib>
#include <iomanip>
#include <sstream>

namespace rupture
{
  namespace BoundaryIntegral
  {
    void
    declare_parameters(ParameterHandler &prm)
    {
      prm.declare_entry(
        "Method",
        "finite elements",
        Patterns::Selection("finite elements|boundary integral"),
        "How the problem is discretized. 'finite elements': the body "
        "meshed in <Scene>, the fault as a contact interface (everything "
        "but <Boundary integral>). 'boundary integral': the fault alone, "
        "with the body's stiffness from its Green's function (the review "
        "paper's dual method) or from finite elements (<Boundary "
        "integral/Stiffness>): quasi-dynamic earthquake cycles on the "
        "antiplane half-space (SCEC SEAS BP1) or a dipping fault in a "
        "plane-strain half-space (BP3).");
      prm.enter_subsection("Boundary integral");
      {
        prm.declare_entry(
          "Geometry",
          "antiplane half-space",
          Patterns::Selection("antiplane half-space|plane strain half-space"),
          "The body whose stiffness turns slip into traction: 'antiplane "
          "half-space', a vertical strike-slip fault at x = 0 from the free "
          "surface y = 0 down, out-of-plane displacement only (the review "
          "paper's section 8, SEAS BP1); 'plane strain half-space', a "
          "fault dipping at <Dip> from the surface point x = 0 down towards "
          "x > 0, in-plane displacement, the slip changing the normal "
          "stress as well as the shear traction (SEAS BP3; <Stiffness> = "
          "finite elements, an isotropic body of the first material's "
          "S- and P-wave speeds).");
        prm.declare_entry("Dip",
                          "90",
                          Patterns::Double(),
                          "With <Geometry> = plane strain half-space: the "
                          "fault's dip (degrees from the horizontal, 10 to "
                          "90). The fault passes through (d cos(dip), "
                          "-d sin(dip)) at the distance d down it; <Fault "
                          "depth>, <Element size> and the stations' places "
                          "are measured along it. 90 with the antiplane "
                          "half-space.");
        prm.declare_entry("Sense of slip",
                          "thrust",
                          Patterns::Selection("thrust|normal"),
                          "With <Geometry> = plane strain half-space: "
                          "'thrust', the block above the fault (the hanging "
                          "wall) moves up the dip relative to the one "
                          "below, or 'normal', down the dip. The plates "
                          "drive the slip that way; the shear traction and "
                          "the slip of the outputs are positive that way.");
        prm.declare_entry(
          "Stiffness",
          "Green's function",
          Patterns::Selection("Green's function|finite elements"),
          "How the body turns the fault's slip into traction. 'Green's "
          "function': in closed form (the dual method, uniform slip on "
          "elements of <Element size>, traction at their centres). 'finite "
          "elements': the body meshed (FE_Q of <Finite-element degree> on a "
          "box of <Domain size>, cells growing by <Cell growth factor> away "
          "from the fault), the fault's nodes the elements (<Element size> "
          "their spacing), one solve per node before the first step.");
        prm.declare_entry("Finite-element degree",
                          "2",
                          Patterns::Integer(1, 4),
                          "With <Stiffness> = finite elements: the "
                          "polynomial degree (1 to 4) of the elements; the "
                          "cells at the fault are degree times <Element "
                          "size> long.");
        prm.declare_entry("Domain size",
                          "400e3",
                          Patterns::Double(0),
                          "With <Stiffness> = finite elements: the width and "
                          "depth (m, at least twice <Fault depth>) of the "
                          "meshed box beside the fault, whose far sides "
                          "move with the plates.");
        prm.declare_entry("Cell growth factor",
                          "1.1",
                          Patterns::Double(1, 2),
                          "With <Stiffness> = finite elements: the ratio (> 1, "
                          "at most 2) of the sizes of neighbouring cells away "
                          "from the fault.");
        prm.declare_entry("Fault depth",
                          "40e3",
                          Patterns::Double(0),
                          "W (m, > 0): the depth (the distance along the "
                          "dip, with a dipping fault) down to which the "
                          "fault is solved; below it the fault slips at "
                          "<Plate rate>, which loads the part above.");
        prm.declare_entry("Element size",
                          "100",
                          Patterns::Double(0),
                          "The length (m, > 0) of the fault's elements (W "
                          "is cut into equal elements of at most this "
                          "length; at most 20000 of them).");
        prm.declare_entry("Plate rate",
                          "1e-9",
                          Patterns::Double(0),
                          "V_p (m/s, > 0): the slip rate of the fault below "
                          "<Fault depth>. The fault starts at the slip rate "
                          "at which the law in its initial state carries "
                          "<Initial shear stress> - eta V_p: with the law's "
                          "<Initial slip rate> = V_p and no <Initial "
                          "state>, V_p itself (the screen output gives the "
                          "range).");
        prm.declare_entry("Normal stress",
                          "50e6",
                          Patterns::Anything(),
                          "sigma_n (Pa, compressive > 0) as a function of "
                          "x, y, z (y up, the vertical fault at x = 0: the "
                          "depth is -y; a dipping fault passes through "
                          "(d cos(dip), -d sin(dip)); constants pi and "
                          "year). With <Geometry> = plane strain half-space "
                          "the value at the start: the slip changes it.");
        prm.declare_entry(
          "Initial shear stress",
          "",
          Patterns::Anything(),
          "tau_0 (Pa) as a function of x, y, z: the shear traction the "
          "fault carries at the start, before radiation damping (SEAS: "
          "tau_0 = sigma_n a_max asinh[V_p / (2 V_0) exp((f_0 + b ln(V_0 / "
          "V_p)) / a_max)] + eta V_p). The law's state at the start is the "
          "one for which it carries tau_0 - eta V_p at V_p.");
        prm.declare_entry(
          "Surface stations",
          "",
          Patterns::Anything(),
          "With <Geometry> = plane strain half-space: points on the free "
          "surface whose displacement and velocity (x and y) are written "
          "with the fault stations' rows, to <name>.dat (the SEAS BP3 "
          "surface stations), as 'name: x, 0; name: x, 0' (m; x <= 0 the "
          "footwall's side, the fault's trace x = 0 included, x > 0 the "
          "hanging wall's). The blocks move rigidly by +-V_p t / 2 along "
          "the slip direction far from the fault; each surface station adds "
          "a row per fault node to the stiffness's solves.");
        prm.declare_entry("Relative tolerance",
                          "1e-7",
                          Patterns::Double(0, 1),
                          "The Dormand-Prince step's error, relative to the "
                          "slip and the state (> 0).");
        prm.declare_entry("Absolute tolerance",
                          "1e-8",
                          Patterns::Double(0),
                          "The error (> 0) below which a change does not "
                          "matter: metres for the slip, and for each state "
                          "variable of the friction law in its own units "
                          "(in its logarithm for those that span decades, "
                          "such as theta).");
        prm.declare_entry(
          "Sampling slip rate change",
          "0",
          Patterns::Double(0),
          "The station and statistics files get a row after a step when "
          "the log10 of the fault's largest slip rate has changed by at "
          "least this much since the last row, or when <Sampling interval> "
          "has passed; 0 writes every step.");
        prm.declare_entry("Sampling interval",
                          "3.15576e7",
                          Patterns::Double(0),
                          "The longest time (s) between two rows of the "
                          "station and statistics files (with <Sampling "
                          "slip rate change> > 0).");
        prm.declare_entry("Profile interval between events",
                          "1.57788e8",
                          Patterns::Double(0),
                          "Time (s) between two slip profiles "
                          "(slip_profiles.dat) outside events (SEAS: 5 "
                          "years); 0 writes none.");
        prm.declare_entry("Profile interval during events",
                          "1",
                          Patterns::Double(0),
                          "Time (s) between two slip profiles during an "
                          "event (SEAS: 1 s); 0 writes none.");
        prm.declare_entry(
          "Events",
          "quasi-dynamic",
          Patterns::Selection("quasi-dynamic|fully dynamic"),
          "How the fast slip is solved. 'quasi-dynamic': radiation damping "
          "stands in for the waves all along (SEAS BP1-QD). 'fully "
          "dynamic': when the largest slip rate reaches <Dynamic above> the "
          "run switches to the waves of the meshed body (central "
          "differences, friction at the fault's nodes, the far side and "
          "the bottom absorbing), and back to the quasi-dynamic fault when "
          "it falls below <Quasi-dynamic below> (SEAS BP1-FD; with "
          "<Geometry> = antiplane half-space and <Stiffness> = finite "
          "elements). The slip, the state and the slip rates carry over "
          "both ways.");
        prm.declare_entry("Dynamic above",
                          "1e-3",
                          Patterns::Double(0),
                          "With <Events> = fully dynamic: the largest slip "
                          "rate (m/s) at which a quasi-dynamic phase ends "
                          "and a fully dynamic one starts.");
        prm.declare_entry("Quasi-dynamic below",
                          "5e-4",
                          Patterns::Double(0),
                          "With <Events> = fully dynamic: the largest slip "
                          "rate (m/s) below which a fully dynamic phase "
                          "ends; less than <Dynamic above>, so that the "
                          "switch does not chatter.");
        prm.declare_entry("Courant number",
                          "0.5",
                          Patterns::Double(0),
                          "With <Events> = fully dynamic: the time step of "
                          "the dynamic phases as a fraction of the stable "
                          "step of the central differences on the meshed "
                          "body without damping; times sqrt(1 + 2 <Kelvin-"
                          "Voigt damping>) at most 1.");
        prm.declare_entry(
          "Kelvin-Voigt damping",
          "0.1",
          Patterns::Double(0),
          "With <Events> = fully dynamic: the viscosity of the dynamic "
          "phases as a time in time steps (0 to 1): the stress is that of "
          "u + this * dt * v, which damps the mesh's highest frequencies "
          "(those the fault's sudden slip excites and that would ring on "
          "at the fault; 0.1 as in the split-node method of Day et al. "
          "2005) and leaves the waves the mesh resolves nearly alone.");
      }
      prm.leave_subsection();
    }



    bool
    chosen(ParameterHandler &prm)
    {
      return prm.get("Method") == "boundary integral";
    }



    namespace
    {


      /// The first number of the list in <Material/@p entry>.
      double
      first_material_value(ParameterHandler &prm, const std::string &entry)
      {
        std::vector<double> values;
        try
          {
            values =
              Utilities::parse_doubles(prm.get(entry), "Material/" + entry);
          }
        catch (const ExceptionBase &e)
          {
            AssertThrow(false,
                        ExcMessage(Utilities::message_of(e) +
                                   " The boundary-integral method takes a "
                                   "homogeneous body: give its constants as "
                                   "numbers (functions of position are for "
                                   "the finite-element methods)."));
          }
        AssertThrow(!values.empty(),
                    ExcMessage("<Material/" + entry + "> is empty."));
        return values[0];
      }

      /// The values at the depths of @p body's elements of the function of
      /// x, y, z @p expression in <Boundary integral/@p entry>.
      std::vector<double>
      values_along(const Stiffness   &body,
                   const std::string &expression,
                   const std::string &entry)
      {
        AssertThrow(!dealii::Utilities::trim(expression).empty(),
                    ExcMessage("<Boundary integral/" + entry +
                               "> is empty. Give a function of x, y, z (y "
                               "up, the fault at x = 0, the depth -y), e.g. "
                               "a number."));
        FunctionParser<3> f(1);
        try
          {
            f.initialize("x,y,z",
                         expression,
                         {{"pi", M_PI}, {"year", year}},
                         false);
          }
        catch (const ExceptionBase &e)
          {
            AssertThrow(false,
                        ExcMessage("<Boundary integral/" + entry + "> = <" +
                                   expression +
                                   "> is not a function of x, y, z: " +
                                   Utilities::message_of(e)));
          }
        std::vector<double> v;
        for (unsigned int i = 0; i < body.size(); ++i)
          {
            double x = 0, y = 0;
            body.position(body.depth(i), x, y);
            const double value = f.value(Point<3>(x, y, 0.));
            AssertThrow(std::isfinite(value),
                        ExcMessage("<Boundary integral/" + entry +
                                   "> is not finite at the depth " +
                                   std::to_string(body.depth(i)) + " m."));
            v.push_back(value);
          }
        return v;
      }
    } // namespace



    void
    Settings::read_anisotropic_moduli(ParameterHandler &prm)
    {
      // An anisotropic first material: the antiplane problem's moduli in
      // the model's frame (x across the fault, y up, the motion along z):
      // sigma_xz = C55 u,x + C45 u,y, sigma_yz = C45 u,x + C44 u,y. The
      // motion along z stays apart from the in-plane motion only where the
      // model plane is a plane of mirror symmetry, and the fault and the
      // free surface keep their right angle under the map to an isotropic
      // body only where C45 = 0.
      const std::vector<std::string> names =
        Utilities::split_list(prm.get("Names"));
      const Material::AnisotropicEntries entries =
        Material::read_anisotropic_entries(prm, names);
      // (The first material's factors: the body is that material.)
      for (const std::string entry : {"Stiffness factor", "Density factor"})
        {
          const auto fields = Utilities::split_fields(prm.get(entry));
          const auto first =
            fields.empty() ? std::string() : dealii::Utilities::trim(fields[0]);
          char        *end   = nullptr;
          const double value = std::strtod(first.c_str(), &end);
          AssertThrow(first.empty() || (end && *end == '\0' && value == 1),
                      ExcMessage("<Material/" + entry +
                                 "> = " + prm.get(entry) +
                                 ": the boundary-integral method needs a "
                                 "homogeneous body (its stiffness comes "
                                 "from the first material alone). Allowed: "
                                 "1 for the first material."));
        }
      if (entries.symmetry.empty() ||
          entries.symmetry[0] == Material::Symmetry::isotropic)
        return;
      anisotropic                       = true;
      const std::string           which = " of material 0 (" + names[0] + ")";
      const Material::VoigtMatrix c =
        Material::anisotropic_stiffness(entries, 0, which);
      AssertThrow(Material::model_plane_is_mirror_plane(c),
                  ExcMessage("Material" + which.substr(12) +
                             " is anisotropic, and in the model's frame "
                             "(after <Material/Material axes>) its tensor "
                             "couples the antiplane motion (along z) to the "
                             "in-plane one: the antiplane problem of the "
                             "boundary-integral method needs the plane z = "
                             "0 to be a plane of mirror symmetry (C14 = C15 "
                             "= C24 = C25 = C46 = C56 = 0). Allowed: axes "
                             "that keep it one."));
      const double C44 = c[3][3], C55 = c[4][4], C45 = c[3][4];
      AssertThrow(std::abs(C45) <= 1e-9 * std::max(C44, C55),
                  ExcMessage("Material" + which.substr(12) +
                             " has C45 = " + number(C45) +
                             " Pa in the model's frame: its antiplane shear "
                             "is oblique to the fault and the free surface, "
                             "which the boundary-integral method's half-space "
                             "cannot take. Allowed: material axes with C45 = "
                             "0 (a symmetry axis along x, y or z)."));
      shear_modulus          = C55;
      vertical_shear_modulus = C44;
    }



    Settings::Settings(ParameterHandler &prm)
    {
      test_mode        = prm.get_bool("Test mode");
      output_directory = prm.get("Output directory");

      // The medium.
      prm.enter_subsection("Material");
      if (prm.get("Parametrization") == "wave speeds")
        shear_modulus = first_material_value(prm, "Density") *
                        std::pow(first_material_value(prm, "S-wave speed"), 2);
      else
        shear_modulus =
          first_material_value(prm, "Young's modulus") /
          (2 * (1 + first_material_value(prm, "Poisson's ratio")));
      vertical_shear_modulus = shear_modulus;
      density                = first_material_value(prm, "Density");
      // (Lame's first constant: only the plane-strain body needs it, which
      // checks it; the antiplane problem does not read it.)
      try
        {
          if (prm.get("Parametrization") == "wave speeds")
            lambda =
              density * std::pow(first_material_value(prm, "P-wave speed"), 2) -
              2 * shear_modulus;
          else
            {
              const double nu = first_material_value(prm, "Poisson's ratio");
              lambda          = 2 * shear_modulus * nu / (1 - 2 * nu);
            }
        }
      catch (const ExceptionBase &)
        {
          lambda = std::nan("");
        }
      read_anisotropic_moduli(prm);
      prm.leave_subsection();

      // The friction law, the damping and the fault's outputs.
      prm.enter_subsection("Fault");
      law      = Friction::create(prm);
      law_name = prm.get("Friction law");
      // 'auto': sqrt(rho mu) / 2 with mu the modulus across the fault (C55
      // for an anisotropic material).
      radiation_damping =
        Fault::read_radiation_damping(prm.get("Radiation damping"));
      if (radiation_damping < 0)
        radiation_damping = 0.5 * std::sqrt(density * shear_modulus);
      AssertThrow(law->has_state_rate(),
                  ExcMessage("<Fault/Friction law> = " + law_name +
                             " gives no rate of change of its state, which "
                             "the boundary-integral method integrates. "
                             "Allowed with <Method> = boundary integral: " +
                             Friction::laws_with_state_rate() + "."));
      prm.enter_subsection("Output");
      events.parse_parameters(prm);
      sampling.event_rate = prm.get_double("Event slip rate");
      stations = Utilities::parse_named_points<2>(prm.get("Stations"),
                                                  "Fault/Output/Stations");
      prm.leave_subsection();
      prm.leave_subsection();

      // The clock.
      prm.enter_subsection("Time integration");
      end_time   = prm.get_double("End time");
      first_step = prm.get_double("Time step");
      AssertThrow(end_time > 0 && std::isfinite(end_time),
                  ExcMessage("<Time integration/End time> must be > 0 (s)."));
      AssertThrow(first_step > 0 && std::isfinite(first_step),
                  ExcMessage("<Time integration/Time step> (the first step "
                             "the boundary-integral method tries) must be "
                             "> 0 (s)."));
      prm.enter_subsection("Step controller");
      integrator.minimum_step   = prm.get_double("Minimum time step");
      integrator.maximum_step   = prm.get_double("Maximum time step");
      integrator.maximum_growth = prm.get_double("Maximum growth factor");
      prm.leave_subsection();
      prm.leave_subsection();

      // The fault.
      prm.enter_subsection("Boundary integral");
      geometry     = prm.get("Geometry");
      dip          = prm.get_double("Dip");
      thrust       = prm.get("Sense of slip") == "thrust";
      stiffness    = prm.get("Stiffness");
      fe_degree    = prm.get_integer("Finite-element degree");
      domain_size  = prm.get_double("Domain size");
      cell_growth  = prm.get_double("Cell growth factor");
      fault_depth  = prm.get_double("Fault depth");
      element_size = prm.get_double("Element size");
      plate_rate   = prm.get_double("Plate rate");
      AssertThrow(std::isfinite(plate_rate) && plate_rate > 0,
                  ExcMessage("<Boundary integral/Plate rate> must be > 0 "
                             "(m/s)."));
      surface_stations =
        Utilities::parse_named_points<2>(prm.get("Surface stations"),
                                         "Boundary integral/Surface stations");
      for (const auto &[name, point] : surface_stations)
        AssertThrow(point[1] == 0 && std::isfinite(point[0]),
                    ExcMessage("The surface station <" + name +
                               "> of <Boundary integral/Surface stations> "
                               "has y = " +
                               number(point[1]) +
                               ", but it must lie on the surface: 'name: x, "
                               "0'."));
      normal_stress                 = prm.get("Normal stress");
      initial_shear_stress          = prm.get("Initial shear stress");
      integrator.relative_tolerance = prm.get_double("Relative tolerance");
      absolute_tolerance            = prm.get_double("Absolute tolerance");
      AssertThrow(integrator.relative_tolerance > 0 &&
                    integrator.relative_tolerance < 1 && absolute_tolerance > 0,
                  ExcMessage("<Boundary integral/Relative tolerance> must lie "
                             "in (0, 1) and <Absolute tolerance> be > 0."));
      sampling.rate_change     = prm.get_double("Sampling slip rate change");
      sampling.interval        = prm.get_double("Sampling interval");
      sampling.profile_between = prm.get_double("Profile interval between "
                                                "events");
      sampling.profile_during  = prm.get_double("Profile interval during "
                                                "events");
      fully_dynamic            = prm.get("Events") == "fully dynamic";
      dynamic_above            = prm.get_double("Dynamic above");
      quasi_dynamic_below      = prm.get_double("Quasi-dynamic below");
      courant                  = prm.get_double("Courant number");
      kelvin_voigt             = prm.get_double("Kelvin-Voigt damping");
      prm.leave_subsection();
      if (fully_dynamic)
        {
          AssertThrow(geometry == "antiplane half-space" &&
                        stiffness == "finite elements",
                      ExcMessage("<Boundary integral/Events> = fully dynamic "
                                 "needs the meshed antiplane body: "
                                 "<Geometry> = antiplane half-space and "
                                 "<Stiffness> = finite elements."));
          AssertThrow(quasi_dynamic_below > 0 &&
                        quasi_dynamic_below < dynamic_above,
                      ExcMessage("<Boundary integral/Quasi-dynamic below> "
                                 "is " +
                                 number(quasi_dynamic_below) +
                                 " m/s and <Dynamic above> " +
                                 number(dynamic_above) +
                                 " m/s, but they must satisfy 0 < <Quasi-"
                                 "dynamic below> < <Dynamic above>: a "
                                 "dynamic phase that ended would start "
                                 "again at once."));
          AssertThrow(courant > 0 && courant <= 1,
                      ExcMessage("<Boundary integral/Courant number> is " +
                                 number(courant) +
                                 ", but it must lie in (0, 1]."));
          AssertThrow(kelvin_voigt >= 0 && kelvin_voigt <= 1,
                      ExcMessage("<Boundary integral/Kelvin-Voigt damping> "
                                 "is " +
                                 number(kelvin_voigt) +
                                 ", but it must lie in [0, 1] (time steps)."));
          AssertThrow(courant * std::sqrt(1 + 2 * kelvin_voigt) <= 1,
                      ExcMessage("<Boundary integral/Courant number> = " +
                                 number(courant) +
                                 " with <Kelvin-Voigt damping> = " +
                                 number(kelvin_voigt) +
                                 " is unstable: the damping shortens the "
                                 "stable step by sqrt(1 + 2 damping), so the "
                                 "Courant number times that must be at most "
                                 "1."));
        }
      if (geometry == "antiplane half-space")
        {
          AssertThrow(dip == 90,
                      ExcMessage("<Boundary integral/Dip> is " + number(dip) +
                                 ", but the antiplane half-space's fault is "
                                 "vertical: 90. A dipping fault needs "
                                 "<Geometry> = plane strain half-space."));
          AssertThrow(surface_stations.empty(),
                      ExcMessage("<Boundary integral/Surface stations> are "
                                 "written with <Geometry> = plane strain "
                                 "half-space only; leave it empty with the "
                                 "antiplane half-space."));
        }
      else
        {
          AssertThrow(stiffness == "finite elements",
                      ExcMessage("<Boundary integral/Geometry> = plane "
                                 "strain half-space takes its stiffness from "
                                 "finite elements: set <Stiffness> = finite "
                                 "elements (there is no Green's function of "
                                 "it in rupture)."));
          AssertThrow(!anisotropic,
                      ExcMessage("<Boundary integral/Geometry> = plane "
                                 "strain half-space takes an isotropic body: "
                                 "the first material must be isotropic "
                                 "(<Material/Symmetry>)."));
          AssertThrow(std::isfinite(dip) && dip >= 10 && dip <= 90,
                      ExcMessage("<Boundary integral/Dip> is " + number(dip) +
                                 ", but it must lie between 10 and 90 "
                                 "(degrees from the horizontal)."));
          AssertThrow(std::isfinite(lambda) &&
                        3 * lambda + 2 * shear_modulus > 0,
                      ExcMessage("<Material>: the plane-strain body needs "
                                 "Poisson's ratio in (-1, 0.5) (a P-wave "
                                 "speed above sqrt(4/3) times the S-wave "
                                 "speed)."));
        }
      // (The stations, before the body's stiffness is computed.)
      for (const auto &[name, point] : stations)
        station_distance(name, point, dip, fault_depth);
      for (const auto &[name, point] : surface_stations)
        {
          AssertThrow(std::abs(point[0]) < domain_size,
                      ExcMessage("The surface station <" + name +
                                 "> of <Boundary integral/Surface stations> "
                                 "is at x = " +
                                 number(point[0]) +
                                 " m, but the meshed surface reaches to "
                                 "+-<Domain size> = " +
                                 number(domain_size) + " m."));
          for (const auto &fault_station : stations)
            AssertThrow(fault_station.first != name,
                        ExcMessage("The surface station <" + name +
                                   "> has the name of a station of "
                                   "<Fault/Output/Stations>: both would "
                                   "write " +
                                   name + ".dat. Give another name."));
        }
      AssertThrow(integrator.minimum_step > 0 &&
                    integrator.maximum_step >= integrator.minimum_step &&
                    integrator.maximum_growth > 1,
                  ExcMessage("<Time integration/Step controller>: the "
                             "minimum time step must be > 0, the maximum at "
                             "least the minimum, the growth factor > 1."));

      // The end: <Termination/Number of events> (the one criterion of
      // <Termination> that a cycle run of this method uses).
      prm.enter_subsection("Termination");
      max_events = prm.get_integer("Number of events");
      prm.leave_subsection();
      AssertThrow(max_events == 0 || events.enabled(),
                  ExcMessage("<Termination/Number of events> counts the "
                             "events of the event catalogue: set "
                             "<Fault/Output/Event catalogue> = true."));

      // Checkpoints.
      prm.enter_subsection("Checkpoint");
      checkpoint_steps   = prm.get_integer("Interval");
      checkpoint_minutes = prm.get_double("Wall-clock interval");
      prm.leave_subsection();
    }



    void
    Settings::fault_stresses(const Stiffness     &body,
                             std::vector<double> &sigma,
                             std::vector<double> &tau0) const
    {
      sigma = values_along(body, normal_stress, "Normal stress");
      tau0  = values_along(body, initial_shear_stress, "Initial shear stress");
      const double eta = radiation_damping;
      for (unsigned int i = 0; i < body.size(); ++i)
        {
          AssertThrow(sigma[i] > 0,
                      ExcMessage("<Boundary integral/Normal stress> is " +
                                 number(sigma[i]) + " Pa at the depth " +
                                 number(body.depth(i)) +
                                 " m, but it must be > 0 (compression)."));
          AssertThrow(tau0[i] - eta * plate_rate > 0,
                      ExcMessage("<Boundary integral/Initial shear stress> "
                                 "is " +
                                 number(tau0[i]) + " Pa at the depth " +
                                 number(body.depth(i)) +
                                 " m, but it must exceed eta V_p = " +
                                 number(eta * plate_rate) +
                                 " Pa, so that the fault slips at V_p."));
        }
    }
  } // namespace BoundaryIntegral
} // namespace rupture
