#include <deal.II/base/mpi.h>

#include <levelsinter/analysis/neck.h>
#include <levelsinter/analysis/packing_analysis.h>
#include <levelsinter/analysis/reference_shapes.h>
#include <levelsinter/level_set/cell_size.h>
#include <levelsinter/level_set/interface_measures.h>

#include <cmath>
#include <limits>

namespace levelsinter
{
  namespace
  {
    // Root-mean-square distance of the points from their mean along axis d.
    template <int dim>
    double
    spread(const std::vector<Point<dim>> &points, const unsigned int d)
    {
      double mean = 0, square = 0;
      for (const auto &p : points)
        mean += p[d] / points.size();
      for (const auto &p : points)
        square += (p[d] - mean) * (p[d] - mean) / points.size();
      return std::sqrt(square);
    }
  } // namespace

  template <int dim>
  PackingAnalysis<dim>::PackingAnalysis(const SceneParameters &scene,
                                        const MPI_Comm         comm)
    : particles(scene.geometry.particles_are_bodies() ?
                  scene.geometry.particles :
                  std::vector<std::vector<double>>())
    , power_cells(particles)
    , symmetry_boundaries(scene.domain.symmetry_planes)
    , comm(comm)
    , directory(scene.output.directory)
  {
    if (!particles.empty())
      centres = UnionOfBalls<dim>(particles).centres();
    Point<dim> lower, upper;
    const auto &analysis = scene.analysis;
    if (!analysis.control_lower_corner.empty())
      for (unsigned int d = 0; d < dim; ++d)
        {
          lower[d] = analysis.control_lower_corner[d];
          upper[d] = analysis.control_upper_corner[d];
        }
    else
      {
        // The centres' bounding box: for a lattice exactly a whole number
        // of unit cells, away from the free faces.
        bool has_volume = centres.size() >= 2;
        if (has_volume)
          {
            const BoundingBox<dim> box(centres);
            lower      = box.get_boundary_points().first;
            upper      = box.get_boundary_points().second;
            has_volume = box.volume() > 0;
          }
        if (!has_volume)
          for (unsigned int d = 0; d < dim; ++d)
            {
              lower[d] = scene.domain.lower_corner[d];
              upper[d] = scene.domain.upper_corner[d];
            }
      }
    window = BoundingBox<dim>(std::make_pair(lower, upper));

    for (const auto &c : centres)
      {
        bool inside = true;
        for (unsigned int d = 0; d < dim; ++d)
          inside = inside && c[d] > lower[d] + 1e-9 * (upper[d] - lower[d]) &&
                   c[d] < upper[d] - 1e-9 * (upper[d] - lower[d]);
        interior.push_back(inside);
        has_interior = has_interior || inside;
      }
    for (unsigned int d = 0; d < dim && centres.size() >= 2; ++d)
      if (spread(centres, d) > 0)
        shrinkage_axes.push_back(d);
    // Near misses: a gap below one cell of the band, where the interface
    // is drawn, which the mesh may join or not; fixed by the scene, so the
    // pairs are the same at every measure() and after a restart.
    pairs = neck_measures::neighbour_pairs(particles, scene.band_cell_size());
  }

  template <int dim>
  void
  PackingAnalysis<dim>::open_logs()
  {
    auto kept = [this](const unsigned int log) {
      return kept_rows ? std::optional<unsigned int>((*kept_rows)[log]) :
                         std::nullopt;
    };
    necks_log = std::make_unique<MetricsLog>(
      directory + "/necks.csv",
      std::vector<std::string>{
        "step", "time", "particle_i", "particle_j", "contact", "neck_radius",
        "gap"},
      comm,
      kept(0));
    std::vector<std::string> pore_columns = {
      "step", "time", "pore", "open", "volume", "area", "sphericity"};
    for (unsigned int d = 0; d < dim; ++d)
      pore_columns.push_back(std::string("centroid_") + "xyz"[d]);
    pores_log = std::make_unique<MetricsLog>(directory + "/pores.csv",
                                             pore_columns,
                                             comm,
                                             kept(1));
    events_log = std::make_unique<MetricsLog>(
      directory + "/pore_events.csv",
      std::vector<std::string>{"time", "step", "event", "pore", "volume"},
      comm,
      kept(2));
  }

