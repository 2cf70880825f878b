// A fully dynamic phase of an antiplane cycle run: central differences on
// the meshed body beside the fault, friction at the fault's nodes.

#include <rupture/boundary_integral/antiplane_body.h>
#include <rupture/boundary_integral/antiplane_dynamics.h>
#include <rupture/boundary_integral/quasi_dynamic_fault.h>
#include <rupture/boundary_integral/text.h>

#include <deal.II/base/exceptions.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/fe_values.h>

#include <algorithm>
#include <cmath>

namespace rupture
{
  namespace BoundaryIntegral
  {
    using namespace dealii;

    AntiplaneDynamics::AntiplaneDynamics(
      std::shared_ptr<const AntiplaneBody> body_,
      const QuasiDynamicFault             &fault,
      const Friction::Interface           &law,
      const double                         density,
      const double                         plate_rate,
      const double                         courant,
      const double                         damping)
      : body(std::move(body_))
      , fault(fault)
      , law(law)
      , plate_rate(plate_rate)
    {
      AssertThrow(std::isfinite(density) && density > 0,
                  ExcMessage("The fully dynamic phases need the density "
                             "(<Material/Density>) > 0; it is " +
                             number(density) + "."));
      AssertThrow(std::isfinite(courant) && courant > 0 && courant <= 1,
                  ExcMessage("<Boundary integral/Courant number> is " +
                             number(courant) + ", but it must lie in (0, 1]."));
      AssertThrow(std::isfinite(damping) && damping >= 0 && damping <= 1 &&
                    courant * std::sqrt(1 + 2 * damping) <= 1,
                  ExcMessage("<Boundary integral/Kelvin-Voigt damping> is " +
                             number(damping) + " with the Courant number " +
                             number(courant) +
                             ": it must lie in [0, 1] (time steps), and the "
                             "Courant number times sqrt(1 + 2 damping) be at "
                             "most 1 (stability)."));
      const types::global_dof_index n_dofs = body->dofs.n_dofs();
      const unsigned int            N      = body->fault_dof.size();
      AssertThrow(N == fault.size(), ExcInternalError());

      // The masses lumped on the Gauss-Lobatto nodes (the element's nodes:
      // the quadrature's points), the dashpots of the far side (x = width,
      // the modulus C55 across it) and of the bottom (C44).
      mass.reinit(n_dofs);
      dashpot.reinit(n_dofs);
      {
        const unsigned int                   p = body->fe.degree;
        const QGaussLobatto<2>               quadrature(p + 1);
        const QGaussLobatto<1>               face_quadrature(p + 1);
        FEValues<2>                          values(body->fe,
                           quadrature,
                           update_values | update_JxW_values);
        FEFaceValues<2>                      face_values(body->fe,
                                    face_quadrature,
                                    update_values | update_JxW_values);
        const unsigned int                   n = body->fe.n_dofs_per_cell();
        std::vector<types::global_dof_index> indices(n);
        // (The sponge: cells more than four times the fault's are too
        // coarse for the waves of an event, which they would reflect back
        // to the fault; mass-proportional damping of rate c / size there,
        // ramped in between four and eight times.)
        const double speed =
          std::sqrt(std::max(body->C55, body->C44) / density);
        for (const auto &cell : body->dofs.active_cell_iterators())
          {
            values.reinit(cell);
            cell->get_dof_indices(indices);
            const double size = std::max(cell->extent_in_direction(0),
                                         cell->extent_in_direction(1));
            const double ramp = std::clamp((size / body->h - 4) / 4, 0., 1.);
            for (unsigned int q = 0; q < quadrature.size(); ++q)
              for (unsigned int a = 0; a < n; ++a)
                {
                  const double m =
                    density * values.shape_value(a, q) * values.JxW(q);
                  mass[indices[a]] += m;
                  dashpot[indices[a]] += ramp * speed / size * m;
                }
            for (const unsigned int f : cell->face_indices())
              if (cell->face(f)->at_boundary() &&
                  (cell->face(f)->boundary_id() == 1 ||
                   cell->face(f)->boundary_id() == 2))
                {
                  const double modulus =
                    cell->face(f)->boundary_id() == 1 ? body->C55 : body->C44;
                  face_values.reinit(cell, f);
                  for (unsigned int q = 0; q < face_quadrature.size(); ++q)
                    for (unsigned int a = 0; a < n; ++a)
                      dashpot[indices[a]] += std::sqrt(density * modulus) *
                                             face_values.shape_value(a, q) *
                                             face_values.JxW(q);
                }
          }
      }

      // Held: the fault below W (the unknowns at x = 0 that are not the
      // fault's elements).
      fault_index.assign(n_dofs, numbers::invalid_unsigned_int);
      for (unsigned int i = 0; i < N; ++i)
        fault_index[body->fault_dof[i]] = i;
      fixed.assign(n_dofs, false);
      for (types::global_dof_index i = 0; i < n_dofs; ++i)
        fixed[i] = body->support[i][0] < 1e-9 * body->h &&
                   fault_index[i] == numbers::invalid_unsigned_int;

      // The stable step: the largest eigenvalue of M^-1 A on the unknowns
      // that move, by power iteration (its Rayleigh quotient converges to
      // it from below: 10 % added).
      Vector<double> x(n_dofs), Ax(n_dofs);
      for (types::global_dof_index i = 0; i < n_dofs; ++i)
        x[i] = fixed[i] ? 0. : std::sin(1.7 * double(i) + 0.3);
      double lambda = 0;
      for (unsigned int k = 0; k < 200; ++k)
        {
          body->A.vmult(Ax, x);
          double xAx = 0, xMx = 0;
          for (types::global_dof_index i = 0; i < n_dofs; ++i)
            if (!fixed[i])
              {
                xAx += x[i] * Ax[i];
                xMx += x[i] * mass[i] * x[i];
              }
          lambda     = xAx / xMx;
          double top = 0;
          for (types::global_dof_index i = 0; i < n_dofs; ++i)
            {
              x[i] = fixed[i] ? 0. : Ax[i] / mass[i];
              top  = std::max(top, std::abs(x[i]));
            }
          x /= top;
        }
      AssertThrow(std::isfinite(lambda) && lambda > 0, ExcInternalError());
      dt        = courant * 2 / std::sqrt(1.1 * lambda);
      viscosity = damping * dt;

      u.reinit(n_dofs);
      v.reinit(n_dofs);
      hold.reinit(n_dofs);
      force.reinit(n_dofs);
      rate.assign(N, 0.);
      traction.assign(N, 0.);
    }



