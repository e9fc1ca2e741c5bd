#include <levelsinter/mechanisms/grain_boundary_diffusion.h>
#include <levelsinter/mechanisms/prescribed_velocity.h>
#include <levelsinter/mechanisms/scene_mechanisms.h>
#include <levelsinter/mechanisms/viscous_flow.h>
#include <levelsinter/mechanisms/surface_diffusion.h>
#include <levelsinter/mechanisms/volume_correction.h>
#include <levelsinter/mechanisms/volume_diffusion.h>

namespace levelsinter
{
  template <int dim>
  std::vector<std::unique_ptr<Mechanism<dim>>>
  make_scene_mechanisms(const SceneParameters &scene, TimerOutput &timer)
  {
    std::vector<std::unique_ptr<Mechanism<dim>>> mechanisms;
    if (scene.velocity.type != PrescribedVelocityParameters::Type::none)
      mechanisms.push_back(std::make_unique<PrescribedVelocity<dim>>(
        scene.velocity, scene.level_set.theta));
    const LevelSetFilter filter(scene.level_set.filter,
                                scene.level_set.filter_thickness);
    if (scene.viscous_flow.enabled)
      mechanisms.push_back(
        std::make_unique<ViscousFlow<dim>>(scene.viscous_flow,
                                           scene.materials,
                                           scene.domain.symmetry_planes,
                                           filter,
                                           scene.refinement.max_level,
                                           timer,
                                           scene.phase_law));
    if (scene.surface_diffusion.enabled)
      {
        auto surface_diffusion = std::make_unique<SurfaceDiffusion<dim>>(
          scene.surface_diffusion,
          scene.seconds_per_time_unit(),
          scene.domain.symmetry_planes,
          filter,
          timer);
        // After surface diffusion (SceneParameters requires it): it reads
        // that solve's curvature and normals of the same step.
        std::unique_ptr<Mechanism<dim>> grain_boundaries;
        if (scene.grain_boundaries.enabled)
          grain_boundaries = std::make_unique<GrainBoundaryDiffusion<dim>>(
            scene.grain_boundaries,
            scene.geometry.particles,
            scene.seconds_per_time_unit(),
            *surface_diffusion,
            timer);
        mechanisms.push_back(std::move(surface_diffusion));
        if (grain_boundaries)
          mechanisms.push_back(std::move(grain_boundaries));
      }
    // SceneParameters refuses it with viscous flow and without the
    // elastic-solid law. With surface diffusion as well (Eq. 118,
    // Algorithm 4) the time loop adds both velocities, transports once and
    // corrects the volume after both.
    if (scene.volume_diffusion.enabled)
      mechanisms.push_back(std::make_unique<VolumeDiffusion<dim>>(
        scene.volume_diffusion,
        scene.seconds_per_time_unit(),
        scene.viscous_flow,
        scene.materials,
        scene.phase_law,
        scene.domain.symmetry_planes,
        filter,
        scene.refinement.max_level,
        timer));
    // Last: it corrects the volume whatever the others moved.
    if (scene.volume_correction.enabled)
      mechanisms.push_back(std::make_unique<VolumeCorrection<dim>>(
        scene.domain.symmetry_planes, filter));
    return mechanisms;
  }

  template std::vector<std::unique_ptr<Mechanism<2>>>
  make_scene_mechanisms<2>(const SceneParameters &, TimerOutput &);
  template std::vector<std::unique_ptr<Mechanism<3>>>
  make_scene_mechanisms<3>(const SceneParameters &, TimerOutput &);
} // namespace levelsinter
