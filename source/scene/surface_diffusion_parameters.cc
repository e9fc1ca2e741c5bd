#include <levelsinter/scene/parameter_entries.h>
#include <levelsinter/scene/surface_diffusion_parameters.h>

#include <cmath>
#include <string>
#include <utility>
#include <vector>

namespace levelsinter
{
  void
  SurfaceDiffusionParameters::declare(ParameterHandler &prm)
  {
    prm.enter_subsection("Surface diffusion");
    {
      prm.declare_entry("Enabled",
                        "false",
                        Patterns::Bool(),
                        "Move the interface by surface diffusion, "
                        "v_n = C_s Delta_s kappa (paper Eq. 75), with the "
                        "mixed curvature / surface-Laplacian system (Eq. 82).");
      prm.declare_entry("Coefficient",
                        "0",
                        Patterns::Double(0),
                        "C_s in m^4/s (in a scene without material data: "
                        "length unit of the domain^4 per scene time unit). "
                        "0: computed as D_s delta_s gamma Omega / kT from "
                        "the five entries below.");
      // The material entries of C_s = D_s delta_s gamma Omega / kT.
      for (const auto &[name, unit] :
           std::vector<std::pair<std::string, std::string>>{
             {"Surface diffusivity", "D_s in m^2/s."},
             {"Surface layer thickness", "delta_s in m."},
             {"Surface energy", "gamma_sf in J/m^2."},
             {"Atomic volume", "Omega in m^3."},
             {"Thermal energy", "kT in J."}})
        prm.declare_entry(name, "0", Patterns::Double(0), unit);
      prm.declare_entry("Time unit",
                        "seconds",
                        Patterns::Selection("seconds|reduced"),
                        "Unit of Time/End time and Time/Time step (the scene "
                        "time unit): seconds, or the reduced time "
                        "t* = C_s t / R^4 with R the reference radius. With "
                        "volume diffusion on as well, at most one of the "
                        "two sections may say reduced: its t* is the "
                        "scene's time and both coefficients are converted "
                        "to it.");
      prm.declare_entry("Reference radius",
                        "0",
                        Patterns::Double(0),
                        "R of the reduced time t* (same length unit as the "
                        "domain; needed when Time unit = reduced).");
      prm.declare_entry("Coupled",
                        "true",
                        Patterns::Bool(),
                        "true: the mixed kappa / v_s system with the dt "
                        "coupling term (Eq. 80-82), stable for large steps; "
                        "false: kappa then v_s (decoupled, explicit in the "
                        "fourth-order operator, only for comparisons).");
      prm.declare_entry("Solver tolerance",
                        "1e-8",
                        Patterns::Double(0),
                        "Relative residual of the kappa / v_s solve (gmres).");
      prm.declare_entry("Linear solver",
                        "gmres",
                        Patterns::Selection("direct|gmres"),
                        "gmres: FGMRES with a block-triangular preconditioner "
                        "(Schur complement (M + b L) M^-1 (M + b K), CG "
                        "with Jacobi, or AMG where Jacobi is slow, inside), "
                        "15-30 iterations whatever h and dt, "
                        "runs in parallel; direct: KLU (Trilinos Amesos) on "
                        "the coupled system, serial factorisation, for small "
                        "2D checks (doc/numerics.md).");
    }
    prm.leave_subsection();
  }

  void
  SurfaceDiffusionParameters::parse(ParameterHandler &prm)
  {
    prm.enter_subsection("Surface diffusion");
    enabled          = prm.get_bool("Enabled");
    coefficient      = prm.get_double("Coefficient");
    diffusivity      = prm.get_double("Surface diffusivity");
    layer_thickness  = prm.get_double("Surface layer thickness");
    surface_energy   = prm.get_double("Surface energy");
    atomic_volume    = prm.get_double("Atomic volume");
    thermal_energy   = prm.get_double("Thermal energy");
    time_unit        = read_selection<TimeUnit>(prm,
                                         "Surface diffusion",
                                         "Time unit",
                                         {{"seconds", TimeUnit::seconds},
                                          {"reduced", TimeUnit::reduced}});
    reference_radius = prm.get_double("Reference radius");
    coupled          = prm.get_bool("Coupled");
    solver_tolerance = prm.get_double("Solver tolerance");
    linear_solver    = read_selection<LinearSolver>(
      prm,
      "Surface diffusion",
      "Linear solver",
      {{"direct", LinearSolver::direct}, {"gmres", LinearSolver::gmres}});
    prm.leave_subsection();
    if (!enabled)
      return;
    if (coefficient == 0 && thermal_energy == 0)
      fail_entry("Surface diffusion/Coefficient",
                 "give C_s or the material entries (Thermal energy is 0)");
    if (!(surface_mobility() > 0))
      fail_entry("Surface diffusion/Coefficient",
                 "C_s = D_s delta_s gamma Omega / kT must be positive");
    if (time_unit == TimeUnit::reduced && reference_radius == 0)
      fail_entry("Surface diffusion/Reference radius",
                 "must be positive when Time unit = reduced");
  }

  double
  SurfaceDiffusionParameters::surface_mobility() const
  {
    if (coefficient > 0)
      return coefficient;
    return diffusivity * layer_thickness * surface_energy * atomic_volume /
           thermal_energy;
  }

  double
  SurfaceDiffusionParameters::reduced_time_scale(const double radius) const
  {
    return std::pow(radius, 4) / surface_mobility();
  }
} // namespace levelsinter
