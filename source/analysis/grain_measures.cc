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

    // Each grain's solid (grain_geometry::grain_volumes) and, once, the
    // solid in the box the centres span.
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

    // Per grain boundary, on each side and, in 2D, at each end: circles
    // fitted to the grain's surface beyond 1.5 l from the boundary's plane
    // (the triple-line kernel has the half-width l, doc/numerics.md), near
    // the triple line (the dihedral angle where the circle meets the
    // plane) and on the whole grain (radius and centre). A grain with more
    // grain boundaries (a row, a packing) leaves out the same 1.5 l about
    // its other boundaries: in a row of squat grains (gamma_gb = gamma_s:
    // centre spacing R) they would take a third of each fit.
    const auto boundaries = grain_geometry::find_grain_boundaries(alpha, cells);
    const auto circles    = grain_geometry::fit_surface_circles(
      alpha, cells, boundaries, 1.5 * grains.kernel_width());
    const unsigned int nb = boundaries.size();
    if (box_has_volume && first)
      {
        interface_measures::RegionIntegrands<dim> integrands;
        integrands.solid_flags = update_JxW_values | update_quadrature_points;
        integrands.on_solid    = [&](const auto &, const auto &values) {
          for (const unsigned int q : values.quadrature_point_indices())
            if (box.point_inside(values.quadrature_point(q)))
              volume[n] += alpha.measure().JxW(values, q);
        };
        interface_measures::integrate_regions(alpha, integrands);
      }
    Utilities::MPI::sum(volume, comm, volume);
    std::vector<Point<dim>>   centroid;
    const std::vector<double> grain_volume =
      grain_geometry::grain_volumes(alpha, cells, nullptr, &centroid);
    std::copy(grain_volume.begin(), grain_volume.end(), volume.begin());
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
        double rate = nan, root_curvature = nan, rate_radius = nan,
               explicit_root = nan, damping = nan;
        for (const auto &contact : grains.contacts())
          if (contact.boundary.i == b.i && contact.boundary.j == b.j)
            {
              rate           = contact.approach_rate;
              root_curvature = contact.root_curvature;
              explicit_root  = contact.explicit_root_curvature;
              damping        = contact.damping;
              rate_radius    = contact.boundary.radius;
              rate_sum += rate;
              ++n_rates;
            }
        // On a body of revolution (3D, axisymmetric) the near circle has
        // its centre on the line of centres, the axis of the pair: the
        // free circle's centre is fitted from a short arc next to the
        // grain's widest section, where rho hardly changes, and scattered
        // from 0 to 111 degrees between rows in 3D (doc/validation.md). In
        // 2D each end is a free circle (the centred one reads a neck that
        // is still opening 5-15 degrees lower). Where it meets the plane
        // zeta = 0 its outward normal has the component -zeta_c / R along
        // +zeta, -cos(psi/2) on j's side (centre at zeta_c > 0 for psi <
        // 180 degrees), +cos(psi/2) on i's. The means over the sides and
        // ends with a fit.
        const auto &circle = circles[&b - boundaries.data()];
        double cos_half = 0, fit_radius = 0, centre[2] = {0, 0},
               near_end = 0;
        unsigned int n_near = 0, n_whole = 0, n_centre[2] = {0, 0},
                     n_end = 0;
        for (unsigned int side = 0; side < 2; ++side)
          for (unsigned int end = 0; end < 2; ++end)
            {
              const auto &near = circle.near[side][end];
              if (std::isfinite(near[2]))
                {
                  cos_half += (side == 1 ? near[0] : -near[0]) / near[2];
                  ++n_near;
                  // Where the near circle meets the plane: the sharp
                  // triple line, the exact state's a = R sin(psi/2). The
                  // rays read a at the groove, which the kink's ridge
                  // rounds over k cells (doc/numerics.md, "The neck's
                  // width at the groove").
                  if (const double crossing =
                        grain_geometry::plane_crossing(near);
                      std::isfinite(crossing))
                    {
                      near_end += crossing;
                      ++n_end;
                    }
                }
              const auto &whole = circle.whole[side][end];
              if (std::isfinite(whole[2]))
                {
                  fit_radius += whole[2];
                  ++n_whole;
                  centre[side] += whole[0];
                  ++n_centre[side];
                }
            }
        const double dihedral_angle =
          n_near > 0 ? 2 * std::acos(std::clamp(cos_half / n_near, -1., 1.)) *
                         180 / M_PI :
                       nan;
        const double circle_distance =
          n_centre[0] > 0 && n_centre[1] > 0 ?
            centre[1] / n_centre[1] - centre[0] / n_centre[0] :
            nan;
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
                        root_curvature,
                        dihedral_angle,
                        n_whole > 0 ? fit_radius / n_whole : nan,
                        circle_distance,
                        explicit_root,
                        n_end > 0 ? near_end / n_end : nan,
                        centroid[b.i].distance(centroid[b.j]),
                        damping});
      }
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
                                     "root_curvature",
                                     "dihedral_angle",
                                     "fitted_radius",
                                     "fitted_centre_distance",
                                     "root_curvature_explicit",
                                     "fitted_gb_radius",
                                     "centroid_distance",
                                     "contact_damping"},
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
