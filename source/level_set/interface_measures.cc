#include <deal.II/base/bounding_box.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/quadrature_lib.h>

#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/mapping_q1.h>

#include <deal.II/hp/fe_collection.h>
#include <deal.II/hp/mapping_collection.h>
#include <deal.II/hp/q_collection.h>

#include <deal.II/non_matching/fe_values.h>
#include <deal.II/non_matching/mesh_classifier.h>

#include <deal.II/boost_adaptors/segment.h>

#include <levelsinter/level_set/box_mapping.h>
#include <levelsinter/level_set/interface_measures.h>

#include <algorithm>
#include <array>
#include <utility>
#include <cmath>
#include <limits>
#include <tuple>

namespace levelsinter::interface_measures
{
  namespace
  {
    // Cut-cell integration of f over the solid and g over the interface.
    template <int dim, typename VolumeIntegrand, typename SurfaceIntegrand>
    void
    integrate_cut(const LevelSetField<dim> &level_set,
                  const UpdateFlags         volume_flags,
                  const UpdateFlags         surface_flags,
                  const VolumeIntegrand    &on_volume,
                  const SurfaceIntegrand   &on_surface)
    {
      RegionIntegrands<dim> integrands;
      integrands.solid_flags   = volume_flags;
      integrands.surface_flags = surface_flags;
      integrands.on_solid      = [&](const auto &, const auto &values) {
        on_volume(values);
      };
      integrands.on_surface = [&](const auto &, const auto &values) {
        on_surface(values);
      };
      integrate_regions(level_set, integrands);
    }

    // alpha_h at a point inside a given cell.
    template <int dim>
    double
    value_in_cell(const LevelSetField<dim>                             &level_set,
                  const typename DoFHandler<dim>::active_cell_iterator &cell,
                  const std::vector<types::global_dof_index>           &indices,
                  const Point<dim>                                     &p)
    {
      const Point<dim> unit =
        StaticMappingQ1<dim>::mapping.transform_real_to_unit_cell(cell, p);
      double value = 0;
      for (unsigned int i = 0; i < indices.size(); ++i)
        value += level_set.alpha()(indices[i]) *
                 level_set.fe().shape_value(i, unit);
      return value;
    }
  } // namespace

  template <int dim>
  void
  integrate_regions(const LevelSetField<dim>     &level_set,
                    const RegionIntegrands<dim> &integrands)
  {
    const auto &dofs = level_set.dof_handler();
    const auto classifier = level_set.classifier();

    // The points as well: every integrand weighs JxW with the scene's
    // measure (SceneMeasure::JxW), which reads them.
    const auto with_points = [](const UpdateFlags region) {
      return region == update_default ? region :
                                        region | update_quadrature_points;
    };
    NonMatching::RegionUpdateFlags flags;
    flags.inside  = with_points(integrands.solid_flags);
    flags.outside = with_points(integrands.atmosphere_flags);
    flags.surface = with_points(integrands.surface_flags);
    const hp::FECollection<dim> fe_collection(level_set.fe());
    // NonMatching::FEValues builds new FEValues on every cut cell: with
    // the box mapping their set-up is nearly free.
    const hp::MappingCollection<dim> mapping(box_mapping<dim>());
    // Three Gauss points per direction integrate the Q1 level set's
    // implicit surface to far below its interpolation error (kept by
    // reference, as the mapping).
    const hp::QCollection<dim> cells{QGauss<dim>(3)};
    const hp::QCollection<1>   lines{QGauss<1>(3)};
    NonMatching::FEValues<dim> cut_values(mapping,
                                          fe_collection,
                                          cells,
                                          lines,
                                          flags,
                                          *classifier,
                                          dofs,
                                          level_set.alpha());
    const bool solid      = integrands.solid_flags != update_default;
    const bool atmosphere = integrands.atmosphere_flags != update_default;
    const bool surface    = integrands.surface_flags != update_default;
    for (const auto &cell : dofs.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          const auto location = classifier->location_to_level_set(cell);
          const bool wanted =
            location == NonMatching::LocationToLevelSet::intersected ?
              solid || atmosphere || surface :
              (location == NonMatching::LocationToLevelSet::inside ?
                 solid :
                 atmosphere);
          if (!wanted)
            continue;
          cut_values.reinit(cell);
          if (solid)
            if (const auto &inside = cut_values.get_inside_fe_values())
              integrands.on_solid(cell, *inside);
          if (atmosphere)
            if (const auto &outside = cut_values.get_outside_fe_values())
              integrands.on_atmosphere(cell, *outside);
          if (surface)
            if (const auto &values = cut_values.get_surface_fe_values())
              integrands.on_surface(cell, *values);
        }
  }

