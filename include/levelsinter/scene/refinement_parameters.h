#pragma once

#include <deal.II/base/parameter_handler.h>

namespace levelsinter
{
  using namespace dealii;

  /** The `Mesh refinement` subsection: the band around the interface. */
  struct RefinementParameters
  {
    /**
     * The band-width rule, in the words used by the entry's documentation,
     * the error message and doc/user_guide.md.
     */
    static const char *const band_width_rule;

    static void
    declare(ParameterHandler &prm);

    /** Read and check; throws std::runtime_error naming the entry. */
    void
    parse(ParameterHandler &prm);

    unsigned int min_level      = 0;
    unsigned int max_level      = 0;
    double       band_width     = 0;
    unsigned int adapt_interval = 1;
    // Extra levels above max_level where the interface is sharply curved
    // (0 = off) and the cells wanted across a curvature radius there.
    unsigned int curvature_levels           = 0;
    double       cells_per_curvature_radius = 4;
  };
} // namespace levelsinter