  template <int dim>
  std::vector<std::string>
  PackingAnalysis<dim>::column_names() const
  {
    std::vector<std::string> names = {"relative_density",
                                      "open_porosity",
                                      "closed_porosity",
                                      "closed_pores",
                                      "closed_pore_volume",
                                      "sub_cell_pockets",
                                      "neck_min",
                                      "neck_mean",
                                      "neck_max",
                                      "contacts",
                                      "coordination_number",
                                      "near_misses",
                                      "near_misses_joined",
                                      "near_miss_gap_min"};
    if (has_interior)
      names.push_back("interior_coordination_number");
    for (const unsigned int d : shrinkage_axes)
      names.push_back(std::string("size_ratio_") + "xyz"[d]);
    return names;
  }

  template <int dim>
  typename PackingAnalysis<dim>::SolidMeasures
  PackingAnalysis<dim>::measure_solid(const LevelSetField<dim> &level_set) const
  {
    SolidMeasures result;
    const unsigned int          n = particles.size();
    std::vector<double>         volume(n, 0.);
    std::vector<Tensor<1, dim>> moment(n);
    for (const auto &cell : level_set.dof_handler().active_cell_iterators())
      if (cell->is_locally_owned() && window.point_inside(cell->center()))
        result.window_volume +=
          cell->measure() * level_set.measure().weight(cell->center());
    interface_measures::RegionIntegrands<dim> integrands;
    integrands.solid_flags = update_JxW_values | update_quadrature_points;
    integrands.on_solid    = [&](const auto &cell, const auto &values) {
      double cell_solid = 0;
      Tensor<1, dim> cell_moment;
      for (const unsigned int q : values.quadrature_point_indices())
        {
          const double JxW = level_set.measure().JxW(values, q);
          cell_solid += JxW;
          cell_moment += JxW * values.quadrature_point(q);
        }
      if (window.point_inside(cell->center()))
        result.window_solid += cell_solid;
      // Cells are small against particles: the cell centre decides.
      if (n > 0)
        {
          const unsigned int owner = power_cells.owner(cell->center());
          volume[owner] += cell_solid;
          moment[owner] += cell_moment;
        }
    };
    interface_measures::integrate_regions(level_set, integrands);
    result.window_volume = Utilities::MPI::sum(result.window_volume, comm);
    result.window_solid  = Utilities::MPI::sum(result.window_solid, comm);
    Utilities::MPI::sum(volume, comm, volume);
    for (unsigned int i = 0; i < n; ++i)
      {
        const Tensor<1, dim> m = Utilities::MPI::sum(moment[i], comm);
        result.centroids.push_back(
          volume[i] > 0 ? Point<dim>(m / volume[i]) : centres[i]);
      }
    return result;
  }

