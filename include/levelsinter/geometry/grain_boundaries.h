#pragma once

#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>

#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>

#include <levelsinter/geometry/power_cells.h>
#include <levelsinter/level_set/level_set_field.h>

#include <array>
#include <vector>

namespace levelsinter
{
  /**
   * Grains as the solid in the power cells of their centres (PowerCells),
   * and the grain boundaries between them: flat, on the radical plane of
   * each pair, ending at the free surface (the triple line, the neck root)
   * or at a third grain (a triple junction). doc/numerics.md, "Grain
   * boundaries and densification".
   */
  namespace grain_geometry
  {
    /** The grain boundary of grains i < j, measured on the level set. */
    template <int dim>
    struct GrainBoundary
    {
      unsigned int i = 0;
      unsigned int j = 0;
      // On the line of centres where the powers of i and j are equal.
      Point<dim> origin;
      // (c_j - c_i) / |c_j - c_i|: the boundary's normal.
      Tensor<1, dim> normal;
      double         centre_distance = 0;
      // A plane 2D boundary (a strip), not a disc (3D, axisymmetric).
      bool strip = false;
      // a: the half width (2D), the radius of the disc of the same area
      // (3D, axisymmetric).
      double radius = 0;
      // 2D: the distances from the origin to the two ends along +t and -t
      // (t the normal turned by +90 degrees), the mirrored one where a ray
      // leaves the domain.
      double end_distance[2] = {0, 0};
      // The whole boundary (per unit depth in 2D) and its part in the
      // domain (symmetry planes cut it).
      double area           = 0;
      double area_in_domain = 0;
      // P and G of the contact law (doc/numerics.md): the length of the
      // triple line (2 per unit depth in 2D) and pi a^4 / 8 (3D) or
      // 2 a^3 / 3 (2D), with N = G gamma_s u / C_gb - F.
      double perimeter  = 0;
      double resistance = 0;
    };

    /**
     * The grain boundaries of the grains @p grains (their centres and
     * weights) on @p level_set: the pairs within 10 % of touching whose
     * radical plane meets the solid between them, with rays in that plane
     * to the interface (RayCaster) or to a third grain's cell. Collective
     * (one reduction for all rays).
     */
    template <int dim>
    std::vector<GrainBoundary<dim>>
    find_grain_boundaries(const LevelSetField<dim> &level_set,
                          const PowerCells<dim>    &grains);

    /**
     * Sets the ends of a 2D strip (@p end_0 along +t, @p end_1 along -t;
     * a disc's radius is @p end_0) and what follows from them: the
     * radius, area, perimeter and resistance; the part of the area in the
     * domain keeps its share of the whole.
     */
    template <int dim>
    void
    set_extent(GrainBoundary<dim> &boundary,
               const double        end_0,
               const double        end_1,
               const bool          body_3d);

    /**
     * Circles fitted (algebraic fit, Kasa) in the meridian plane (zeta,
     * rho) of each grain boundary to the surface of each of its grains
     * (side 0: grain i at zeta < 0, side 1: j) and, on a 2D strip, at each
     * end (0 along +t): near the triple line, from @p inner to @p inner +
     * R / 4 off the plane (R the larger grain's radius; on a body of
     * revolution with the centre on the line of centres, the pair's
     * axis), and over the whole grain beyond @p inner. Surface points
     * within @p inner of a grain's other boundaries are left out: their
     * grooves are not on the circle. Each circle is (zeta_c, rho_c,
     * radius), NaN without enough points. Collective.
     */
    struct SurfaceCircles
    {
      std::array<double, 3> near[2][2];
      std::array<double, 3> whole[2][2];
    };

    template <int dim>
    std::vector<SurfaceCircles>
    fit_surface_circles(const LevelSetField<dim>              &level_set,
                        const PowerCells<dim>                 &grains,
                        const std::vector<GrainBoundary<dim>> &boundaries,
                        const double                           inner);

    /**
     * Where @p circle (zeta_c, rho_c, radius) meets the plane zeta = 0 on
     * its outer side, rho_c + sqrt(radius^2 - zeta_c^2): for a near
     * circle the sharp triple line, whose corner the smooth level set
     * fills; NaN if it does not meet the plane.
     */
    double
    plane_crossing(const std::array<double, 3> &circle);

    /**
     * The kernel about the triple line of @p boundary at @p x: phi(zeta /
     * l) phi((rho - a) / l), zeta the distance from the boundary's plane,
     * rho from the line of centres (in 2D to the end on x's side), phi(s)
     * = (1 + cos pi s) / 2 on |s| < 1, else 0. With @p plateau p > 0 it is
     * phi(zeta / l) phi(max(|rho - a| - p, 0) / max(l, p)): flat along the
     * plane over p either side of the triple line (the sharp triple-line
     * condition's kernel, narrow across the plane).
     */
    template <int dim>
    double
    triple_line_weight(const GrainBoundary<dim> &boundary,
                       const Point<dim>         &x,
                       const double              width,
                       const double              plateau = 0);

    /**
     * The shares of the point @p x among the grains @p near (PowerCells::
     * candidates, owner first): grain k's share is the product over the
     * others l of min(1, max(0, 1/2 + s_kl / @p width)), s_kl the distance
     * of x from the plane of (k, l) on k's side, normalised to sum 1. A
     * point that changes owner would move its whole quadrature weight
     * between grains; with the ramp a grain's volume changes smoothly as
     * the planes move, and a point on a plane is shared half and half.
     */
    template <int dim>
    void
    grain_shares(const PowerCells<dim>           &grains,
                 const Point<dim>                &x,
                 const std::vector<unsigned int> &near,
                 const double                     width,
                 std::vector<double>             &share);

    /**
     * Each grain's solid volume (area in 2D; axisymmetric: per radian):
     * the cut-cell quadrature of the solid split by grain_shares() with the
     * width of each mesh cell. With @p jacobian, also the derivatives
     * dV_i / dw_j of these volumes in the weights (w_i = r_i^2), from the
     * ramps of pairs (exact where two grains meet). With @p centroids,
     * also each grain's centroid (of its solid in the domain, split the
     * same way; NaN for a grain without solid). Collective.
     */
    template <int dim>
    std::vector<double>
    grain_volumes(const LevelSetField<dim> &level_set,
                  const PowerCells<dim>    &grains,
                  FullMatrix<double>       *jacobian  = nullptr,
                  std::vector<Point<dim>>  *centroids = nullptr);

    /**
     * Per cell of the level set's mesh (active cell index; locally owned
     * cells only): the grain whose cell holds the cell's centre, -1 on
     * cells with no solid (alpha > 0 at every vertex); and 1 where the
     * solid vertices belong to two or more grains (a grain boundary or a
     * triple line crosses the cell), else 0, if @p boundary is given.
     */
    template <int dim>
    void
    cell_grains(const LevelSetField<dim> &level_set,
                const PowerCells<dim>    &grains,
                dealii::Vector<float>    &grain_id,
                dealii::Vector<float>    *boundary = nullptr);
  } // namespace grain_geometry
} // namespace levelsinter
