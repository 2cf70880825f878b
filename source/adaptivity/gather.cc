#include <rupture/adaptivity/gather.h>

#include <deal.II/base/mpi.h>

namespace rupture
{
  namespace Adaptivity
  {
    namespace
    {
      /// Every process's flat vectors of @p width numbers per item, on
      /// every process, as one flat vector.
      std::vector<double>
      all_gather_flat(const std::vector<double> &mine,
                      const MPI_Comm             communicator,
                      const unsigned int         width)
      {
        std::vector<double> all;
        for (const auto &from :
             dealii::Utilities::MPI::all_gather(communicator, mine))
          all.insert(all.end(),
                     from.begin(),
                     from.begin() + (from.size() / width) * width);
        return all;
      }
    } // namespace



    template <int dim>
    std::vector<dealii::Point<dim>>
    all_gather(const std::vector<dealii::Point<dim>> &mine,
               const MPI_Comm                         communicator)
    {
      std::vector<double> flat;
      for (const auto &p : mine)
        for (unsigned int d = 0; d < dim; ++d)
          flat.push_back(p[d]);
      flat = all_gather_flat(flat, communicator, dim);
      std::vector<dealii::Point<dim>> all(flat.size() / dim);
      for (unsigned int i = 0; i < all.size(); ++i)
        for (unsigned int d = 0; d < dim; ++d)
          all[i][d] = flat[i * dim + d];
      return all;
    }



    template <int dim>
    std::vector<std::pair<dealii::Point<dim>, double>>
    all_gather(const std::vector<std::pair<dealii::Point<dim>, double>> &mine,
               const MPI_Comm communicator)
    {
      std::vector<double> flat;
      for (const auto &p : mine)
        {
          for (unsigned int d = 0; d < dim; ++d)
            flat.push_back(p.first[d]);
          flat.push_back(p.second);
        }
      flat = all_gather_flat(flat, communicator, dim + 1);
      std::vector<std::pair<dealii::Point<dim>, double>> all(flat.size() /
                                                             (dim + 1));
      for (unsigned int i = 0; i < all.size(); ++i)
        {
          for (unsigned int d = 0; d < dim; ++d)
            all[i].first[d] = flat[i * (dim + 1) + d];
          all[i].second = flat[i * (dim + 1) + dim];
        }
      return all;
    }



    template std::vector<dealii::Point<2>>
    all_gather(const std::vector<dealii::Point<2>> &, const MPI_Comm);
    template std::vector<dealii::Point<3>>
    all_gather(const std::vector<dealii::Point<3>> &, const MPI_Comm);
    template std::vector<std::pair<dealii::Point<2>, double>>
    all_gather(const std::vector<std::pair<dealii::Point<2>, double>> &,
               const MPI_Comm);
    template std::vector<std::pair<dealii::Point<3>, double>>
    all_gather(const std::vector<std::pair<dealii::Point<3>, double>> &,
               const MPI_Comm);
  } // namespace Adaptivity
} // namespace rupture
