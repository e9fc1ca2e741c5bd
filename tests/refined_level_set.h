#pragma once

// Shared by the analysis tests: a level set that is the interpolated
// signed distance phi on a box mesh refined around its zero level set.

#include <deal.II/base/function.h>

#include <deal.II/distributed/tria.h>

#include <levelsinter/grid/box_mesh.h>
#include <levelsinter/level_set/level_set_field.h>
#include <levelsinter/scene/domain_parameters.h>

#include <cmath>

namespace levelsinter::study
{
  /**
   * @p domain refined twice, then where |phi| < the cell diameter (every
   * cell the zero level set crosses) up to @p level; alpha = phi at the
   * vertices.
   */
  template <int dim>
  void
  build_refined_level_set(parallel::distributed::Triangulation<dim> &tria,
                          LevelSetField<dim>                        &level_set,
                          const DomainParameters                    &domain,
                          const Function<dim>                       &phi,
                          const unsigned int                         level)
  {
    make_box_mesh(tria, domain);
    tria.refine_global(2);
    for (unsigned int l = 2; l < level; ++l)
      {
        for (const auto &cell : tria.active_cell_iterators())
          if (cell->is_locally_owned() &&
              std::abs(phi.value(cell->center())) < cell->diameter())
            cell->set_refine_flag();
        tria.execute_coarsening_and_refinement();
      }
    level_set.setup_dofs();
    level_set.interpolate(phi);
  }
} // namespace levelsinter::study
