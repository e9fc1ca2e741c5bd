#include <levelsinter/geometry/power_cells.h>

#include <limits>

namespace levelsinter
{
  template <int dim>
  PowerCells<dim>::PowerCells(const std::vector<std::vector<double>> &particles)
  {
    for (const auto &p : particles)
      {
        Point<dim> c;
        for (unsigned int d = 0; d < dim; ++d)
          c[d] = p[d];
        centre.push_back(c);
        squared_radius.push_back(p[dim] * p[dim]);
      }
  }

  template <int dim>
  unsigned int
  PowerCells<dim>::owner(const Point<dim>                &x,
                         const std::vector<unsigned int> &near) const
  {
    unsigned int best = near[0];
    for (unsigned int k = 1; k < near.size(); ++k)
      if (power(x, near[k]) < power(x, best))
        best = near[k];
    return best;
  }

  template <int dim>
  unsigned int
  PowerCells<dim>::owner(const Point<dim> &x) const
  {
    unsigned int best = 0;
    for (unsigned int i = 1; i < centre.size(); ++i)
      if (power(x, i) < power(x, best))
        best = i;
    return best;
  }

  template <int dim>
  void
  PowerCells<dim>::candidates(const Point<dim>          &x,
                              const double               rho,
                              std::vector<unsigned int> &result) const
  {
    result.clear();
    const unsigned int best    = owner(x);
    const double       p_best  = power(x, best);
    result.push_back(best);
    // p_j - p_best is affine with gradient 2 (c_best - c_j): within rho of
    // x it drops at most 2 |c_j - c_best| rho below its value at x.
    for (unsigned int j = 0; j < centre.size(); ++j)
      if (j != best &&
          power(x, j) - p_best <= 2 * centre[j].distance(centre[best]) * rho)
        result.push_back(j);
  }

  template class PowerCells<2>;
  template class PowerCells<3>;
} // namespace levelsinter
