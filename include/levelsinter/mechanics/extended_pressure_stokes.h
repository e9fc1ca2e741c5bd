#pragma once

#include <deal.II/base/index_set.h>

#include <deal.II/dofs/dof_handler.h>

#include <deal.II/fe/fe_system.h>

#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/trilinos_block_sparse_matrix.h>
#include <deal.II/lac/trilinos_parallel_block_vector.h>

#include <deal.II/non_matching/mesh_classifier.h>

#include <levelsinter/level_set/level_set_field.h>
#include <levelsinter/mechanics/free_rigid_motion.h>
#include <levelsinter/mechanics/phase_law.h>
#include <levelsinter/mechanics/two_phase_stokes.h>
#include <levelsinter/mechanics/velocity_pressure_operator.h>
#include <levelsinter/scene/viscous_flow_parameters.h>

#include <memory>
#include <vector>

namespace levelsinter
{
  using namespace dealii;

  /**
   * The velocity-pressure problem of TwoPhaseStokes (Eq. 93-94) with a
   * pressure that jumps where the interface is (doc/numerics.md, "Sharp
   * interfaces"): one continuous Q1 velocity over the box and one
   * continuous Q1 pressure per phase, p_s (component dim) and p_f
   * (component dim + 1), both present on the cells that {alpha_h = 0}
   * cuts. Every term is integrated over the part of a cell in its phase
   * with cut-cell quadrature (NonMatching::FEValues), with the pure
   * phase's coefficients (PhaseLaw at H_s = 1 or 0): sharp viscosities
   * and moduli, each phase's pressure tested only on its side, the ASGS
   * stabilisation of each phase within it (so it never acts on the
   * Laplace jump), the atmosphere's compressibility up to the interface,
   * and the surface tension on {alpha_h = 0}: tensorial (Eq. 108), or the
   * curvature load gamma kappa_h n, which a constant solid pressure
   * balances exactly (CurvatureSurfaceTensionAssembler). A
   * pressure ghost penalty on the faces of cut cells
   * (GhostPenaltyAssembler) keeps a phase's pressure bounded on small cut
   * parts. Off the cells that hold its phase a pressure's DoFs are
   * constrained to zero (one element on every cell, so the state transfer
   * and checkpoints of the velocity work unchanged; the zero rows cost a
   * diagonal entry each).
   *
   * The block form is TwoPhaseStokes' (doc/mechanics_operator.md): the
   * velocity in block 0, both pressures in block 1, solved by FGMRES with
   * BlockSchurPreconditioner (solve_block_system()).
   */
  template <int dim>
  class ExtendedPressureStokes : public VelocityPressureOperator<dim>
  {
  public:
    using Settings    = typename TwoPhaseStokes<dim>::Settings;
    using BlockVector = TrilinosWrappers::MPI::BlockVector;

    /** @p settings as for TwoPhaseStokes, with a sharp surface-tension
     * form (sharp or sharp_curvature) and the iterative solver; @p ghost_penalty: g of
     * GhostPenaltyAssembler. */
    ExtendedPressureStokes(const Triangulation<dim> &tria,
                           const Settings           &settings,
                           const PhaseLaw<dim>      &phase_law,
                           const double              ghost_penalty);

    void
    setup_dofs() override;

    /** @p curvature: the nodal curvature of the sharp-curvature form (not
     * read by the sharp tensorial form); @p interface_level_set is not
     * read. */
    void
    assemble(const LevelSetField<dim>            &alpha,
             const TrilinosWrappers::MPI::Vector &curvature,
             const TrilinosWrappers::MPI::Vector &interface_level_set,
             const double surface_time_step) override;

    unsigned int
    solve() override;

    void
    remove_rigid_motion(const LevelSetField<dim> &alpha) override;

    BlockVector &
    displacement() override
    {
      return old_displacement;
    }

    const BlockVector &
    solution() const override
    {
      return ghosted_solution;
    }

    const DoFHandler<dim> &
    dof_handler() const override
    {
      return dofs;
    }

    const FESystem<dim> &
    fe() const override
    {
      return finite_element;
    }

    unsigned int
    pressure_component(const Phase phase) const override
    {
      return phase == Phase::solid ? dim : dim + 1;
    }

  private:
    /** The velocity constraints, and with @p classifier the zero pressure
     * of each phase off the cells that hold it. */
    void
    make_constraints(const NonMatching::MeshClassifier<dim> *classifier);

    void
    assemble_ghost_penalty(const LevelSetField<dim>               &alpha,
                           const NonMatching::MeshClassifier<dim> &classifier);

    const Settings            settings;
    const FreeRigidMotions    free_motions;
    const PhaseLaw<dim>      &phase_law;
    const double              ghost_penalty;
    const FESystem<dim>       finite_element;
    DoFHandler<dim>           dofs;
    std::vector<IndexSet>     owned_partitioning;
    std::vector<IndexSet>     relevant_partitioning;
    IndexSet                  relevant_dofs;
    AffineConstraints<double> constraints;

    TrilinosWrappers::BlockSparseMatrix system_matrix;
    TrilinosWrappers::BlockSparseMatrix schur_matrix; // (1,1) block only
    std::vector<std::vector<double>>    velocity_modes;
    BlockVector                         system_rhs;
    BlockVector                         ghosted_solution;
    BlockVector                         old_displacement;
  };

  /**
   * The discretisation a scene's `Viscous flow/Pressure space` chooses:
   * TwoPhaseStokes (continuous), ExtendedPressureStokes (extended) or
   * SolidElasticStokes (solid), for @p settings
   * (TwoPhaseStokes::Settings::from()) and @p law.
   */
  template <int dim>
  std::unique_ptr<VelocityPressureOperator<dim>>
  make_velocity_pressure_operator(
    const Triangulation<dim>                     &tria,
    const typename TwoPhaseStokes<dim>::Settings &settings,
    const PhaseLaw<dim>                          &law,
    const ViscousFlowParameters                  &parameters);
} // namespace levelsinter
