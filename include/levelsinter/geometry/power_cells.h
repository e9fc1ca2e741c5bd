#pragma once

#include <deal.II/base/point.h>

#include <cmath>
#include <vector>

namespace levelsinter
{
  using namespace dealii;

  /**
   * The power cells of the particles (x, y[, z], r): the points where
   * |x - c_i|^2 - r_i^2 is smallest for particle i (for two overlapping
   * balls the cell boundary is their radical plane). An Eulerian level set
   * carries no particle labels, so the analysis gives the solid in the
   * power cell of particle i to particle i (its centroid, its id in the
   * output). The grains of the grain-boundary mechanism are the same
   * cells of the moving grain centres (geometry/grain_boundaries.h).
   */
  template <int dim>
  class PowerCells
  {
  public:
    explicit PowerCells(const std::vector<std::vector<double>> &particles);

    /** The particle whose power cell holds @p x (the first of ties). */
    unsigned int
    owner(const Point<dim> &x) const;

    /** The owner of @p x among @p near. */
    unsigned int
    owner(const Point<dim> &x, const std::vector<unsigned int> &near) const;

    /**
     * The particles whose power may be smallest somewhere in the ball of
     * radius @p rho about @p x; owner(x) comes first.
     */
    void
    candidates(const Point<dim>          &x,
               const double               rho,
               std::vector<unsigned int> &result) const;

    const std::vector<Point<dim>> &
    centres() const
    {
      return centre;
    }

    /** The power |x - c_i|^2 - r_i^2 of @p x for particle @p i. */
    double
    power(const Point<dim> &x, const unsigned int i) const
    {
      return x.distance_square(centre[i]) - squared_radius[i];
    }

    /** r_i. */
    double
    radius(const unsigned int i) const
    {
      return std::sqrt(squared_radius[i]);
    }

  private:

    std::vector<Point<dim>> centre;
    std::vector<double>     squared_radius;
  };
} // namespace levelsinter
