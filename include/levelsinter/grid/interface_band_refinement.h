#pragma once

#include <deal.II/distributed/tria.h>

#include <deal.II/fe/fe_values.h>

#include <deal.II/lac/trilinos_vector.h>
#include <deal.II/lac/vector.h>

#include <levelsinter/level_set/level_set_field.h>
#include <levelsinter/level_set/level_set_filter.h>
#include <levelsinter/level_set/scene_measure.h>
#include <levelsinter/scene/scene_parameters.h>

#include <array>

namespace levelsinter
{
  /**
   * Refinement concentrated in a band around alpha = 0: a cell whose
   * vertices come within the band width of the interface (distance read back
   * through the filter) or that the interface crosses is refined up to the
   * maximum level; every other cell is coarsened down to the minimum level.
   * p4est's 2:1 balance grades the mesh in between.
   *
   * With curvature refinement levels k > 0, a band cell of size h at the
   * maximum level or above is refined further, up to k extra levels, while
   * N_r h |grad N| > 1 at its centre (N the nodal normals of the distance,
   * |grad N| the Frobenius norm, sqrt(k1^2 + k2^2) of the principal
   * curvatures; N_r = cells per curvature radius): necks whose meniscus is
   * narrower than a few band cells. Extra level j is confined to the band
   * width / 2^j, so that each level's band holds as many of its own cells as
   * the main band. A cell is coarsened back only once its parent would
   * resolve the curvature radius with 2 N_r cells: the factor 2 between the
   * two thresholds keeps cells from being refined and coarsened in turn.
   */
  template <int dim>
  class InterfaceBandRefinement
  {
  public:
    /** @p symmetry_boundaries: box faces across which the scene is
     *  mirrored (the curvature reads a kink on them, nodal_normals()). */
    InterfaceBandRefinement(
      const SceneParameters::Refinement     &settings,
      const LevelSetFilter                  &filter,
      const std::vector<types::boundary_id> &symmetry_boundaries);

    /**
     * Set refine/coarsen flags from alpha. Returns true if any cell
     * anywhere was flagged (all processes agree).
     */
    bool
    mark_cells(parallel::distributed::Triangulation<dim> &tria,
               const LevelSetField<dim>                  &level_set) const;

    /**
     * The points of @p interface_points (on the interface) that lie in a
     * locally owned cell coarser than the maximum level, gathered from all
     * ranks: parts of the interface the band missed. The initial
     * refinement can miss a body whose surface passes between the nodes of
     * the coarse levels, which then never see it.
     */
    std::vector<Point<dim>>
    points_in_coarse_cells(
      const parallel::distributed::Triangulation<dim> &tria,
      const std::vector<Point<dim>>                   &interface_points) const;

    /** The finest level a cell can reach: maximum level + curvature levels. */
    unsigned int
    finest_level() const;

    /**
     * Interface cells at the finest level whose curvature radius is smaller
     * than the cell (h |grad N| > 1): there a curvature-driven speed is too
     * low, since the kink of the Q1 interface stands in for the unresolved
     * radius (doc/validation.md, "Neck speed on Hopper's exact shape").
     */
    struct CurvatureResolution
    {
      unsigned int under_resolved_cells  = 0;
      double       max_curvature_times_h = 0;
    };

    /** The above over all ranks (every process gets the same result). */
    CurvatureResolution
    curvature_resolution(const LevelSetField<dim> &level_set) const;

  private:
    /**
     * |grad N| at a cell's centre, N the Q1-interpolated nodal normals of
     * the distance: sqrt(k1^2 + k2^2), |kappa| in 2D; unlike div N it does
     * not cancel on a saddle-shaped neck. On a body of revolution the 3D
     * one, with the hoop curvature N_r / r as k2.
     */
    class CellCurvature
    {
    public:
      CellCurvature(const LevelSetField<dim>             &level_set,
                    const LevelSetFilter                 &filter,
                    const std::vector<types::boundary_id> &symmetry_boundaries);

      double
      operator()(const typename DoFHandler<dim>::active_cell_iterator &cell);

    private:
      // Of the distance, not of alpha: the filter's curvature would tilt
      // them (geometry/nodal_normals.h) and read as interface curvature.
      std::array<TrilinosWrappers::MPI::Vector, dim> normals;
      SceneMeasure                                   measure;
      FEValues<dim>                                  fe_values;
      dealii::Vector<double>                         local_normal;
    };

    /** Whether the interface crosses a cell with level-set DoFs @p indices
     *  (alpha changes sign). */
    static bool
    crossed(const std::vector<types::global_dof_index> &indices,
            const LevelSetField<dim>                   &level_set);

    SceneParameters::Refinement     settings;
    LevelSetFilter                  filter;
    std::vector<types::boundary_id> symmetry_boundaries;
  };
} // namespace levelsinter
