#pragma once

#include <deal.II/lac/trilinos_block_sparse_matrix.h>
#include <deal.II/lac/trilinos_parallel_block_vector.h>
#include <deal.II/lac/trilinos_precondition.h>

namespace levelsinter
{
  using namespace dealii;

  /**
   * Block upper-triangular preconditioner for the saddle-point system
   *   [A  B^T] [v]   [f]
   *   [B  -C ] [p] = [g]
   * (A viscous, C the ASGS stabilisation plus the compressibility mass):
   *   P = [A  B^T; 0  -S],  S ~ B A^{-1} B^T + C ~ M_{1/eta} + C,
   * with one AMG V-cycle for A and one for the assembled S approximation.
   * The viscosity-weighted pressure mass is spectrally equivalent to
   * B A^{-1} B^T independently of h and of the viscosity contrast (Grinevich
   * & Olshanskii 2009), so the outer FGMRES iteration count should stay flat.
   */
  class BlockSchurPreconditioner
  {
  public:
    BlockSchurPreconditioner(
      const TrilinosWrappers::BlockSparseMatrix &system_matrix,
      const TrilinosWrappers::PreconditionAMG   &velocity_amg,
      const TrilinosWrappers::PreconditionAMG   &schur_amg)
      : system_matrix(system_matrix)
      , velocity_amg(velocity_amg)
      , schur_amg(schur_amg)
    {}

    void
    vmult(TrilinosWrappers::MPI::BlockVector       &dst,
          const TrilinosWrappers::MPI::BlockVector &src) const
    {
      // p = -S^{-1} g, then v = A^{-1} (f - B^T p).
      schur_amg.vmult(dst.block(1), src.block(1));
      dst.block(1) *= -1.;
      TrilinosWrappers::MPI::Vector residual(src.block(0));
      system_matrix.block(0, 1).vmult(residual, dst.block(1));
      residual.sadd(-1., src.block(0));
      velocity_amg.vmult(dst.block(0), residual);
    }

  private:
    const TrilinosWrappers::BlockSparseMatrix &system_matrix;
    const TrilinosWrappers::PreconditionAMG   &velocity_amg;
    const TrilinosWrappers::PreconditionAMG   &schur_amg;
  };
} // namespace levelsinter
