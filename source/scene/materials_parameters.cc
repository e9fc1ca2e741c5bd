#include <levelsinter/scene/materials_parameters.h>

namespace levelsinter
{
  void
  MaterialsParameters::declare(ParameterHandler &prm)
  {
    prm.enter_subsection("Materials");
    {
      prm.declare_entry("Surface tension",
                        "1",
                        Patterns::Double(0),
                        "gamma on alpha = 0 (the solid's surface energy), "
                        "in N/m (in a scene without material data: solid "
                        "viscosity x length unit per scene time unit). "
                        "Drives viscous flow and loads the elastic solid of "
                        "volume diffusion; must be positive with either "
                        "(with viscous flow it may be 0 if Viscous "
                        "flow/External pressure drives the flow).");
      prm.declare_entry("Fluid viscosity",
                        "1e-3",
                        Patterns::Double(0),
                        "eta_f of the atmosphere (the pores), in Pa s, "
                        "same unit as Viscous flow/Solid viscosity; "
                        "eta_f/eta_s down to 1e-6. Must be positive with "
                        "viscous flow or volume diffusion.");
      prm.declare_entry("Fluid compressibility",
                        "1",
                        Patterns::Double(0),
                        "c in div v = -c p / eta_f in the atmosphere (no "
                        "unit; its bulk viscosity is eta_f / c); lets closed "
                        "pores shrink. 0: incompressible atmosphere.");
    }
    prm.leave_subsection();
  }

  void
  MaterialsParameters::parse(ParameterHandler &prm)
  {
    prm.enter_subsection("Materials");
    surface_tension       = prm.get_double("Surface tension");
    fluid_viscosity       = prm.get_double("Fluid viscosity");
    fluid_compressibility = prm.get_double("Fluid compressibility");
    prm.leave_subsection();
  }
} // namespace levelsinter
