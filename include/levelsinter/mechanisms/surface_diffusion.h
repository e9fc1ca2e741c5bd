#pragma once

#include <deal.II/base/timer.h>

#include <levelsinter/geometry/mixed_curvature_solver.h>
#include <levelsinter/mechanisms/mechanism.h>
#include <levelsinter/scene/scene_parameters.h>

#include <functional>

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

    /** kappa and v_s of the level set alone (no lag, no coupling). */
    void
    add_probe_velocity(const LevelSetField<dim> &alpha,
                       const double              t,
                       VelocityField<dim>       &velocity) override;

    /** The step's v_s becomes v_s^{n-1} of the next (Eq. 81). */
    void
    accept_step(const LevelSetField<dim> &alpha) override;

    bool
    curvature_driven() const override
    {
      return true;
    }

    /** v_s^{n-1} of the next step goes to the new mesh. */
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
     * The lagged velocity v_s^{n-1} of A^n (Eq. 81) that the last accepted
     * step used; empty before the first step.
     */
    const TrilinosWrappers::MPI::Vector &
    lagged_velocity() const
    {
      return lag_of_last_step;
    }

    /**
     * Writes a field on the level set's DoFs (the locally owned entries of
     * its vector) at the level set's state, before each solve.
     */
    using NodalSource =
      std::function<void(const LevelSetField<dim> &,
                         TrilinosWrappers::MPI::Vector &)>;

    /**
     * A chemical potential mu from @p source, added to the curvature: v_s
     * = C Delta_s (kappa + mu) (MixedCurvatureSolver::set_potential). The
     * triple-line condition of grain boundaries.
     */
    void
    set_potential_source(const NodalSource &source)
    {
      potential_source = source;
    }

    /**
     * A factor c of the coefficient at each node from @p source: v_s =
     * div_s (c C grad_s kappa) (MixedCurvatureSolver::set_mobility).
     * Per-grain materials of grain boundaries.
     */
    void
    set_mobility_source(const NodalSource &source)
    {
      mobility_source = source;
    }

    /**
     * The coefficient of Delta_s kappa in the time unit of the scene (with
     * a mobility source, the one its factors multiply).
     */
    double
    coefficient() const
    {
      return mobility;
    }

  private:
    // mu of the potential source and c of the mobility source at the
    // level set's state (ghosted).
    void
    update_sources(const LevelSetField<dim> &alpha);

    // v = v_s N_alpha (Eq. 84) of the last solve, added to @p velocity.
    void
    add_normal_velocity(const LevelSetField<dim> &alpha,
                        VelocityField<dim>       &velocity) const;

    const double              mobility;
    MixedCurvatureSolver<dim> solver;
    TimerOutput              &timer;
    // v_s^{n-1} for A^n (Eq. 81): the v_s of the last accepted step, which
    // every trial of the next step uses; and the one the last accepted
    // step used.
    TrilinosWrappers::MPI::Vector previous_velocity;
    TrilinosWrappers::MPI::Vector lag_of_last_step;
    NodalSource                   potential_source;
    TrilinosWrappers::MPI::Vector potential;
    NodalSource                   mobility_source;
    TrilinosWrappers::MPI::Vector mobility_factor;
    unsigned int                  iterations = 0;
  };
} // namespace levelsinter
