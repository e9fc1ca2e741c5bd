#include <levelsinter/analysis/particle_centres.h>
#include <levelsinter/level_set/interface_measures.h>

#include <cmath>
#include <limits>

namespace levelsinter
{
  template <int dim>
  ParticleCentres<dim>::ParticleCentres(
    const std::vector<std::vector<double>> &particles,
    const DomainParameters                 &domain,
    const MPI_Comm                          comm)
    : power_cells(particles)
    , tolerance(0)
    , comm(comm)
  {
    for (const types::boundary_id id : domain.symmetry_planes)
      planes.emplace_back(id / 2,
                          id % 2 ? domain.upper_corner[id / 2] :
                                   domain.lower_corner[id / 2]);
    for (unsigned int d = 0; d < dim; ++d)
      tolerance = std::max(tolerance,
                           1e-9 * (domain.upper_corner[d] -
                                   domain.lower_corner[d]));
  }

  template <int dim>
  std::vector<Point<dim>>
  ParticleCentres<dim>::centroids(const LevelSetField<dim> &level_set) const
  {
    const auto               &centres = power_cells.centres();
    const unsigned int        n       = centres.size();
    std::vector<double>       volume(n, 0.);
    std::vector<double>       moment(n * dim, 0.);
    std::vector<unsigned int> near;
    interface_measures::RegionIntegrands<dim> integrands;
    integrands.solid_flags = update_JxW_values | update_quadrature_points;
    integrands.on_solid    = [&](const auto &cell, const auto &values) {
      power_cells.candidates(cell->center(), cell->diameter() / 2, near);
      for (const unsigned int q : values.quadrature_point_indices())
        {
          const Point<dim>  &x     = values.quadrature_point(q);
          const unsigned int owner = power_cells.owner(x, near);
          const double JxW = level_set.measure().JxW(values, q);
          volume[owner] += JxW;
          for (unsigned int d = 0; d < dim; ++d)
            moment[owner * dim + d] += JxW * x[d];
        }
    };
    interface_measures::integrate_regions(level_set, integrands);
    Utilities::MPI::sum(volume, comm, volume);
    Utilities::MPI::sum(moment, comm, moment);

    const double            nan = std::numeric_limits<double>::quiet_NaN();
    std::vector<Point<dim>> result(n);
    std::vector<bool>       known(n, false);
    for (unsigned int i = 0; i < n; ++i)
      if (volume[i] > 0)
        {
          known[i] = true;
          for (unsigned int d = 0; d < dim; ++d)
            result[i][d] = moment[i * dim + d] / volume[i];
          for (const auto &[axis, coordinate] : planes)
            if (std::abs(centres[i][axis] - coordinate) <= tolerance)
              result[i][axis] = coordinate;
        }
      else
        for (unsigned int d = 0; d < dim; ++d)
          result[i][d] = nan;
    // Mirror images, across up to dim planes (a corner image).
    const auto reflect = [](Point<dim>                             p,
                            const std::pair<unsigned int, double> &plane) {
      p[plane.first] = 2 * plane.second - p[plane.first];
      return p;
    };
    for (unsigned int pass = 0; pass < dim; ++pass)
      for (unsigned int i = 0; i < n; ++i)
        if (!known[i])
          for (const auto &plane : planes)
            for (unsigned int j = 0; j < n; ++j)
              if (known[j] && !known[i] &&
                  reflect(centres[i], plane).distance(centres[j]) <= tolerance)
                {
                  result[i] = reflect(result[j], plane);
                  known[i]  = true;
                }
    return result;
  }

  template <int dim>
  std::vector<std::string>
  ParticleCentres<dim>::column_names() const
  {
    if (power_cells.centres().size() == 2)
      return {"centre_distance", "centre_distance_change"};
    return {"centre_distance_change_mean"};
  }

  template <int dim>
  std::vector<double>
  ParticleCentres<dim>::measure(
    const LevelSetField<dim>                   &level_set,
    const std::vector<neck_measures::PairNeck> &necks)
  {
    const std::vector<Point<dim>> now = centroids(level_set);
    if (initial.empty())
      initial = now;
    const auto change = [&](const unsigned int i, const unsigned int j) {
      const double d0 = initial[i].distance(initial[j]);
      return (now[i].distance(now[j]) - d0) / d0;
    };
    if (now.size() == 2)
      return {now[0].distance(now[1]), change(0, 1)};
    double       sum      = 0;
    unsigned int contacts = 0;
    for (const auto &neck : necks)
      if (const double c = change(neck.i, neck.j);
          neck.contact && neck.radius > 0 && std::isfinite(c))
        {
          sum += c;
          ++contacts;
        }
    return {contacts > 0 ? sum / contacts :
                           std::numeric_limits<double>::quiet_NaN()};
  }

  template class ParticleCentres<2>;
  template class ParticleCentres<3>;
} // namespace levelsinter
