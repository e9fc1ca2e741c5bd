#pragma once

#include <deal.II/dofs/dof_handler.h>

#include <levelsinter/level_set/level_set_field.h>
#include <levelsinter/level_set/level_set_filter.h>

namespace levelsinter
{
  using namespace dealii;

  /**
   * Whether every vertex of @p cell lies where the filter still has slope
   * > 0.3 (|d| < 0.8 E for the sine filter): alpha, and the normals taken
   * from it, carry the geometry there; beyond, alpha saturates and the
   * normal is undefined. The band of the curvature and the normal-gradient
   * systems.
   */
  template <int dim>
  bool
  in_geometry_band(const LevelSetFilter                                 &filter,
                   const TrilinosWrappers::MPI::Vector                  &alpha,
                   const typename DoFHandler<dim>::active_cell_iterator &cell)
  {
    for (const unsigned int v : cell->vertex_indices())
      if (filter.gradient_norm_target(alpha(cell->vertex_dof_index(v, 0))) <
          0.3)
        return false;
    return true;
  }

  /** The same for the level set's own values. */
  template <int dim>
  bool
  in_geometry_band(const LevelSetFilter                                 &filter,
                   const LevelSetField<dim>                             &level_set,
                   const typename DoFHandler<dim>::active_cell_iterator &cell)
  {
    return in_geometry_band<dim>(filter, level_set.alpha(), cell);
  }
} // namespace levelsinter
