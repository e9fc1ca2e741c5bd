#pragma once

#include <deal.II/base/timer.h>

#include <deal.II/lac/trilinos_vector.h>

#include <deal.II/numerics/data_postprocessor.h>

#include <levelsinter/geometry/normal_gradient_extension.h>
#include <levelsinter/level_set/level_set_filter.h>
#include <levelsinter/mechanics/phase_law.h>
#include <levelsinter/mechanics/extended_pressure_stokes.h>
#include <levelsinter/mechanisms/mechanism.h>
#include <levelsinter/scene/phase_law_parameters.h>
#include <levelsinter/scene/viscous_flow_parameters.h>
#include <levelsinter/scene/volume_diffusion_parameters.h>

#include <memory>

namespace levelsinter
{
  /**
   * Volume diffusion (paper Sect. 6, Algorithm 3): each step solves the
   * elastic-solid / fluid problem (Eq. 92-94, ElasticSolidFluid) under the
   * sharp tensorial surface tension (Eq. 108), extends xi = grad p . N from
   * the solid's pressure (Eq. 110-111, NormalGradientExtension) and adds
   * v = -C_v xi N at the level-set nodes (Eq. 112). The particles do not
   * move with the elastic velocity; it only builds the displacement
   * u^n = u^{n-1} + dt v^n whose strain the next step's history reads.
   * Surface energy gamma and atmosphere: `Materials`; solver: the
   * `Viscous flow` entries (disabled as a mechanism); moduli: `Phase law`.
   */
  template <int dim>
  class VolumeDiffusion : public Mechanism<dim>
  {
  public:
    VolumeDiffusion(const VolumeDiffusionParameters       &parameters,
                    const double                           seconds_per_unit,
                    const ViscousFlowParameters           &mechanics,
                    const MaterialsParameters             &materials,
                    const PhaseLawParameters              &law,
                    const std::vector<types::boundary_id> &symmetry_planes,
                    const LevelSetFilter                  &filter,
                    const unsigned int                     band_level,
                    TimerOutput                           &timer);

    std::string
    name() const override
    {
      return "volume diffusion";
    }

    /** Creates the elastic problem on first use, then redistributes its
     * DoFs (the displacement comes back through add_state()). */
    void
    setup(const LevelSetField<dim> &alpha) override;

    void
    add_velocity(const LevelSetField<dim> &alpha,
                 const double              t,
                 const double              dt,
                 VelocityField<dim>       &velocity) override;

    /**
     * The rate form needs a step; where eta_f / (G dt) is small the elastic
     * pressure does not depend on it (paper Sect. 6.6: below 2e-5 the
     * atmosphere does not disturb the grains), so the probe takes the step
     * at which that ratio is 1e-5.
     */
    void
    add_probe_velocity(const LevelSetField<dim> &alpha,
                       const double              t,
                       VelocityField<dim>       &velocity) override;

    /** u^n = u^{n-1} + dt v^n with the step's elastic velocity (Eq. 92),
     * once per elastic solve: a step that kept an earlier step's solve
     * (`Elastic solve interval`) adds no increment. */
    void
    accept_step(const LevelSetField<dim> &alpha) override;

    void
    reject_step() override;

    /**
     * A step taken again shorter from the same state keeps the elastic
     * solve and xi where the law's pressure does not depend on the step
     * (the elastic solid: dt v = Delta u is what the solve finds), so that
     * a one-step speed spike costs no second elastic assembly and solve.
     */
    void
    shorten_step() override;

    /** The displacement u^{n-1} of the next step on the new mesh. */
    void
    add_state(const LevelSetField<dim> &alpha,
              StateTransfer<dim>       &transfer) override;

    /**
     * The explicit stability limit of v = -C_v xi N (measured, h^3):
     * dt <= f c_s h_min^3 / ((2/3)(1 + nu) C_v gamma), f = `Time step
     * factor` (doc/numerics.md, "Volume diffusion"). Infinity if f = 0.
     */
    double
    time_step_limit(const LevelSetField<dim> &alpha) const override;

    /** Pressure, xi, displacement and velocity of the last step. */
    void
    add_output_fields(const LevelSetField<dim> &alpha,
                      DataOut<dim>             &data_out) const override;

    std::vector<std::string>
    metric_names() const override
    {
      return {"volume_diffusion_mechanics_iterations",
              "volume_diffusion_xi_iterations",
              "volume_diffusion_unsourced_cells"};
    }

    std::vector<double>
    metric_values() const override
    {
      return {double(mechanics_iterations),
              double(xi_iterations),
              double(extension.unsourced_interface_cells())};
    }

    /** The elastic problem of the last step (for tests and output). */
    const VelocityPressureOperator<dim> &
    mechanics() const
    {
      return *operator_;
    }

    /** xi of the last step on the level set's DoFs. */
    const NormalGradientExtension<dim> &
    normal_gradient() const
    {
      return extension;
    }

  private:
    // Solve the elastic problem with the step @p step_seconds and extend
    // its xi.
    void
    solve(const LevelSetField<dim> &alpha,
          const double              t,
          const double              step_seconds);

    // Add v = -C_v xi N (Eq. 112) of the last solve.
    void
    add_diffusion_velocity(const LevelSetField<dim> &alpha,
                           VelocityField<dim>       &velocity) const;

    const double                          coefficient; // C_v, scene time
    // The elastic problem runs in seconds (eta_f in MPa s, Eq. 92-94)
    // whatever the scene's time unit: dt_s = dt x this.
    const double                          seconds_per_time_unit;
    typename TwoPhaseStokes<dim>::Settings settings;
    // Its `Pressure space` chooses the discretisation.
    const ViscousFlowParameters           mechanics_parameters;
    const std::unique_ptr<PhaseLaw<dim>>  phases;
    const double                          probe_step; // seconds
    // f / ((2/3)(1 + nu) C_v gamma) of time_step_limit(); 0: no limit.
    const double                          limit_per_h3;
    double                                h_min = 0; // after setup()
    TimerOutput                          &timer;
    std::unique_ptr<VelocityPressureOperator<dim>> operator_;
    NormalGradientExtension<dim>          extension;
    // The step of the last elastic solve, in seconds, and whether the
    // next add_velocity() keeps that solve (shorten_step()).
    double       solved_step          = 0;
    bool         keep_solve           = false;
    // `Elastic solve interval`, the accepted steps since the last solve,
    // whether the current step solved, and whether the next step must
    // (no solve on the current DoFs yet).
    const unsigned int solve_interval;
    // `Elastic state = total`: the displacement is never advanced.
    const bool         total_elastic_state;
    unsigned int       steps_since_solve = 0;
    bool               solved_in_step    = false;
    bool               must_solve        = true;
    unsigned int mechanics_iterations = 0;
    unsigned int xi_iterations        = 0;
    bool         warned_unsourced     = false;
    // The velocity of the last step for the field output, which keeps a
    // reference to it until the patches are built.
    mutable std::unique_ptr<VelocityField<dim>> output_velocity;
    // Likewise the displacement's velocity block (its pressure block is
    // unused).
    mutable std::unique_ptr<DataPostprocessor<dim>> output_displacement;
  };
} // namespace levelsinter
