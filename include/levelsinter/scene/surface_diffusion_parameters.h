#pragma once

#include <deal.II/base/parameter_handler.h>

namespace levelsinter
{
  using namespace dealii;

  /** The `Surface diffusion` subsection (paper Sect. 5):
   * v_n = C_s Delta_s kappa (SurfaceDiffusion mechanism). */
  struct SurfaceDiffusionParameters
  {
    enum class TimeUnit
    {
      seconds,
      reduced // t* = C_s t / R^4
    };

    enum class LinearSolver
    {
      direct,
      gmres
    };

    static void
    declare(ParameterHandler &prm);

    /** Read and check; throws std::runtime_error naming the entry. */
    void
    parse(ParameterHandler &prm);

    /** C_s = D_s delta_s gamma_sf Omega / kT, or the given coefficient. */
    double
    surface_mobility() const;

    /**
     * Seconds per unit of the reduced time t* = C_s t / R^4 for the radius
     * @p radius: R^4 / C_s.
     */
    double
    reduced_time_scale(const double radius) const;

    bool         enabled          = false;
    double       coefficient      = 0; // C_s; 0: from the material entries
    double       diffusivity      = 0; // D_s
    double       layer_thickness  = 0; // delta_s
    double       surface_energy   = 0; // gamma_sf
    double       atomic_volume    = 0; // Omega
    double       thermal_energy   = 0; // kT
    TimeUnit     time_unit        = TimeUnit::seconds;
    double       reference_radius = 0;    // R of t*
    bool         coupled          = true; // mixed (Eq. 82) or decoupled
    double       solver_tolerance = 1e-8;
    LinearSolver linear_solver    = LinearSolver::gmres;
  };
} // namespace levelsinter
