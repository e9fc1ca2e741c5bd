#pragma once

#include <deal.II/base/parameter_handler.h>

namespace levelsinter
{
  using namespace dealii;

  /** The `Level set` subsection: filter, transport and reinitialisation. */
  struct LevelSetParameters
  {
    enum class Filter
    {
      sine, // Eq. 65
      tanh  // Eq. 69
    };

    enum class ReinitializationPace
    {
      step,            // strength and diffusion per step (lambda = h / dt)
      interface_motion // per time the fastest interface point takes to
                       // cross the finest cell
    };

    enum class SolidReinitialization
    {
      automatic, // band cells for surface diffusion without viscous flow
      band_cells,
      finest_cells
    };

    static void
    declare(ParameterHandler &prm);

    /** Read and check; throws std::runtime_error naming the entry. */
    void
    parse(ParameterHandler &prm);

    Filter       filter           = Filter::sine;
    double       filter_thickness = 0;
    double       theta            = 0.5;
    double       solver_tolerance = 1e-10;
    unsigned int max_iterations   = 1000;
    double       reinitialization_strength  = 0.25;
    double       reinitialization_diffusion = 0.05;
    double       reinitialization_tolerance = 0.25;
    ReinitializationPace reinitialization_pace = ReinitializationPace::step;
    SolidReinitialization solid_reinitialization =
      SolidReinitialization::automatic;
    // The choice above with 'automatic' resolved from the mechanisms
    // (SceneParameters::check_across_sections()).
    bool solid_reinitialization_from_band = false;
  };
} // namespace levelsinter