  template <int dim>
  VolumeAndArea
  volume_and_area(const LevelSetField<dim> &level_set)
  {
    if (const auto &measured = level_set.measured_volume_and_area())
      return *measured;
    VolumeAndArea       result;
    const SceneMeasure &measure = level_set.measure();
    integrate_cut<dim>(
      level_set,
      update_JxW_values,
      update_JxW_values,
      [&](const FEValues<dim> &values) {
        for (const unsigned int q : values.quadrature_point_indices())
          result.solid_volume += measure.JxW(values, q);
      },
      [&](const NonMatching::FEImmersedSurfaceValues<dim> &values) {
        for (const unsigned int q : values.quadrature_point_indices())
          result.interface_area += measure.JxW(values, q);
      });
    const MPI_Comm comm = level_set.dof_handler().get_communicator();
    result.solid_volume   = Utilities::MPI::sum(result.solid_volume, comm);
    result.interface_area = Utilities::MPI::sum(result.interface_area, comm);
    level_set.keep_volume_and_area(result);
    return result;
  }

  template <int dim>
  double
  atmosphere_volume(const LevelSetField<dim> &level_set,
                    const BoundingBox<dim>   &window)
  {
    // The window's cells minus the solid in them; cells fully in the
    // atmosphere are skipped by the cut integration but counted here.
    // A box cell's measure is its area times the weight at its centre
    // (the weight is linear in r).
    double              cells = 0, solid = 0;
    const SceneMeasure &measure = level_set.measure();
    for (const auto &cell : level_set.dof_handler().active_cell_iterators())
      if (cell->is_locally_owned() && window.point_inside(cell->center()))
        cells += cell->measure() * measure.weight(cell->center());
    integrate_cut<dim>(
      level_set,
      update_JxW_values,
      update_default,
      [&](const FEValues<dim> &values) {
        if (window.point_inside(values.get_cell()->center()))
          for (const unsigned int q : values.quadrature_point_indices())
            solid += measure.JxW(values, q);
      },
      [](const NonMatching::FEImmersedSurfaceValues<dim> &) {});
    return Utilities::MPI::sum(cells - solid,
                               level_set.dof_handler().get_communicator());
  }

  template <int dim>
  double
  interface_integral(
    const LevelSetField<dim> &level_set,
    const std::function<double(const Point<dim> &, const Tensor<1, dim> &)>
      &integrand)
  {
    double result = 0;
    integrate_cut<dim>(
      level_set,
      update_default,
      update_JxW_values | update_quadrature_points | update_normal_vectors,
      [](const FEValues<dim> &) {},
      [&](const NonMatching::FEImmersedSurfaceValues<dim> &values) {
        for (const unsigned int q : values.quadrature_point_indices())
          result += integrand(values.quadrature_point(q),
                              values.normal_vector(q)) *
                    level_set.measure().JxW(values, q);
      });
    return Utilities::MPI::sum(result,
                               level_set.dof_handler().get_communicator());
  }

  template <int dim>
  ShapeError
  shape_error(const LevelSetField<dim> &level_set,
              const Function<dim>      &exact_signed_distance)
  {
    ShapeError result;
    integrate_cut<dim>(
      level_set,
      update_default,
      update_JxW_values | update_quadrature_points,
      [](const FEValues<dim> &) {},
      [&](const NonMatching::FEImmersedSurfaceValues<dim> &values) {
        for (const unsigned int q : values.quadrature_point_indices())
          {
            const double d =
              std::abs(exact_signed_distance.value(values.quadrature_point(q)));
            result.symmetric_difference +=
              d * level_set.measure().JxW(values, q);
            result.max_distance = std::max(result.max_distance, d);
          }
      });
    const MPI_Comm comm = level_set.dof_handler().get_communicator();
    result.symmetric_difference =
      Utilities::MPI::sum(result.symmetric_difference, comm);
    result.max_distance = Utilities::MPI::max(result.max_distance, comm);
    return result;
  }

