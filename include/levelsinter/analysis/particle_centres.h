#pragma once

#include <deal.II/base/mpi.h>
#include <deal.II/base/point.h>

#include <boost/serialization/vector.hpp>

#include <levelsinter/analysis/neck.h>
#include <levelsinter/geometry/power_cells.h>
#include <levelsinter/level_set/level_set_field.h>
#include <levelsinter/scene/domain_parameters.h>

#include <string>
#include <vector>

namespace levelsinter
{
  /**
   * Particle centres and their approach (densification: the paper's Sect.
   * 2.1 defines it as the rate at which particle centres approach). An
   * Eulerian level set carries no particle labels and particles merge, so
   * the centre of particle i is defined as the centroid of the solid in its
   * power cell of the initial centres c_i and radii r_i (the points where
   * |x - c_i|^2 - r_i^2 is smallest; for two overlapping balls the cell
   * boundary is their radical plane), integrated with the sharp cut-cell
   * quadrature of interface_measures, point by point where a cell boundary
   * crosses a mesh cell. A rigid motion of the particles moves the centroids
   * with them; matter moved within a cell moves its centroid too (a neck
   * filled from the nearby surface draws the centroid towards the neck).
   *
   * With symmetry planes the scene is mirrored: a coordinate of a centre
   * that lies on a plane is the plane's (the particle is its own image), and
   * a particle with no solid in the domain whose mirror across a plane is a
   * listed particle gets the mirror of that particle's centroid.
   */
  template <int dim>
  class ParticleCentres
  {
  public:
    /** Rows (x, y[, z], r) as the scene parameters hold them. */
    ParticleCentres(const std::vector<std::vector<double>> &particles,
                    const DomainParameters                 &domain,
                    const MPI_Comm                          comm);

    /** The centroids; NaN for a particle with no solid. */
    std::vector<Point<dim>>
    centroids(const LevelSetField<dim> &level_set) const;

    /**
     * metrics.csv columns of measure(): for two particles centre_distance
     * and centre_distance_change; for more, centre_distance_change_mean.
     */
    std::vector<std::string>
    column_names() const;

    /**
     * The centroid distance of the pair and its change relative to the
     * distance at the first call, (d - d_0) / d_0 (negative: the centres
     * approach); for more than two particles the mean of that change over
     * the contacts of @p necks with a positive neck radius.
     */
    std::vector<double>
    measure(const LevelSetField<dim>                   &level_set,
            const std::vector<neck_measures::PairNeck> &necks);

    /** The reference centres (the first measure()) for a restart. */
    template <class Archive>
    void
    serialize(Archive &archive, const unsigned int)
    {
      archive &initial;
    }

  private:
    PowerCells<dim>                              power_cells;
    // (axis, coordinate) of each symmetry plane.
    std::vector<std::pair<unsigned int, double>> planes;
    double                                       tolerance;
    MPI_Comm                                     comm;
    std::vector<Point<dim>>                      initial;
  };
} // namespace levelsinter
