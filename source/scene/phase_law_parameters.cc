#include <levelsinter/scene/parameter_entries.h>
#include <levelsinter/scene/phase_law_parameters.h>


namespace levelsinter
{
  void
  PhaseLawParameters::declare(ParameterHandler &prm)
  {
    prm.enter_subsection("Phase law");
    {
      prm.declare_entry("Law",
                        "newtonian",
                        Patterns::Selection("newtonian|elastic-solid"),
                        "newtonian: viscous particles (Viscous flow/Solid "
                        "viscosity). elastic-solid: linear elastic particles "
                        "in rate form, u^n = u^{n-1} + dt v^n (paper Eq. "
                        "92-94), with the moduli below.");
      prm.declare_entry("Shear modulus",
                        "156e9",
                        Patterns::Double(0),
                        "G of the elastic particles (Pa); default: the "
                        "paper's Table 6.");
      prm.declare_entry("Bulk modulus",
                        "260e9",
                        Patterns::Double(0),
                        "K of the elastic particles (Pa); default: the "
                        "paper's Table 6.");
    }
    prm.leave_subsection();
  }

  void
  PhaseLawParameters::parse(ParameterHandler &prm)
  {
    prm.enter_subsection("Phase law");
    {
      law = read_selection<Law>(prm,
                                "Phase law",
                                "Law",
                                {{"newtonian", Law::newtonian},
                                 {"elastic-solid", Law::elastic_solid}});
      shear_modulus = prm.get_double("Shear modulus");
      bulk_modulus  = prm.get_double("Bulk modulus");
    }
    prm.leave_subsection();
    if (law == Law::elastic_solid && (shear_modulus <= 0 || bulk_modulus <= 0))
      fail_entry("Phase law/Shear modulus",
                 "the elastic-solid law needs both moduli (shear and bulk) "
                 "> 0");
  }
} // namespace levelsinter
