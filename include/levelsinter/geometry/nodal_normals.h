#pragma once

#include <deal.II/lac/trilinos_vector.h>

#include <levelsinter/level_set/level_set_field.h>
#include <levelsinter/level_set/level_set_filter.h>

#include <array>
#include <vector>

namespace levelsinter
{
  using namespace dealii;

  /**
   * Nodal unit normals N_alpha (Eq. 84): the cell normals (the Q1 gradient
   * at each cell centre) summed at every vertex, then normalised; one
   * ghosted vector per axis on the level set's DoFs. Zero where alpha is
   * saturated in every cell around the node (no direction there).
   *
   * With @p from_distance the cell gradient is that of the Q1 interpolant
   * of the distance d = filter^-1(alpha) instead of alpha: the filter's
   * curvature f''(d) tilts the interpolant's gradient by O((h/E)^2), which
   * does not vanish when E is a fixed number of cells (doc/numerics.md,
   * "Surface-tension forms").
   *
   * On the box faces listed in @p symmetry_boundaries (ids 0..2dim-1) the
   * field continues as its mirror image: the mirror cells would add the
   * reflected normals, so the component across the face is dropped there.
   * Without it a kink on the face (a neck on its symmetry plane) is seen
   * from one side only and reads as smooth.
   */
  template <int dim>
  std::array<TrilinosWrappers::MPI::Vector, dim>
  nodal_normals(const LevelSetField<dim>             &level_set,
                const LevelSetFilter                 &filter,
                const bool                            from_distance,
                const std::vector<types::boundary_id> &symmetry_boundaries = {});

  /**
   * The same for the values @p alpha (ghosted) on the level set's DoFs in
   * place of its own (the csf-curvature form's redistanced level set,
   * redistanced_level_set()).
   */
  template <int dim>
  std::array<TrilinosWrappers::MPI::Vector, dim>
  nodal_normals(const LevelSetField<dim>             &level_set,
                const TrilinosWrappers::MPI::Vector  &alpha,
                const LevelSetFilter                 &filter,
                const bool                            from_distance,
                const std::vector<types::boundary_id> &symmetry_boundaries);
} // namespace levelsinter
