#include <levelsinter/scene/parameter_entries.h>
#include <levelsinter/scene/phase_law_parameters.h>


namespace levelsinter
{
  void
  PhaseLawParameters::declare(ParameterHandler &prm)
  {
    prm.enter_subsection("Phase law");
    {
      prm.declare_entry(
        "Law",
        "newtonian",
        Patterns::Selection("newtonian|elastic-solid|giesekus|xpp"),
        "newtonian: viscous particles (Viscous flow/Solid viscosity). "
        "elastic-solid: linear elastic particles in rate form, u^n = "
        "u^{n-1} + dt v^n (paper Eq. 92-94), with the moduli below. "
        "giesekus, xpp: viscoelastic melts (viscoelastic seed, Eq. 4-7): "
        "solvent viscosity Viscous flow/Solid viscosity plus the polymer "
        "stress G (c - I) of a conformation tensor c carried with the flow "
        "(Giesekus with the mobility below, 0 = Oldroyd-B; or the extended "
        "Pom-Pom model), G = Polymer viscosity / Relaxation time.");
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
      prm.declare_entry("Relaxation time",
                        "1",
                        Patterns::Double(0),
                        "lambda of the viscoelastic melt (s; XPP: the "
                        "backbone orientation's). De = lambda gamma / "
                        "(eta_0 R) with eta_0 = Solid viscosity + Polymer "
                        "viscosity (seed Eq. 21).");
      prm.declare_entry("Polymer viscosity",
                        "1",
                        Patterns::Double(0),
                        "eta_p = G lambda of the viscoelastic melt (Pa s); "
                        "beta = eta_s / eta_0 (seed Eq. 20).");
      prm.declare_entry("Giesekus mobility",
                        "0.1",
                        Patterns::Double(0, 0.5),
                        "alpha of the Giesekus model (no unit, 0 to 0.5; 0 "
                        "is Oldroyd-B).");
      prm.declare_entry("XPP stretch relaxation time",
                        "0.5",
                        Patterns::Double(0),
                        "lambda_s of the XPP model (s).");
      prm.declare_entry("XPP arms",
                        "2",
                        Patterns::Double(0),
                        "q, the number of arms at the backbone's ends in "
                        "the XPP model (no unit).");
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
                                 {"elastic-solid", Law::elastic_solid},
                                 {"giesekus", Law::giesekus},
                                 {"xpp", Law::xpp}});
      shear_modulus     = prm.get_double("Shear modulus");
      bulk_modulus      = prm.get_double("Bulk modulus");
      relaxation_time   = prm.get_double("Relaxation time");
      polymer_viscosity = prm.get_double("Polymer viscosity");
      giesekus_mobility = prm.get_double("Giesekus mobility");
      xpp_stretch_relaxation_time =
        prm.get_double("XPP stretch relaxation time");
      xpp_arms = prm.get_double("XPP arms");
    }
    prm.leave_subsection();
    if (is_viscoelastic() && relaxation_time <= 0)
      fail_entry("Phase law/Relaxation time",
                 "a viscoelastic law needs a relaxation time > 0");
    if (is_viscoelastic() && polymer_viscosity <= 0)
      fail_entry("Phase law/Polymer viscosity",
                 "a viscoelastic law needs a polymer viscosity > 0 (use "
                 "'newtonian' for a purely viscous melt)");
    if (law == Law::xpp && (xpp_stretch_relaxation_time <= 0 || xpp_arms <= 0))
      fail_entry("Phase law/XPP stretch relaxation time",
                 "the XPP law needs a stretch relaxation time > 0 and a "
                 "number of arms > 0");
    if (law == Law::elastic_solid && (shear_modulus <= 0 || bulk_modulus <= 0))
      fail_entry("Phase law/Shear modulus",
                 "the elastic-solid law needs both moduli (shear and bulk) "
                 "> 0");
  }
} // namespace levelsinter
