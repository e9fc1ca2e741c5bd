#pragma once

#include <deal.II/base/function.h>
#include <deal.II/base/point.h>

#include <vector>

namespace levelsinter
{
  using namespace dealii;

  /**
   * Signed distance of the union of balls, negative inside: min_i
   * (|x - c_i| - r_i) outside (exact); inside, the distance to the exposed
   * parts of the spheres and to the junction rings of overlapping pairs
   * (exact where at most two balls overlap). min_i alone would put alpha
   * near 0 along the middle of a neck, where any velocity error then
   * pinches the solid from inside (seen in surface diffusion).
   */
  template <int dim>
  class UnionOfBalls : public Function<dim>
  {
  public:
    UnionOfBalls(const std::vector<Point<dim>> &centres,
                 const std::vector<double>     &radii);

    /** Rows (x, y[, z], r), as the scene parameters hold them. */
    explicit UnionOfBalls(const std::vector<std::vector<double>> &particles);

    double
    value(const Point<dim> &p, const unsigned int component = 0) const override;

    const std::vector<Point<dim>> &
    centres() const
    {
      return ball_centres;
    }

    const std::vector<double> &
    radii() const
    {
      return ball_radii;
    }

  private:
    void
    find_neighbours();

    double
    depth_inside(const Point<dim> &p, const std::vector<double> &gaps) const;

    std::vector<Point<dim>> ball_centres;
    std::vector<double>     ball_radii;
    // The balls that overlap ball i: only they can cover a point of its
    // sphere or form a junction ring with it.
    std::vector<std::vector<unsigned int>> neighbours;
    double                                 largest_radius = 0;
  };

  /**
   * A ball whose radius is modulated by one mode, the Mullins test of
   * surface diffusion: r = R (1 + delta cos(n theta)) in 2D,
   * r = R (1 + delta P_n(cos theta)) in 3D (axisymmetric about z, P_n the
   * Legendre polynomial, i.e. the spherical harmonic Y_n^0 up to a factor).
   * value() is the signed distance to first order in the slope,
   * (|x - c| - r(angle)) / sqrt(1 + |r'(angle)|^2 / |x - c|^2): exact zero
   * set, a distance accurate to O(delta^2) near it.
   */
  template <int dim>
  class PerturbedBall : public Function<dim>
  {
  public:
    /** @p revolution: a 2D scene that stands for a body of revolution
     * about x = 0 (Geometry/Axisymmetric) gets the 3D shape, P_n of the
     * angle from the axis. */
    PerturbedBall(const Point<dim>  &centre,
                  const double       radius,
                  const double       amplitude,
                  const unsigned int mode,
                  const bool         revolution = false);

    double
    value(const Point<dim> &p, const unsigned int component = 0) const override;

    /** The mode's amplitude delta of a shape given by r(angle). */
    double
    amplitude() const
    {
      return delta;
    }

  private:
    Point<dim>   centre;
    double       radius;
    double       delta;
    unsigned int mode;
    bool         revolution;
  };

  /**
   * Exact signed distance to Zalesak's slotted disk (2D): a disk with a
   * vertical slot of the given width cut from its bottom up to the given
   * depth. The boundary is one circular arc and three segments.
   */
  class SlottedDisk : public Function<2>
  {
  public:
    SlottedDisk(const Point<2> &centre,
                const double    radius,
                const double    slot_width,
                const double    slot_depth);

    double
    value(const Point<2> &p, const unsigned int component = 0) const override;

    /** Exact area and perimeter (for conservation and shape errors). */
    double
    area() const;
    double
    perimeter() const;

  private:
    bool
    inside(const Point<2> &p) const;

    Point<2> centre;
    double   radius;
    double   half_width;
    double   slot_top; // y of the slot's upper end
    double   slot_bottom; // y where the slot leaves the disk (on the arc)
  };

  /**
   * Exact volume (area in 2D) and surface area (perimeter in 2D) of two
   * equal balls of radius r whose centres are d apart (d < 2r: they
   * overlap in a lens).
   */
  template <int dim>
  double
  two_ball_volume(const double r, const double d);

  template <int dim>
  double
  two_ball_surface(const double r, const double d);
} // namespace levelsinter

#include <levelsinter/scene/scene_parameters.h>

#include <memory>

namespace levelsinter
{
  /** The signed distance of the scene's solid at t = 0 (Geometry section). */
  template <int dim>
  std::unique_ptr<Function<dim>>
  make_initial_signed_distance(const SceneParameters &scene);
} // namespace levelsinter
