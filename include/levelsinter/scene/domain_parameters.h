#pragma once

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/types.h>

#include <vector>

namespace levelsinter
{
  using namespace dealii;

  /**
   * The `Domain` subsection: the box, its coarse cells and the faces the
   * scene is mirrored across. Coordinates are std::vector<double> of length
   * `dimension` because the dimension itself is a parameter.
   */
  struct DomainParameters
  {
    static void
    declare(ParameterHandler &prm);

    /** Read and check; throws std::runtime_error naming the entry. */
    void
    parse(ParameterHandler &prm, const unsigned int dimension);

    std::vector<double>       lower_corner;
    std::vector<double>       upper_corner;
    std::vector<unsigned int> subdivisions;
    // Box faces with zero normal velocity (0..5 for x-, x+, y-, y+, z-, z+,
    // the boundary ids of the box mesh): every mechanism and the refinement
    // treat the scene as mirrored across them.
    std::vector<types::boundary_id> symmetry_planes;

    /** Largest edge of the coarse cells (level 0). */
    double
    coarse_cell_size() const;
  };
} // namespace levelsinter
