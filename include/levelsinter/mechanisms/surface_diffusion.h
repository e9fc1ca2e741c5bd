#pragma once

#include <deal.II/base/timer.h>

#include <levelsinter/geometry/mixed_curvature_solver.h>
#include <levelsinter/mechanisms/mechanism.h>
#include <levelsinter/scene/scene_parameters.h>

namespace levelsinter
{
  /**
   * Surface diffusion (paper Sect. 5): each step solves the mixed
   * kappa / v_s system (MixedCurvatureSolver) and adds v = v_s N_alpha, with
   * N_alpha the normalised nodal average of the cell normals (Eq. 84).
   * In reduced time t* = C_s t / R^4 the flow is v_n = R^4 Delta_s kappa,
   * so only the coefficient changes: C_s times the scene's seconds per
   * time unit (SceneParameters::seconds_per_time_unit()).
   */
  template <int dim>
  class SurfaceDiffusion : public Mechanism<dim>
  {
  public:
    SurfaceDiffusion(const SceneParameters::SurfaceDiffusion &parameters,
                     const double         seconds_per_time_unit,
                     const std::vector<types::boundary_id> &symmetry_planes,
                     const LevelSetFilter &filter,
                     TimerOutput          &timer);

    std::string
    name() const override
    {
      return "surface diffusion";
    }

    void
    setup(const LevelSetField<dim> &alpha) override;

    void
    add_velocity(const LevelSetField<dim> &alpha,
                 const double              t,
                 const double              dt,
                 VelocityField<dim>       &velocity) override;

    bool
    curvature_driven() const override
    {
      return true;
    }

    /** The v_s of the last solve becomes v_s^{n-1} on the new mesh. */
    void
    add_state(const LevelSetField<dim> &alpha,
              StateTransfer<dim>       &transfer) override;

    /** kappa and v_s of the last solve. */
    void
    add_output_fields(const LevelSetField<dim> &alpha,
                      DataOut<dim>             &data_out) const override;

    std::vector<std::string>
    metric_names() const override;

    std::vector<double>
    metric_values() const override;

    /** The curvature of the last solve, for other mechanisms and output. */
    const MixedCurvatureSolver<dim> &
    geometry() const
    {
      return solver;
    }

    /**
     * v_s^{n-1}, the lagged velocity of A^n (Eq. 81) the next step uses;
     * empty before the first step.
     */
    const TrilinosWrappers::MPI::Vector &
    lagged_velocity() const
    {
      return previous_velocity;
    }

    /** The coefficient of Delta_s kappa in the time unit of the scene. */
    double
    coefficient() const
    {
      return mobility;
    }

  private:
    const double              mobility;
    MixedCurvatureSolver<dim> solver;
    TimerOutput              &timer;
    // v_s^{n-1} for A^n (Eq. 81), and the time of the last solve on this
    // mesh (-1: none): the time loop may ask twice for the same t
    // (step-size retry), and then the previous step's v_s must still be the
    // lagged one.
    TrilinosWrappers::MPI::Vector previous_velocity;
    double                        solved_time = -1;
    unsigned int                  iterations  = 0;
  };
} // namespace levelsinter
