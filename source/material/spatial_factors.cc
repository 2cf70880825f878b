#include <rupture/base/utilities.h>
#include <rupture/material/spatial_factors.h>

#include <deal.II/base/mpi.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/mapping_q1.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <sstream>

namespace rupture
{
  namespace Material
  {
    bool
    read_number(const std::string &text, double &value)
    {
      const auto first = text.find_first_not_of(" \t");
      if (first == std::string::npos)
        return false;
      const auto        last    = text.find_last_not_of(" \t");
      const std::string trimmed = text.substr(first, last - first + 1);
      char             *end     = nullptr;
      const double      x       = std::strtod(trimmed.c_str(), &end);
      if (end != trimmed.c_str() + trimmed.size())
        return false;
      value = x;
      return true;
    }



    void
    SpatialFactors::parse(ParameterHandler               &prm,
                          const std::vector<std::string> &material_names)
    {
      names                = material_names;
      const unsigned int n = names.size();
      for (const std::string entry : {"Stiffness factor", "Density factor"})
        {
          std::vector<std::string> fields =
            Utilities::split_fields(prm.get(entry));
          AssertThrow(fields.size() == 1 || fields.size() == n,
                      ExcMessage("The entry <Material/" + entry + "> has " +
                                 std::to_string(fields.size()) +
                                 " fields separated by ';', but <Material/"
                                 "Names> lists " +
                                 std::to_string(n) +
                                 " materials. Give one function of x, y, z "
                                 "per material, or a single one for all."));
          if (fields.size() == 1)
            fields.assign(n, fields[0]);
          auto &functions =
            (entry == std::string("Stiffness factor") ? stiffness_functions :
                                                        density_functions);
          auto &numbers =
            (entry == std::string("Stiffness factor") ? stiffness_numbers :
                                                        density_numbers);
          functions.clear();
          numbers.clear();
          for (unsigned int i = 0; i < n; ++i)
            {
              const std::string which = "<Material/" + entry +
                                        "> of material " + std::to_string(i) +
                                        " (" + names[i] + ")";
              double value = 1;
              if (fields[i].empty() || read_number(fields[i], value))
                {
                  AssertThrow(std::isfinite(value) && value > 0 && value < 1e10,
                              ExcMessage(which + " is " + fields[i] +
                                         ". Allowed: a positive number below "
                                         "1e10, or a function of x, y, z "
                                         "that is positive on the material's "
                                         "cells."));
                  functions.emplace_back();
                  numbers.push_back(value);
                }
              else
                {
                  functions.push_back(Utilities::parse_function<3>(
                    fields[i], 1, "Material/" + entry, "x,y,z"));
                  numbers.push_back(1.);
                }
            }
        }
    }



    bool
    SpatialFactors::varies() const
    {
      for (const auto *list : {&stiffness_functions, &density_functions})
        for (const auto &f : *list)
          if (f)
            return true;
      return false;
    }



    double
    SpatialFactors::constant_stiffness(const unsigned int material) const
    {
      return stiffness_numbers[material];
    }



    double
    SpatialFactors::constant_density(const unsigned int material) const
    {
      return density_numbers[material];
    }



    template <int dim>
    double
    SpatialFactors::stiffness(const types::material_id material,
                              const Point<dim>        &p) const
    {
      const auto &f = stiffness_functions[material];
      return f ? f->value(padded(p)) : 1.;
    }



    template <int dim>
    double
    SpatialFactors::density(const types::material_id material,
                            const Point<dim>        &p) const
    {
      const auto &f = density_functions[material];
      return f ? f->value(padded(p)) : 1.;
    }



    template <int dim>
    std::vector<Point<dim>>
    check_points(const typename Triangulation<dim>::active_cell_iterator &cell,
                 const unsigned int degree)
    {
      const MappingQ1<dim>     mapping;
      const QGauss<dim>        gauss(degree + 1);
      const QGaussLobatto<dim> lobatto(degree + 1);
      // (The Gauss-Lobatto points include the vertices.)
      std::vector<Point<dim>> points;
      for (const Quadrature<dim> *q :
           {static_cast<const Quadrature<dim> *>(&gauss),
            static_cast<const Quadrature<dim> *>(&lobatto)})
        for (const Point<dim> &xi : q->get_points())
          points.push_back(mapping.transform_unit_to_real_cell(cell, xi));
      // The centre: the stress output's constants. (The absorbing
      // boundaries' impedance takes the faces' Gauss-Lobatto points, among
      // the cell's.)
      points.push_back(cell->center());
      return points;
    }



    template <int dim>
    std::vector<double>
    SpatialFactors::check(const Triangulation<dim> &mesh,
                          const unsigned int        degree,
                          const MPI_Comm            communicator) const
    {
      std::vector<double> largest(names.size(), 1.);
      if (!varies())
        return largest;
      std::fill(largest.begin(), largest.end(), 0.);
      std::string error;
      for (const auto &cell : mesh.active_cell_iterators())
        if (cell->is_locally_owned() && error.empty())
          {
            const types::material_id id = cell->material_id();
            if (id >= names.size())
              continue; // (reported by the material check)
            const std::vector<Point<dim>> points =
              check_points<dim>(cell, degree);
            for (const Point<dim> &p : points)
              {
                const double s = stiffness(id, p), r = density(id, p);
                for (const auto &[value, entry] :
                     {std::make_pair(s, "Stiffness factor"),
                      std::make_pair(r, "Density factor")})
                  if (!(std::isfinite(value) && value > 0 && value < 1e10) &&
                      error.empty())
                    {
                      std::ostringstream message;
                      message << "<Material/" << entry << "> of material " << id
                              << " (" << names[id] << ") is " << value
                              << " at (" << p
                              << "), a point of its cells. Allowed: "
                                 "functions of x, y, z that are positive "
                                 "and below 1e10 on the material's cells.";
                      error = message.str();
                    }
                if (error.empty())
                  largest[id] = std::max(largest[id], std::sqrt(s / r));
              }
          }
      Utilities::throw_if_any(error, communicator);
      for (double &x : largest)
        x = dealii::Utilities::MPI::max(x, communicator);
      return largest;
    }



#define RUPTURE_INSTANTIATE(dim)                                            \
  template std::vector<Point<dim>> check_points<dim>(                       \
    const typename Triangulation<dim>::active_cell_iterator &,              \
    const unsigned int);                                                    \
  template double SpatialFactors::stiffness<dim>(const types::material_id,  \
                                                 const Point<dim> &) const; \
  template double SpatialFactors::density<dim>(const types::material_id,    \
                                               const Point<dim> &) const;   \
  template std::vector<double> SpatialFactors::check<dim>(                  \
    const Triangulation<dim> &, const unsigned int, const MPI_Comm) const;
    RUPTURE_INSTANTIATE(2)
    RUPTURE_INSTANTIATE(3)
#undef RUPTURE_INSTANTIATE
  } // namespace Material
} // namespace rupture
