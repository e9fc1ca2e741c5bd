#pragma once

#include <deal.II/distributed/tria.h>

#include <levelsinter/scene/scene_parameters.h>

namespace levelsinter
{
  /** The box domain of the scene, its coarse cells and face ids 0..2*dim-1
   *  (x-, x+, y-, y+, z-, z+). */
  template <int dim>
  void
  make_box_mesh(parallel::distributed::Triangulation<dim> &tria,
                const SceneParameters::Domain             &domain);
} // namespace levelsinter
