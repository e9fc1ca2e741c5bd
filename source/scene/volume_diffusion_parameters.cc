#include <levelsinter/scene/parameter_entries.h>
#include <levelsinter/scene/volume_diffusion_parameters.h>

#include <utility>
#include <vector>

namespace levelsinter
{
  namespace
  {
    [[noreturn]] void
    fail(const std::string &entry, const std::string &message)
    {
      fail_entry("Volume diffusion/" + entry, message);
    }
  } // namespace

  void
  VolumeDiffusionParameters::declare(ParameterHandler &prm)
  {
    prm.enter_subsection("Volume diffusion");
    {
      prm.declare_entry("Enabled",
                        "false",
                        Patterns::Bool(),
                        "Move the interface by volume (lattice) diffusion, "
                        "v = -C_v (grad p . n) n (paper Eq. 112), p the "
                        "pressure of the elastic solid under surface "
                        "tension.");
      prm.declare_entry("Coefficient",
                        "0",
                        Patterns::Double(0),
                        "C_v [m^4/(N s)] (in a scene in um and MPa: "
                        "um^2/(MPa s)). 0: computed as (1 - f) Omega D_v "
                        "/ kT from the four entries below.");
      // The material entries of C_v = (1 - f) Omega D_v / kT.
      for (const auto &[name, documentation] :
           std::vector<std::pair<std::string, std::string>>{
             {"Volume diffusivity", "D_v [m^2/s]."},
             {"Atomic volume", "Omega [m^3]."},
             {"Thermal energy", "kT [J]."}})
        prm.declare_entry(name, "0", Patterns::Double(0), documentation);
      prm.declare_entry("Vacancy volume fraction",
                        "0",
                        Patterns::Double(0, 1),
                        "f: the volume of a vacancy as a fraction of Omega "
                        "(Eq. 10), 0 <= f < 1.");
      prm.declare_entry("Time unit",
                        "seconds",
                        Patterns::Selection("seconds|reduced"),
                        "Unit of Time/End time and Time/Time step: seconds, "
                        "or the reduced time t* = C_v gamma t / R^3 with "
                        "gamma the surface energy and R the reference "
                        "radius. With surface diffusion on as well, at "
                        "most one of the two sections may say reduced: "
                        "its t* is the scene's time and both coefficients "
                        "are converted to it.");
      prm.declare_entry("Reference radius",
                        "0",
                        Patterns::Double(0),
                        "R of the reduced time t* (needed when Time unit = "
                        "reduced).");
      prm.declare_entry("Interior offset",
                        "6",
                        Patterns::Double(0),
                        "lambda of Eq. 110 in cell sizes: grad p . n is read "
                        "only at nodes deeper than lambda in the solid, "
                        "clear of the pressure's transition zone, and "
                        "carried out to the interface along n "
                        "(doc/numerics.md). 6: on a circle, where xi is 0, "
                        "the elastic pressure leaves a spurious C_v |xi| of "
                        "0.011 um/s at 6 cells against 0.60 at 3 (h = 1/128, "
                        "measured); 3 suffices for a smeared jump alone.");
      prm.declare_entry("Extrapolation",
                        "linear",
                        Patterns::Selection("linear|limited|constant"),
                        "How grad p . n read lambda inside reaches the "
                        "interface: linear (with its normal derivative, "
                        "second order in h), limited (linear with the "
                        "correction at each source at most twice the value "
                        "read there: no grid-scale ridge of xi grows, "
                        "doc/numerics.md) or constant (Eq. 111 as in the "
                        "paper, an O(lambda) error).");
      prm.declare_entry("Pressure gradient",
                        "nodal",
                        Patterns::Selection("nodal|recovered|flux"),
                        "grad p at the nodes where xi is read: nodal (the "
                        "cells' gradients at the vertex, averaged) or "
                        "recovered (a lumped L2 projection over the solid "
                        "part of the cells, with cut-cell quadrature: it "
                        "reads no atmosphere). doc/numerics.md, \"Volume "
                        "diffusion: a recovered gradient\". Or flux: xi "
                        "read on the interface itself as the boundary flux "
                        "of the solid's harmonic pressure (Green's formula "
                        "with cut-cell quadrature), without the interior "
                        "offset (Interior offset and Extrapolation are not "
                        "read); for Viscous flow/Pressure space = solid. "
                        "doc/numerics.md, \"Volume diffusion: xi as the "
                        "boundary flux\".");
      prm.declare_entry("Elastic state",
                        "incremental",
                        Patterns::Selection("incremental|total"),
                        "incremental: u^n = u^{n-1} + dt v^n (Eq. 92), the "
                        "ghost penalty and drag act on each step's increment "
                        "only, so their hold on the accumulated displacement "
                        "fades over the steps; total: every elastic solve "
                        "starts from u = 0, the stress of the current shape, "
                        "with the stabilisation on the whole displacement. "
                        "doc/numerics.md, \"Volume diffusion: the elastic "
                        "state in the cut cells\".");
      prm.declare_entry("Solver tolerance",
                        "1e-10",
                        Patterns::Double(0),
                        "Relative residual of the extension solve (GMRES "
                        "with ILU).");
      prm.declare_entry("Maximum solver iterations",
                        "1000",
                        Patterns::Integer(1),
                        "GMRES iteration limit of the extension solve; "
                        "reaching it stops the run.");
      prm.declare_entry("Time step factor",
                        "0.5",
                        Patterns::Double(0),
                        "The time step stays below this fraction of the "
                        "explicit stability limit of v = -C_v xi N, "
                        "measured on a perturbed cylinder: dt <= factor x "
                        "c h_min^3 / ((2/3)(1 + nu) C_v gamma) "
                        "(doc/numerics.md). 0: no limit (Time step and the "
                        "CFL number alone choose dt).");
      prm.declare_entry("Elastic solve interval",
                        "1",
                        Patterns::Integer(1),
                        "Solve the elastic problem at most every this many "
                        "steps: the steps between keep its pressure and xi "
                        "while the mesh stays (a step after a mesh "
                        "adaptation, or after a restart, always solves). 1: "
                        "every step.");
    }
    prm.leave_subsection();
  }

