#include <deal.II/base/quadrature_lib.h>
#include <deal.II/base/timer.h>

#include <deal.II/dofs/dof_tools.h>

#include <deal.II/fe/fe_values.h>

#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/solver_cg.h>
#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/solver_gmres.h>
#include <deal.II/lac/sparsity_tools.h>
#include <deal.II/lac/trilinos_solver.h>

#include <levelsinter/geometry/geometry_band.h>
#include <levelsinter/geometry/mixed_curvature_solver.h>
#include <levelsinter/geometry/nodal_normals.h>
#include <levelsinter/level_set/box_mapping.h>
#include <levelsinter/level_set/ghosted_vector.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>

namespace levelsinter
{
  namespace
  {
    using SparseMatrix = TrilinosWrappers::SparseMatrix;
    using Vector       = TrilinosWrappers::MPI::Vector;
    using BlockVector  = TrilinosWrappers::MPI::BlockVector;

    // The 2x2 block system [[kk, kv], [vk, vv]] acting on (kappa, w).
    struct BlockSystem
    {
      const SparseMatrix &kk, &kv, &vk, &vv;

      void
      vmult(BlockVector &dst, const BlockVector &src) const
      {
        kk.vmult(dst.block(0), src.block(0));
        kv.vmult_add(dst.block(0), src.block(1));
        vk.vmult(dst.block(1), src.block(0));
        vv.vmult_add(dst.block(1), src.block(1));
      }
    };

    // x = A^-1 b for an SPD block by CG to a relative tolerance. The blocks
    // are M + b L with b = sqrt(C dt): while b is small against h^2 they are
    // mass-like and Jacobi-preconditioned CG needs 4-12 iterations at a
    // fraction of an AMG V-cycle's cost (measured: the whole kappa / v_s
    // solve of a 27-particle packing 2.3x cheaper than with AMG on every
    // block). When Jacobi needs more than jacobi_limit iterations (large b /
    // h^2: long steps on fine meshes), AMG is built once and used from then
    // on; the outer FGMRES tolerates the change of preconditioner.
    class InnerSolve
    {
    public:
      InnerSolve(const SparseMatrix &matrix, const double tolerance)
        : matrix(matrix)
        , tolerance(tolerance)
      {
        jacobi.initialize(matrix);
      }

      void
      vmult(Vector &dst, const Vector &src) const
      {
        dst                = 0;
        const double target = tolerance * src.l2_norm();
        if (!amg_built)
          {
            SolverControl    control(jacobi_limit, target, false, false);
            SolverCG<Vector> cg(control);
            try
              {
                cg.solve(matrix, dst, src, jacobi);
                return;
              }
            catch (const SolverControl::NoConvergence &)
              {
                build_amg();
              }
          }
        SolverControl    control(1000, target);
        SolverCG<Vector> cg(control);
        cg.solve(matrix, dst, src, amg);
      }

    private:
      void
      build_amg() const
      {
        TrilinosWrappers::PreconditionAMG::AdditionalData data;
        data.elliptic = true;
        // Drops the weak couplings across the level sets from the
        // aggregation (M + b L is strongly anisotropic): measured 10-45 %
        // fewer inner iterations than the default 1e-4 (doc/numerics.md).
        data.aggregation_threshold = 0.02;
        amg.initialize(matrix, data);
        amg_built = true;
      }

      static constexpr unsigned int jacobi_limit = 25;

      const SparseMatrix                        &matrix;
      const double                               tolerance;
      TrilinosWrappers::PreconditionJacobi       jacobi;
      mutable TrilinosWrappers::PreconditionAMG amg;
      mutable bool                               amg_built = false;
    };

    // Inverse of the block upper-triangular factor [[M, -b K_A], [0, S]] of
    // the block LU factorisation, S = M_g + b^2 L M^-1 K_A the Schur
    // complement of w. S is replaced by (M + b L) M^-1 (M + b K_A): the
    // Cahn-Hilliard factorisation of Bosch, Stoll & Benner (2014) with the
    // two different operators kept in the order in which S multiplies them
    // (doc/numerics.md). Each factor and M are inner CG solves with AMG to a
    // loose tolerance, hence flexible GMRES outside.
    struct SchurPreconditioner
    {
      const SparseMatrix &mass;
      const SparseMatrix &coupling;
      const InnerSolve   &mass_inverse;
      const InnerSolve   &tangential_inverse;
      const InnerSolve   &isotropic_inverse;

