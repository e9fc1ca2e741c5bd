#include <levelsinter/analysis/neck.h>
#include <levelsinter/level_set/interface_measures.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace levelsinter::neck_measures
{
  using interface_measures::exit_distances;

  namespace
  {
    // Mean exit distance from the point c1 + s (c2 - c1) over rays in the
    // plane through it normal to c2 - c1 (2 rays in 2D, 8 in 3D). Rays that
    // leave the domain before meeting the interface (symmetry planes) are
    // skipped.
    template <int dim>
    double
    cross_section_radius(const LevelSetField<dim> &level_set,
                         const Point<dim>         &c1,
                         const Point<dim>         &c2,
                         const double              s)
    {
      const Tensor<1, dim> axis = (c2 - c1) / (c2 - c1).norm();
      std::vector<Tensor<1, dim>> directions;
      if constexpr (dim == 2)
        {
          const Tensor<1, dim> t({-axis[1], axis[0]});
          directions = {t, -t};
        }
      else
        {
          Tensor<1, dim> helper;
          helper[std::abs(axis[0]) < 0.9 ? 0 : 1] = 1;
          Tensor<1, dim> u = cross_product_3d(axis, helper);
          u /= u.norm();
          const Tensor<1, dim> w = cross_product_3d(axis, u);
          for (unsigned int k = 0; k < 8; ++k)
            directions.push_back(std::cos(k * M_PI / 4) * u +
                                 std::sin(k * M_PI / 4) * w);
        }
      double       sum     = 0;
      unsigned int n_valid = 0;
      for (const double d :
           exit_distances(level_set, c1 + s * (c2 - c1), directions))
        if (std::isfinite(d))
          {
            sum += d;
            ++n_valid;
          }
      return n_valid ? sum / n_valid : 0.;
    }
  } // namespace

  template <int dim>
  double
  neck_radius(const LevelSetField<dim> &level_set,
              const Point<dim>         &c1,
              const Point<dim>         &c2)
  {
    return cross_section_radius(level_set, c1, c2, 0.5);
  }

  template <int dim>
  Neck
  narrowest_neck(const LevelSetField<dim> &level_set,
                 const Point<dim>         &c1,
                 const Point<dim>         &c2)
  {
    // The cross-section radius falls from the first centre to the neck and
    // rises again to the second: a scan brackets the minimum, a golden-
    // section search narrows the bracket to 1e-4 of the centre distance
    // (the radius is flat there, so its error is of second order).
    auto         radius  = [&](const double s) {
      return cross_section_radius(level_set, c1, c2, s);
    };
    const unsigned int n_scan = 16;
    unsigned int       best   = 1;
    double             r_best = radius(1. / n_scan);
    for (unsigned int k = 2; k < n_scan; ++k)
      if (const double r = radius(double(k) / n_scan); r < r_best)
        {
          r_best = r;
          best   = k;
        }
    const double golden = (std::sqrt(5.) - 1) / 2;
    double       a = double(best - 1) / n_scan, b = double(best + 1) / n_scan;
    double       x1 = b - golden * (b - a), x2 = a + golden * (b - a);
    double       f1 = radius(x1), f2 = radius(x2);
    while (b - a > 1e-4)
      if (f1 < f2)
        {
          b  = x2;
          x2 = x1;
          f2 = f1;
          x1 = b - golden * (b - a);
          f1 = radius(x1);
        }
      else
        {
          a  = x1;
          x1 = x2;
          f1 = f2;
          x2 = a + golden * (b - a);
          f2 = radius(x2);
        }
    Neck neck;
    neck.position = f1 < f2 ? x1 : x2;
    neck.radius   = std::min({f1, f2, r_best});
    return neck;
  }
  template <int dim>
  std::vector<PairNeck>
  pair_necks(const LevelSetField<dim>               &level_set,
             const std::vector<std::vector<double>> &particles)
  {
    std::vector<PairNeck> necks;
    for (unsigned int i = 0; i < particles.size(); ++i)
      for (unsigned int j = i + 1; j < particles.size(); ++j)
        {
          Point<dim> c1, c2;
          for (unsigned int d = 0; d < dim; ++d)
            {
              c1[d] = particles[i][d];
              c2[d] = particles[j][d];
            }
          if (particles.size() == 2 ||
              c1.distance(c2) < particles[i][dim] + particles[j][dim])
            // Equal particles neck on the mid-plane (by symmetry, and
            // exactly on symmetric meshes); unequal ones on their narrowest
            // cross-section, which a search finds.
            necks.push_back({i,
                             j,
                             particles[i][dim] == particles[j][dim] ?
                               neck_radius(level_set, c1, c2) :
                               narrowest_neck(level_set, c1, c2).radius});
        }
    return necks;
  }

  template <int dim>
  double
  smallest_neck_radius(const LevelSetField<dim>               &level_set,
                       const std::vector<std::vector<double>> &particles)
  {
    double neck = std::numeric_limits<double>::quiet_NaN();
    for (const PairNeck &pair : pair_necks(level_set, particles))
      neck = std::fmin(neck, pair.radius);
    return neck;
  }

  template double
  neck_radius(const LevelSetField<2> &, const Point<2> &, const Point<2> &);
  template double
  neck_radius(const LevelSetField<3> &, const Point<3> &, const Point<3> &);
  template std::vector<PairNeck>
  pair_necks(const LevelSetField<2> &, const std::vector<std::vector<double>> &);
  template std::vector<PairNeck>
  pair_necks(const LevelSetField<3> &, const std::vector<std::vector<double>> &);
  template double
  smallest_neck_radius(const LevelSetField<2> &,
                       const std::vector<std::vector<double>> &);
  template double
  smallest_neck_radius(const LevelSetField<3> &,
                       const std::vector<std::vector<double>> &);
  template Neck
  narrowest_neck(const LevelSetField<2> &, const Point<2> &, const Point<2> &);
  template Neck
  narrowest_neck(const LevelSetField<3> &, const Point<3> &, const Point<3> &);
} // namespace levelsinter::neck_measures