  template <int dim>
  std::vector<double>
  PackingAnalysis<dim>::measure(const unsigned int        step,
                                const double              t,
                                const LevelSetField<dim> &level_set)
  {
    const double nan = std::numeric_limits<double>::quiet_NaN();

    const SolidMeasures solid = measure_solid(level_set);
    const double relative_density =
      solid.window_volume > 0 ? solid.window_solid / solid.window_volume : nan;

    // Closed components smaller than one finest cell are sub-cell pockets
    // of the Q1 level set (at contacts and in crevices: median 0.03 h^3 in
    // the 154-particle packing), not pores the mesh resolves; they are
    // counted apart and neither tracked nor logged.
    const double cell_volume = std::pow(
      finest_cell_size(level_set.dof_handler().get_triangulation()), dim);
    last_pores.clear();
    unsigned int n_pockets = 0;
    for (const auto &pore : find_pores(level_set, symmetry_boundaries, window))
      if (pore.open || pore.volume >= cell_volume)
        last_pores.push_back(pore);
      else
        ++n_pockets;
    const std::vector<Pore<dim>> &pores = last_pores;
    std::vector<typename PoreTracker<dim>::Event> events;
    const std::vector<unsigned int> ids = tracker.update(pores, events);
    double closed_in_window = 0, closed_volume = 0;
    unsigned int n_closed = 0;
    for (const auto &pore : pores)
      if (!pore.open)
        {
          ++n_closed;
          closed_volume += pore.volume;
          closed_in_window += pore.volume_in_window;
        }
    const double closed_porosity =
      solid.window_volume > 0 ? closed_in_window / solid.window_volume : nan;

    neck_measures::measure_necks(level_set, particles, pairs);
    const auto  &necks    = pairs;
    double       neck_min = nan, neck_max = nan, neck_sum = 0, gap_min = nan;
    unsigned int contacts = 0, near_misses = 0, joined = 0;
    std::vector<unsigned int> coordination(particles.size(), 0);
    for (const auto &neck : necks)
      if (!neck.contact)
        {
          ++near_misses;
          joined += neck.radius > 0;
          gap_min = std::fmin(gap_min, neck.gap);
        }
      else if (neck.radius > 0)
        {
          neck_min = std::fmin(neck_min, neck.radius);
          neck_max = std::fmax(neck_max, neck.radius);
          neck_sum += neck.radius;
          ++contacts;
          ++coordination[neck.i];
          ++coordination[neck.j];
        }
    unsigned int interior_count = 0, interior_contacts = 0;
    for (unsigned int i = 0; i < particles.size(); ++i)
      if (interior[i])
        {
          ++interior_count;
          interior_contacts += coordination[i];
        }

    std::vector<double> row = {
      relative_density,
      1 - relative_density - closed_porosity,
      closed_porosity,
      double(n_closed),
      closed_volume,
      double(n_pockets),
      neck_min,
      contacts > 0 ? neck_sum / contacts : nan,
      neck_max,
      double(contacts),
      particles.empty() ? nan : 2. * contacts / particles.size(),
      double(near_misses),
      double(joined),
      gap_min};
    if (has_interior)
      row.push_back(double(interior_contacts) / interior_count);
    if (initial_spread.empty())
      for (const unsigned int d : shrinkage_axes)
        initial_spread.push_back(spread(solid.centroids, d));
    for (unsigned int a = 0; a < shrinkage_axes.size(); ++a)
      row.push_back(spread(solid.centroids, shrinkage_axes[a]) /
                    initial_spread[a]);

    if (!directory.empty())
      {
        if (!necks_log)
          open_logs();
        for (const auto &neck : necks)
          necks_log->add_row({double(step),
                              t,
                              double(neck.i),
                              double(neck.j),
                              double(neck.contact),
                              neck.radius,
                              neck.gap});
        for (unsigned int p = 0; p < pores.size(); ++p)
          {
            std::vector<double> values = {double(step),
                                          t,
                                          double(ids[p]),
                                          double(pores[p].open),
                                          pores[p].volume,
                                          pores[p].area,
                                          pores[p].sphericity()};
            for (unsigned int d = 0; d < dim; ++d)
              values.push_back(pores[p].centroid[d]);
            pores_log->add_row(values);
          }
        for (const auto &event : events)
          events_log->add_text_row({MetricsLog::format(t),
                                    std::to_string(step),
                                    event.name,
                                    std::to_string(event.pore),
                                    MetricsLog::format(event.volume)});
      }
    return row;
  }

  template class PackingAnalysis<2>;
  template class PackingAnalysis<3>;
} // namespace levelsinter