      void
      vmult(BlockVector &dst, const BlockVector &src) const
      {
        a.reinit(src.block(0), true);
        c.reinit(src.block(0), true);
        tangential_inverse.vmult(a, src.block(1));
        mass.vmult(c, a);
        isotropic_inverse.vmult(dst.block(1), c);
        // kappa: M x = f - kv y (kv holds -b K_A).
        coupling.vmult(a, dst.block(1));
        a *= -1;
        a += src.block(0);
        mass_inverse.vmult(dst.block(0), a);
      }

      mutable Vector a = {}, c = {};
    };
  } // namespace

  template <int dim>
  MixedCurvatureSolver<dim>::MixedCurvatureSolver(const LevelSetFilter &filter,
                                                  const Settings &settings,
                                                  TimerOutput    &timer)
    : filter(filter)
    , settings(settings)
    , timer(timer)
  {}

  template <int dim>
  void
  MixedCurvatureSolver<dim>::setup(const LevelSetField<dim> &level_set)
  {
    const auto    &dofs  = level_set.dof_handler();
    const MPI_Comm comm  = dofs.get_communicator();
    const auto    &owned = level_set.locally_owned();
    rhs.reinit(owned, comm);
    kappa.reinit(owned, level_set.locally_relevant(), comm);
    velocity.reinit(owned, level_set.locally_relevant(), comm);
  }

