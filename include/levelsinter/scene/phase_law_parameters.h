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
      elastic_solid
    } law = Law::newtonian;
    double      shear_modulus = 156e9;       // G (Pa)
    double      bulk_modulus  = 260e9;       // K (Pa)
  };
} // namespace levelsinter
