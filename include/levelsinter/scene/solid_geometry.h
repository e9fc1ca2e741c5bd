#pragma once

#include <deal.II/base/function.h>
#include <deal.II/base/function_parser.h>
#include <deal.II/base/point.h>

#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

namespace levelsinter
{
  using namespace dealii;

  /**
   * Rows "v1, v2, ...; ..." of an entry, each with names.size() finite
   * numbers; errors name @p entry_name, the row and what is wrong.
   */
  std::vector<std::vector<double>>
  parse_shape_rows(const std::string              &text,
                   const std::vector<std::string> &names,
                   const std::string              &entry_name);

  /**
   * The columns of a superellipse row: x, y, a, b, p, angle in 2D and
   * x, y, z, a, b, c, p, angle_x, angle_y, angle_z in 3D (angles in
   * degrees; the body is turned about x, then y, then z). An ellipse row
   * lacks p (it is 2).
   */
  std::vector<std::string>
  superellipse_columns(const unsigned int dim, const bool with_exponent);

  /**
   * Read the rows of an `Ellipses` (@p with_exponent false) or
   * `Superellipses` entry into superellipse rows (p = 2 for ellipses) and
   * check the semi-axes (> 0) and the exponent (>= 2: below, the shape has
   * tips of unbounded curvature that no level set resolves).
   */
  std::vector<std::vector<double>>
  parse_superellipses(const std::string &text,
                      const unsigned int dim,
                      const bool         with_exponent,
                      const std::string &entry_name);

  /**
   * Each superellipse row's surface must lie in the box [@p lower_corner,
   * @p upper_corner] but across faces its centre lies on (symmetry
   * planes); errors name @p entry_name and the row.
   */
  template <int dim>
  void
  check_superellipses_in_domain(const std::vector<std::vector<double>> &rows,
                                const std::vector<double> &lower_corner,
                                const std::vector<double> &upper_corner,
                                const std::string         &entry_name);

  /**
   * The implicit function must parse, be a number and be negative
   * somewhere on a grid over the box; errors name @p entry_name.
   */
  template <int dim>
  void
  check_implicit_function(const std::string                   &expression,
                          const std::map<std::string, double> &constants,
                          const std::vector<double>           &lower_corner,
                          const std::vector<double>           &upper_corner,
                          const std::string                   &entry_name);

  /**
   * The muparser function of x, y[, z] (and t if @p time_dependent) whose
   * @p n_components components @p expression gives, separated by ';'. It
   * is evaluated once, so that an unknown symbol fails here; a failure
   * throws std::runtime_error naming @p entry_name with the parser's
   * diagnosis, which deal.II would otherwise print to std::cerr first.
   */
  template <int dim>
  std::unique_ptr<FunctionParser<dim>>
  make_expression_function(const std::string                   &expression,
                           const unsigned int                   n_components,
                           const std::map<std::string, double> &constants,
                           const std::string                   &entry_name,
                           const bool time_dependent = false);

  /**
   * The constants of an implicit function, "name = value, ..." (pi is
   * always defined); errors name @p entry_name.
   */
  std::map<std::string, double>
  parse_constants(const std::string &text, const std::string &entry_name);

  /**
   * Signed distance to the zero set of a level function phi (negative
   * inside) whose zero set is not a sphere: the closest point on
   * {phi = 0} is found by projection (Newton steps along grad phi onto the
   * surface, then tangential steps toward the query point, halved while
   * they do not bring the surface point closer), so that the zero set of
   * the distance is that of phi to the projection's tolerance (1e-12 of
   * the length scale) and the distance is exact wherever the nearest
   * surface point is the one the projection reaches (within the reach of
   * the surface, in particular in the filter band). grad phi is by
   * central differences. Where the projection does not converge (far from
   * a surface phi describes badly), phi / |grad phi| is returned.
   */
  template <int dim>
  class ImplicitSurfaceDistance : public Function<dim>
  {
  public:
    ImplicitSurfaceDistance(std::function<double(const Point<dim> &)> phi,
                            const double length_scale);

    double
    value(const Point<dim> &p, const unsigned int component = 0) const override;

  private:
    Tensor<1, dim>
    gradient_of_phi(const Point<dim> &x) const;

    /** Newton steps along grad phi from @p x onto {phi = 0}. */
    bool
    project_onto_surface(Point<dim> &x) const;

    std::function<double(const Point<dim> &)> phi;
    double                                    length_scale;
  };

  /**
   * The signed distance to a superellipse |x'/a|^p + |y'/b|^p = 1 (a
   * superellipsoid in 3D), x' the body frame of a row of
   * parse_superellipses(). phi = min(a, b[, c]) (N(x') - 1), N the
   * scaled p-norm: homogeneous, so |grad phi| stays near 1 everywhere.
   */
  template <int dim>
  std::unique_ptr<Function<dim>>
  make_superellipse_distance(const std::vector<double> &row);

  /**
   * The signed distance to {f = 0}, f a muparser expression of x, y[, z]
   * and @p constants, negative inside. @p length_scale: the domain's size
   * (differencing step and tolerances). Throws std::runtime_error naming
   * @p entry_name if the expression does not parse or evaluate.
   */
  template <int dim>
  std::unique_ptr<Function<dim>>
  make_implicit_distance(const std::string                   &expression,
                         const std::map<std::string, double> &constants,
                         const double                         length_scale,
                         const std::string                   &entry_name);

  /**
   * A solid made of parts minus holes, from the parts' and holes' signed
   * distances: min over the parts (union), then max with minus the holes'
   * min (difference). Exact where one part's or one hole's surface is the
   * nearest (near the interface, away from the junctions).
   */
  template <int dim>
  class SolidMinusHoles : public Function<dim>
  {
  public:
    SolidMinusHoles(std::vector<std::unique_ptr<Function<dim>>> parts,
                    std::vector<std::unique_ptr<Function<dim>>> holes);

    double
    value(const Point<dim> &p, const unsigned int component = 0) const override;

  private:
    std::vector<std::unique_ptr<Function<dim>>> parts;
    std::vector<std::unique_ptr<Function<dim>>> holes;
  };
} // namespace levelsinter
