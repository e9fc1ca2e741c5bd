#include <deal.II/base/mpi.h>

#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>

#include <levelsinter/geometry/grain_boundaries.h>
#include <levelsinter/level_set/interface_measures.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <set>

namespace levelsinter::grain_geometry
{
  namespace
  {
    // Unit directions in the plane normal to @p normal: +-t in 2D (t the
    // normal turned by +90 degrees), 8 evenly spaced in 3D.
    template <int dim>
    std::vector<Tensor<1, dim>>
    in_plane_directions(const Tensor<1, dim> &normal)
    {
      std::vector<Tensor<1, dim>> directions;
      if constexpr (dim == 2)
        {
          const Tensor<1, dim> t({-normal[1], normal[0]});
          directions = {t, -t};
        }
      else
        {
          Tensor<1, dim> helper;
          helper[std::abs(normal[0]) < 0.9 ? 0 : 1] = 1;
          Tensor<1, dim> u = cross_product_3d(normal, helper);
          u /= u.norm();
          const Tensor<1, dim> w = cross_product_3d(normal, u);
          // Half a step off u and w: a symmetry plane through the line of
          // centres (a coordinate plane; u and w are coordinate axes when
          // the line of centres is one) then holds no ray, and the rays in
          // the domain are its share of the boundary.
          for (unsigned int k = 0; k < 8; ++k)
            directions.push_back(std::cos((k + 0.5) * M_PI / 4) * u +
                                 std::sin((k + 0.5) * M_PI / 4) * w);
        }
      return directions;
    }

    double
    bump(const double s)
    {
      return std::abs(s) < 1 ? (1 + std::cos(M_PI * s)) / 2 : 0.;
    }

    // Sums of the algebraic circle fit (Kasa) of points (zeta, rho) in the
    // meridian plane of a grain boundary: minimise sum (z + D zeta + E rho
    // + F)^2, z = zeta^2 + rho^2, weighted by the surface element.
    constexpr unsigned int n_moments = 9;

    void
    add_moments(const double zeta, const double rho, const double w, double *m)
    {
      const double z = zeta * zeta + rho * rho;
      const double terms[n_moments] = {
        zeta * zeta, zeta * rho, zeta, rho * rho, rho, 1, z * zeta, z * rho, z};
      for (unsigned int k = 0; k < n_moments; ++k)
        m[k] += w * terms[k];
    }

    // The circle of the fit: (zeta_c, rho_c, R); NaN without enough
    // points.
    std::array<double, 3>
    fitted_circle(const double *m)
    {
      const double nan = std::numeric_limits<double>::quiet_NaN();
      if (!(m[5] > 0))
        return {{nan, nan, nan}};
      FullMatrix<double> normal(3, 3), inverse(3, 3);
      const double       entries[9] = {
        m[0], m[1], m[2], m[1], m[3], m[4], m[2], m[4], m[5]};
      normal.fill(entries);
      if (!(std::abs(normal.determinant()) > 1e-30 * std::pow(m[5], 3)))
        return {{nan, nan, nan}};
      inverse.invert(normal);
      dealii::Vector<double> rhs(3), def(3);
      rhs(0) = -m[6];
      rhs(1) = -m[7];
      rhs(2) = -m[8];
      inverse.vmult(def, rhs);
      const double zeta_c = -def(0) / 2, rho_c = -def(1) / 2;
      const double radius2 = zeta_c * zeta_c + rho_c * rho_c - def(2);
      return {{zeta_c, rho_c, radius2 > 0 ? std::sqrt(radius2) : nan}};
    }

    // The circle of the fit with its centre on the line of centres (rho_c
    // = 0): minimise sum (z + D zeta + F)^2. (zeta_c, 0, R); NaN without
    // enough points.
    std::array<double, 3>
    fitted_axial_circle(const double *m)
    {
      const double nan = std::numeric_limits<double>::quiet_NaN();
      const double det = m[0] * m[5] - m[2] * m[2];
      if (!(m[5] > 0) || !(std::abs(det) > 1e-14 * m[0] * m[5]))
        return {{nan, nan, nan}};
      const double D = (-m[6] * m[5] + m[8] * m[2]) / det;
      const double F = (-m[8] * m[0] + m[6] * m[2]) / det;
      const double zeta_c  = -D / 2;
      const double radius2 = zeta_c * zeta_c - F;
      return {{zeta_c, 0., radius2 > 0 ? std::sqrt(radius2) : nan}};
    }
  } // namespace

