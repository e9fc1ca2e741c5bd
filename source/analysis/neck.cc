#include <levelsinter/analysis/neck.h>
#include <levelsinter/level_set/cell_size.h>
#include <levelsinter/level_set/interface_measures.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace levelsinter::neck_measures
{
  using interface_measures::Ray;
  using interface_measures::RayCaster;

  namespace
  {
    // The cross-section of the pair (c1, c2) at c1 + s (c2 - c1).
    template <int dim>
    struct Section
    {
      Point<dim> c1, c2;
      double     s;
    };

    constexpr unsigned int n_section_rays(const int dim)
    {
      return dim == 2 ? 2 : 8;
    }

    // The rays of a cross-section: from its point, in the plane normal to
    // c2 - c1 (2 rays in 2D, 8 in 3D).
    template <int dim>
    void
    add_section_rays(const Section<dim> &section, std::vector<Ray<dim>> &rays)
    {
      const auto &[c1, c2, s]     = section;
      const Tensor<1, dim> axis   = (c2 - c1) / (c2 - c1).norm();
      const Point<dim>     origin = c1 + s * (c2 - c1);
      if constexpr (dim == 2)
        {
          const Tensor<1, dim> t({-axis[1], axis[0]});
          rays.push_back({origin, t});
          rays.push_back({origin, -t});
        }
      else
        {
          Tensor<1, dim> helper;
          helper[std::abs(axis[0]) < 0.9 ? 0 : 1] = 1;
          Tensor<1, dim> u = cross_product_3d(axis, helper);
          u /= u.norm();
          const Tensor<1, dim> w = cross_product_3d(axis, u);
          for (unsigned int k = 0; k < n_section_rays(dim); ++k)
            rays.push_back({origin,
                            std::cos(k * M_PI / 4) * u +
                              std::sin(k * M_PI / 4) * w});
        }
    }

    // Mean exit distance from each section's point over its rays, all
    // sections in one pass of the caster. Rays that leave the domain before
    // meeting the interface (symmetry planes) are skipped; 0 if all do.
    template <int dim>
    std::vector<double>
    cross_section_radii(const RayCaster<dim>             &caster,
                        const std::vector<Section<dim>> &sections)
    {
      const unsigned int    n_rays = n_section_rays(dim);
      std::vector<Ray<dim>> rays;
      for (const auto &section : sections)
        add_section_rays(section, rays);
      const std::vector<double> exits = caster.exit_distances(rays);
      std::vector<double>       radii;
      for (unsigned int i = 0; i < sections.size(); ++i)
        {
          double       sum     = 0;
          unsigned int n_valid = 0;
          for (unsigned int k = i * n_rays; k < (i + 1) * n_rays; ++k)
            if (std::isfinite(exits[k]))
              {
                sum += exits[k];
                ++n_valid;
              }
          radii.push_back(n_valid ? sum / n_valid : 0.);
        }
      return radii;
    }

    // narrowest_neck() of several pairs at once: the searches advance in
    // step, so that each round is one pass of the caster (one reduction
    // over the ranks) for all pairs.
    template <int dim>
    std::vector<Neck>
    narrowest_necks(const RayCaster<dim>                                &caster,
                    const std::vector<std::pair<Point<dim>, Point<dim>>> &pairs)
    {
      // The cross-section radius falls from the first centre to the neck
      // and rises again to the second: a scan brackets the minimum, a
      // golden-section search narrows the bracket to 1e-4 of the centre
      // distance (the radius is flat there, so its error is of second
      // order).
      const unsigned int        n_scan = 16;
      std::vector<Section<dim>> sections;
      for (const auto &[c1, c2] : pairs)
        for (unsigned int k = 1; k < n_scan; ++k)
          sections.push_back({c1, c2, double(k) / n_scan});
      const std::vector<double> scan = cross_section_radii(caster, sections);

      struct Search
      {
        double a, b, x1, x2, f1, f2, r_best;
        bool   new_x1; // which point the round evaluates
      };
      const double        golden = (std::sqrt(5.) - 1) / 2;
      std::vector<Search> searches;
      sections.clear();
      for (unsigned int p = 0; p < pairs.size(); ++p)
        {
          auto radius = [&](const unsigned int k) {
            return scan[p * (n_scan - 1) + k - 1];
          };
          unsigned int best = 1;
          for (unsigned int k = 2; k < n_scan; ++k)
            if (radius(k) < radius(best))
              best = k;
          Search      search;
          search.r_best = radius(best);
          search.a      = double(best - 1) / n_scan;
          search.b      = double(best + 1) / n_scan;
          search.x1     = search.b - golden * (search.b - search.a);
          search.x2     = search.a + golden * (search.b - search.a);
          searches.push_back(search);
          sections.push_back({pairs[p].first, pairs[p].second, search.x1});
          sections.push_back({pairs[p].first, pairs[p].second, search.x2});
        }
      const std::vector<double> initial = cross_section_radii(caster, sections);
      for (unsigned int p = 0; p < pairs.size(); ++p)
        {
          searches[p].f1 = initial[2 * p];
          searches[p].f2 = initial[2 * p + 1];
        }

      std::vector<unsigned int> active;
      while (true)
        {
          active.clear();
          sections.clear();
          for (unsigned int p = 0; p < pairs.size(); ++p)
            if (Search &q = searches[p]; q.b - q.a > 1e-4)
              {
                q.new_x1 = q.f1 < q.f2;
                if (q.new_x1)
                  {
                    q.b  = q.x2;
                    q.x2 = q.x1;
                    q.f2 = q.f1;
                    q.x1 = q.b - golden * (q.b - q.a);
                  }
                else
                  {
                    q.a  = q.x1;
                    q.x1 = q.x2;
                    q.f1 = q.f2;
                    q.x2 = q.a + golden * (q.b - q.a);
                  }
                active.push_back(p);
                sections.push_back({pairs[p].first,
                                    pairs[p].second,
                                    q.new_x1 ? q.x1 : q.x2});
              }
          if (active.empty())
            break;
          const std::vector<double> radii =
            cross_section_radii(caster, sections);
          for (unsigned int i = 0; i < active.size(); ++i)
            {
              Search &q                   = searches[active[i]];
              (q.new_x1 ? q.f1 : q.f2) = radii[i];
            }
        }

      std::vector<Neck> necks;
      for (const Search &q : searches)
        {
          Neck neck;
          neck.position = q.f1 < q.f2 ? q.x1 : q.x2;
          neck.radius   = std::min({q.f1, q.f2, q.r_best});
          necks.push_back(neck);
        }
      return necks;
    }
  } // namespace

  template <int dim>
  double
  neck_radius(const LevelSetField<dim> &level_set,
              const Point<dim>         &c1,
              const Point<dim>         &c2)
  {
    return cross_section_radii(RayCaster<dim>(level_set), {{c1, c2, 0.5}})[0];
  }

  template <int dim>
  NeckShape<dim>
  neck_shape(const LevelSetField<dim> &level_set,
             const Point<dim>         &c1,
             const Point<dim>         &c2,
             const double              spacing)
  {
    // The mid-plane's rays find the neck point; 2 n + 1 cross-sections
    // spaced by @p spacing along the axis give the profile r(x), fitted by
    // a least-squares parabola (the neck is a minimum of r, so r'(0) ~ 0 and
    // r''(0) carries the curvature; the fit averages the O(h^2) wiggles of
    // the Q1 interface that a three-point difference would amplify).
    constexpr int             n = 3;
    const double              length = c1.distance(c2);
    std::vector<Section<dim>> sections;
    for (int k = -n; k <= n; ++k)
      sections.push_back({c1, c2, 0.5 + k * spacing / length});
    const RayCaster<dim>  caster(level_set);
    std::vector<Ray<dim>> rays;
    add_section_rays(sections[n], rays);
    const std::vector<double> exits = caster.exit_distances(rays);
    std::vector<double> radii = cross_section_radii(caster, sections);
    // The profile of two equal particles is even about the mid-plane: fit
    // its even part. A section beyond a symmetry plane through the neck
    // lies outside the mesh (radius 0): its mirror image stands for it.
    for (int k = 1; k <= n; ++k)
      {
        double &left = radii[n - k], &right = radii[n + k];
        const double even =
          (left > 0 && right > 0) ? (left + right) / 2 : std::max(left, right);
        left = right = even;
      }

    NeckShape<dim> shape;
    shape.point       = c1 + 0.5 * (c2 - c1);
    shape.inner_point = shape.point;
    for (unsigned int k = 0; k < rays.size(); ++k)
      if (std::isfinite(exits[k]) && exits[k] > 0)
        {
          const auto &[origin, direction] = rays[k];
          shape.point                     = origin + exits[k] * direction;
          shape.inner_point =
            origin + std::max(exits[k] - spacing, exits[k] / 2) * direction;
          break;
        }
    // r = a + b x + c x^2 over x = k spacing, k = -n..n: the odd and even
    // moments decouple (sum k = sum k^3 = 0).
    double s0 = 0, s2 = 0, s4 = 0, m0 = 0, m1 = 0, m2 = 0;
    for (int k = -n; k <= n; ++k)
      {
        const double x = k * spacing, r = radii[k + n];
        s0 += 1;
        s2 += x * x;
        s4 += x * x * x * x;
        m0 += r;
        m1 += x * r;
        m2 += x * x * r;
      }
    const double b = m1 / s2;
    const double c = (s0 * m2 - s2 * m0) / (s0 * s4 - s2 * s2);
    const double a = (m0 - c * s2) / s0;
    const double slope = std::sqrt(1 + b * b);
    // Eq. 45-47 of the viscoelastic seed: 1/R1 + 1/R2 with R1 = (1 +
    // r'^2)^(3/2) / r'' (the profile) and, about the axis, R2 = -r (1 +
    // r'^2)^(1/2) (the hoop, in 3D and on an axisymmetric scene: 2D
    // cylinders have none).
    shape.curvature = 2 * c / (slope * slope * slope);
    if (dim == 3 || level_set.measure().is_axisymmetric())
      shape.curvature -= 1 / (a * slope);
    return shape;
  }

  template <int dim>
  Neck
  narrowest_neck(const LevelSetField<dim> &level_set,
                 const Point<dim>         &c1,
                 const Point<dim>         &c2)
  {
    return narrowest_necks(RayCaster<dim>(level_set), {{c1, c2}})[0];
  }

  std::vector<PairNeck>
  neighbour_pairs(const std::vector<std::vector<double>> &particles,
                  const double                            near_miss_gap)
  {
    std::vector<PairNeck> pairs;
    for (unsigned int i = 0; i < particles.size(); ++i)
      for (unsigned int j = i + 1; j < particles.size(); ++j)
        {
          const auto  &p = particles[i], &q = particles[j];
          const auto   dim   = p.size() - 1;
          double       d2    = 0;
          for (unsigned int k = 0; k < dim; ++k)
            d2 += (p[k] - q[k]) * (p[k] - q[k]);
          const double sum = p[dim] + q[dim];
          const double gap = std::sqrt(d2) - sum;
          // Touching: within levelsinter-pack's default contact gap, far
          // below any cell (the mesh joins such pairs).
          const bool contact = particles.size() == 2 || gap <= 1e-3 * sum;
          if (contact || gap < near_miss_gap)
            pairs.push_back({i, j, contact, 0., 0.});
        }
    return pairs;
  }

  template <int dim>
  void
  measure_necks(const LevelSetField<dim>               &level_set,
                const std::vector<std::vector<double>> &particles,
                std::vector<PairNeck>                  &pairs)
  {
    // Equal particles neck on the mid-plane (by symmetry, and exactly on
    // symmetric meshes); unequal ones on their narrowest cross-section,
    // which a search finds.
    const auto centre = [&](const unsigned int i) {
      Point<dim> c;
      for (unsigned int d = 0; d < dim; ++d)
        c[d] = particles[i][d];
      return c;
    };
    std::vector<PairNeck *>                        equal, unequal, near_misses;
    std::vector<Section<dim>>                      mid_planes;
    std::vector<std::pair<Point<dim>, Point<dim>>> searched;
    std::vector<Ray<dim>>                          gap_rays;
    for (PairNeck &pair : pairs)
      {
        const Point<dim> c1 = centre(pair.i), c2 = centre(pair.j);
        if (particles[pair.i][dim] == particles[pair.j][dim])
          {
            equal.push_back(&pair);
            mid_planes.push_back({c1, c2, 0.5});
          }
        else
          {
            unequal.push_back(&pair);
            searched.emplace_back(c1, c2);
          }
        if (!pair.contact)
          {
            const Tensor<1, dim> axis = (c2 - c1) / c1.distance(c2);
            near_misses.push_back(&pair);
            gap_rays.push_back({c1, axis});
            gap_rays.push_back({c2, -axis});
          }
      }
    const RayCaster<dim>      caster(level_set);
    const std::vector<double> mid = cross_section_radii(caster, mid_planes);
    const std::vector<Neck>   narrowest = narrowest_necks(caster, searched);
    for (unsigned int k = 0; k < equal.size(); ++k)
      equal[k]->radius = mid[k];
    for (unsigned int k = 0; k < unequal.size(); ++k)
      unequal[k]->radius = narrowest[k].radius;
    const std::vector<double> exits =
      near_misses.empty() ? std::vector<double>() :
                            caster.exit_distances(gap_rays);
    for (PairNeck &pair : pairs)
      pair.gap = std::numeric_limits<double>::quiet_NaN();
    // A ray that leaves the box first (a partner across a symmetry plane)
    // measures nothing: NaN.
    for (unsigned int k = 0; k < near_misses.size(); ++k)
      if (std::isfinite(exits[2 * k]) && std::isfinite(exits[2 * k + 1]))
        near_misses[k]->gap = std::max(
          0.,
          centre(near_misses[k]->i).distance(centre(near_misses[k]->j)) -
            exits[2 * k] - exits[2 * k + 1]);
  }

  double
  smallest_neck_radius(const std::vector<PairNeck> &necks)
  {
    double neck = std::numeric_limits<double>::quiet_NaN();
    for (const PairNeck &pair : necks)
      if (pair.contact)
        neck = std::fmin(neck, pair.radius);
    return neck;
  }

  template <int dim>
  double
  smallest_neck_radius(const LevelSetField<dim>               &level_set,
                       const std::vector<std::vector<double>> &particles)
  {
    std::vector<PairNeck> contacts = neighbour_pairs(particles, 0);
    measure_necks(level_set, particles, contacts);
    return smallest_neck_radius(contacts);
  }

  template double
  neck_radius(const LevelSetField<2> &, const Point<2> &, const Point<2> &);
  template double
  neck_radius(const LevelSetField<3> &, const Point<3> &, const Point<3> &);
  template void
  measure_necks(const LevelSetField<2> &,
                const std::vector<std::vector<double>> &,
                std::vector<PairNeck> &);
  template void
  measure_necks(const LevelSetField<3> &,
                const std::vector<std::vector<double>> &,
                std::vector<PairNeck> &);
  template double
  smallest_neck_radius(const LevelSetField<2> &,
                       const std::vector<std::vector<double>> &);
  template double
  smallest_neck_radius(const LevelSetField<3> &,
                       const std::vector<std::vector<double>> &);
  template NeckShape<2>
  neck_shape(const LevelSetField<2> &,
             const Point<2> &,
             const Point<2> &,
             const double);
  template NeckShape<3>
  neck_shape(const LevelSetField<3> &,
             const Point<3> &,
             const Point<3> &,
             const double);
  template Neck
  narrowest_neck(const LevelSetField<2> &, const Point<2> &, const Point<2> &);
  template Neck
  narrowest_neck(const LevelSetField<3> &, const Point<3> &, const Point<3> &);
} // namespace levelsinter::neck_measures
