#include <deal.II/base/bounding_box.h>
#include <deal.II/base/mpi.h>

#include <levelsinter/analysis/grain_measures.h>
#include <levelsinter/level_set/interface_measures.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

namespace levelsinter
{
  namespace
  {
    // The extent max - min of the points along axis d.
    template <int dim>
    double
    extent(const std::vector<Point<dim>> &points, const unsigned int d)
    {
      double low = points[0][d], high = points[0][d];
      for (const auto &p : points)
        {
          low  = std::min(low, p[d]);
          high = std::max(high, p[d]);
        }
      return high - low;
    }
  } // namespace

  template <int dim>
  GrainMeasures<dim>::GrainMeasures(const GrainBoundaryDiffusion<dim> &grains,
                                    const std::string &directory,
                                    const MPI_Comm     comm,
                                    TimerOutput       &timer)
    : grains(grains)
    , directory(directory)
    , comm(comm)
    , timer(timer)
    , initial_centre(grains.centres())
  {
    box_has_volume = true;
    for (unsigned int d = 0; d < dim; ++d)
      if (const double e = extent(initial_centre, d); e > 0)
        {
          axes.push_back(d);
          initial_extent.push_back(e);
        }
      else
        box_has_volume = false;
  }

  template <int dim>
  std::vector<std::string>
  GrainMeasures<dim>::column_names() const
  {
    std::vector<std::string> names = {"grains",
                                      "grain_boundaries",
                                      "grain_boundary_radius_min",
                                      "grain_boundary_radius_mean",
                                      "grain_boundary_radius_max",
                                      "grain_boundary_area",
                                      "approach_rate_mean",
                                      "grain_centre_distance_change_mean",
                                      "grain_volume_change_max"};
    for (const unsigned int d : axes)
      names.push_back(std::string("shrinkage_") + "xyz"[d]);
    if (box_has_volume)
      names.emplace_back("grain_relative_density");
    return names;
  }

