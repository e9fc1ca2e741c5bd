#pragma once

#include <levelsinter/level_set/level_set_filter.h>
#include <levelsinter/mechanisms/mechanism.h>

namespace levelsinter
{
  /**
   * The artificial volume-conservation velocity v^c = v^c N_alpha of
   * Eq. 113-116: a normal speed, uniform over the interface, that gives
   * back over one step the solid volume gained or lost since t = 0,
   *
   *   v^c = (V_0 - V) / (dt S),
   *
   * V and S the solid volume and interface measure at the end of the step.
   * As in the paper's Algorithm 2 it moves alpha in a transport of its own
   * after the step, so the step's own checks (the surface-energy check of
   * ViscousFlow) see only the physical motion. The deficit is measured
   * against t = 0 rather than against the last step: what the remeshing
   * loses is given back too. N_alpha are the nodal normals of the
   * interpolated distance (nodal_normals()), zero where alpha is saturated,
   * so the far field is untouched.
   */
  template <int dim>
  class VolumeCorrection : public Mechanism<dim>
  {
  public:
    VolumeCorrection(const std::vector<types::boundary_id> &symmetry_planes,
                     const LevelSetFilter                  &filter);

    std::string
    name() const override
    {
      return "volume correction";
    }

    void
    setup(const LevelSetField<dim> &) override
    {}

    void
    add_velocity(const LevelSetField<dim> &alpha,
                 const double              t,
                 const double              dt,
                 VelocityField<dim>       &velocity) override;

    void
    add_probe_velocity(const LevelSetField<dim> &alpha,
                       const double              t,
                       VelocityField<dim>       &velocity) override;

    bool
    add_correction_velocity(const LevelSetField<dim> &alpha,
                            const double              dt,
                            VelocityField<dim>       &velocity) override;

    /** The volume to keep. */
    std::string
    save() const override;

    void
    load(const std::string &state) override;

    std::vector<std::string>
    metric_names() const override;

    std::vector<double>
    metric_values() const override;

  private:
    // The first volume seen (t = 0 after any set_level_set(), or the
    // resumed state) is the one to keep.
    void
    keep_initial_volume(const LevelSetField<dim> &alpha);

    // Mirrored normals on these faces (nodal_normals()).
    const std::vector<types::boundary_id> symmetry_planes;
    const LevelSetFilter                  filter;
    double               initial_volume = -1;
    double               speed          = 0;
  };
} // namespace levelsinter
