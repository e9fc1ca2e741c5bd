#pragma once

#include <deal.II/base/timer.h>

#include <deal.II/lac/trilinos_parallel_block_vector.h>
#include <deal.II/lac/trilinos_precondition.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <levelsinter/level_set/level_set_field.h>
#include <levelsinter/level_set/level_set_filter.h>

#include <array>
#include <vector>

namespace levelsinter
{
  using namespace dealii;

  /**
   * The curvature kappa = div n and the surface Laplacian term
   * v_s = C Delta_s kappa of the level set, both Q1 on the level set's DoFs,
   * from the mixed system of Eq. 82 (derivation and signs in
   * doc/numerics.md):
   *
   *   (kappa, psi) - dt (grad v_s / A, grad psi) = -(grad d / A, grad psi)
   *   C (g P grad kappa, grad psi) + (g v_s, psi)  = 0
   *
   * with d the distance the filtered alpha stands for, g = |grad d|,
   * A = |grad(d - dt v_s^{n-1})| (Eq. 81) and P = I - n (x) n (Eq. 77). The
   * dt term (Eq. 80) makes the step implicit in the fourth-order operator.
   * With `coupled = false` dt is dropped there: the decoupled scheme
   * (kappa, then v_s), kept to measure what the coupling buys.
   *
   * Solver: v_s is scaled by s = sqrt(C/dt), which turns the system into
   * [[M, -b K_A], [b L, M_g]] with b = sqrt(C dt). Either KLU on the whole
   * system (serial factorisation), or FGMRES with the block upper-triangular
   * preconditioner whose Schur complement M_g + b^2 L M^-1 K_A is replaced
   * by (M + b L) M^-1 (M + b K_A), each factor inverted by CG with AMG
   * (Bosch, Stoll & Benner 2014 for Cahn-Hilliard, adapted to L != K_A;
   * doc/numerics.md): 20-30 iterations independently of h and dt.
   */
  template <int dim>
  class MixedCurvatureSolver
  {
  public:
    using Vector      = TrilinosWrappers::MPI::Vector;
    using BlockVector = TrilinosWrappers::MPI::BlockVector;

    struct Settings
    {
      bool         coupled        = true;
      // KLU on the assembled 2x2 system, or FGMRES (see the class comment).
      bool         direct         = false;
      double       tolerance      = 1e-8;
      unsigned int max_iterations = 500;
      // Nodal normals (Eq. 84) from the interpolated distance rather than
      // alpha (nodal_normals()): kappa then converges at second order with
      // E a fixed number of cells.
      bool normals_from_distance = false;
      // Box faces that are symmetry planes (`Domain/Symmetry planes`): the
      // nodal normals there are mirrored (nodal_normals()). Without it a
      // neck on the plane sees one-sided normals and stops growing.
      std::vector<types::boundary_id> symmetry_boundaries;
    };

    MixedCurvatureSolver(const LevelSetFilter &filter,
                         const Settings       &settings,
                         TimerOutput          &timer);

    /** Size matrices and vectors for the level set's DoFs; after remeshing. */
    void
    setup(const LevelSetField<dim> &level_set);

    /**
     * Solve for kappa and v_s = C Delta_s kappa at the level set's current
     * state; @p previous_velocity is v_s^{n-1} on the same DoFs (ghosted)
     * for A^n, or an empty vector (A = |grad d|). Returns the iterations.
     */
    unsigned int
    solve(const LevelSetField<dim> &level_set,
          const double              coefficient,
          const double              dt,
          const Vector             &previous_velocity);

    /**
     * The same with the values @p alpha (ghosted, on the level set's DoFs)
     * in place of the level set's own, for the normals, the band and the
     * weights (the csf-curvature form's redistanced level set,
     * redistanced_level_set()).
     */
    unsigned int
    solve(const LevelSetField<dim> &level_set,
          const Vector             &alpha,
          const double              coefficient,
          const double              dt,
          const Vector             &previous_velocity);

    /** kappa (ghosted): 1/R on a circle, 2/R on a sphere. */
    const Vector &
    curvature() const
    {
      return kappa;
    }

    /** v_s = C Delta_s kappa (ghosted), the outward normal speed (Eq. 75). */
    const Vector &
    normal_velocity() const
    {
      return velocity;
    }

    /** Nodal-averaged unit normals N_alpha (Eq. 84), one vector per axis. */
    const std::array<Vector, dim> &
    nodal_normals() const
    {
      return normals;
    }

    /** The filter whose band (|d| < 0.8 E) the system lives on. */
    const LevelSetFilter &
    band_filter() const
    {
      return filter;
    }

    /**
     * A chemical potential mu (ghosted, on the level set's DoFs; nullptr:
     * none) added to the curvature from the next solve on: the kappa row
     * then holds kappa + mu and v_s = C Delta_s (kappa + mu), which
     * curvature() returns. The regularised triple-line condition of grain
     * boundaries (GrainBoundaryDiffusion); the vector must live until the
     * solve.
     */
    void
    set_potential(const Vector *mu)
    {
      potential = mu;
    }

    /**
     * A factor c of the coefficient (ghosted, on the level set's DoFs;
     * nullptr: 1) from the next solve on: v_s = div_s (c C grad_s kappa),
     * the weak form's flux c C grad_s kappa continuous where c jumps.
     * Per-grain materials of grain boundaries (GrainBoundaryDiffusion);
     * the vector must live until the solve.
     */
    void
    set_mobility(const Vector *c)
    {
      mobility = c;
    }

  private:
    void
    assemble(const LevelSetField<dim> &level_set,
             const Vector             &alpha,
             const double              coefficient,
             const double              dt,
             const Vector             &previous_velocity);

    unsigned int
    solve_coupled(const LevelSetField<dim> &level_set, const double scale);

    unsigned int
    solve_direct(const LevelSetField<dim> &level_set, const double scale);

    unsigned int
    solve_decoupled(const LevelSetField<dim> &level_set);

    const LevelSetFilter filter;
    const Settings       settings;
    TimerOutput         &timer;

    // Blocks of the (scaled) system, rows (kappa, v_s); empty between
    // solves.
    TrilinosWrappers::SparseMatrix kk, kv, vk, vv;
    Vector                         rhs;
    Vector                         kappa;
    Vector                         velocity;
    std::array<Vector, dim>        normals;
    const Vector                  *potential = nullptr;
    const Vector                  *mobility  = nullptr;

  public:
    /** CPU seconds of the last linear solve, summed over the ranks. */
    double solve_cpu_time = 0;
  };
} // namespace levelsinter