  template <int dim>
  void
  MixedCurvatureSolver<dim>::assemble(const LevelSetField<dim> &level_set,
                                      const Vector             &alpha,
                                      const double              coefficient,
                                      const double              dt,
                                      const Vector &previous_velocity)
  {
    TimerOutput::Scope scope(timer, "curvature assembly");
    normals = levelsinter::nodal_normals(level_set,
                                         alpha,
                                         filter,
                                         settings.normals_from_distance,
                                         settings.symmetry_boundaries);
    // The blocks live from here to the end of the solve: between steps
    // they would sit beside the elastic problem's matrices and AMG, whose
    // solve sets the coupled packings' peak memory.
    for (auto *m : {&kk, &kv, &vk, &vv})
      m->reinit(level_set.sparsity_pattern());
    rhs = 0;

    const bool   coupled = settings.coupled && dt > 0;
    const double b       = std::sqrt(coefficient * dt);
    // Row factors of the off-diagonal blocks: scaled system when coupled,
    // plain (kappa then v_s = -C M_g^{-1} L kappa) when not.
    const double kv_factor = coupled ? -b : 0.;
    const double vk_factor = coupled ? b : coefficient;
    const double lag       = previous_velocity.size() > 0 ? dt : 0.;

    const QGauss<dim>  quadrature(2);
    FEValues<dim> fe_values(box_mapping<dim>(),
                            level_set.fe(),
                            quadrature,
                            update_values | update_gradients |
                              update_JxW_values | update_quadrature_points);
    const SceneMeasure &measure = level_set.measure();
    const unsigned int n  = level_set.fe().dofs_per_cell;
    const unsigned int nq = quadrature.size();
    FullMatrix<double> m_kk(n, n), m_kv(n, n), m_vk(n, n), m_vv(n, n);
    dealii::Vector<double>               local_rhs(n);
    std::vector<types::global_dof_index> indices(n);
    std::vector<double>                  alpha_values(nq);
    std::vector<Tensor<1, dim>> alpha_gradients(nq), lag_gradients(nq),
      normal_gradients(nq);
    std::vector<double> divergence(nq), radial_normal(nq), mu(nq);
    std::vector<double> mobility_factor(nq, 1.);

    // DoFs no band cell touches get kappa = v_s = 0 (identity rows).
    Vector touched;
    touched.reinit(level_set.locally_owned(),
                   level_set.locally_relevant(),
                   level_set.dof_handler().get_communicator(),
                   true);

    for (const auto &cell : level_set.dof_handler().active_cell_iterators())
      if (cell->is_locally_owned() &&
          in_geometry_band<dim>(filter, alpha, cell))
        {
          fe_values.reinit(cell);
          fe_values.get_function_values(alpha, alpha_values);
          fe_values.get_function_gradients(alpha, alpha_gradients);
          if (lag > 0)
            fe_values.get_function_gradients(previous_velocity, lag_gradients);
          // div N, on a body of revolution with the azimuthal N_r / r.
          fe_values.get_function_values(normals[0], radial_normal);
          for (unsigned int q = 0; q < nq; ++q)
            divergence[q] =
              radial_normal[q] *
              measure.inverse_radius(fe_values.quadrature_point(q));
          for (unsigned int c = 0; c < dim; ++c)
            {
              fe_values.get_function_gradients(normals[c], normal_gradients);
              for (unsigned int q = 0; q < nq; ++q)
                divergence[q] += normal_gradients[q][c];
            }
          if (potential)
            {
              fe_values.get_function_values(*potential, mu);
              for (unsigned int q = 0; q < nq; ++q)
                divergence[q] += mu[q];
            }
          if (mobility)
            fe_values.get_function_values(*mobility, mobility_factor);
          m_kk = 0;
          m_kv = 0;
          m_vk = 0;
          m_vv = 0;
          local_rhs = 0;
          for (unsigned int q = 0; q < nq; ++q)
            {
              // grad d = grad alpha / f'(d): the filter undone, |grad d| = 1
              // for a perfectly reinitialised alpha.
              const double slope =
                std::max(filter.gradient_norm_target(alpha_values[q]), 0.1);
              const double   grad_norm = alpha_gradients[q].norm();
              Tensor<2, dim> P         = unit_symmetric_tensor<dim>();
              if (grad_norm > 0)
                {
                  const Tensor<1, dim> normal = alpha_gradients[q] / grad_norm;
                  P -= outer_product(normal, normal);
                }
              const Tensor<1, dim> grad_d = alpha_gradients[q] / slope;
              // Clipped so that a badly reinitialised cell cannot make the
              // weights vanish or explode.
              const double g = std::clamp(grad_d.norm(), 0.2, 5.);
              const double A =
                std::clamp((grad_d - lag * lag_gradients[q]).norm(), 0.2, 5.);
              // In the scene's measure: on a body of revolution the forms
              // integrated by parts (Eq. 80 and the surface Laplacian) are
              // the 3D ones, with no further term (doc/numerics.md).
              const double JxW = measure.JxW(fe_values, q);
              for (unsigned int i = 0; i < n; ++i)
                {
                  const double          phi_i    = fe_values.shape_value(i, q);
                  const Tensor<1, dim> &grad_i   = fe_values.shape_grad(i, q);
                  const Tensor<1, dim>  P_grad_i = P * grad_i;
                  for (unsigned int j = 0; j < n; ++j)
                    {
                      const double phi_j = fe_values.shape_value(j, q);
                      const Tensor<1, dim> &grad_j = fe_values.shape_grad(j, q);
                      const double mass       = phi_i * phi_j * JxW;
                      const double tangential = P_grad_i * grad_j * JxW;
                      m_kk(i, j) += mass;
                      m_kv(i, j) += kv_factor * (grad_i * grad_j) * JxW / A;
                      m_vk(i, j) +=
                        vk_factor * mobility_factor[q] * g * tangential;
                      m_vv(i, j) += g * mass;
                    }
                  // kappa = div N (Eq. 80 at dt = 0), not integrated by
                  // parts: the band has no boundary term to lose.
                  local_rhs(i) += divergence[q] * phi_i * JxW;
                }
            }
          cell->get_dof_indices(indices);
          const auto &constraints = level_set.constraints();
          constraints.distribute_local_to_global(m_kk, local_rhs, indices, kk, rhs);
          constraints.distribute_local_to_global(m_vv, indices, vv);
          // Off-diagonal blocks: no diagonal entries on constrained rows.
          constraints.distribute_local_to_global(m_kv, indices, indices, kv);
          constraints.distribute_local_to_global(m_vk, indices, indices, vk);
          for (const auto i : indices)
            touched(i) += 1;
        }
    for (auto *m : {&kk, &kv, &vk, &vv})
      m->compress(VectorOperation::add);
    rhs.compress(VectorOperation::add);
    touched.compress(VectorOperation::add);
    for (const auto i : level_set.locally_owned())
      if (touched(i) == 0)
        for (auto *m : {&kk, &vv})
          m->set(i, i, 1.);
    for (auto *m : {&kk, &vv})
      m->compress(VectorOperation::insert);
  }

