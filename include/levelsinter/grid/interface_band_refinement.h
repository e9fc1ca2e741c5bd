#pragma once

#include <deal.II/distributed/tria.h>

#include <levelsinter/level_set/level_set_field.h>
#include <levelsinter/level_set/level_set_filter.h>
#include <levelsinter/scene/scene_parameters.h>

namespace levelsinter
{
  /** The box domain of the scene, its coarse cells and face ids 0..2*dim-1
   *  (x-, x+, y-, y+, z-, z+). */
  template <int dim>
  void
  make_box_mesh(parallel::distributed::Triangulation<dim> &tria,
                const SceneParameters::Domain             &domain);

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
    InterfaceBandRefinement(const SceneParameters::Refinement &settings,
                            const LevelSetFilter              &filter);

    /**
     * Set refine/coarsen flags from alpha. Returns true if any cell
     * anywhere was flagged (all processes agree).
     */
    bool
    mark_cells(parallel::distributed::Triangulation<dim> &tria,
               const LevelSetField<dim>                  &level_set) const;

    /** The finest level a cell can reach: maximum level + curvature levels. */
    unsigned int
    finest_level() const;

  private:
    SceneParameters::Refinement settings;
    LevelSetFilter              filter;
  };
} // namespace levelsinter
