#pragma once

#include <deal.II/base/bounding_box.h>
#include <deal.II/base/function.h>
#include <deal.II/base/point.h>

#include <deal.II/dofs/dof_handler.h>

#include <deal.II/fe/fe_values.h>

#include <deal.II/non_matching/fe_immersed_values.h>

#include <deal.II/numerics/rtree.h>

#include <levelsinter/level_set/level_set_field.h>
#include <levelsinter/level_set/level_set_filter.h>

#include <functional>
#include <vector>

namespace levelsinter
{
  /**
   * Geometry measured on the discrete zero level set {alpha_h = 0} with
   * sharp cut-cell quadrature (deal.II NonMatching, Saye's algorithm): the
   * measurement error is that of the Q1 level set itself, not of a smeared
   * Heaviside.
   */
  namespace interface_measures
  {
    /**
     * What to integrate on each locally owned cell: quadrature of the
     * solid part {alpha_h < 0}, the atmosphere part {alpha_h > 0} and the
     * interface in the cell (empty functions and update_default flags skip
     * a region). Whole cells get the cell's Gauss rule.
     */
    template <int dim>
    struct RegionIntegrands
    {
      using Cell = typename DoFHandler<dim>::active_cell_iterator;

      UpdateFlags solid_flags      = update_default;
      UpdateFlags atmosphere_flags = update_default;
      UpdateFlags surface_flags    = update_default;
      std::function<void(const Cell &, const FEValues<dim> &)> on_solid;
      std::function<void(const Cell &, const FEValues<dim> &)> on_atmosphere;
      std::function<void(const Cell &,
                         const NonMatching::FEImmersedSurfaceValues<dim> &)>
        on_surface;
    };

    /** Visit the locally owned cells with sharp cut-cell quadrature. */
    template <int dim>
    void
    integrate_regions(const LevelSetField<dim>     &level_set,
                      const RegionIntegrands<dim> &integrands);

    /**
     * The solid's volume and the interface's area (VolumeAndArea, declared
     * with LevelSetField). Measured once per state of alpha: the field
     * keeps the result until alpha changes (measured_volume_and_area()).
     */
    template <int dim>
    VolumeAndArea
    volume_and_area(const LevelSetField<dim> &level_set);

    /**
     * Volume (area in 2D) of the atmosphere {alpha_h > 0} in the cells whose
     * centre lies in @p window: with a window that holds a closed pore and
     * solid around it, the pore's volume.
     */
    template <int dim>
    double
    atmosphere_volume(const LevelSetField<dim> &level_set,
                      const BoundingBox<dim>   &window);

    /**
     * The integral over {alpha_h = 0} of f(x, n), n the unit normal pointing
     * out of the solid (e.g. Fourier modes of a perturbed circle).
     */
    template <int dim>
    double
    interface_integral(
      const LevelSetField<dim> &level_set,
      const std::function<double(const Point<dim> &, const Tensor<1, dim> &)>
        &integrand);

    /**
     * Distance of the discrete interface from an exact one, given as a signed
     * distance function: the integral of |d| over {alpha_h = 0} (to first
     * order the area of the symmetric difference between the two solids), and
     * the largest |d| at a quadrature point.
     */
    struct ShapeError
    {
      double symmetric_difference = 0;
      double max_distance         = 0;
    };

    template <int dim>
    ShapeError
    shape_error(const LevelSetField<dim> &level_set,
                const Function<dim>      &exact_signed_distance);

    /** A ray: an origin and a unit direction. */
    template <int dim>
    struct Ray
    {
      Point<dim>     origin;
      Tensor<1, dim> direction;
    };

    /**
     * Casts rays on the discrete level set. A tree of the locally owned
     * cells' bounding boxes, built once, gives the cells a ray crosses;
     * they are walked from the origin and the walk stops at the first
     * crossing of the interface, so that a ray costs a few cells, not a
     * pass over the mesh. Keep it while the mesh and alpha stay as they
     * are.
     */
    template <int dim>
    class RayCaster
    {
    public:
      explicit RayCaster(const LevelSetField<dim> &level_set);

      /**
       * Per ray, the distance from its origin to the first point where it
       * leaves the solid; 0 if the origin lies in the pore, +infinity if
       * the ray leaves the domain without meeting the interface. One
       * reduction over the ranks for all the rays (collective).
       */
      std::vector<double>
      exit_distances(const std::vector<Ray<dim>> &rays) const;

    private:
      using Cell = typename DoFHandler<dim>::active_cell_iterator;
      const LevelSetField<dim> &level_set;
      RTree<std::pair<BoundingBox<dim>, Cell>> tree;
      BoundingBox<dim>                         extent; // of the local cells
    };

    /**
     * RayCaster::exit_distances() of the rays from @p origin along each
     * unit direction.
     */
    template <int dim>
    std::vector<double>
    exit_distances(const LevelSetField<dim>          &level_set,
                   const Point<dim>                  &origin,
                   const std::vector<Tensor<1, dim>> &directions);

    /**
     * How well alpha satisfies the reinitialisation target |grad alpha| =
     * g(alpha) (Eq. 67) where the filter is not saturated (|d| <= E/2):
     * the largest and the root-mean-square deviation over that region.
     */
    struct GradientNormError
    {
      double max_error = 0;
      double rms_error = 0;
    };

    template <int dim>
    GradientNormError
    gradient_norm_error(const LevelSetField<dim> &level_set,
                        const LevelSetFilter     &filter);
  } // namespace interface_measures
} // namespace levelsinter