  void
  VolumeDiffusionParameters::parse(ParameterHandler &prm)
  {
    prm.enter_subsection("Volume diffusion");
    enabled          = prm.get_bool("Enabled");
    coefficient      = prm.get_double("Coefficient");
    diffusivity      = prm.get_double("Volume diffusivity");
    atomic_volume    = prm.get_double("Atomic volume");
    thermal_energy   = prm.get_double("Thermal energy");
    vacancy_fraction = prm.get_double("Vacancy volume fraction");
    time_unit        = read_selection<TimeUnit>(prm,
                                         "Volume diffusion",
                                         "Time unit",
                                         {{"seconds", TimeUnit::seconds},
                                          {"reduced", TimeUnit::reduced}});
    reference_radius = prm.get_double("Reference radius");
    interior_offset  = prm.get_double("Interior offset");
    linear_extrapolation  = prm.get("Extrapolation") != "constant";
    limited_extrapolation = prm.get("Extrapolation") == "limited";
    recovered_gradient   = prm.get("Pressure gradient") == "recovered";
    boundary_flux        = prm.get("Pressure gradient") == "flux";
    total_elastic_state  = prm.get("Elastic state") == "total";
    solver_tolerance = prm.get_double("Solver tolerance");
    max_iterations   = prm.get_integer("Maximum solver iterations");
    time_step_factor = prm.get_double("Time step factor");
    solve_interval   = prm.get_integer("Elastic solve interval");
    prm.leave_subsection();

    if (!enabled)
      return;
    if (coefficient == 0 && thermal_energy == 0)
      fail("Coefficient",
           "give C_v or the material entries (Thermal energy is 0)");
    if (vacancy_fraction >= 1)
      fail("Vacancy volume fraction", "must be below 1");
    if (!(mobility() > 0))
      fail("Coefficient",
           "C_v = (1 - f) Omega D_v / kT must be positive");
    if (time_unit == TimeUnit::reduced && reference_radius == 0)
      fail("Reference radius", "must be positive when Time unit = reduced");
    if (interior_offset <= 0)
      fail("Interior offset", "must be positive");
    if (time_step_factor > 1)
      fail("Time step factor",
           "must be at most 1 (1 is the measured stability limit itself)");
  }

  double
  VolumeDiffusionParameters::mobility() const
  {
    if (coefficient > 0)
      return coefficient;
    return (1 - vacancy_fraction) * atomic_volume * diffusivity /
           thermal_energy;
  }

  double
  VolumeDiffusionParameters::reduced_time_scale(
    const double radius,
    const double surface_energy) const
  {
    return radius * radius * radius / (mobility() * surface_energy);
  }
} // namespace levelsinter
