#include <levelsinter/analysis/reference_shapes.h>
#include <levelsinter/scene/hopper.h>
#include <levelsinter/scene/solid_geometry.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace levelsinter
{
  template <int dim>
  UnionOfBalls<dim>::UnionOfBalls(const std::vector<Point<dim>> &centres,
                                  const std::vector<double>     &radii)
    : ball_centres(centres)
    , ball_radii(radii)
  {
    if (centres.size() != radii.size() || centres.empty())
      throw std::invalid_argument("UnionOfBalls needs one radius per centre");
    find_neighbours();
  }

  template <int dim>
  UnionOfBalls<dim>::UnionOfBalls(
    const std::vector<std::vector<double>> &particles)
  {
    for (const auto &row : particles)
      {
        if (row.size() != dim + 1)
          throw std::invalid_argument("a particle needs dim + 1 values");
        Point<dim> c;
        for (unsigned int d = 0; d < dim; ++d)
          c[d] = row[d];
        ball_centres.push_back(c);
        ball_radii.push_back(row[dim]);
      }
    if (ball_centres.empty())
      throw std::invalid_argument("UnionOfBalls needs at least one ball");
    find_neighbours();
  }

  template <int dim>
  void
  UnionOfBalls<dim>::find_neighbours()
  {
    const unsigned int n = ball_centres.size();
    neighbours.assign(n, {});
    largest_radius = *std::max_element(ball_radii.begin(), ball_radii.end());
    for (unsigned int i = 0; i < n; ++i)
      for (unsigned int j = i + 1; j < n; ++j)
        if (ball_centres[i].distance(ball_centres[j]) <
            ball_radii[i] + ball_radii[j])
          {
            neighbours[i].push_back(j);
            neighbours[j].push_back(i);
          }
  }

  template <int dim>
  double
  UnionOfBalls<dim>::value(const Point<dim> &p, const unsigned int) const
  {
    std::vector<double> gaps(ball_centres.size());
    for (unsigned int i = 0; i < ball_centres.size(); ++i)
      gaps[i] = p.distance(ball_centres[i]) - ball_radii[i];
    const double d = *std::min_element(gaps.begin(), gaps.end());
    if (d >= 0)
      return d;
    return -depth_inside(p, gaps);
  }

  template <int dim>
  double
  UnionOfBalls<dim>::depth_inside(const Point<dim>          &p,
                                  const std::vector<double> &gaps) const
  {
    // Distance to the union's boundary from inside: for each sphere the
    // nearest point is the radial projection if no other ball covers it,
    // else on the junction ring (circle in 3D, two points in 2D) with an
    // overlapping ball. Third balls covering a junction are ignored.
    // A boundary point at distance <= bound lies on a sphere with
    // gap <= bound, so only those spheres are searched; the bound grows
    // until the nearest point found is within it (then it is the nearest of
    // all). Costs O(neighbours) per sphere instead of O(n^2).
    auto covered = [&](const Point<dim> &q, const unsigned int i) {
      for (const unsigned int k : neighbours[i])
        if (q.distance(ball_centres[k]) < ball_radii[k] * (1 - 1e-12))
          return true;
      return false;
    };
    for (double bound = largest_radius;; bound *= 2)
      {
        double depth = std::numeric_limits<double>::max();
        for (unsigned int i = 0; i < ball_centres.size(); ++i)
          {
            if (gaps[i] > bound)
              continue;
            const Tensor<1, dim> x = p - ball_centres[i];
            const double         r = x.norm();
            if (r > 0 && !covered(ball_centres[i] + ball_radii[i] / r * x, i))
              depth = std::min(depth, std::abs(ball_radii[i] - r));
            for (const unsigned int j : neighbours[i])
              {
                const Tensor<1, dim> axis = ball_centres[j] - ball_centres[i];
                const double         c    = axis.norm();
                if (c <= std::abs(ball_radii[i] - ball_radii[j]))
                  continue;
                const Tensor<1, dim> e = axis / c;
                const double l = (c * c + ball_radii[i] * ball_radii[i] -
                                  ball_radii[j] * ball_radii[j]) /
                                 (2 * c);
                const double ring =
                  std::sqrt(ball_radii[i] * ball_radii[i] - l * l);
                const double t   = (x - l * e) * e;
                const double rho = (x - l * e - t * e).norm();
                depth            = std::min(depth, std::hypot(t, rho - ring));
              }
          }
        if (depth <= bound)
          return depth;
      }
  }

  SlottedDisk::SlottedDisk(const Point<2> &centre,
                           const double    radius,
                           const double    slot_width,
                           const double    slot_depth)
    : centre(centre)
    , radius(radius)
    , half_width(slot_width / 2)
    , slot_top(centre[1] - radius + slot_depth)
    , slot_bottom(centre[1] -
                  std::sqrt(radius * radius - half_width * half_width))
  {}

  bool
  SlottedDisk::inside(const Point<2> &p) const
  {
    const bool in_disk = p.distance(centre) < radius;
    const bool in_slot =
      std::abs(p[0] - centre[0]) < half_width && p[1] < slot_top;
    return in_disk && !in_slot;
  }

  namespace
  {
    double
    distance_to_segment(const Point<2> &p, const Point<2> &a, const Point<2> &b)
    {
      const Tensor<1, 2> ab = b - a;
      const double t = std::clamp((p - a) * ab / ab.norm_square(), 0.0, 1.0);
      return p.distance(a + t * ab);
    }
  } // namespace

  double
  SlottedDisk::value(const Point<2> &p, const unsigned int) const
  {
    const double   xl = centre[0] - half_width, xr = centre[0] + half_width;
    const Point<2> bl(xl, slot_bottom), tl(xl, slot_top), tr(xr, slot_top),
      br(xr, slot_bottom);
    double d = std::min({distance_to_segment(p, bl, tl),
                         distance_to_segment(p, tl, tr),
                         distance_to_segment(p, tr, br)});
    // The arc excludes the slot's mouth: points whose angular projection
    // falls in the mouth are nearest to one of its end points instead.
    const Tensor<1, 2> r = p - centre;
    const double       rn = r.norm();
    const bool in_mouth = r[1] < 0 && std::abs(r[0]) < half_width * rn / radius;
    if (!in_mouth && rn > 0)
      d = std::min(d, std::abs(rn - radius));
    else
      d = std::min({d, p.distance(bl), p.distance(br)});
    return inside(p) ? -d : d;
  }

  double
  SlottedDisk::area() const
  {
    // Disk minus the part of the slot rectangle inside the disk: the
    // rectangle above the mouth plus the circular segment below it.
    const double R = radius, a = half_width;
    const double h         = std::sqrt(R * R - a * a);
    const double segment   = R * R * std::asin(a / R) - a * h;
    const double rectangle = 2 * a * (slot_top - slot_bottom);
    return M_PI * R * R - segment - rectangle;
  }

  double
  SlottedDisk::perimeter() const
  {
    const double arc = 2 * radius * (M_PI - std::asin(half_width / radius));
    return arc + 2 * (slot_top - slot_bottom) + 2 * half_width;
  }

  template <>
  double
  two_ball_volume<2>(const double r, const double d)
  {
    const double theta = std::acos(d / (2 * r));
    const double lens  = 2 * (r * r * theta - (d / 2) * r * std::sin(theta));
    return 2 * M_PI * r * r - lens;
  }

  template <>
  double
  two_ball_volume<3>(const double r, const double d)
  {
    const double h = r - d / 2;
    return 2 * (4. / 3. * M_PI * r * r * r - M_PI * h * h * (3 * r - h) / 3);
  }

  template <>
  double
  two_ball_surface<2>(const double r, const double d)
  {
    const double theta = std::acos(d / (2 * r));
    return 2 * (2 * M_PI - 2 * theta) * r;
  }

  template <>
  double
  two_ball_surface<3>(const double r, const double d)
  {
    const double h = r - d / 2;
    return 2 * (4 * M_PI * r * r - 2 * M_PI * r * h);
  }

  template <int dim>
  PerturbedBall<dim>::PerturbedBall(const Point<dim>  &centre,
                                    const double       radius,
                                    const double       amplitude,
                                    const unsigned int mode,
                                    const bool         revolution)
    : centre(centre)
    , radius(radius)
    , delta(amplitude)
    , mode(mode)
    , revolution(revolution)
  {}

  template <int dim>
  double
  PerturbedBall<dim>::value(const Point<dim> &p, const unsigned int) const
  {
    const Tensor<1, dim> x = p - centre;
    const double         r = x.norm();
    if (r == 0)
      return -radius * (1 - delta);
    double shape = 0, slope = 0; // r(angle)/R - 1 and its angular derivative
    if (dim == 2 && !revolution)
      {
        const double theta = std::atan2(x[1], x[0]);
        shape               = delta * std::cos(mode * theta);
        slope               = -delta * mode * std::sin(mode * theta);
      }
    else
      {
        // P_n(c) and P_n'(c) by the three-term recurrences; the polar
        // angle from the last axis (the axis of revolution in 2D).
        const double c = x[dim - 1] / r;
        double       p_prev = 1, p = c, dp_prev = 0, dp = 1;
        if (mode == 0)
          p = 1, dp = 0;
        for (unsigned int k = 1; k < mode; ++k)
          {
            const double p_next  = ((2 * k + 1) * c * p - k * p_prev) / (k + 1);
            const double dp_next = dp_prev + (2 * k + 1) * p;
            p_prev               = p;
            p                    = p_next;
            dp_prev              = dp;
            dp                   = dp_next;
          }
        shape = delta * p;
        slope = -delta * dp * std::sqrt(std::max(0., 1 - c * c));
      }
    const double surface = radius * (1 + shape);
    return (r - surface) /
           std::sqrt(1 + radius * radius * slope * slope / (r * r));
  }

  template <int dim>
  std::unique_ptr<Function<dim>>
  make_initial_signed_distance(const SceneParameters &scene)
  {
    const auto &g = scene.geometry;
    if (g.shape == GeometryParameters::Shape::particles)
      {
        if (g.pores.empty() && g.superellipses.empty() &&
            g.elliptic_pores.empty() && g.implicit_function.empty())
          return std::make_unique<UnionOfBalls<dim>>(g.particles);
        std::vector<std::unique_ptr<Function<dim>>> parts, holes;
        if (!g.particles.empty())
          parts.push_back(std::make_unique<UnionOfBalls<dim>>(g.particles));
        for (const auto &row : g.superellipses)
          parts.push_back(make_superellipse_distance<dim>(row));
        if (!g.implicit_function.empty())
          parts.push_back(make_implicit_distance<dim>(
            g.implicit_function,
            g.implicit_constants,
            scene.domain.coarse_cell_size(),
            "Geometry/Implicit function"));
        if (!g.pores.empty())
          holes.push_back(std::make_unique<UnionOfBalls<dim>>(g.pores));
        for (const auto &row : g.elliptic_pores)
          holes.push_back(make_superellipse_distance<dim>(row));
        return std::make_unique<SolidMinusHoles<dim>>(std::move(parts),
                                                      std::move(holes));
      }
    if (scene.geometry.shape ==
        GeometryParameters::Shape::perturbed_particle)
      {
        const auto &particle = scene.geometry.particles.at(0);
        Point<dim>  centre;
        for (unsigned int d = 0; d < dim; ++d)
          centre[d] = particle[d];
        return std::make_unique<PerturbedBall<dim>>(
          centre,
          particle[dim],
          scene.geometry.perturbation_amplitude,
          scene.geometry.perturbation_mode,
          scene.geometry.axisymmetric);
      }
    if constexpr (dim == 2)
      {
        if (g.shape == GeometryParameters::Shape::hopper)
          {
            // The circles' overlap gives the neck (checked when parsed).
            return std::make_unique<HopperSignedDistance>(
              HopperPair(g.particles));
          }
        return std::make_unique<SlottedDisk>(
          Point<2>(g.slotted_disk_centre[0], g.slotted_disk_centre[1]),
          g.slotted_disk_radius,
          g.slot_width,
          g.slot_depth);
      }
    throw std::invalid_argument(
      "the slotted disk and Hopper's shape exist in 2D only");
  }

  template std::unique_ptr<Function<2>>
  make_initial_signed_distance<2>(const SceneParameters &);
  template std::unique_ptr<Function<3>>
  make_initial_signed_distance<3>(const SceneParameters &);
  template class UnionOfBalls<2>;
  template class UnionOfBalls<3>;
  template class PerturbedBall<2>;
  template class PerturbedBall<3>;
} // namespace levelsinter
