#include <deal.II/base/quadrature_lib.h>

#include <levelsinter/analysis/hopper.h>

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
    // Gauss quadrature on 64 panels converges to ~1e-8 (checked against
    // the values DESIGN.md quotes).
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

  HopperLevelSet::HopperLevelSet(const Hopper         &hopper,
                                 const double          m,
                                 const LevelSetFilter &filter)
    : m(m)
    , hopper(hopper)
    , points(hopper.boundary(m, 20000))
    , filter(filter)
  {}

  double
  HopperLevelSet::value(const Point<2> &p, const unsigned int) const
  {
    double d2 = std::numeric_limits<double>::max();
    for (unsigned int i = 0; i < points.size(); ++i)
      {
        const Point<2>     &a  = points[i];
        const Point<2>     &b  = points[(i + 1) % points.size()];
        const Tensor<1, 2>  ab = b - a;
        const double        s =
          std::clamp((p - a) * ab / ab.norm_square(), 0., 1.);
        d2 = std::min(d2, (p - (a + s * ab)).norm_square());
      }
    const double d = std::sqrt(d2);
    return filter.filter(hopper.implicit(m, p) <= 0 ? -d : d);
  }
} // namespace levelsinter