  template <int dim>
  void
  set_extent(GrainBoundary<dim> &boundary,
             const double        end_0,
             const double        end_1,
             const bool          body_3d)
  {
    const double old_area = boundary.area;
    if (body_3d)
      {
        // dim == 3 or axisymmetric: a disc.
        const double a      = end_0;
        boundary.radius     = a;
        boundary.area       = M_PI * a * a;
        boundary.perimeter  = 2 * M_PI * a;
        boundary.resistance = M_PI * std::pow(a, 4) / 8;
      }
    else
      {
        boundary.strip           = true;
        boundary.end_distance[0] = end_0;
        boundary.end_distance[1] = end_1;
        const double a           = (end_0 + end_1) / 2;
        boundary.radius          = a;
        boundary.area            = 2 * a;
        boundary.perimeter       = 2;
        boundary.resistance      = 2 * std::pow(a, 3) / 3;
      }
    if (old_area > 0)
      boundary.area_in_domain *= boundary.area / old_area;
  }

  template <int dim>
  std::vector<GrainBoundary<dim>>
  find_grain_boundaries(const LevelSetField<dim> &level_set,
                        const PowerCells<dim>    &grains)
  {
    const auto        &c = grains.centres();
    const unsigned int n = c.size();
    std::vector<GrainBoundary<dim>>           candidates;
    std::vector<interface_measures::Ray<dim>> rays;
    for (unsigned int i = 0; i < n; ++i)
      for (unsigned int j = i + 1; j < n; ++j)
        {
          const double d  = c[i].distance(c[j]);
          const double ri = grains.radius(i), rj = grains.radius(j);
          if (d >= 1.1 * (ri + rj))
            continue;
          GrainBoundary<dim> b;
          b.i               = i;
          b.j               = j;
          b.centre_distance = d;
          b.normal          = (c[j] - c[i]) / d;
          // Rounding of the moving centres tilts a normal along an axis by
          // 1e-15: snap it, so that the rays of a boundary on a mesh line
          // run exactly along it (RayCaster's box search missed such
          // nearly parallel rays: exit +infinity at a symmetric pair).
          for (unsigned int k = 0; k < dim; ++k)
            if (std::abs(b.normal[k]) < 1e-12)
              b.normal[k] = 0;
          b.normal /= b.normal.norm();
          // |x - c_i|^2 - r_i^2 = |x - c_j|^2 - r_j^2 on the line.
          b.origin = c[i] + (d * d + ri * ri - rj * rj) / (2 * d) * b.normal;
          // The rays start 1e-9 R off the plane, inside the cells on j's
          // side when the plane is a mesh face (the same search dropped
          // rays along a face); alpha moves by far less than rounding.
          const Point<dim> start = b.origin + 1e-9 * (ri + rj) * b.normal;
          for (const auto &t : in_plane_directions(b.normal))
            rays.push_back({start, t});
          candidates.push_back(b);
        }
    const std::vector<double> exits =
      interface_measures::RayCaster<dim>(level_set).exit_distances(rays);

    const bool body_3d =
      level_set.measure().template body_dimension<dim>() == 3;
    const unsigned int n_rays = dim == 2 ? 2 : 8;
    std::vector<GrainBoundary<dim>> result;
    for (unsigned int b = 0; b < candidates.size(); ++b)
      {
        auto &boundary = candidates[b];
        // Along a ray the power of a third grain k minus that of i is
        // affine: g(s) = g(0) + 2 s t . (c_i - c_k).
        bool owned = true;
        std::vector<double> lengths;
        std::vector<bool>   valid;
        for (unsigned int r = 0; r < n_rays; ++r)
          {
            const auto &ray  = rays[b * n_rays + r];
            double      exit = exits[b * n_rays + r];

            if (!std::isfinite(exit))
              {
                lengths.push_back(0);
                valid.push_back(false);
                continue;
              }
            for (unsigned int k = 0; k < n; ++k)
              if (k != boundary.i && k != boundary.j)
                {
                  const double g0 = grains.power(ray.origin, k) -
                                    grains.power(ray.origin, boundary.i);
                  const double slope =
                    2 * (ray.direction * (c[boundary.i] - c[k]));
                  if (g0 <= 0)
                    owned = false;
                  else if (slope < 0)
                    exit = std::min(exit, g0 / -slope);
                }
            lengths.push_back(exit);
            valid.push_back(true);
          }
        const unsigned int n_valid = std::count(valid.begin(), valid.end(), true);
        if (!owned || n_valid == 0)
          continue;
        double sum = 0, square = 0;
        for (unsigned int r = 0; r < n_rays; ++r)
          if (valid[r])
            {
              sum += lengths[r];
              square += lengths[r] * lengths[r];
            }
        if (sum == 0)
          continue; // the origin lies in the pore
        if (body_3d)
          {
            // dim == 3 (8 rays) or axisymmetric (the one ray along r).
            const double a = std::sqrt(square / n_valid);
            set_extent(boundary, a, a, true);
            boundary.area_in_domain = dim == 3 ?
                                        boundary.area * n_valid / n_rays :
                                        boundary.area;
          }
        else
          {
            set_extent(boundary,
                       valid[0] ? lengths[0] : lengths[1],
                       valid[1] ? lengths[1] : lengths[0],
                       false);
            boundary.area_in_domain = sum;
          }
        result.push_back(boundary);
      }
    return result;
  }

