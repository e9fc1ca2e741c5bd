#include <levelsinter/scene/grain_boundary_parameters.h>
#include <levelsinter/scene/parameter_entries.h>

#include <cmath>
#include <string>

namespace levelsinter
{
  namespace
  {
    // A list of per-grain factors of the current subsection: empty, or
    // positive numbers (their count is checked against the particles by
    // SceneParameters::check_grains).
    std::vector<double>
    read_factors(ParameterHandler &prm, const std::string &entry)
    {
      const auto factors = Utilities::string_to_double(
        Utilities::split_string_list(prm.get(entry), ','));
      for (const double f : factors)
        if (!(f > 0))
          fail_entry("Grain boundaries/" + entry,
                     "every factor must be positive (a grain without "
                     "diffusion is not a material the contact law and the "
                     "surface-diffusion solve can hold)");
      return factors;
    }
  } // namespace

  void
  GrainBoundaryParameters::declare(ParameterHandler &prm)
  {
    prm.enter_subsection("Grain boundaries");
    {
      prm.declare_entry("Enabled",
                        "false",
                        Patterns::Bool(),
                        "Each particle of Geometry/Particles is a grain: "
                        "the solid is split among the grains by the power "
                        "cells of their moving centres, and grain-boundary "
                        "diffusion (paper Eq. 26, 30) between rigid grains "
                        "makes them approach (densification). Needs "
                        "Surface diffusion/Enabled = true.");
      prm.declare_entry("Energy ratio",
                        "0",
                        Patterns::Double(0),
                        "gamma_gb / gamma_s, from 0 (no grain-boundary "
                        "energy) to below 2; sets the dihedral angle psi, "
                        "cos(psi/2) = gamma_gb / (2 gamma_s), of the "
                        "triple line's force balance.");
      prm.declare_entry("Coefficient",
                        "0",
                        Patterns::Double(0),
                        "C_gb = delta_gb D_gb gamma_s Omega / kT in m^4/s "
                        "(in a scene without material data: length unit of "
                        "the domain^4 per time unit, like Surface "
                        "diffusion/Coefficient; C_gb / C_s = delta_gb D_gb "
                        "/ (delta_s D_s)). delta_gb is the grain-boundary "
                        "width, D_gb its diffusivity.");
      prm.declare_entry("Sliding resistance",
                        "1",
                        Patterns::Double(0),
                        "beta: the resistance of a grain boundary to "
                        "tangential relative motion of its grains, as a "
                        "multiple of its resistance to approach.");
      prm.declare_entry("Deposition width",
                        "2",
                        Patterns::Double(0.5),
                        "Half-width l, in finest cells, of the band about "
                        "the triple line where the matter taken out of the "
                        "grain boundary is deposited and the neck-root "
                        "curvature is averaged.");
      prm.declare_entry("Triple-line condition",
                        "false",
                        Patterns::Bool(),
                        "Surface diffusion respects the dihedral angle psi "
                        "at the triple lines: the chemical potential of the "
                        "surface carries the grain-boundary energy there "
                        "(doc/numerics.md, \"The dihedral angle at the "
                        "triple line\"), and the neck root's curvature of "
                        "the contact law is that potential.");
      prm.declare_entry("Triple-line kink width",
                        "0",
                        Patterns::Double(0),
                        "With the triple-line condition: 0 spreads the "
                        "turning of the surface's tangent at the triple "
                        "line (pi - psi) over the kernel of Deposition "
                        "width about the line; a width k > 0 puts it on "
                        "the grain boundary's plane, within k finest cells "
                        "of it, for every level curve of the band that "
                        "crosses the plane near the line (doc/numerics.md, "
                        "\"The sharp triple-line condition\").");
      prm.declare_entry("Conserve grain volumes",
                        "false",
                        Patterns::Bool(),
                        "After each step the power cells' weights are "
                        "corrected so that every grain keeps its volume at "
                        "t = 0 (times the solid's volume ratio): the grain "
                        "boundaries move by what surface diffusion and the "
                        "deposition carry across them (doc/numerics.md, "
                        "\"Volume per grain\").");
      prm.declare_entry("Implicit contact law",
                        "false",
                        Patterns::Bool(),
                        "The contact law reads the neck-root curvature "
                        "after the step's deposition (backward Euler in "
                        "the approach): the coupled step is stable for any "
                        "time step, where the explicit law oscillates "
                        "from step to step once the time step exceeds "
                        "about C_gb dt / (a l^3) ~ 1 (doc/numerics.md, "
                        "\"Settling: the implicit contact law\"). Its step "
                        "is limited by accuracy instead: no contact's "
                        "approach or deposition moves the surface by more "
                        "than 0.03 finest cell in a step (doc/numerics.md, "
                        "\"Settling: the step's accuracy and clear "
                        "stops\").");
      prm.declare_entry("Sharp contact radius",
                        "false",
                        Patterns::Bool(),
                        "With the sharp triple-line condition (kink width k "
                        "> 0): the contact law reads the grain boundary's "
                        "radius a where circles fitted to the grains' "
                        "surfaces next to the triple line meet its plane "
                        "(the sharp triple line), not where the rays along "
                        "the plane leave the discrete solid: the level set "
                        "fills the groove's corner, which put the rays' a "
                        "1.2-2.3 % wide of the resting shape's and kept the "
                        "grains of a pair at rest separating "
                        "(doc/numerics.md, \"Settling: the sharp contact "
                        "radius\"). Where the two differ by more than k "
                        "cells (a neck still forming) the rays' a is kept.");
      prm.declare_entry("Surface diffusion factors",
                        "",
                        Patterns::List(Patterns::Double(0), 0, 1000000, ","),
                        "Per-grain materials: one positive factor per "
                        "particle (in their order), the grain's surface "
                        "diffusion coefficient in units of Surface "
                        "diffusion/Coefficient. A surface node takes its "
                        "grain's factor (the mean of the grains it lies "
                        "between on a grain boundary). Empty: 1 for every "
                        "grain, one material (doc/numerics.md, \"Per-grain "
                        "materials\").");
      prm.declare_entry("Coefficient factors",
                        "",
                        Patterns::List(Patterns::Double(0), 0, 1000000, ","),
                        "Per-grain materials: one positive factor per "
                        "particle, the grain's C_gb in units of Grain "
                        "boundaries/Coefficient; the boundary of grains i "
                        "and j diffuses with the mean of their factors. "
                        "Empty: 1 for every grain.");
    }
    prm.leave_subsection();
  }