  template <int dim>
  std::vector<double>
  GrainMeasures<dim>::measure(const StepRecord<dim> &record)
  {
    TimerOutput::Scope scope(timer, "grain measures");
    const double       nan     = std::numeric_limits<double>::quiet_NaN();
    const auto        &alpha   = record.level_set;
    const auto        &centres = grains.centres();
    const PowerCells<dim> cells = grains.grains();
    const unsigned int    n     = centres.size();

    // Each grain's solid, point by point where a cell boundary crosses a
    // mesh cell, and the solid in the box the centres span.
    Point<dim> low = centres[0], high = centres[0];
    for (const auto &c : centres)
      for (unsigned int d = 0; d < dim; ++d)
        {
          low[d]  = std::min(low[d], c[d]);
          high[d] = std::max(high[d], c[d]);
        }
    const BoundingBox<dim>    box(std::make_pair(low, high));
    std::vector<double>       volume(n + 1, 0.); // the box's solid last
    const bool                first = initial_volume.empty();
    std::vector<unsigned int> near;
    interface_measures::RegionIntegrands<dim> integrands;
    integrands.solid_flags = update_JxW_values | update_quadrature_points;
    integrands.on_solid    = [&](const auto &cell, const auto &values) {
      cells.candidates(cell->center(), cell->diameter() / 2, near);
      for (const unsigned int q : values.quadrature_point_indices())
        {
          const Point<dim> &x   = values.quadrature_point(q);
          const double      JxW = alpha.measure().JxW(values, q);
          volume[cells.owner(x, near)] += JxW;
          if (box_has_volume && first && box.point_inside(x))
            volume[n] += JxW;
        }
    };
    interface_measures::integrate_regions(alpha, integrands);
    Utilities::MPI::sum(volume, comm, volume);
    double solid = 0;
    for (unsigned int i = 0; i < n; ++i)
      solid += volume[i];
    if (first)
      {
        initial_volume.assign(volume.begin(), volume.begin() + n);
        initial_density = box_has_volume ? volume[n] / box.volume() : 0;
      }

    unsigned int n_grains       = 0;
    double       volume_change  = 0;
    for (unsigned int i = 0; i < n; ++i)
      if (volume[i] > 0)
        {
          ++n_grains;
          volume_change =
            std::max(volume_change,
                     std::abs(volume[i] - initial_volume[i]) / initial_volume[i]);
        }

    const auto boundaries = grain_geometry::find_grain_boundaries(alpha, cells);
    double radius_min = nan, radius_max = nan, radius_sum = 0, area = 0,
           rate_sum = 0, distance_change_sum = 0;
    unsigned int n_rates = 0;
    std::vector<std::vector<double>> rows;
    for (const auto &b : boundaries)
      {
        radius_min = std::fmin(radius_min, b.radius);
        radius_max = std::fmax(radius_max, b.radius);
        radius_sum += b.radius;
        area += b.area;
        const double d0 = initial_centre[b.i].distance(initial_centre[b.j]);
        const double distance_change = (b.centre_distance - d0) / d0;
        distance_change_sum += distance_change;
        // The approach rate of the last step's contact, and the radius and
        // root curvature it was computed from (at the step's start).
        double rate = nan, root_curvature = nan, rate_radius = nan;
        for (const auto &contact : grains.contacts())
          if (contact.boundary.i == b.i && contact.boundary.j == b.j)
            {
              rate           = contact.approach_rate;
              root_curvature = contact.root_curvature;
              rate_radius    = contact.boundary.radius;
              rate_sum += rate;
              ++n_rates;
            }
        rows.push_back({double(record.step),
                        record.time,
                        double(b.i),
                        double(b.j),
                        b.radius,
                        b.area,
                        b.centre_distance,
                        distance_change,
                        rate,
                        rate_radius,
                        root_curvature});
      }
    const unsigned int nb = boundaries.size();

    std::vector<double> values = {double(n_grains),
                                  double(nb),
                                  radius_min,
                                  nb > 0 ? radius_sum / nb : nan,
                                  radius_max,
                                  area,
                                  n_rates > 0 ? rate_sum / n_rates : nan,
                                  nb > 0 ? distance_change_sum / nb : nan,
                                  volume_change};
    // The dilatometric density: the box's solid fraction at t = 0 times
    // the solid's volume ratio over the box's (the box's solid moves with
    // its grains). Sampling the shrinking box with the quadrature points
    // instead jumped by 10 % when a layer of points of a coarse cell deep
    // in the solid left it.
    double box_ratio = 1;
    for (unsigned int a = 0; a < axes.size(); ++a)
      {
        const double ratio = extent(centres, axes[a]) / initial_extent[a];
        values.push_back(1 - ratio);
        box_ratio *= ratio;
      }
    if (box_has_volume)
      {
        double initial_solid = 0;
        for (const double v : initial_volume)
          initial_solid += v;
        values.push_back(initial_density * solid / initial_solid / box_ratio);
      }

    if (!directory.empty())
      {
        if (!log)
          log = std::make_unique<MetricsLog>(
            directory + "/grain_boundaries.csv",
            std::vector<std::string>{"step",
                                     "time",
                                     "grain_i",
                                     "grain_j",
                                     "radius",
                                     "area",
                                     "centre_distance",
                                     "centre_distance_change",
                                     "approach_rate",
                                     "rate_radius",
                                     "root_curvature"},
            comm,
            kept_rows);
        for (const auto &row : rows)
          log->add_row(row);
      }
    return values;
  }

  template <int dim>
  std::string
  GrainMeasures<dim>::save() const
  {
    std::ostringstream out;
    out.precision(17);
    out << (log ? log->n_rows() : 0) << ' ' << initial_density << ' '
        << initial_volume.size();
    for (const double v : initial_volume)
      out << ' ' << v;
    return out.str();
  }

  template <int dim>
  void
  GrainMeasures<dim>::load(const std::string &state)
  {
    std::istringstream in(state);
    unsigned int       rows = 0;
    std::size_t        n    = 0;
    in >> rows >> initial_density >> n;
    kept_rows = rows;
    initial_volume.resize(n);
    for (double &v : initial_volume)
      in >> v;
  }

  template class GrainMeasures<2>;
  template class GrainMeasures<3>;
} // namespace levelsinter