  template <int dim>
  std::vector<SurfaceCircles>
  fit_surface_circles(const LevelSetField<dim>              &level_set,
                      const PowerCells<dim>                 &grains,
                      const std::vector<GrainBoundary<dim>> &boundaries,
                      const double                           inner)
  {
    const unsigned int nb = boundaries.size();
    const bool         revolution =
      level_set.measure().template body_dimension<dim>() == 3;
    // Per boundary, near / whole, side and end: the fit's sums.
    std::vector<double> moments(nb * 8 * n_moments, 0.);
    const auto          fit = [&](const unsigned int b,
                         const unsigned int whole,
                         const unsigned int side,
                         const unsigned int end) {
      return &moments[(((b * 2 + whole) * 2 + side) * 2 + end) * n_moments];
    };
    const auto near_other = [&](const unsigned int  b,
                                const unsigned int  grain,
                                const Point<dim>   &x) {
      for (unsigned int o = 0; o < nb; ++o)
        if (o != b && (boundaries[o].i == grain || boundaries[o].j == grain))
          {
            const Tensor<1, dim> offset = x - boundaries[o].origin;
            const double         zeta   = offset * boundaries[o].normal;
            if (std::abs(zeta) < inner &&
                (offset - zeta * boundaries[o].normal).norm() <
                  boundaries[o].radius + inner)
              return true;
          }
      return false;
    };
    std::vector<unsigned int>                 near;
    interface_measures::RegionIntegrands<dim> integrands;
    integrands.surface_flags = update_JxW_values | update_quadrature_points;
    integrands.on_surface    = [&](const auto &cell, const auto &values) {
      grains.candidates(cell->center(), cell->diameter() / 2, near);
      for (unsigned int b = 0; b < nb; ++b)
        {
          const auto  &boundary = boundaries[b];
          const double size     = std::max(grains.radius(boundary.i),
                                       grains.radius(boundary.j));
          const double near_end = inner + size / 4;
          if (cell->center().distance(boundary.origin) >
              boundary.radius + 3 * size + cell->diameter())
            continue;
          for (const unsigned int q : values.quadrature_point_indices())
            {
              const Point<dim>    &x      = values.quadrature_point(q);
              const Tensor<1, dim> offset = x - boundary.origin;
              const double         zeta   = offset * boundary.normal;
              const unsigned int   side   = zeta > 0 ? 1 : 0;
              const unsigned int   owner  = grains.owner(x, near);
              if (std::abs(zeta) < inner ||
                  owner != (side == 1 ? boundary.j : boundary.i) ||
                  near_other(b, owner, x))
                continue;
              const Tensor<1, dim> radial = offset - zeta * boundary.normal;
              unsigned int         end    = 0;
              if constexpr (dim == 2)
                if (boundary.strip)
                  end = radial * Tensor<1, dim>({-boundary.normal[1],
                                                 boundary.normal[0]}) >= 0 ?
                          0 :
                          1;
              const double rho = radial.norm();
              if (rho < boundary.radius / 2)
                continue;
              add_moments(zeta, rho, values.JxW(q), fit(b, 1, side, end));
              if (std::abs(zeta) < near_end)
                add_moments(zeta, rho, values.JxW(q), fit(b, 0, side, end));
            }
        }
    };
    interface_measures::integrate_regions(level_set, integrands);
    Utilities::MPI::sum(moments,
                        level_set.dof_handler().get_communicator(),
                        moments);
    std::vector<SurfaceCircles> circles(nb);
    for (unsigned int b = 0; b < nb; ++b)
      for (unsigned int side = 0; side < 2; ++side)
        for (unsigned int end = 0; end < 2; ++end)
          {
            circles[b].near[side][end] =
              revolution ? fitted_axial_circle(fit(b, 0, side, end)) :
                           fitted_circle(fit(b, 0, side, end));
            circles[b].whole[side][end] = fitted_circle(fit(b, 1, side, end));
          }
    return circles;
  }

