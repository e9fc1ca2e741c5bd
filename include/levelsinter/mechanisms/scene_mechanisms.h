#pragma once

#include <deal.II/base/timer.h>

#include <levelsinter/mechanisms/mechanism.h>
#include <levelsinter/scene/scene_parameters.h>

#include <memory>
#include <vector>

namespace levelsinter
{
  /**
   * The mechanisms a scene switches on, in the order their velocities are
   * summed. Only these are built: a scene computes only what it needs.
   */
  template <int dim>
  std::vector<std::unique_ptr<Mechanism<dim>>>
  make_scene_mechanisms(const SceneParameters &scene, TimerOutput &timer);
} // namespace levelsinter
