#pragma once

#include <deal.II/base/parameter_handler.h>

namespace levelsinter
{
  using namespace dealii;

  /** The `Materials` subsection: what the phases are, whatever moves the
   * interface: the surface energy of the solid and the atmosphere around
   * it. Viscous flow and volume diffusion both read it; each mechanism's
   * own section keeps what only it uses (e.g. the particles' viscosity). */
  struct MaterialsParameters
  {
    static void
    declare(ParameterHandler &prm);

    /** Read; the rules that depend on the mechanisms are checked by
     * SceneParameters. */
    void
    parse(ParameterHandler &prm);

    double surface_tension       = 1;
    double fluid_viscosity       = 1e-3;
    double fluid_compressibility = 1;
  };
} // namespace levelsinter