  double
  plane_crossing(const std::array<double, 3> &circle)
  {
    return std::abs(circle[0]) < circle[2] ?
             circle[1] + std::sqrt(circle[2] * circle[2] -
                                   circle[0] * circle[0]) :
             std::numeric_limits<double>::quiet_NaN();
  }

  template <int dim>
  double
  triple_line_weight(const GrainBoundary<dim> &boundary,
                     const Point<dim>         &x,
                     const double              width,
                     const double              plateau)
  {
    const Tensor<1, dim> offset = x - boundary.origin;
    const double         zeta   = offset * boundary.normal;
    const Tensor<1, dim> radial = offset - zeta * boundary.normal;
    double               end    = boundary.radius;
    if constexpr (dim == 2)
      if (boundary.strip)
        {
          // The end on x's side of the line of centres.
          const Tensor<1, dim> t({-boundary.normal[1], boundary.normal[0]});
          end = boundary.end_distance[radial * t >= 0 ? 0 : 1];
        }
    const double along = std::max(std::abs(radial.norm() - end) - plateau, 0.);
    return bump(zeta / width) * bump(along / std::max(width, plateau));
  }

  template <int dim>
  void
  grain_shares(const PowerCells<dim>           &grains,
               const Point<dim>                &x,
               const std::vector<unsigned int> &near,
               const double                     width,
               std::vector<double>             &share)
  {
    const auto &c = grains.centres();
    share.assign(near.size(), 1.);
    double sum = 0;
    for (unsigned int a = 0; a < near.size(); ++a)
      {
        for (unsigned int b = 0; b < near.size() && share[a] > 0; ++b)
          if (b != a)
            {
              // The powers' difference is affine in x, with the gradient
              // 2 (c_l - c_k): over that norm, the distance from the plane.
              const unsigned int k = near[a], l = near[b];
              const double       s = (grains.power(x, l) - grains.power(x, k)) /
                                     (2 * c[k].distance(c[l]));
              share[a] *= std::clamp(0.5 + s / width, 0., 1.);
            }
        sum += share[a];
      }
    // The owner's share is positive (every s_kl >= 0 for it).
    for (double &v : share)
      v /= sum;
  }

  template <int dim>
  std::vector<double>
  grain_volumes(const LevelSetField<dim> &level_set,
                const PowerCells<dim>    &grains,
                FullMatrix<double>       *jacobian,
                std::vector<Point<dim>>  *centroids)
  {
    const auto               &c = grains.centres();
    const unsigned int        n = c.size();
    std::vector<double>       volume(n, 0.);
    std::vector<double>       moment(centroids ? n * dim : 0, 0.);
    std::vector<unsigned int> near;
    std::vector<double>       share;
    if (jacobian)
      jacobian->reinit(n, n);
    interface_measures::RegionIntegrands<dim> integrands;
    integrands.solid_flags = update_JxW_values | update_quadrature_points;
    integrands.on_solid    = [&](const auto &cell, const auto &values) {
      const double width = cell->minimum_vertex_distance();
      grains.candidates(cell->center(), cell->diameter() / 2 + width, near);
      for (const unsigned int q : values.quadrature_point_indices())
        {
          const Point<dim> &x   = values.quadrature_point(q);
          const double      JxW = level_set.measure().JxW(values, q);
          grain_shares(grains, x, near, width, share);
          for (unsigned int a = 0; a < near.size(); ++a)
            volume[near[a]] += share[a] * JxW;
          if (centroids)
            for (unsigned int a = 0; a < near.size(); ++a)
              for (unsigned int d = 0; d < dim; ++d)
                moment[near[a] * dim + d] += share[a] * JxW * x[d];
          // Within the ramp of (k, l) the share of k grows by 1 / (2 d_kl
          // width) per unit of w_k.
          if (jacobian)
            for (unsigned int a = 0; a < near.size(); ++a)
              for (unsigned int b = a + 1; b < near.size(); ++b)
                {
                  const unsigned int k = near[a], l = near[b];
                  const double       d = c[k].distance(c[l]);
                  const double s = (grains.power(x, l) - grains.power(x, k)) /
                                   (2 * d);
                  if (share[a] > 0 && share[b] > 0 && std::abs(s) < width / 2)
                    {
                      const double slope = JxW / (2 * d * width);
                      (*jacobian)(k, k) += slope;
                      (*jacobian)(l, l) += slope;
                      (*jacobian)(k, l) -= slope;
                      (*jacobian)(l, k) -= slope;
                    }
                }
        }
    };
    interface_measures::integrate_regions(level_set, integrands);
    const MPI_Comm comm = level_set.dof_handler().get_communicator();
    Utilities::MPI::sum(volume, comm, volume);
    if (jacobian)
      Utilities::MPI::sum(*jacobian, comm, *jacobian);
    if (centroids)
      {
        Utilities::MPI::sum(moment, comm, moment);
        centroids->assign(n, Point<dim>());
        for (unsigned int i = 0; i < n; ++i)
          for (unsigned int d = 0; d < dim; ++d)
            (*centroids)[i][d] =
              volume[i] > 0 ? moment[i * dim + d] / volume[i] :
                              std::numeric_limits<double>::quiet_NaN();
      }
    return volume;
  }