    void
    AntiplaneDynamics::start(const double t0, const std::vector<double> &y)
    {
      const unsigned int N = fault.size();
      t                    = t0;
      // The static fields of the slip and of the slip rates: u = (s - V_p
      // t) / 2 and v = (V - V_p) / 2 at the fault, 0 at the other held
      // unknowns.
      u = 0;
      v = 0;
      for (unsigned int i = 0; i < N; ++i)
        {
          u[body->fault_dof[i]] = 0.5 * (y[i] - plate_rate * t);
          v[body->fault_dof[i]] =
            0.5 * (fault.signed_slip_rate(i) - plate_rate);
        }
      body->solve_static(u);
      body->solve_static(v);
      // The force that held the far side and the bottom.
      body->A.vmult(force, u);
      hold = 0;
      for (types::global_dof_index i = 0; i < u.size(); ++i)
        if (body->held[i] && !fixed[i] &&
            fault_index[i] == numbers::invalid_unsigned_int)
          hold[i] = force[i];
      states.resize(N);
      for (unsigned int i = 0; i < N; ++i)
        fault.unpack_state(i, y, states[i]);
      recorded      = y;
      recorded_time = t;
      for (unsigned int i = 0; i < N; ++i)
        {
          rate[i]     = fault.signed_slip_rate(i);
          traction[i] = fault.shear_stress(i);
        }
    }



