#pragma once

#include <deal.II/lac/trilinos_block_sparse_matrix.h>
#include <deal.II/lac/trilinos_parallel_block_vector.h>
#include <deal.II/lac/trilinos_precondition.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>

#include <vector>

namespace levelsinter
{
  using namespace dealii;

  /**
   * Block upper-triangular preconditioner for the saddle-point system
   *   [A  B^T] [v]   [f]
   *   [B  -C ] [p] = [g]
   * (A viscous, C the ASGS stabilisation plus the compressibility mass):
   *   P = [A  B^T; 0  -S],  S ~ B A^{-1} B^T + C ~ M_{1/eta_K} + C,
   * with one AMG W-cycle for A (step-32/55 structure) and a few
   * Jacobi-preconditioned CG iterations for the assembled S approximation.
   * M_{1/eta_K} weights the pressure mass with the inverse of the
   * cell-mean viscosity (Grinevich & Olshanskii 2009), which keeps the
   * outer FGMRES count nearly flat in h and in the viscosity contrast
   * (doc/numerics.md, "Stokes preconditioner"). The inner CG makes the
   * preconditioner nonlinear, which FGMRES allows.
   */
  class BlockSchurPreconditioner
  {
  public:
    /**
     * Set up the AMG hierarchy of A with @p velocity_near_null_space (the
     * rigid-body modes, one vector per mode over the locally owned rows of
     * A), and the Jacobi preconditioner of @p schur_approximation. @p dim
     * sets how large a coarse level of A is still solved directly;
     * @p smoothed_aggregation chooses smoothed or plain aggregation;
     * @p smoother_sweeps is the degree of the Chebyshev smoother.
     */
    BlockSchurPreconditioner(
      const TrilinosWrappers::BlockSparseMatrix &system_matrix,
      const TrilinosWrappers::SparseMatrix      &schur_approximation,
      const std::vector<std::vector<double>>    &velocity_near_null_space,
      const unsigned int                         dim,
      const bool                                 smoothed_aggregation,
      const unsigned int                         smoother_sweeps);

    void
    vmult(TrilinosWrappers::MPI::BlockVector       &dst,
          const TrilinosWrappers::MPI::BlockVector &src) const;

  private:
    const TrilinosWrappers::BlockSparseMatrix &system_matrix;
    TrilinosWrappers::PreconditionAMG          velocity_amg;
    const TrilinosWrappers::SparseMatrix      &schur_approximation;
    TrilinosWrappers::PreconditionJacobi       schur_jacobi;
  };
} // namespace levelsinter
