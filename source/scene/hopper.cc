#include <deal.II/base/quadrature_lib.h>

#include <levelsinter/scene/hopper.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <limits>

namespace levelsinter
{
  namespace
  {
    // f changes sign on [a, b]; f(a) has the sign of -f(b).
    template <typename F>
    double
    bisect(const F &f, double a, double b)
    {
      const double fa = f(a);
      for (unsigned int i = 0; i < 200 && b - a > 1e-14; ++i)
        {
          const double c = 0.5 * (a + b);
          if ((f(c) > 0) == (fa > 0))
            a = c;
          else
            b = c;
        }
      return 0.5 * (a + b);
    }
  } // namespace

  Hopper::Hopper(const double R)
    : R(R)
  {}

  double
  Hopper::neck(const double m) const
  {
    return std::sqrt(2.) * R * (1 - m) / std::sqrt(1 + m * m);
  }

  double
  Hopper::neck_speed(const double m) const
  {
    // Central differences in m.
    const double dm = 1e-4 * std::min(m, 1 - m);
    return (neck(m + dm) - neck(m - dm)) / (time(m + dm) - time(m - dm));
  }

  double
  Hopper::m_of_neck(const double y) const
  {
    // y_n decreases monotonically with m.
    return bisect([&](const double m) { return neck(m) - y; }, 0, 1);
  }

  double
  Hopper::time(const double m) const
  {
    // The integrand vanishes like 1/log at k = 1 (K(k) diverges);
    // substituting k = 1 - (1 - m) s^2 removes the endpoint steepness, then
    // Gauss quadrature on 64 panels converges to ~1e-8 (it reproduces
    // Hopper's 0.0601 / 0.4619 / 1.4447 at y_n / R = 0.1 / 0.5 / 1,
    // doc/validation.md "Hopper's two cylinders").
    const QGauss<1> gauss(8);
    const unsigned  panels = 64;
    double          sum    = 0;
    for (unsigned int p = 0; p < panels; ++p)
      for (unsigned int q = 0; q < gauss.size(); ++q)
        {
          const double s  = (p + gauss.point(q)[0]) / panels;
          const double k  = 1 - (1 - m) * s * s;
          const double dk = 2 * (1 - m) * s / panels * gauss.weight(q);
          sum += dk / (k * std::sqrt(1 + k * k) * std::comp_ellint_1(k));
        }
    return M_PI / std::sqrt(2.) * sum;
  }

  double
  Hopper::m_of_time(const double tau) const
  {
    // time() decreases with m.
    return bisect([&](const double m) { return tau - time(m); }, 0, 1);
  }

  std::vector<Point<2>>
  Hopper::boundary(const double m, const unsigned int n) const
  {
    const double A = std::sqrt(2.) * R * (1 - m * m) / std::sqrt(1 + m * m);
    std::vector<Point<2>> points(n);
    for (unsigned int i = 0; i < n; ++i)
      {
        const std::complex<double> zeta = std::polar(1.0, 2 * M_PI * i / n);
        const std::complex<double> z    = A * zeta / (1. - m * zeta * zeta);
        points[i]                       = Point<2>(z.real(), z.imag());
      }
    return points;
  }

  double
  Hopper::implicit(const double m, const Point<2> &p) const
  {
    const double x2 = p[0] * p[0], y2 = p[1] * p[1];
    return (x2 + y2) * (x2 + y2) -
           2 * R * R / (1 + m * m) *
             ((1 + m) * (1 + m) * x2 + (1 - m) * (1 - m) * y2);
  }

  namespace
  {
    double
    squared_distance_to_segment(const Point<2> &p,
                                const Point<2> &a,
                                const Point<2> &b)
    {
      const Tensor<1, 2> ab = b - a;
      const double       s = std::clamp((p - a) * ab / ab.norm_square(), 0., 1.);
      return (p - (a + s * ab)).norm_square();
    }

    // Sides of the fine polygon per side of the coarse one that the search
    // looks at first.
    constexpr unsigned int chunk = 40;

    // From the first circle's centre to the second's.
    Tensor<1, 2>
    line_of_centres(const std::vector<std::vector<double>> &circles)
    {
      return Tensor<1, 2>({circles.at(1).at(0) - circles.at(0).at(0),
                           circles[1].at(1) - circles[0].at(1)});
    }
  } // namespace

  HopperPair::HopperPair(const std::vector<std::vector<double>> &circles)
    : R(circles.at(0).at(2))
    , half_distance(line_of_centres(circles).norm() / 2)
    , centre((circles[0][0] + circles[1][0]) / 2,
             (circles[0][1] + circles[1][1]) / 2)
  {
    if (half_distance > 0)
      direction = line_of_centres(circles) / (2 * half_distance);
  }

  bool
  HopperPair::overlapping() const
  {
    return half_distance > 0 && half_distance < R;
  }

  double
  HopperPair::m() const
  {
    return Hopper(R).m_of_neck(
      std::sqrt(R * R - half_distance * half_distance));
  }

  HopperSignedDistance::HopperSignedDistance(const HopperPair &pair)
    : hopper(pair.R)
    , m(pair.m())
    , centre(pair.centre)
    , axis(pair.direction)
    , points(hopper.boundary(m, 500 * chunk))
    , deviation(500)
  {
    for (unsigned int c = 0; c < deviation.size(); ++c)
      for (unsigned int i = c * chunk; i <= (c + 1) * chunk; ++i)
        deviation[c] = std::max(
          deviation[c],
          std::sqrt(squared_distance_to_segment(points[i % points.size()],
                                                coarse_vertex(c),
                                                coarse_vertex(c + 1))));
  }

  const Point<2> &
  HopperSignedDistance::coarse_vertex(const unsigned int c) const
  {
    return points[(c * chunk) % points.size()];
  }

  double
  HopperSignedDistance::value(const Point<2> &x, const unsigned int) const
  {
    // x in the shape's own frame: the line of centres along the first axis.
    const Tensor<1, 2> r = x - centre;
    const Point<2>     p(r * axis, axis[0] * r[1] - axis[1] * r[0]);
    // The fine polygon lies within deviation[c] of coarse side c, so only
    // the coarse sides nearer than the nearest coarse vertex (a vertex of
    // the fine polygon too) by that much can hold the nearest point.
    double d2 = std::numeric_limits<double>::max();
    for (unsigned int c = 0; c < deviation.size(); ++c)
      d2 = std::min(d2, (p - coarse_vertex(c)).norm_square());
    const double upper = std::sqrt(d2);
    for (unsigned int c = 0; c < deviation.size(); ++c)
      if (std::sqrt(squared_distance_to_segment(p,
                                                coarse_vertex(c),
                                                coarse_vertex(c + 1))) -
            deviation[c] <=
          upper)
        for (unsigned int i = c * chunk; i < (c + 1) * chunk; ++i)
          d2 = std::min(d2,
                        squared_distance_to_segment(
                          p, points[i], points[(i + 1) % points.size()]));
    const double d = std::sqrt(d2);
    return hopper.implicit(m, p) <= 0 ? -d : d;
  }
} // namespace levelsinter
