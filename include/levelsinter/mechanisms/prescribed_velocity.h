#pragma once

#include <deal.II/base/function.h>

#include <levelsinter/scene/scene_parameters.h>

#include <memory>

namespace levelsinter
{
  /**
   * The velocity a transport scene prescribes (Velocity section): none,
   * constant, rigid rotation, or a parsed expression of x and t. Returned as
   * a dim-component Function whose time the caller sets.
   */
  template <int dim>
  std::unique_ptr<Function<dim>>
  make_prescribed_velocity(const SceneParameters::Velocity &parameters);
} // namespace levelsinter
