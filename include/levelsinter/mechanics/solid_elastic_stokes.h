#pragma once

#include <deal.II/base/index_set.h>

#include <deal.II/dofs/dof_handler.h>

#include <deal.II/fe/fe_system.h>

#include <deal.II/hp/fe_collection.h>

#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/trilinos_block_sparse_matrix.h>
#include <deal.II/lac/trilinos_parallel_block_vector.h>

#include <deal.II/non_matching/mesh_classifier.h>

#include <levelsinter/level_set/level_set_field.h>
#include <levelsinter/mechanics/free_rigid_motion.h>
#include <levelsinter/mechanics/phase_law.h>
#include <levelsinter/mechanics/two_phase_stokes.h>
#include <levelsinter/mechanics/velocity_pressure_operator.h>

#include <memory>
#include <vector>

namespace levelsinter
{
  using namespace dealii;

  /**
   * The elastic problem of volume diffusion (Eq. 92-94 with H_s = 1) on the
   * solid only, the atmosphere a void (doc/mechanics_operator.md, "The
   * solid-only elastic problem"): (v, p) live on the cells that hold solid
   * (an hp::FECollection of the Q1/Q1 element and FE_Nothing, the active
   * index from NonMatching::MeshClassifier on alpha), each cut cell
   * integrated over its part in {alpha_h < 0} (NonMatching::FEValues,
   * StokesCellData::select_phase()) with the solid's coefficients, the
   * sharp tensorial surface tension (Eq. 108) on {alpha_h = 0} as the
   * whole traction there (the void carries none), and
   * - a ghost penalty on the faces of cut cells, for the pressure as in
   *   ExtendedPressureStokes, g (a2/a1) h^3 [d_n p][d_n q], and for the
   *   velocity, g a1 h [d_n v][d_n w] (Burman & Hansbo 2012): a vertex of
   *   a cut cell whose solid part is a sliver has no other stiffness;
   * - a drag c_d (v, w), c_d = 1e-6 a1 / L^2 (L the box's largest edge;
   *   DragAssembler), for the rigid motions of each body that the
   *   atmosphere's viscosity held before (its stress is 1e-6 of the
   *   solid's at the body's size, below the atmosphere's eta_f / (G dt));
   *   remove_rigid_motion() then takes out the free rigid motion as before.
   * The unknown stays the velocity v = Delta u / dt of the contract
   * (advance_displacement()); with the atmosphere gone the system is a
   * diagonal scaling by dt of a dt-free one (a1 = 2 G dt, c_p = 1 / (K dt),
   * tau = a2 h^2 / a1, c_d ~ a1), so Delta u = dt v does not depend on dt.
   *
   * The state lives on a second DoFHandler over the whole mesh with the
   * same Q1/Q1 element (dof_handler()): the solution and the displacement
   * u^{n-1} are copied there after each solve (zero off the cells with
   * solid), so the state transfer, the checkpoints, the output and the
   * xi extension work as with the other spaces. A cell that becomes solid
   * reads u^{n-1} from that vector: the displacement its vertices had as
   * vertices of cut cells (the solid's velocity continued into the cut
   * cells), zero at a vertex that never was. The solid DoFs are numbered
   * again (and the matrices built again) only when the set of cells with
   * solid changes.
   */
  template <int dim>
  class SolidElasticStokes : public VelocityPressureOperator<dim>
  {
  public:
    using Settings    = typename TwoPhaseStokes<dim>::Settings;
    using BlockVector = TrilinosWrappers::MPI::BlockVector;

    /** @p settings as for TwoPhaseStokes, with the sharp tensorial form
     * and the iterative solver; @p ghost_penalty: g above. */
    SolidElasticStokes(const Triangulation<dim> &tria,
                       const Settings           &settings,
                       const PhaseLaw<dim>      &phase_law,
                       const double              ghost_penalty);

    /** Number the DoFs of the whole mesh (the state); the solid's are
     * numbered by the next assemble(), which knows the level set. */
    void
    setup_dofs() override;

    /** Classify the cells on @p alpha; where the set of cells with solid
     * changed (or the mesh), number the solid DoFs and build the
     * patterns again. */
    void
    fit_to(const LevelSetField<dim> &alpha) override;

    /** The curvature and @p interface_level_set are not read. */
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

    /** The whole mesh's DoFs, on which solution() and displacement()
     * live. */
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
    pressure_component(const Phase) const override
    {
      return dim;
    }

    /** Velocity and pressure unknowns of the solid problem (0 before the
     * first assemble()). */
    types::global_dof_index
    n_solid_dofs() const
    {
      return solid_dofs.n_dofs();
    }

  private:
    /** Set the active FE index of each cell from @p classifier; whether
     * it changed anywhere (or the solid DoFs are not numbered yet). */
    bool
    update_solid_cells(const NonMatching::MeshClassifier<dim> &classifier);

    /** Number the solid DoFs, their constraints, patterns and vectors. */
    void
    setup_solid_system();

    void
    assemble_ghost_penalty(const LevelSetField<dim> &alpha);

    /** Copy @p from (ghosted, on @p from_dofs) to the owned entries of
     * @p to (on @p to_dofs) on the cells with solid; then @p to_constraints
     * and the ghosts. */
    void
    copy_on_solid_cells(const DoFHandler<dim>           &from_dofs,
                        const BlockVector               &from,
                        const DoFHandler<dim>           &to_dofs,
                        const AffineConstraints<double> &to_constraints,
                        BlockVector                     &to) const;

    const Settings            settings;
    const FreeRigidMotions    free_motions;
    const PhaseLaw<dim>      &phase_law;
    const double              ghost_penalty;
    const FESystem<dim>       finite_element;
    const hp::FECollection<dim> fe_collection; // {solid, FE_Nothing}
    // c_d / a1 of the drag.
    const double drag_per_a1;

    // The whole mesh: the state and what the mechanisms read.
    DoFHandler<dim>           dofs;
    AffineConstraints<double> hanging_node_constraints;
    BlockVector               ghosted_solution;
    BlockVector               old_displacement;

    // The solid.
    DoFHandler<dim>                     solid_dofs;
    bool                                solid_dofs_current = false;
    // The cells' location on the level set of the last fit_to().
    std::shared_ptr<const NonMatching::MeshClassifier<dim>> classifier;
    std::vector<IndexSet>               owned_partitioning;
    std::vector<IndexSet>               relevant_partitioning;
    AffineConstraints<double>           constraints;
    TrilinosWrappers::BlockSparseMatrix system_matrix;
    TrilinosWrappers::BlockSparseMatrix schur_matrix; // (1,1) block only
    std::vector<std::vector<double>>    velocity_modes;
    BlockVector                         system_rhs;
    BlockVector                         solid_solution;
    BlockVector                         solid_displacement;
  };
} // namespace levelsinter