  template <int dim>
  unsigned int
  MixedCurvatureSolver<dim>::solve(const LevelSetField<dim> &level_set,
                                   const double              coefficient,
                                   const double              dt,
                                   const Vector &previous_velocity)
  {
    return solve(
      level_set, level_set.alpha(), coefficient, dt, previous_velocity);
  }

  template <int dim>
  unsigned int
  MixedCurvatureSolver<dim>::solve(const LevelSetField<dim> &level_set,
                                   const Vector             &alpha,
                                   const double              coefficient,
                                   const double              dt,
                                   const Vector &previous_velocity)
  {
    assemble(level_set, alpha, coefficient, dt, previous_velocity);
    TimerOutput::Scope scope(timer, "curvature solve");
    // CPU time summed over the ranks (deal.II's Timer with a communicator).
    Timer        cpu_timer(level_set.dof_handler().get_communicator());
    unsigned int iterations = 0;
    if (settings.coupled && dt > 0 && settings.direct)
      iterations = solve_direct(level_set, std::sqrt(coefficient / dt));
    else if (settings.coupled && dt > 0)
      iterations = solve_coupled(level_set, std::sqrt(coefficient / dt));
    else
      iterations = solve_decoupled(level_set);
    for (auto *m : {&kk, &kv, &vk, &vv})
      m->clear();
    solve_cpu_time = cpu_timer.cpu_time();
    return iterations;
  }

  template <int dim>
  unsigned int
  MixedCurvatureSolver<dim>::solve_coupled(const LevelSetField<dim> &level_set,
                                           const double              scale)
  {
    const MPI_Comm comm  = level_set.dof_handler().get_communicator();
    const auto    &owned = level_set.locally_owned();
    BlockVector    solution({owned, owned}, comm);
    BlockVector    block_rhs({owned, owned}, comm);
    block_rhs.block(0) = rhs;

    // M + b L and M + b K_A from the blocks (kv holds -b K_A, vk b L), on
    // the same pattern; identity rows outside the band come from M. Like
    // the blocks, they live for this solve only.
    SparseMatrix tangential_shift, isotropic_shift;
    tangential_shift.copy_from(kk);
    tangential_shift.add(1., vk);
    isotropic_shift.copy_from(kk);
    isotropic_shift.add(-1., kv);
    const InnerSolve mass_inverse(kk, 1e-2),
      tangential_inverse(tangential_shift, 1e-2),
      isotropic_inverse(isotropic_shift, 1e-2);
    const BlockSystem         block_system{kk, kv, vk, vv};
    const SchurPreconditioner preconditioner{
      kk, kv, mass_inverse, tangential_inverse, isotropic_inverse};
    SolverControl control(settings.max_iterations,
                          settings.tolerance * block_rhs.l2_norm());
    unsigned int  iterations = 0;
    if (block_rhs.l2_norm() > 0)
      {
        SolverFGMRES<BlockVector> gmres(
          control, SolverFGMRES<BlockVector>::AdditionalData(100));
        gmres.solve(block_system, solution, block_rhs, preconditioner);
        iterations = control.last_step();
      }

    const auto &constraints = level_set.constraints();
    constraints.distribute(solution.block(0));
    constraints.distribute(solution.block(1));
    kappa = solution.block(0);
    solution.block(1) *= scale;
    velocity = solution.block(1);
    return iterations;
  }

