#pragma once

#include <deal.II/base/index_set.h>

#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/trilinos_block_sparse_matrix.h>

#include <vector>

namespace levelsinter
{
  using namespace dealii;

  /**
   * Size @p schur, the Schur-complement approximation of a velocity-pressure
   * block system, from @p system: the pressure block (1,1) takes the
   * system's layout (the approximation couples the pressures as the system
   * does), the velocity block (0,0) only the diagonal entries of the rows
   * @p constraints constrain (AffineConstraints sets them when a cell's
   * contribution goes in), the coupling blocks none. This saves building
   * a second sparsity pattern over the cells and faces.
   * @p owned and @p relevant are the two blocks' partitions.
   */
  void
  make_schur_layout(const TrilinosWrappers::BlockSparseMatrix &system,
                    const std::vector<IndexSet>               &owned,
                    const std::vector<IndexSet>               &relevant,
                    const AffineConstraints<double>           &constraints,
                    TrilinosWrappers::BlockSparseMatrix       &schur);
} // namespace levelsinter
