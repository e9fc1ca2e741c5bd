#include <deal.II/lac/solver_cg.h>
#include <deal.II/lac/solver_control.h>

#include <levelsinter/mechanics/block_schur_preconditioner.h>

#include <Epetra_MultiVector.h>
#include <Teuchos_ParameterList.hpp>

#include <algorithm>
#include <memory>

namespace levelsinter
{
  BlockSchurPreconditioner::BlockSchurPreconditioner(
    const TrilinosWrappers::BlockSparseMatrix &system_matrix,
    const TrilinosWrappers::SparseMatrix      &schur_approximation,
    const std::vector<std::vector<double>>    &velocity_near_null_space,
    const unsigned int                         dim,
    const bool                                 smoothed_aggregation,
    const unsigned int                         smoother_sweeps)
    : system_matrix(system_matrix)
    , schur_approximation(schur_approximation)
  {
    {
      // Smoothed aggregation for a vector elliptic operator: Chebyshev
      // smoother (2 sweeps unless told), Q1 (no higher-order aggregation), no dropping
      // of weak connections and a W-cycle. With a viscosity contrast the
      // V-cycle's coarse correction is what weakens as h shrinks (an exact
      // solve of the first coarse level restores the count; more smoothing
      // there does not): the W-cycle revisits the coarse levels, and
      // without dropping the aggregates straddle the interface, where the
      // prolongator smoothing follows the viscosity jump. Measured on
      // Hopper's case at eta_f/eta_s = 1e-6, R/h = 80, mean outer count:
      // threshold 1e-4 and V-cycle 42, threshold 0 and W-cycle 35 at lower
      // CPU time (doc/numerics.md, "Stokes preconditioner").
      TrilinosWrappers::PreconditionAMG::AdditionalData data;
      data.elliptic              = true;
      data.higher_order_elements = false;
      data.smoother_type         = "Chebyshev";
      data.smoother_sweeps       = smoother_sweeps;
      data.aggregation_threshold = 0;
      data.w_cycle               = true;
      const auto &matrix = system_matrix.block(0, 0).trilinos_matrix();
      Teuchos::ParameterList              parameters;
      std::unique_ptr<Epetra_MultiVector> no_constant_modes;
      data.set_parameters(parameters, no_constant_modes, matrix);
      // Plain aggregation keeps the tentative prolongator (one nonzero
      // per row and mode): its coarse operators are sparse and cheap to
      // form, at about 2.3x the outer iterations. On the 27 spheres made
      // like the 154 (1 rank): peak resident set 3.15 GB against 4.06 GB,
      // elastic solve CPU 1.19x (doc/performance.md).
      if (!smoothed_aggregation)
        parameters.set("aggregation: damping factor", 0.);
      // With a viscosity contrast the count jumps by 7 where ML's first
      // coarse level outgrows its direct solve (2000 rows, from R/h = 80
      // in 2D). In 2D that level (1/8 of the velocity rows) is solved
      // directly up to 16 000 rows at no extra cost per solve (R/h = 320);
      // a quarter of the rows keeps the fine level itself out of the
      // direct solve (which doubles the cost of small problems). 3D keeps
      // ML's default: solving its first coarse level directly saves 3 of
      // 43 iterations at R/h = 20 but costs 1.7x per solve (denser coarse
      // operator, doc/numerics.md).
      if (dim == 2)
        parameters.set("coarse: max size",
                       std::clamp(matrix.NumGlobalRows() / 4, 2000, 16000));
      // deal.II 9.4 takes only 0/1 constant modes; the rotations need
      // real values, so the null space goes to ML directly (ML copies it
      // during the setup).
      Epetra_MultiVector modes(matrix.OperatorDomainMap(),
                               velocity_near_null_space.size());
      for (unsigned int m = 0; m < velocity_near_null_space.size(); ++m)
        {
          AssertDimension(velocity_near_null_space[m].size(),
                          static_cast<std::size_t>(modes.MyLength()));
          for (unsigned int row = 0; row < velocity_near_null_space[m].size();
               ++row)
            modes[m][row] = velocity_near_null_space[m][row];
        }
      parameters.set("null space: type", "pre-computed");
      parameters.set("null space: dimension", modes.NumVectors());
      parameters.set("null space: vectors", modes.Values());
      velocity_amg.initialize(system_matrix.block(0, 0), parameters);
    }
    schur_jacobi.initialize(schur_approximation);
  }

  void
  BlockSchurPreconditioner::vmult(
    TrilinosWrappers::MPI::BlockVector       &dst,
    const TrilinosWrappers::MPI::BlockVector &src) const
  {
    // p = -S^{-1} g, then v = A^{-1} (f - B^T p).
    // S ~ M_{1/eta_K} + C is a mass matrix plus an h^2-scaled Laplacian:
    // its diagonal makes it well conditioned in h and in the viscosity,
    // so CG with Jacobi reaches 0.1 in 3-4 iterations at any resolution,
    // where one AMG V-cycle is a poor approximation of its inverse on
    // adapted 3D meshes (outer count 35 / 39 against 27 / 30 at R/h = 10 /
    // 20, doc/numerics.md).
    {
      ReductionControl control(100, 0., 0.1, false, false);
      SolverCG<TrilinosWrappers::MPI::Vector> cg(control);
      dst.block(1) = 0.;
      cg.solve(schur_approximation, dst.block(1), src.block(1), schur_jacobi);
    }
    dst.block(1) *= -1.;
    TrilinosWrappers::MPI::Vector residual(src.block(0));
    system_matrix.block(0, 1).vmult(residual, dst.block(1));
    residual.sadd(-1., src.block(0));
    velocity_amg.vmult(dst.block(0), residual);
  }
} // namespace levelsinter
