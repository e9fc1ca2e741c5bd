#pragma once

#include <deal.II/base/parameter_handler.h>

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
    declare_parameters(ParameterHandler &prm);

    /** Read and check; throws std::runtime_error naming the entry. */
    void
    parse_parameters(ParameterHandler &prm, const unsigned int dimension);

    /** On with "true", or with "auto" for a scene of two or more particles. */
    bool
    enabled(const std::string &shape, const unsigned int n_particles) const;

    std::string packing_analysis = "auto"; // auto, true, false
    // Empty: the bounding box of the particle centres.
    std::vector<double> control_lower_corner;
    std::vector<double> control_upper_corner;
  };
} // namespace levelsinter