  template <int dim>
  void
  cell_grains(const LevelSetField<dim> &level_set,
              const PowerCells<dim>    &grains,
              dealii::Vector<float>    &grain_id,
              dealii::Vector<float>    *boundary)
  {
    const auto &dofs = level_set.dof_handler();
    grain_id.reinit(dofs.get_triangulation().n_active_cells());
    if (boundary)
      boundary->reinit(grain_id.size());
    std::vector<types::global_dof_index> indices(
      dofs.get_fe().n_dofs_per_cell());
    std::vector<unsigned int> near;
    for (const auto &cell : dofs.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          // Q1 takes its minimum at a vertex: solid in the cell iff a
          // vertex value is <= 0. Its dofs are its vertices, in order.
          cell->get_dof_indices(indices);
          grains.candidates(cell->center(), cell->diameter() / 2, near);
          std::set<unsigned int> owners;
          for (unsigned int v = 0; v < indices.size(); ++v)
            if (level_set.alpha()(indices[v]) <= 0)
              owners.insert(grains.owner(cell->vertex(v), near));
          const auto index = cell->active_cell_index();
          grain_id(index) =
            owners.empty() ? -1.f : float(grains.owner(cell->center(), near));
          if (boundary)
            (*boundary)(index) = owners.size() >= 2 ? 1.f : 0.f;
        }
  }

  template void
  set_extent(GrainBoundary<2> &, const double, const double, const bool);
  template void
  set_extent(GrainBoundary<3> &, const double, const double, const bool);
  template std::vector<GrainBoundary<2>>
  find_grain_boundaries(const LevelSetField<2> &, const PowerCells<2> &);
  template std::vector<SurfaceCircles>
  fit_surface_circles(const LevelSetField<2> &,
                      const PowerCells<2> &,
                      const std::vector<GrainBoundary<2>> &,
                      const double);
  template std::vector<SurfaceCircles>
  fit_surface_circles(const LevelSetField<3> &,
                      const PowerCells<3> &,
                      const std::vector<GrainBoundary<3>> &,
                      const double);
  template std::vector<GrainBoundary<3>>
  find_grain_boundaries(const LevelSetField<3> &, const PowerCells<3> &);
  template double
  triple_line_weight(const GrainBoundary<2> &,
                     const Point<2> &,
                     const double,
                     const double);
  template double
  triple_line_weight(const GrainBoundary<3> &,
                     const Point<3> &,
                     const double,
                     const double);
  template void
  grain_shares(const PowerCells<2> &,
               const Point<2> &,
               const std::vector<unsigned int> &,
               const double,
               std::vector<double> &);
  template void
  grain_shares(const PowerCells<3> &,
               const Point<3> &,
               const std::vector<unsigned int> &,
               const double,
               std::vector<double> &);
  template std::vector<double>
  grain_volumes(const LevelSetField<2> &,
                const PowerCells<2> &,
                FullMatrix<double> *,
                std::vector<Point<2>> *);
  template std::vector<double>
  grain_volumes(const LevelSetField<3> &,
                const PowerCells<3> &,
                FullMatrix<double> *,
                std::vector<Point<3>> *);
  template void
  cell_grains(const LevelSetField<2> &,
              const PowerCells<2> &,
              dealii::Vector<float> &,
              dealii::Vector<float> *);
  template void
  cell_grains(const LevelSetField<3> &,
              const PowerCells<3> &,
              dealii::Vector<float> &,
              dealii::Vector<float> *);
} // namespace levelsinter::grain_geometry
