#pragma once

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/point.h>

#include <levelsinter/scene/phase_law_parameters.h>
#include <levelsinter/scene/viscous_flow_parameters.h>

#include <string>
#include <vector>

namespace levelsinter
{
  using namespace dealii;

  /**
   * Everything a scene file says, parsed and checked. The entries are
   * declared once (declare_parameters()) so that `--print-parameters` and the
   * parser always agree. Coordinates are kept as std::vector<double> of
   * length `dimension` because the dimension itself is a parameter.
   */
  struct SceneParameters
  {
    static void
    declare_parameters(ParameterHandler &prm);

    /**
     * Read the values out of a parsed handler and check the ones the
     * patterns cannot (vector lengths, orderings, files). Throws
     * std::runtime_error with a message naming the entry.
     * @p scene_directory resolves relative file names.
     */
    void
    parse_parameters(ParameterHandler &prm, const std::string &scene_directory);

    /**
     * Edge length of the cells at `Mesh refinement/Maximum level`, the
     * level of the band around the interface (the largest over the axes
     * if the coarse cells are not square). Curvature refinement makes
     * cells finer than this near sharp features.
     */
    double
    band_cell_size() const;

    unsigned int dimension = 2;

    struct Domain
    {
      std::vector<double>       lower_corner;
      std::vector<double>       upper_corner;
      std::vector<unsigned int> subdivisions;
    } domain;

    struct Geometry
    {
      std::string shape; // "particles", "slotted disk", "perturbed particle"
      // Inline particles and the particle file are merged: x, y[, z], r.
      std::vector<std::vector<double>> particles;
      std::string                      particle_file;
      std::vector<double>              slotted_disk_centre;
      double                           slotted_disk_radius = 0;
      double                           slot_width          = 0;
      double                           slot_depth          = 0;
      // "perturbed particle": the first particle, radius modulated by one
      // mode (Mullins test of surface diffusion).
      double       perturbation_amplitude = 0;
      unsigned int perturbation_mode      = 2;
    } geometry;

    struct LevelSet
    {
      std::string  filter; // "sine" (Eq. 65) or "tanh" (Eq. 69)
      double       filter_thickness = 0;
      double       theta            = 0.5;
      double       solver_tolerance = 1e-10;
      unsigned int max_iterations   = 1000;
      double       reinitialization_strength  = 0.25;
      double       reinitialization_diffusion = 0.05;
      double       reinitialization_tolerance = 0.25;
      // "auto" is resolved when the scene is read (surface diffusion
      // without viscous flow).
      bool         solid_reinitialization_from_band = false;
    } level_set;

    struct Refinement
    {
      unsigned int min_level      = 0;
      unsigned int max_level      = 0;
      double       band_width     = 0;
      unsigned int adapt_interval = 1;
      // Extra levels above max_level where the interface is sharply curved
      // (0 = off) and the cells wanted across a curvature radius there.
      unsigned int curvature_levels         = 0;
      double       cells_per_curvature_radius = 4;
    } refinement;

    struct Time
    {
      double       end_time  = 0;
      double       time_step = 0; // 0: from the CFL number
      double       cfl       = 0.5;
      unsigned int max_steps = 0; // 0: unlimited
      // r > 0: the step is max(time_step, r t) (before the caps).
      double relative_time_step = 0;
    } time;

    struct Velocity
    {
      std::string         type; // none, constant, rotation, expression
      std::vector<double> constant;
      std::vector<double> rotation_centre;
      std::vector<double> rotation_axis;
      double              angular_velocity = 0;
      std::string         expression;
      std::string         expression_constants;
    } velocity;

    // Surface diffusion (paper Sect. 5): v_n = C_s Delta_s kappa.
    struct SurfaceDiffusion
    {
      bool        enabled     = false;
      double      coefficient = 0; // C_s; 0: from the material entries
      double      diffusivity = 0; // D_s
      double      layer_thickness = 0; // delta_s
      double      surface_energy  = 0; // gamma_sf
      double      atomic_volume   = 0; // Omega
      double      thermal_energy  = 0; // kT
      std::string time_unit        = "seconds"; // or "reduced": t* = C_s t/R^4
      double      reference_radius = 0;         // R of t*
      bool        coupled          = true;      // mixed (Eq. 82) or decoupled
      double      solver_tolerance = 1e-8;
      std::string linear_solver    = "direct"; // or "gmres"

      /** C_s = D_s delta_s gamma_sf Omega / kT, or the given coefficient. */
      double
      surface_mobility() const;
    } surface_diffusion;

    // v^c (Eq. 113-116), a mechanism of its own on top of the others.
    bool volume_correction = false;

    struct Output
    {
      std::string  directory;
      unsigned int field_interval    = 0;
      bool         write_vtu         = true;
      bool         write_xdmf        = true;
      unsigned int metrics_interval  = 1;
      unsigned int progress_interval = 10;
    } output;

    ViscousFlowParameters viscous_flow;
    PhaseLawParameters    phase_law;
  };
} // namespace levelsinter
