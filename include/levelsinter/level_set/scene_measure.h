#pragma once

#include <deal.II/base/numbers.h>
#include <deal.II/base/point.h>

namespace levelsinter
{
  using namespace dealii;

  /**
   * The measure of a scene's integrals. An axisymmetric 2D scene
   * (`Geometry/Axisymmetric`) stands for the body of revolution about the
   * line x = 0: x = r >= 0 is the distance from the axis, y = z the
   * coordinate along it, and every volume, area and integral is that of
   * the 3D body, dV = 2 pi r dr dz and dS = 2 pi r ds. Otherwise the
   * measure is dx (areas and lengths in 2D).
   *
   * The forms of the velocity-pressure problem carry the hoop terms with
   * inverse_radius() (e_thth = v_r / r): it is 0 off the axisymmetric
   * case, so each form is written once and reduces to the plane one.
   */
  class SceneMeasure
  {
  public:
    SceneMeasure() = default;

    explicit SceneMeasure(const bool axisymmetric)
      : axisymmetric(axisymmetric)
    {}

    bool
    is_axisymmetric() const
    {
      return axisymmetric;
    }

    /** The factor of dx in the measure at @p x: 2 pi r or 1. */
    template <int dim>
    double
    weight(const Point<dim> &x) const
    {
      return axisymmetric ? 2 * numbers::PI * x[0] : 1.;
    }

    /** JxW of quadrature point @p q of @p values (which must have its
     * quadrature points) in this measure. */
    template <typename Values>
    double
    JxW(const Values &values, const unsigned int q) const
    {
      return axisymmetric ?
               values.JxW(q) * weight(values.quadrature_point(q)) :
               values.JxW(q);
    }

    /** 1 / r of the hoop terms at @p x, 0 off the axisymmetric case. The
     * quadrature points of the forms lie inside cells, never on the
     * axis. */
    template <int dim>
    double
    inverse_radius(const Point<dim> &x) const
    {
      return axisymmetric ? 1 / x[0] : 0.;
    }

    /** Dimension of the measured body: 3 for a body of revolution. */
    template <int dim>
    unsigned int
    body_dimension() const
    {
      return axisymmetric ? 3 : dim;
    }

  private:
    bool axisymmetric = false;
  };
} // namespace levelsinter
