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

  private:
    SceneParameters::Refinement settings;
    LevelSetFilter              filter;
  };
} // namespace levelsinter
