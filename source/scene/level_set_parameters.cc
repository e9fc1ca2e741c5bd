#include <levelsinter/scene/level_set_parameters.h>
#include <levelsinter/scene/parameter_entries.h>

namespace levelsinter
{
  void
  LevelSetParameters::declare(ParameterHandler &prm)
  {
    prm.enter_subsection("Level set");
    {
      prm.declare_entry("Filter",
                        "sine",
                        Patterns::Selection("sine|tanh"),
                        "Filter of the signed distance: 'sine' (paper Eq. 65, "
                        "saturates at 2E/pi) or 'tanh' (Eq. 69, E tanh(d/E)).");
      prm.declare_entry(
        "Filter thickness",
        "0.05",
        Patterns::Double(0),
        "Thickness E of the filter (same length unit as the domain). The "
        "refinement band is located by reading distances back through the "
        "filter, so Mesh refinement/Band width must be smaller than E.");
      prm.declare_entry("Theta",
                        "0.5",
                        Patterns::Double(0.5, 1),
                        "Time discretisation of the transport term: 0.5 "
                        "Crank-Nicolson, 1 backward Euler.");
      prm.declare_entry(
        "Reinitialisation strength",
        "0.25",
        Patterns::Double(0),
        "lambda dt / h_min in Eq. 68 (no unit): how far the "
        "reinitialisation moves alpha per step in units of the finest cell. "
        "The paper uses 1; 0.25 conserves volume better and is stable "
        "(doc/numerics.md); 0 turns reinitialisation off (pure transport).");
      prm.declare_entry(
        "Reinitialisation diffusion",
        "0.05",
        Patterns::Double(0, 1),
        "c in the consistent diffusion nu div(grad alpha - g(alpha) n), "
        "nu = c (h_min / dt) h (no unit), added to the reinitialisation. It "
        "vanishes on an exact filtered distance; without it the scheme grows "
        "grid-scale wiggles where the interface is diagonal to the cells "
        "(doc/numerics.md).");
      prm.declare_entry(
        "Reinitialisation tolerance",
        "0.25",
        Patterns::Double(0),
        "delta (no unit, a deviation of |grad alpha|): the reinitialisation "
        "(and its diffusion) acts at full strength where "
        "||grad alpha| - g(alpha)| >= delta and in proportion to the "
        "deviation below it, so that a level set already at its target is "
        "not rebuilt every step. 0 reinitialises everywhere at full "
        "strength, as in the paper (doc/numerics.md).");
      prm.declare_entry(
        "Reinitialisation pace",
        "step",
        Patterns::Selection("step|interface motion"),
        "step: the strength and the diffusion act per step, so a smaller "
        "step reinitialises more per unit time (a fixed-step study in dt "
        "or h then measures the reinitialisation too). interface motion: "
        "each step takes the share min(1, v dt / h_min) of them, v the "
        "largest speed near the interface (the CFL number's), i.e. they "
        "act per time the fastest interface point takes to cross the "
        "finest cell: the same per unit time for any step, and never more "
        "per step than with 'step' (doc/numerics.md).");
      prm.declare_entry(
        "Solid reinitialisation from band cells",
        "auto",
        Patterns::Selection("auto|true|false"),
        "true: inside the solid the reinitialisation speed is strength x "
        "h / dt with h the cell size at 'Mesh refinement/Maximum level' "
        "instead of the finest cell, so that with curvature refinement "
        "levels the level set inside a growing neck stays a distance "
        "(surface-diffusion necks; doc/user_guide.md). false: the finest "
        "cell everywhere. auto: true when surface diffusion is enabled and "
        "viscous flow is not (measured better for surface-diffusion necks, "
        "worse for viscous ones). Changes nothing without curvature "
        "refinement levels.");
      prm.declare_entry("Solver tolerance",
                        "1e-10",
                        Patterns::Double(0, 1),
                        "Relative residual reduction of the GMRES solve of "
                        "each transport step.");
      prm.declare_entry("Maximum solver iterations",
                        "1000",
                        Patterns::Integer(1),
                        "GMRES iterations allowed per transport step.");
    }
    prm.leave_subsection();
  }

  void
  LevelSetParameters::parse(ParameterHandler &prm)
  {
    prm.enter_subsection("Level set");
    filter = read_selection<Filter>(prm,
                                    "Level set",
                                    "Filter",
                                    {{"sine", Filter::sine},
                                     {"tanh", Filter::tanh}});
    filter_thickness = prm.get_double("Filter thickness");
    theta            = prm.get_double("Theta");
    solver_tolerance = prm.get_double("Solver tolerance");
    max_iterations   = prm.get_integer("Maximum solver iterations");
    reinitialization_strength  = prm.get_double("Reinitialisation strength");
    reinitialization_diffusion = prm.get_double("Reinitialisation diffusion");
    reinitialization_tolerance = prm.get_double("Reinitialisation tolerance");
    reinitialization_pace      = read_selection<ReinitializationPace>(
      prm,
      "Level set",
      "Reinitialisation pace",
      {{"step", ReinitializationPace::step},
       {"interface motion", ReinitializationPace::interface_motion}});
    solid_reinitialization     = read_selection<SolidReinitialization>(
      prm,
      "Level set",
      "Solid reinitialisation from band cells",
      {{"auto", SolidReinitialization::automatic},
       {"true", SolidReinitialization::band_cells},
       {"false", SolidReinitialization::finest_cells}});
    prm.leave_subsection();
    if (filter_thickness <= 0)
      fail_entry("Level set/Filter thickness", "must be positive");
  }
} // namespace levelsinter
