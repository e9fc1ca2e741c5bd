#pragma once

#include <deal.II/base/function.h>
#include <deal.II/base/timer.h>

#include <deal.II/lac/trilinos_vector.h>

#include <levelsinter/geometry/mixed_curvature_solver.h>
#include <levelsinter/level_set/interface_measures.h>
#include <levelsinter/level_set/level_set_filter.h>

#include <levelsinter/mechanics/phase_law.h>
#include <levelsinter/mechanics/extended_pressure_stokes.h>
#include <levelsinter/mechanics/viscoelastic_state.h>
#include <levelsinter/mechanisms/mechanism.h>
#include <levelsinter/scene/viscous_flow_parameters.h>

#include <memory>

namespace levelsinter
{
  /**
   * Viscous sintering: Newtonian particles flow under their own surface
   * tension. Each step solves the two-phase Stokes problem from alpha and
   * adds its velocity to the interface velocity. The csf-curvature and
   * sharp-curvature forms get their curvature from the level set
   * (projection, see update_curvature()) unless a test prescribes the
   * exact one. The
   * polymer of a viscoelastic melt is a ViscoelasticState, whose fields
   * and metrics this mechanism passes on.
   */
  template <int dim>
  class ViscousFlow : public Mechanism<dim>
  {
  public:
    /**
     * @p symmetry_planes: `Domain/Symmetry planes`, faces with zero normal
     * velocity. @p band_level: the refinement level of the interface band,
     * where the smoothing width E of the phases is set
     * (TwoPhaseStokes::Settings). @p law: the particles' phase law
     * (make_phase_law()); one with history (elastic) is a logic error
     * (SceneParameters refuses it): moving the interface with v is viscous
     * sintering only. @p materials: surface tension and atmosphere.
     */
    ViscousFlow(const ViscousFlowParameters           &parameters,
                const MaterialsParameters             &materials,
                const std::vector<types::boundary_id> &symmetry_planes,
                const LevelSetFilter                  &filter,
                const unsigned int                     band_level,
                TimerOutput                           &timer,
                const PhaseLawParameters &law = PhaseLawParameters());

    std::string
    name() const override
    {
      return "viscous flow";
    }

    void
    setup(const LevelSetField<dim> &alpha) override;

    void
    add_velocity(const LevelSetField<dim> &alpha,
                 const double              t,
                 const double              dt,
                 VelocityField<dim>       &velocity) override;

    /** The Stokes velocity with the surface tension explicit and no
     * polymer stress update. */
    void
    add_probe_velocity(const LevelSetField<dim> &alpha,
                       const double              t,
                       VelocityField<dim>       &velocity) override;

    bool
    curvature_driven() const override
    {
      return true;
    }

    /**
     * Explicit capillary limit dt <= c eta h_min / gamma (eta: the
     * particles' zero-shear viscosity); none when the surface tension is
     * semi-implicit.
     */
    double
    time_step_limit(const LevelSetField<dim> &alpha) const override;

    /**
     * Rejects a step that increases the interface measure by more than
     * 0.1 %: without external pressure the Stokes flow only dissipates
     * the surface energy gamma |Gamma|, so a growing interface is the
     * explicit capillary instability (dt above the capillary limit), not
     * physics.
     */
    void
    check_step(const LevelSetField<dim> &alpha) override;

    /**
     * The last Stokes solution (velocity and pressure) and, in the
     * curvature forms, the curvature it used.
     */
    void
    add_output_fields(const LevelSetField<dim> &alpha,
                      DataOut<dim>             &data_out) const override;

    /** The conformation tensor of a viscoelastic melt (its committed
     * state, ViscoelasticState) travels across mesh adaptation. */
    void
    add_state(const LevelSetField<dim> &alpha,
              StateTransfer<dim>       &transfer) override;

    /** Stokes iterations and CPU seconds; for a viscoelastic melt also
     * ViscoelasticState's. */
    std::vector<std::string>
    metric_names() const override;

    std::vector<double>
    metric_values() const override;

    /** A viscoelastic melt: the conformation of the step becomes the
     * state (ViscoelasticState::accept()). */
    void
    accept_step(const LevelSetField<dim> &alpha) override;

    void
    reject_step() override;

    /** A viscoelastic melt: ViscoelasticState's (tr c at the point). */
    std::vector<std::string>
    point_metric_names() const override;

    std::vector<double>
    point_metric_values(const LevelSetField<dim> &alpha,
                        const Point<dim>         &point) const override;

    /**
     * Use @p kappa (evaluated at the level-set nodes) instead of the
     * projected curvature: benchmarks with a known interface (static
     * bubble, kappa = 1/R) separate the curvature error from the rest.
     */
    void
    prescribe_curvature(std::shared_ptr<const Function<dim>> kappa)
    {
      exact_curvature = std::move(kappa);
    }

    /** Nodal curvature on the level-set DoFs used by the last solve
     * (the curvature forms only; empty otherwise). */
    const TrilinosWrappers::MPI::Vector &
    curvature() const
    {
      return kappa;
    }

    /** The last Stokes solution (v, p), for tests and output. */
    const VelocityPressureOperator<dim> &
    stokes() const
    {
      return *operator_;
    }

  private:
    // Solve the Stokes problem for the step dt (0: the probe, no step:
    // explicit surface tension, no history, no polymer stress update) and
    // add its velocity.
    void
    solve_velocity(const LevelSetField<dim> &alpha,
                   const double              dt,
                   VelocityField<dim>       &velocity);

    void
    update_curvature(const LevelSetField<dim> &alpha);

    const ViscousFlowParameters          parameters;
    const MaterialsParameters            materials;
    const std::vector<types::boundary_id> symmetry_planes;
    const LevelSetFilter                 filter;
    const unsigned int                   band_level;
    TimerOutput                         &timer;
    // A viscoelastic melt's polymer (none otherwise), read by its law.
    const std::unique_ptr<ViscoelasticState<dim>> viscoelastic;
    const std::unique_ptr<PhaseLaw<dim>>          phases;
    // eta_s, plus eta_p for a viscoelastic melt: the capillary limit's.
    const double zero_shear_viscosity;
    // A viscoelastic melt's relaxation time lambda (0 otherwise).
    const double relaxation_time;
    std::unique_ptr<VelocityPressureOperator<dim>> operator_;
    std::unique_ptr<MixedCurvatureSolver<dim>> curvature_solver;
    std::shared_ptr<const Function<dim>>       exact_curvature;
    TrilinosWrappers::MPI::Vector              kappa;
    // csf-curvature: the level set H_h and kappa are taken from, alpha
    // redistanced where it is no distance (redistanced_level_set()).
    TrilinosWrappers::MPI::Vector              interface_level_set;
    double                               h_min           = 0;
    // Interface measure at the start of the step (check_step()), measured
    // at its first trial and kept for its CFL re-choice and retries.
    interface_measures::VolumeAndArea measures_at_step_start;
    bool step_started = false;
    unsigned int                         last_iterations = 0;
    // CPU seconds of the last solve (preconditioner setup included),
    // summed over the ranks: unlike wall time it does not depend on what
    // else runs on the machine.
    double last_solve_cpu = 0;
  };
} // namespace levelsinter
