#include <levelsinter/scene/parameter_entries.h>
#include <levelsinter/scene/viscous_flow_parameters.h>

#include <string>
#include <utility>
#include <vector>

namespace levelsinter
{
  void
  ViscousFlowParameters::declare(ParameterHandler &prm)
  {
    prm.enter_subsection("Viscous flow");
    {
      prm.declare_entry("Enabled",
                        "false",
                        Patterns::Bool(),
                        "Solve two-phase Stokes with surface tension every "
                        "step and move the interface with its velocity.");
      prm.declare_entry("Solid viscosity",
                        "1",
                        Patterns::Double(0),
                        "eta_s of the particles, in Pa s (or the scene's "
                        "viscosity unit, e.g. 1). The surface tension and "
                        "the atmosphere are in the Materials section.");
      prm.declare_entry("Surface tension form",
                        "sharp",
                        Patterns::Selection(
                          "csf|sharp|csf-curvature|sharp-curvature"),
                        "Tensorial form gamma (I - n n) : grad w (Eq. 108), "
                        "integrated with the regularised Dirac (csf, Eq. "
                        "100-104) or on the zero level set with cut-cell "
                        "quadrature (sharp); or csf-curvature: the force "
                        "gamma kappa grad H_h (Eq. 100 in balanced-force "
                        "form, H_h the Q1 smoothed solid fraction) with the "
                        "curvature projected from the level set; or "
                        "sharp-curvature: the load gamma kappa n on the zero "
                        "level set (cut-cell quadrature) with that "
                        "curvature, balanced with 'Pressure space = "
                        "extended' (a constant kappa is met by a constant "
                        "pressure in the solid).");
      prm.declare_entry("Surface tension time integration",
                        "explicit",
                        Patterns::Selection("explicit|semi-implicit"),
                        "explicit: the load at the current interface, "
                        "stable for dt below the capillary limit (see "
                        "'Capillary time step factor'); semi-implicit: the "
                        "Laplace-Beltrami term at the new position x + dt v "
                        "(adds dt gamma int grad_s v : grad_s w to the "
                        "velocity block), no capillary limit.");
      prm.declare_entry("Interface half width",
                        "1.5",
                        Patterns::Double(0),
                        "E of the smoothed Heaviside and Dirac (Eq. 102-104), "
                        "in cell sizes (no unit): E = this x h_K in each cell K, so "
                        "the jump spans the same number of cells on the "
                        "band and on cells refined further at necks; cells "
                        "coarser than the band use the band cells' size.");
      prm.declare_entry("Stabilisation constant",
                        "0.1",
                        Patterns::Double(0),
                        "c in the ASGS parameter tau_K = c a2 h_K^2 / a1 (no "
                        "unit; "
                        "Eq. 99 has c = 1). The smearing of the Laplace "
                        "jump and the solid-volume drift grow with c, the "
                        "solver iterations shrink (doc/validation.md).");
      prm.declare_entry("External pressure",
                        "0",
                        Patterns::Double(),
                        "p_ext on the free box faces (traction -p_ext n), in "
                        "Pa (or the scene's stress unit, surface tension "
                        "per length unit).");
      prm.declare_entry("Linear solver",
                        "iterative",
                        Patterns::Selection("iterative|direct"),
                        "iterative: FGMRES with the block preconditioner "
                        "(AMG + viscosity-weighted pressure mass); direct: "
                        "Trilinos Amesos, for small 2D problems.");
      prm.declare_entry("Solver tolerance",
                        "1e-10",
                        Patterns::Double(0),
                        "Relative residual at which FGMRES stops.");
      prm.declare_entry("Maximum solver iterations",
                        "500",
                        Patterns::Integer(1),
                        "FGMRES iteration limit; reaching it stops the run.");
      prm.declare_entry("AMG aggregation",
                        "smoothed",
                        Patterns::Selection("smoothed|unsmoothed"),
                        "The AMG of the velocity block (iterative solver): "
                        "smoothed aggregation, or unsmoothed (plain) "
                        "aggregation, whose sparser coarse levels cut the "
                        "peak memory of a 3D packing by about a fifth at "
                        "about 2.3x the FGMRES iterations and a fifth more "
                        "solve time (doc/performance.md).");
      prm.declare_entry("Capillary time step factor",
                        "1",
                        Patterns::Double(0),
                        "c in the explicit capillary limit dt <= c eta_s "
                        "h_min / gamma (no unit); 0 disables it. Not applied with "
                        "semi-implicit surface tension.");
      prm.declare_entry("Pressure space",
                        "continuous",
                        Patterns::Selection("continuous|extended|solid"),
                        "continuous: one Q1 pressure over the box, the phases "
                        "smeared over the interface half width; extended: one "
                        "Q1 pressure per phase, both present on the cells the "
                        "interface cuts and each integrated over its own "
                        "side of alpha_h = 0 with cut-cell quadrature, the "
                        "viscosities sharp, so the pressure jumps at the "
                        "interface (doc/numerics.md, 'Sharp interfaces'). "
                        "extended needs 'Surface tension form = sharp' (or "
                        "sharp-curvature) and "
                        "the iterative linear solver, and refuses "
                        "viscoelastic melts. solid: the elastic problem of "
                        "volume diffusion on the cells with solid only, the "
                        "atmosphere a void (its viscosity left out), the "
                        "solid's part of each cut cell by cut-cell "
                        "quadrature, the surface tension on alpha_h = 0 and "
                        "a ghost penalty on the faces of cut cells "
                        "(doc/mechanics_operator.md); volume diffusion only, "
                        "with the iterative linear solver.");
      prm.declare_entry("Ghost penalty",
                        "0.1",
                        Patterns::Double(0),
                        "g of the pressure ghost penalty of the extended "
                        "pressure space, g (a2/a1) h^3 [d_n p][d_n q] on the "
                        "faces of cut cells (no unit; doc/numerics.md); the "
                        "solid space adds g a1 h [d_n v][d_n w] for the "
                        "velocity.");
      prm.declare_entry("Pore closure radius",
                        "0",
                        Patterns::Double(0),
                        "In finest cells h_min: a closed pore whose radius "
                        "(of the ball of its volume) is below it closes at "
                        "least as fast as a small pore in a viscous body, "
                        "dr/dt = -gamma / (2 eta_s), and is removed when "
                        "that radius reaches zero; the solid volume this "
                        "adds is the metrics.csv column "
                        "pore_closure_volume (doc/numerics.md, 'A pore "
                        "below a few cells'). 0 (the default): no rule.");
    }
    prm.leave_subsection();
  }

