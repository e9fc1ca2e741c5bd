#pragma once

#include <deal.II/base/timer.h>

#include <levelsinter/mechanics/phase_law.h>
#include <levelsinter/mechanics/two_phase_stokes.h>
#include <levelsinter/mechanisms/mechanism.h>
#include <levelsinter/scene/viscous_flow_parameters.h>

#include <memory>

namespace levelsinter
{
  /**
   * Viscous sintering: Newtonian particles flow under their own surface
   * tension. Each step solves the two-phase Stokes problem from alpha and
   * adds its velocity to the interface velocity.
   */
  template <int dim>
  class ViscousFlow : public Mechanism<dim>
  {
  public:
    ViscousFlow(const ViscousFlowParameters &parameters, TimerOutput &timer);

    void
    setup(const LevelSetField<dim> &alpha) override;

    void
    add_velocity(const LevelSetField<dim> &alpha,
                 const double              t,
                 const double              dt,
                 VelocityField<dim>       &velocity) override;

    /** Explicit capillary limit dt <= c eta_s h_min / gamma. */
    double
    time_step_limit(const LevelSetField<dim> &alpha) const override;

    std::vector<std::string>
    metric_names() const override
    {
      return {"stokes_iterations", "stokes_solve_cpu"};
    }

    std::vector<double>
    metric_values() const override
    {
      return {double(last_iterations), last_solve_cpu};
    }

    /** The last Stokes solution (v, p), for tests and output. */
    const TwoPhaseStokes<dim> &
    stokes() const
    {
      return *operator_;
    }

  private:
    const ViscousFlowParameters          parameters;
    TimerOutput                         &timer;
    const NewtonianPhases                phases;
    std::unique_ptr<TwoPhaseStokes<dim>> operator_;
    double                               h_min           = 0;
    unsigned int                         last_iterations = 0;
    // CPU seconds of the last solve (preconditioner setup included),
    // summed over the ranks: unlike wall time it does not depend on what
    // else runs on the machine.
    double last_solve_cpu = 0;
  };
} // namespace levelsinter
