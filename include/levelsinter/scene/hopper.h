#pragma once

#include <deal.II/base/function.h>
#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>

#include <vector>

namespace levelsinter
{
  using namespace dealii;

  /**
   * Hopper's exact coalescence of two equal viscous cylinders of radius R
   * (doc/validation.md, "Hopper's two cylinders"), centred at the origin
   * with the line of centres along x: the boundary is
   * z = A zeta / (1 - m zeta^2), |zeta| = 1,
   * with A = sqrt2 R (1 - m^2) / sqrt(1 + m^2); the neck half-width is
   * y_n = sqrt2 R (1 - m) / sqrt(1 + m^2) and the dimensionless time
   * t gamma / (eta R) = (pi / sqrt2) int_m^1 dk / (k sqrt(1 + k^2) K(k)).
   * m = 1: two touching circles; m = 0: the final circle of radius sqrt2 R.
   */
  class Hopper
  {
  public:
    explicit Hopper(const double R);

    /** Neck half-width y_n at parameter m. */
    double
    neck(const double m) const;

    /** d y_n / d(t gamma / (eta R)) at m. */
    double
    neck_speed(const double m) const;

    /** m for a neck half-width y. */
    double
    m_of_neck(const double y) const;

    /** Dimensionless time t gamma / (eta R) from touching (m = 1) to m. */
    double
    time(const double m) const;

    /** m reached at dimensionless time tau. */
    double
    m_of_time(const double tau) const;

    /** @p n boundary points z(theta) of the shape with parameter m. */
    std::vector<Point<2>>
    boundary(const double m, const unsigned int n) const;

    /** The implicit quartic of the shape: negative inside the solid. */
    double
    implicit(const double m, const Point<2> &p) const;

  private:
    double R;
  };

  /**
   * The shape Geometry/Shape = hopper takes from two equal circles: their
   * radius R, the midpoint of their centres and the unit vector from the
   * first centre to the second (the line of centres), and Hopper's m of the
   * neck half-width sqrt(R^2 - c^2) of their overlap, c half the centre
   * distance.
   */
  struct HopperPair
  {
    /** From two circles 'x, y, r' (Geometry/Particles), the first one's
     *  radius taken for both. */
    explicit HopperPair(const std::vector<std::vector<double>> &circles);

    /** Whether the circles overlap (0 < 2c < 2R): only then is there a
     *  neck, and m() defined. */
    bool
    overlapping() const;

    /** Hopper's m of the overlap's neck (needs overlapping()). */
    double
    m() const;

    double       R;
    double       half_distance;
    Point<2>     centre;
    Tensor<1, 2> direction;
  };

  /**
   * Signed distance (negative inside) to Hopper's shape of @p pair (its m,
   * centre and line of centres): the distance
   * to a fine polygon of the boundary (20 000 sides, sagitta below 1e-5 R
   * for m < 0.9; searched through a coarse one of 500 sides), the sign from
   * the implicit quartic. The start of
   * Geometry/Shape = hopper.
   */
  class HopperSignedDistance : public Function<2>
  {
  public:
    explicit HopperSignedDistance(const HopperPair &pair);

    double
    value(const Point<2> &p, const unsigned int component = 0) const override;

  private:
    /** Vertex @p c of the coarse polygon (every chunk-th fine vertex). */
    const Point<2> &
    coarse_vertex(const unsigned int c) const;

    Hopper                hopper;
    double                m;
    Point<2>              centre;
    Tensor<1, 2>          axis;
    std::vector<Point<2>> points;
    // The largest distance of the fine polygon from each coarse side.
    std::vector<double>   deviation;
  };
} // namespace levelsinter