  template <int dim>
  RayCaster<dim>::RayCaster(const LevelSetField<dim> &level_set)
    : level_set(level_set)
  {
    std::vector<std::pair<BoundingBox<dim>, Cell>> boxes;
    for (const auto &cell : level_set.dof_handler().active_cell_iterators())
      if (cell->is_locally_owned())
        {
          // Each box widened by 1e-8 of the cell: a ray along a face, or
          // tilted out of it by rounding (1e-15 rad), then runs inside the
          // boxes on both sides. Boost's segment-box test decides such a
          // ray by the sign of rounding errors and missed both cells (exit
          // +infinity; tests/ray_caster_test.cc).
          auto [lower, upper] = cell->bounding_box().get_boundary_points();
          const double margin = 1e-8 * cell->diameter();
          for (unsigned int d = 0; d < dim; ++d)
            {
              lower[d] -= margin;
              upper[d] += margin;
            }
          boxes.emplace_back(BoundingBox<dim>(std::make_pair(lower, upper)),
                             cell);
          if (boxes.size() == 1)
            extent = boxes[0].first;
          extent.merge_with(boxes.back().first);
        }
    tree = pack_rtree(boxes);
  }

  template <int dim>
  std::vector<double>
  RayCaster<dim>::exit_distances(const std::vector<Ray<dim>> &rays) const
  {
    constexpr double infinity = std::numeric_limits<double>::infinity();
    // Per ray: first crossing from solid to pore, and from pore to solid.
    std::vector<double> leaving(rays.size(), infinity);
    std::vector<double> entering(rays.size(), infinity);
    std::vector<types::global_dof_index> indices(level_set.fe().dofs_per_cell);
    std::vector<std::pair<BoundingBox<dim>, Cell>> hits;
    // (entry s0, exit s1, hit) of the boxes the ray crosses.
    std::vector<std::tuple<double, double, unsigned int>> crossed;
    for (unsigned int r = 0; r < rays.size() && !tree.empty(); ++r)
      {
        const Point<dim>     &origin    = rays[r].origin;
        const Tensor<1, dim> &direction = rays[r].direction;
        // A segment long enough to leave every local cell.
        const double reach =
          origin.distance(extent.center()) +
          extent.get_boundary_points().first.distance(
            extent.get_boundary_points().second);
        hits.clear();
        tree.query(boost::geometry::index::intersects(
                     Segment<dim>(origin, origin + reach * direction)),
                   std::back_inserter(hits));
        crossed.clear();
        for (unsigned int h = 0; h < hits.size(); ++h)
          {
            // Slab test: the part [s0, s1] of the ray inside the box.
            const auto &[lower, upper] = hits[h].first.get_boundary_points();
            double s0 = 0, s1 = infinity;
            for (unsigned int d = 0; d < dim && s0 <= s1; ++d)
              if (std::abs(direction[d]) < 1e-14)
                {
                  if (origin[d] < lower[d] || origin[d] > upper[d])
                    s1 = -1;
                }
              else
                {
                  double a = (lower[d] - origin[d]) / direction[d];
                  double b = (upper[d] - origin[d]) / direction[d];
                  if (a > b)
                    std::swap(a, b);
                  s0 = std::max(s0, a);
                  s1 = std::min(s1, b);
                }
            if (s0 <= s1)
              crossed.emplace_back(s0, s1, h);
          }
        // From the origin outwards; a cell entered beyond the first
        // crossing found cannot hold an earlier one.
        std::sort(crossed.begin(), crossed.end());
        for (const auto &[s0, s1, h] : crossed)
          {
            if (s0 > std::min(leaving[r], entering[r]))
              break;
            const Cell &cell = hits[h].second;
            cell->get_dof_indices(indices);
            // Along a line alpha_h is a polynomial of degree <= dim in s;
            // 8 sub-intervals separate its roots on a cell, bisection
            // locates each to rounding.
            const unsigned int n_sub = 8;
            auto               at    = [&, s0 = s0, s1 = s1](const double s) {
              return value_in_cell<dim>(level_set,
                                        cell,
                                        indices,
                                        origin + s * direction);
            };
            double a_prev = at(s0);
            for (unsigned int k = 1; k <= n_sub; ++k)
              {
                const double s_lo = s0 + (s1 - s0) * (k - 1) / n_sub;
                const double s_hi = s0 + (s1 - s0) * k / n_sub;
                const double a_hi = at(s_hi);
                if ((a_prev < 0) != (a_hi < 0))
                  {
                    double lo = s_lo, hi = s_hi, f_lo = a_prev;
                    for (unsigned int it = 0; it < 60; ++it)
                      {
                        const double mid   = 0.5 * (lo + hi);
                        const double f_mid = at(mid);
                        if ((f_mid < 0) == (f_lo < 0))
                          {
                            lo   = mid;
                            f_lo = f_mid;
                          }
                        else
                          hi = mid;
                      }
                    auto &target = (a_prev < 0) ? leaving[r] : entering[r];
                    target       = std::min(target, 0.5 * (lo + hi));
                  }
                a_prev = a_hi;
              }
          }
      }

    // Each rank found its first crossing of each ray (or none); the
    // nearest over the ranks decides, as if one rank had walked it all.
    const MPI_Comm comm = level_set.dof_handler().get_communicator();
    Utilities::MPI::min(leaving, comm, leaving);
    Utilities::MPI::min(entering, comm, entering);
    for (unsigned int r = 0; r < rays.size(); ++r)
      if (entering[r] < leaving[r])
        leaving[r] = 0; // the origin lies in the pore
    return leaving;
  }