  void
  GrainBoundaryParameters::parse(ParameterHandler &prm)
  {
    prm.enter_subsection("Grain boundaries");
    enabled            = prm.get_bool("Enabled");
    energy_ratio       = prm.get_double("Energy ratio");
    coefficient        = prm.get_double("Coefficient");
    sliding_resistance = prm.get_double("Sliding resistance");
    deposition_width   = prm.get_double("Deposition width");
    triple_line        = prm.get_bool("Triple-line condition");
    kink_width         = prm.get_double("Triple-line kink width");
    conserve_volumes   = prm.get_bool("Conserve grain volumes");
    implicit_contact   = prm.get_bool("Implicit contact law");
    sharp_contact      = prm.get_bool("Sharp contact radius");
    surface_factors    = read_factors(prm, "Surface diffusion factors");
    coefficient_factors = read_factors(prm, "Coefficient factors");
    prm.leave_subsection();
    if (!enabled)
      return;
    if (!(energy_ratio < 2))
      fail_entry("Grain boundaries/Energy ratio",
                 "gamma_gb / gamma_s must lie in [0, 2): at 2 and above "
                 "the grains do not wet each other (no dihedral angle)");
    if (kink_width > 0 && !triple_line)
      fail_entry("Grain boundaries/Triple-line kink width",
                 "a kink width needs Triple-line condition = true (it "
                 "places that condition's turning); set it to 0 or turn "
                 "the condition on");
    if (sharp_contact && !(kink_width > 0))
      fail_entry("Grain boundaries/Sharp contact radius",
                 "the sharp contact radius extrapolates the surfaces to the "
                 "groove that the sharp triple-line condition forms: it "
                 "needs Triple-line condition = true and a Triple-line kink "
                 "width > 0");
    if (!(coefficient > 0))
      fail_entry("Grain boundaries/Coefficient",
                 "C_gb = delta_gb D_gb gamma_s Omega / kT must be positive");
  }

  double
  GrainBoundaryParameters::sin_half_dihedral_angle() const
  {
    const double c = energy_ratio / 2;
    return std::sqrt(1 - c * c);
  }

  double
  GrainBoundaryParameters::triple_line_turning() const
  {
    return 2 * std::asin(energy_ratio / 2);
  }

  double
  GrainBoundaryParameters::surface_factor(const unsigned int i) const
  {
    return surface_factors.empty() ? 1. : surface_factors[i];
  }

  double
  GrainBoundaryParameters::boundary_factor(const unsigned int i,
                                           const unsigned int j) const
  {
    return coefficient_factors.empty() ?
             1. :
             (coefficient_factors[i] + coefficient_factors[j]) / 2;
  }
} // namespace levelsinter
