#pragma once

#include <deal.II/base/function.h>

#include <levelsinter/mechanisms/mechanism.h>
#include <levelsinter/scene/scene_parameters.h>

#include <memory>

namespace levelsinter
{
  /**
   * The velocity a transport scene prescribes (Velocity section, not
   * `none`): constant, rigid rotation, or a parsed expression of x and t.
   * Returned as a dim-component Function whose time the caller sets.
   */
  template <int dim>
  std::unique_ptr<Function<dim>>
  make_prescribed_velocity(const SceneParameters::Velocity &parameters);

  /**
   * The prescribed velocity as a mechanism: evaluated at t + theta dt, the
   * time level at which the theta scheme of the transport uses it.
   */
  template <int dim>
  class PrescribedVelocity : public Mechanism<dim>
  {
  public:
    PrescribedVelocity(const SceneParameters::Velocity &parameters,
                       const double                     theta);

    std::string
    name() const override
    {
      return "prescribed velocity";
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

  private:
    std::unique_ptr<Function<dim>> function;
    const double                   theta;
  };
} // namespace levelsinter
