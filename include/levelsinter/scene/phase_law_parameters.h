#pragma once

#include <deal.II/base/parameter_handler.h>

#include <string>

namespace levelsinter
{
  using namespace dealii;

  /**
   * The `Phase law` subsection of a scene: how the particles respond in the
   * velocity-pressure problem (TwoPhaseStokes). The atmosphere is the
   * Newtonian fluid of `Viscous flow` (viscosity and compressibility) in
   * both laws.
   */
  struct PhaseLawParameters
  {
    static void
    declare(ParameterHandler &prm);

    /** Read and check; throws std::runtime_error naming the entry. */
    void
    parse(ParameterHandler &prm);

    enum class Law
    {
      newtonian,
      elastic_solid,
      giesekus,
      xpp
    } law = Law::newtonian;
    double shear_modulus = 156e9; // G (Pa)
    double bulk_modulus  = 260e9; // K (Pa)
    // Viscoelastic melts (the viscoelastic seed, Eq. 4-7); the solvent
    // viscosity is Viscous flow/Solid viscosity.
    double relaxation_time             = 1;   // lambda (s)
    double polymer_viscosity           = 1;   // eta_p = G lambda (Pa s)
    double giesekus_mobility           = 0.1; // alpha
    double xpp_stretch_relaxation_time = 0.5; // lambda_s (s)
    double xpp_arms                    = 2;   // q

    bool
    is_viscoelastic() const
    {
      return law == Law::giesekus || law == Law::xpp;
    }
  };
} // namespace levelsinter
