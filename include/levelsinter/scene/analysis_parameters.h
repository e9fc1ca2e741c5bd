#pragma once

#include <deal.II/base/parameter_handler.h>

#include <levelsinter/scene/geometry_parameters.h>

#include <string>
#include <vector>

namespace levelsinter
{
  using namespace dealii;

  /** The `Analysis` subsection of a scene: the packing metrics recorded
   * every metrics interval (pores, relative density, necks, coordination,
   * shrinkage; PackingAnalysis). */
  struct AnalysisParameters
  {
    static void
    declare(ParameterHandler &prm);

    /** Read and check; throws std::runtime_error naming the entry. */
    void
    parse(ParameterHandler &prm, const unsigned int dimension);

    /** On with "true", or with "auto" for a scene of two or more particles. */
    bool
    enabled(const GeometryParameters::Shape shape,
            const unsigned int              n_particles) const;

    enum class Mode
    {
      automatic,
      on,
      off
    } packing_analysis = Mode::automatic;
    // Empty: the bounding box of the particle centres.
    std::vector<double> control_lower_corner;
    std::vector<double> control_upper_corner;
  };
} // namespace levelsinter