  template <int dim>
  std::vector<double>
  exit_distances(const LevelSetField<dim>          &level_set,
                 const Point<dim>                  &origin,
                 const std::vector<Tensor<1, dim>> &directions)
  {
    std::vector<Ray<dim>> rays;
    for (const auto &direction : directions)
      rays.push_back({origin, direction});
    return RayCaster<dim>(level_set).exit_distances(rays);
  }

  template <int dim>
  GradientNormError
  gradient_norm_error(const LevelSetField<dim> &level_set,
                      const LevelSetFilter     &filter)
  {
    const QGauss<dim> quadrature(2);
    FEValues<dim>     values(level_set.fe(),
                         quadrature,
                         update_values | update_gradients |
                           update_JxW_values | update_quadrature_points);
    std::vector<double>         alpha(quadrature.size());
    std::vector<Tensor<1, dim>> grad(quadrature.size());
    double max_error = 0, sum_sq = 0, measure = 0;
    for (const auto &cell : level_set.dof_handler().active_cell_iterators())
      if (cell->is_locally_owned())
        {
          values.reinit(cell);
          values.get_function_values(level_set.alpha(), alpha);
          values.get_function_gradients(level_set.alpha(), grad);
          for (const unsigned int q : values.quadrature_point_indices())
            if (std::abs(filter.distance(alpha[q])) <= 0.5 * filter.thickness())
              {
                const double e =
                  grad[q].norm() - filter.gradient_norm_target(alpha[q]);
                max_error = std::max(max_error, std::abs(e));
                const double JxW = level_set.measure().JxW(values, q);
                sum_sq += e * e * JxW;
                measure += JxW;
              }
        }
    const MPI_Comm comm = level_set.dof_handler().get_communicator();
    GradientNormError result;
    result.max_error = Utilities::MPI::max(max_error, comm);
    sum_sq           = Utilities::MPI::sum(sum_sq, comm);
    measure          = Utilities::MPI::sum(measure, comm);
    result.rms_error = measure > 0 ? std::sqrt(sum_sq / measure) : 0.;
    return result;
  }

  template void
  integrate_regions(const LevelSetField<2> &, const RegionIntegrands<2> &);
  template void
  integrate_regions(const LevelSetField<3> &, const RegionIntegrands<3> &);
  template VolumeAndArea
  volume_and_area(const LevelSetField<2> &);
  template VolumeAndArea
  volume_and_area(const LevelSetField<3> &);
  template double
  atmosphere_volume(const LevelSetField<2> &, const BoundingBox<2> &);
  template double
  atmosphere_volume(const LevelSetField<3> &, const BoundingBox<3> &);
  template double
  interface_integral(
    const LevelSetField<2> &,
    const std::function<double(const Point<2> &, const Tensor<1, 2> &)> &);
  template double
  interface_integral(
    const LevelSetField<3> &,
    const std::function<double(const Point<3> &, const Tensor<1, 3> &)> &);
  template ShapeError
  shape_error(const LevelSetField<2> &, const Function<2> &);
  template ShapeError
  shape_error(const LevelSetField<3> &, const Function<3> &);

  template class RayCaster<2>;
  template class RayCaster<3>;
  template std::vector<double>
  exit_distances(const LevelSetField<2> &,
                 const Point<2> &,
                 const std::vector<Tensor<1, 2>> &);
  template std::vector<double>
  exit_distances(const LevelSetField<3> &,
                 const Point<3> &,
                 const std::vector<Tensor<1, 3>> &);
  template GradientNormError
  gradient_norm_error(const LevelSetField<2> &, const LevelSetFilter &);
  template GradientNormError
  gradient_norm_error(const LevelSetField<3> &, const LevelSetFilter &);
} // namespace levelsinter::interface_measures
