#pragma once

#include <deal.II/base/parameter_handler.h>

#include <string>

namespace levelsinter
{
  using namespace dealii;

  /**
   * The `Volume diffusion` subsection of a scene: the interface moves with
   * v = -C_v (grad p . n) n (paper Eq. 112), p the pressure of the elastic
   * solid under surface tension, C_v = (1 - f) Omega D_v / kT (Eq. 25 and
   * 32; why one factor (1 - f) and not two: doc/numerics.md, "Volume
   * diffusion").
   */
  struct VolumeDiffusionParameters
  {
    static void
    declare(ParameterHandler &prm);

    /** Read and check; throws std::runtime_error naming the entry. */
    void
    parse(ParameterHandler &prm);

    /** C_v [m^4/(N s)]: the given coefficient or (1 - f) Omega D_v / kT. */
    double
    mobility() const;

    /**
     * Seconds per unit of the reduced time t* = C_v gamma t / R^3 for the
     * radius @p radius and the surface energy @p surface_energy (gamma of
     * the mechanics): R^3 / (C_v gamma).
     */
    double
    reduced_time_scale(const double radius, const double surface_energy) const;

    bool         enabled          = false;
    double       coefficient      = 0; // C_v; 0: from the material entries
    double       diffusivity      = 0; // D_v [m^2/s]
    double       atomic_volume    = 0; // Omega [m^3]
    double       vacancy_fraction = 0; // f: vacancy volume / Omega
    double       thermal_energy   = 0; // kT [J]
    enum class TimeUnit
    {
      seconds,
      reduced // t* = C_v gamma t / R^3
    } time_unit = TimeUnit::seconds;
    double       reference_radius = 0;         // R of t*
    double       interior_offset  = 6;         // lambda in cells (Eq. 110)
    bool         linear_extrapolation = true;  // or constant (Eq. 111)
    bool         limited_extrapolation = false; // linear, |d eta| bounded
    bool         recovered_gradient   = false; // grad p over the solid part
    bool         boundary_flux        = false; // xi from Green's formula
    // Each elastic solve from u = 0, the stress of the current shape (no
    // u^{n-1}); false: u^n = u^{n-1} + dt v^n (the paper's Eq. 92).
    bool         total_elastic_state  = false;
    double       solver_tolerance = 1e-10;
    unsigned int max_iterations   = 1000;
    // Fraction of the measured explicit stability limit of v = -C_v xi N
    // the time step is kept below (VolumeDiffusion::time_step_limit());
    // 0: no limit.
    double       time_step_factor = 0.5;
    // Steps that share one elastic solve while the mesh stays (1: every
    // step solves).
    unsigned int solve_interval   = 1;
  };
} // namespace levelsinter