  template <int dim>
  unsigned int
  MixedCurvatureSolver<dim>::solve_direct(const LevelSetField<dim> &level_set,
                                          const double              scale)
  {
    // The four blocks copied into one matrix, kappa_i -> i, v_i -> N + i,
    // factorised by KLU (Amesos): robust for any dt / h^4, serial in the
    // factorisation.
    const MPI_Comm  comm = level_set.dof_handler().get_communicator();
    const auto      n    = level_set.dof_handler().n_dofs();
    const IndexSet &owned = level_set.locally_owned();
    IndexSet        owned2(2 * n), relevant2(2 * n);
    owned2.add_indices(owned);
    owned2.add_indices(owned, n);
    relevant2.add_indices(level_set.locally_relevant());
    relevant2.add_indices(level_set.locally_relevant(), n);
    DynamicSparsityPattern dsp(relevant2);
    const std::array<std::pair<const SparseMatrix *, std::array<types::global_dof_index, 2>>, 4>
      blocks = {{{&kk, {{0, 0}}}, {&kv, {{0, n}}}, {&vk, {{n, 0}}}, {&vv, {{n, n}}}}};
    for (const auto &[block, offset] : blocks)
      for (const auto row : owned)
        for (auto entry = block->begin(row); entry != block->end(row); ++entry)
          dsp.add(row + offset[0], entry->column() + offset[1]);
    SparsityTools::distribute_sparsity_pattern(dsp, owned2, comm, relevant2);
    TrilinosWrappers::SparseMatrix matrix;
    matrix.reinit(owned2, owned2, dsp, comm);
    for (const auto &[block, offset] : blocks)
      for (const auto row : owned)
        for (auto entry = block->begin(row); entry != block->end(row); ++entry)
          matrix.set(row + offset[0], entry->column() + offset[1], entry->value());
    matrix.compress(VectorOperation::insert);

    Vector full_rhs(owned2, comm), full_solution(owned2, comm);
    for (const auto i : owned)
      full_rhs(i) = rhs(i);
    full_rhs.compress(VectorOperation::insert);
    SolverControl                  control;
    TrilinosWrappers::SolverDirect direct(control);
    direct.solve(matrix, full_solution, full_rhs);

    Vector k(owned, comm), v(owned, comm);
    for (const auto i : owned)
      {
        k(i) = full_solution(i);
        v(i) = scale * full_solution(i + n);
      }
    const auto &relevant = level_set.locally_relevant();
    kappa    = ghosted_from_owned(k, level_set.constraints(), relevant);
    velocity = ghosted_from_owned(v, level_set.constraints(), relevant);
    return 1;
  }

  template <int dim>
  unsigned int
  MixedCurvatureSolver<dim>::solve_decoupled(const LevelSetField<dim> &level_set)
  {
    const MPI_Comm comm  = level_set.dof_handler().get_communicator();
    const auto    &owned = level_set.locally_owned();
    Vector         k(owned, comm), v(owned, comm), vrhs(owned, comm);
    const auto    &constraints = level_set.constraints();
    unsigned int   iterations  = 0;

    // Two mass-matrix solves: Jacobi-preconditioned CG converges in a
    // number of steps independent of h.
    auto mass_solve = [&](const SparseMatrix &m, Vector &x, const Vector &f) {
      if (f.l2_norm() == 0)
        return;
      TrilinosWrappers::PreconditionJacobi jacobi;
      jacobi.initialize(m);
      SolverControl      control(settings.max_iterations,
                            settings.tolerance * f.l2_norm());
      SolverCG<Vector> cg(control);
      cg.solve(m, x, f, jacobi);
      iterations += control.last_step();
    };
    mass_solve(kk, k, rhs);
    kappa = ghosted_from_owned(k, constraints, level_set.locally_relevant());
    vk.vmult(vrhs, k);
    vrhs *= -1;
    mass_solve(vv, v, vrhs);
    velocity = ghosted_from_owned(v, constraints, level_set.locally_relevant());
    return iterations;
  }

  template class MixedCurvatureSolver<2>;
  template class MixedCurvatureSolver<3>;
} // namespace levelsinter