  void
  ViscousFlowParameters::parse(ParameterHandler &prm)
  {
    prm.enter_subsection("Viscous flow");
    enabled              = prm.get_bool("Enabled");
    solid_viscosity      = prm.get_double("Solid viscosity");
    surface_tension_form  = read_selection<SurfaceTensionForm>(
      prm,
      "Viscous flow",
      "Surface tension form",
      {{"csf", SurfaceTensionForm::csf},
       {"sharp", SurfaceTensionForm::sharp},
       {"csf-curvature", SurfaceTensionForm::csf_curvature},
       {"sharp-curvature", SurfaceTensionForm::sharp_curvature}});
    semi_implicit_surface_tension =
      read_selection<bool>(prm,
                           "Viscous flow",
                           "Surface tension time integration",
                           {{"explicit", false}, {"semi-implicit", true}});
    interface_half_width   = prm.get_double("Interface half width");
    stabilisation_constant = prm.get_double("Stabilisation constant");
    external_pressure      = prm.get_double("External pressure");
    linear_solver          = read_selection<LinearSolver>(
      prm,
      "Viscous flow",
      "Linear solver",
      {{"iterative", LinearSolver::iterative},
       {"direct", LinearSolver::direct}});
    solver_tolerance           = prm.get_double("Solver tolerance");
    max_iterations             = prm.get_integer("Maximum solver iterations");
    smoothed_aggregation       = read_selection<bool>(
      prm,
      "Viscous flow",
      "AMG aggregation",
      {{"smoothed", true}, {"unsmoothed", false}});
    capillary_time_step_factor = prm.get_double("Capillary time step factor");
    pressure_space             = read_selection<PressureSpace>(
      prm,
      "Viscous flow",
      "Pressure space",
      {{"continuous", PressureSpace::continuous},
       {"extended", PressureSpace::extended},
       {"solid", PressureSpace::solid}});
    ghost_penalty = prm.get_double("Ghost penalty");
    pore_closure_radius = prm.get_double("Pore closure radius");
    prm.leave_subsection();

    // The volume-diffusion mechanics reads this section too, enabled or
    // not: its checks come first.
    if (pressure_space != PressureSpace::continuous &&
        linear_solver == LinearSolver::direct)
      fail_entry("Viscous flow/Linear solver",
                 "must be 'iterative' with 'Pressure space = extended' or "
                 "'solid'");
    // The flow of the solid moves the interface, and the level set's nodes
    // in the atmosphere would have no velocity to move with.
    if (enabled && pressure_space == PressureSpace::solid)
      fail_entry("Viscous flow/Pressure space",
                 "'solid' is the elastic problem of volume diffusion; "
                 "viscous flow needs 'continuous' or 'extended'");
    if (enabled && pressure_space == PressureSpace::extended &&
        surface_tension_form != SurfaceTensionForm::sharp &&
        surface_tension_form != SurfaceTensionForm::sharp_curvature)
      fail_entry("Viscous flow/Surface tension form",
                 "must be 'sharp' or 'sharp-curvature' with 'Pressure space "
                 "= extended' (the pressure jumps at alpha_h = 0, where the "
                 "load acts)");

    if (!enabled)
      return;
    const std::vector<std::pair<double, std::string>> positive = {
      {solid_viscosity, "Solid viscosity"},
      {interface_half_width, "Interface half width"},
      {stabilisation_constant, "Stabilisation constant"}};
    for (const auto &[value, entry] : positive)
      if (value <= 0)
        fail_entry("Viscous flow/" + entry,
                   "must be positive when viscous flow is enabled");
  }
} // namespace levelsinter
