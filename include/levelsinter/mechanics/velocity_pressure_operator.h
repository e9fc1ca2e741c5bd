#pragma once

#include <deal.II/dofs/dof_handler.h>

#include <deal.II/fe/fe_system.h>

#include <deal.II/lac/trilinos_block_sparse_matrix.h>
#include <deal.II/lac/trilinos_parallel_block_vector.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <levelsinter/level_set/level_set_field.h>
#include <levelsinter/level_set/velocity_field.h>

#include <string>
#include <vector>

namespace levelsinter
{
  using namespace dealii;

  /** The two phases of the velocity-pressure problem. */
  enum class Phase
  {
    solid,
    fluid
  };

  /**
   * The contract of doc/mechanics_operator.md: what ViscousFlow and
   * VolumeDiffusion (and through them the output, the state transfer and
   * the checkpoints) use of a discretisation of the velocity-pressure
   * problem (Eq. 93-94). Every discretisation numbers its velocity DoFs
   * (components 0..dim-1 of fe(), Q1) into block 0 and all its pressure
   * DoFs into block 1. The smeared Q1/Q1 form is TwoPhaseStokes, the
   * extended pressure ExtendedPressureStokes;
   * make_velocity_pressure_operator() chooses by the scene's `Viscous
   * flow/Pressure space`.
   */
  template <int dim>
  class VelocityPressureOperator
  {
  public:
    using BlockVector = TrilinosWrappers::MPI::BlockVector;

    virtual ~VelocityPressureOperator() = default;

    /** Number the DoFs for the mesh; the displacement starts at zero. */
    virtual void
    setup_dofs() = 0;

    /** Fit the unknowns to the level set @p alpha, before assemble(): a
     * space on part of the mesh (SolidElasticStokes) numbers its DoFs and
     * builds its patterns here, timed apart from the assembly; a space on
     * the whole mesh has nothing to do. */
    virtual void
    fit_to(const LevelSetField<dim> &)
    {}

    /** The system for the level set @p alpha (TwoPhaseStokes::assemble()),
     * after fit_to(alpha). */
    virtual void
    assemble(const LevelSetField<dim>            &alpha,
             const TrilinosWrappers::MPI::Vector &curvature,
             const TrilinosWrappers::MPI::Vector &interface_level_set,
             const double                         surface_time_step) = 0;

    /** Solve; returns the number of outer iterations (0: direct). */
    virtual unsigned int
    solve() = 0;

    /** Subtract the free rigid motion of the solid (call after solve()). */
    virtual void
    remove_rigid_motion(const LevelSetField<dim> &alpha) = 0;

    /** u^n = u^{n-1} + dt v^n (Eq. 92) with the last solution's velocity,
     * once per accepted step, after solve(). */
    void
    advance_displacement(const double dt);

    /** u^{n-1} (velocity block, ghosted), writable for a mesh change. */
    virtual BlockVector &
    displacement() = 0;

    /** The ghosted solution (v, p). */
    virtual const BlockVector &
    solution() const = 0;

    virtual const DoFHandler<dim> &
    dof_handler() const = 0;

    virtual const FESystem<dim> &
    fe() const = 0;

    /** The component of fe() that holds the pressure of @p phase (the same
     * for both phases where the pressure is one continuous field). */
    virtual unsigned int
    pressure_component(const Phase phase) const = 0;

    /** Add the nodal velocity of the last solution to @p velocity (same
     * mesh, Q1: vertex by vertex). */
    void
    add_vertex_velocities(VelocityField<dim> &velocity) const;

    /** The solution as one ghosted vector on dof_handler(), the form the
     * normal-gradient extension reads (with pressure_component()). */
    TrilinosWrappers::MPI::Vector
    plain_solution() const;

    /** Output names of the pressure components of fe(), in order:
     * PREFIX_pressure, or PREFIX_solid_pressure and PREFIX_fluid_pressure
     * where each phase has its own. */
    std::vector<std::string>
    pressure_names(const std::string &prefix) const;
  };

  /**
   * FGMRES with BlockSchurPreconditioner (AMG on the velocity block with
   * @p velocity_modes as near-null space, CG/Jacobi on the Schur
   * approximation @p schur) on the block system, to the relative residual
   * @p tolerance, from @p solution (owned, without ghosts), with smoothed
   * or plain aggregation in the AMG (@p smoothed_aggregation) and its
   * Chebyshev smoother of degree @p smoother_sweeps; returns the
   * iterations. A failure throws with the entries that help.
   */
  unsigned int
  solve_block_system(const TrilinosWrappers::BlockSparseMatrix &matrix,
                     const TrilinosWrappers::SparseMatrix      &schur,
                     const std::vector<std::vector<double>>    &velocity_modes,
                     const unsigned int                         dim,
                     const TrilinosWrappers::MPI::BlockVector  &rhs,
                     TrilinosWrappers::MPI::BlockVector        &solution,
                     const double                               tolerance,
                     const unsigned int max_iterations,
                     const bool         smoothed_aggregation,
                     const unsigned int smoother_sweeps = 2);
} // namespace levelsinter