    double
    AntiplaneDynamics::solve_rate(const unsigned int     i,
                                  const double           target,
                                  const double           guess,
                                  const Friction::State &state) const
    {
      const unsigned int dof = body->fault_dof[i];
      const double       Z   = mass[dof] / (2 * body->tributary[i] * dt);
      const double       p   = fault.initial_normal_stress(i);
      const Point<3>    &x   = fault.point(i);
      // h(m) = |T'| - 2 Z m - S(m) falls with the mean rate's size m.
      const auto h = [&](const double m, double &dh) {
        double       dS = 0, dp = 0;
        const double S = law.strength_at_rate(x, state, m, p, dS, dp);
        dh             = -2 * Z - dS;
        return target - 2 * Z * m - S;
      };
      double dh = 0;
      if (target == 0 || h(0., dh) <= 0)
        return 0;
      // (|T'| / 2Z brackets the root where the strength is not negative
      // there; the logarithmic law's can be: then the bracket grows.)
      double lo = 0, hi = target / (2 * Z);
      for (unsigned int k = 0; k < 400 && h(hi, dh) > 0; ++k)
        hi *= 2;
      double m = std::clamp(guess, 1e-3 * hi, hi);
      for (unsigned int iteration = 0; iteration < 200; ++iteration)
        {
          const double r = h(m, dh);
          if (r > 0)
            lo = m;
          else
            hi = m;
          if (r == 0 || hi - lo <= 1e-14 * hi)
            return m;
          double next = m - r / dh;
          if (!(next > lo && next < hi) || !std::isfinite(next))
            next = 0.5 * (lo + hi);
          if (std::abs(next - m) <= 1e-14 * std::max(m, 1e-300))
            return next;
          m = next;
        }
      return m;
    }



    void
    AntiplaneDynamics::step()
    {
      const unsigned int            N      = fault.size();
      const types::global_dof_index n_dofs = u.size();
      // (Kelvin-Voigt damping: the stress of the displacement and of the
      // velocity times the damping time.)
      if (viscosity > 0)
        {
          scratch = u;
          scratch.add(viscosity, v);
          body->A.vmult(force, scratch);
        }
      else
        body->A.vmult(force, u);
      // The bulk and the absorbing sides.
      for (types::global_dof_index i = 0; i < n_dofs; ++i)
        if (fixed[i])
          v[i] = 0;
        else if (fault_index[i] == numbers::invalid_unsigned_int)
          {
            const double c = 0.5 * dt * dashpot[i];
            v[i] = ((mass[i] - c) * v[i] + dt * (hold[i] - force[i])) /
                   (mass[i] + c);
          }
      // The fault: friction at t_k.
      recorded_time = t;
      for (unsigned int i = 0; i < N; ++i)
        {
          const types::global_dof_index dof = body->fault_dof[i];
          const double Z      = mass[dof] / (2 * body->tributary[i] * dt);
          const double before = 2 * v[dof] + plate_rate;
          // The traction at t_k is T' - 2 Z V_k with the mean rate
          // V_k = (V_- + W) / 2 and T' = tau + 2 Z V_-; friction holds at
          // V_k, of T''s sense: |T'| - 2 Z |V_k| = S(|V_k|). Any sense of W
          // (a node that stops or turns), V_k = 0 where S(0) holds T'.
          const double loaded = fault.initial_shear(i) -
                                force[dof] / body->tributary[i] +
                                2 * Z * before;
          const double sense = loaded < 0 ? -1. : 1.;
          const double mean =
            sense *
            solve_rate(i, std::abs(loaded), std::abs(before), states[i]);
          const double W = 2 * mean - before;
          traction[i]    = loaded - 2 * Z * mean;
          rate[i]        = mean;
          recorded[i]    = plate_rate * t + 2 * u[dof];
          fault.pack_state(i, states[i], recorded);
          v[dof] = 0.5 * (W - plate_rate);
          // The state over the step to t_k+1 at the rate W.
          Friction::State next;
          law.update_state(fault.point(i),
                           states[i],
                           std::abs(W) * dt,
                           dt,
                           std::abs(traction[i]),
                           next);
          states[i] = next;
        }
      u.add(dt, v);
      t += dt;
    }



    double
    AntiplaneDynamics::max_slip_rate() const
    {
      double largest = 0;
      for (const double V : rate)
        largest = std::max(largest, std::abs(V));
      return largest;
    }



  } // namespace BoundaryIntegral
} // namespace rupture
