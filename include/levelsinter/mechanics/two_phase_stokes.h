#pragma once

#include <deal.II/base/index_set.h>
#include <deal.II/base/types.h>

#include <deal.II/dofs/dof_handler.h>

#include <deal.II/fe/fe_system.h>

#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/trilinos_block_sparse_matrix.h>
#include <deal.II/lac/trilinos_parallel_block_vector.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <levelsinter/level_set/level_set_field.h>
#include <levelsinter/mechanics/free_rigid_motion.h>
#include <levelsinter/mechanics/phase_law.h>
#include <levelsinter/mechanics/velocity_pressure_operator.h>
#include <levelsinter/scene/materials_parameters.h>
#include <levelsinter/scene/viscous_flow_parameters.h>

#include <vector>

namespace levelsinter
{
  using namespace dealii;

  /**
   * Velocity-pressure problem on the whole box with phases from the level
   * set (paper Eq. 93-94 with the phase law of PhaseLaw):
   *   int a1 eps(v):eps(w) - a2 p div w = F_gamma(w) - int_free p_ext n.w
   *   -int q div v - int c_p p q - sum_K int_K tau_K (grad p - f) . grad q = 0
   * Equal-order Q1/Q1 with ASGS pressure stabilisation (Eq. 98),
   * tau_K = c_tau a2 h_K^2 / a1 (Eq. 99, c_tau = 1 there). Surface tension
   * (sign of Laplace's law p_in - p_out = gamma kappa) in one of four
   * forms:
   * - tensorial (Eq. 108), F_gamma(w) = -gamma int_Gamma (I - n (x) n) :
   *   grad w, over Gamma either smeared with the regularised Dirac (csf,
   *   Eq. 100-104, dS -> delta(alpha) |grad alpha| dV) or sharp on
   *   {alpha_h = 0} with NonMatching quadrature. Exact for rigid motions
   *   (their gradient is skew): zero net force and torque, so pinning rigid
   *   modes leaves no reaction. It is a surface functional, not a force
   *   density, so f = 0 in the stabilisation.
   * - csf_curvature (Eq. 100 written as a balanced force),
   *   F_gamma(w) = int f . w with f = gamma kappa_h grad H_h, where H_h is
   *   the Q1 interpolant of the smoothed solid fraction H_s(alpha_h)
   *   (Eq. 102) of the interface level set passed to assemble() (alpha
   *   where it is a distance) and kappa_h the nodal curvature: for
   *   constant kappa_h, f is the gradient of p_h = gamma kappa H_h, a member
   *   of the pressure space, so (v, p) = (0, p_h) solves the discrete
   *   problem exactly; the residual-consistent stabilisation (the same f in
   *   tau_K (grad p - f)) keeps it so.
   * - sharp_curvature, F_gamma(w) = -gamma int_Gamma kappa_h n . w on
   *   {alpha_h = 0} (cut-cell quadrature, CurvatureSurfaceTensionAssembler):
   *   balanced with the extended pressure (ExtendedPressureStokes), where a
   *   constant kappa_h is met by a constant solid pressure; with the one
   *   continuous pressure here the jump stays smeared (doc/numerics.md,
   *   "Sharp interfaces").
   * A positive surface time step dt in assemble() makes the load
   * semi-implicit (Baensch 2001): the Laplace-Beltrami form at the new
   * position x + dt v adds dt gamma int_Gamma grad_Gamma v : grad_Gamma w
   * to the velocity block, on the same surface measure as the load (sharp
   * for the sharp forms, smeared otherwise).
   * Each term is one StokesAssembler (stokes_assemblers.h), or a
   * StokesFaceAssembler for a term on the free box faces, over the cell
   * data of StokesCellData, which gathers what they read; a law with
   * history fills its own state (PhaseLaw::material_states()): the
   * elastic solid reads the displacement kept here
   * (advance_displacement()), a viscoelastic melt its ViscoelasticState.
   */
  template <int dim>
  class TwoPhaseStokes : public VelocityPressureOperator<dim>
  {
  public:
    enum class SurfaceTensionForm
    {
      csf,
      sharp,
      csf_curvature,
      sharp_curvature
    };

    struct Settings
    {
      double             surface_tension      = 0;
      SurfaceTensionForm form                 = SurfaceTensionForm::sharp;
      /**
       * E of Eq. 102-104 in cell sizes: E_K = this x h_K in cell K at the
       * band level or finer; a coarser cell takes the size of its
       * descendants at @p band_level.
       */
      double             interface_half_width_cells = 1.5;
      /** Refinement level of the interface band. */
      unsigned int       band_level = 0;
      double             stabilisation_constant = 1; // c_tau
      double             external_pressure      = 0; // on the free faces
      /** Box faces (colorized ids 0..2dim-1) with zero normal velocity. */
      std::vector<types::boundary_id> symmetry_boundaries;
      bool                            direct_solver = false;
      double                          tolerance     = 1e-10; // relative
      unsigned int                    max_iterations = 500;
      /** Smoothed (or plain) aggregation in the velocity AMG. */
      bool                            smoothed_aggregation = true;
      /**
       * The atmosphere is a void that only takes up volume (volume
       * diffusion's elastic problem): where alpha > E its viscosity is
       * constant and only the compressible layer's weight varies, which
       * the cell integrates with the 2-point rule as the uniform phases
       * (StokesCellData::reinit()).
       */
      bool                            void_atmosphere = false;

      /** The settings a scene's `Viscous flow` entries give, with the
       * symmetry planes of its domain and the interface band at
       * @p band_level. */
      static Settings
      from(const ViscousFlowParameters           &parameters,
           const MaterialsParameters             &materials,
           const std::vector<types::boundary_id> &symmetry_planes,
           const unsigned int                     band_level);
    };

    using BlockVector = TrilinosWrappers::MPI::BlockVector;

    TwoPhaseStokes(const Triangulation<dim> &tria,
                   const Settings           &settings,
                   const PhaseLaw<dim>      &phase_law);

    /** Number the DoFs (velocity block, then pressure) for the mesh; the
     * displacement starts at zero. */
    void
    setup_dofs() override;

    /**
     * Assemble matrix and right-hand side for the level set @p alpha.
     * @p curvature: nodal kappa on the level set's DoFs (ghosted), used by
     * the csf_curvature form only (may be empty otherwise).
     * @p interface_level_set: the level set H_h is taken from (ghosted, on
     * its DoFs), a distance near the interface (redistanced_level_set());
     * csf_curvature only (may be empty otherwise).
     * @p surface_time_step: dt of the semi-implicit Laplace-Beltrami term;
     * 0 leaves the surface tension explicit.
     */
    void
    assemble(const LevelSetField<dim>            &alpha,
             const TrilinosWrappers::MPI::Vector &curvature,
             const TrilinosWrappers::MPI::Vector &interface_level_set,
             const double                         surface_time_step) override;

    /** Solve; returns the number of outer iterations (0: direct). */
    unsigned int
    solve() override;

    /**
     * Subtract the rigid motion of the solid {alpha < 0} left free by the
     * symmetry planes (remove_free_rigid_motion()): call after solve().
     */
    void
    remove_rigid_motion(const LevelSetField<dim> &alpha) override;

    /**
     * The displacement u^{n-1} that the next assembly reads (velocity
     * block; the pressure block is unused), ghosted. Writable so that a
     * mesh change can carry it over.
     */
    BlockVector &
    displacement() override
    {
      return old_displacement;
    }

    /** The ghosted solution (v, p). */
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

    /** One continuous pressure for both phases. */
    unsigned int
    pressure_component(const Phase) const override
    {
      return dim;
    }

  private:
    void
    make_constraints();
    template <typename MatrixType, typename VectorType>
    void
    assemble_into(const LevelSetField<dim>            &alpha,
                  const TrilinosWrappers::MPI::Vector &curvature,
                  const TrilinosWrappers::MPI::Vector &interface_level_set,
                  const double                         surface_time_step,
                  MatrixType                          &matrix,
                  VectorType                          &rhs);

    Settings                  settings;
    const FreeRigidMotions    free_motions;
    const PhaseLaw<dim>      &phase_law;
    FESystem<dim>             finite_element;
    DoFHandler<dim>           dofs;
    std::vector<IndexSet>     owned_partitioning;
    std::vector<IndexSet>     relevant_partitioning;
    IndexSet                  owned_dofs;
    IndexSet                  relevant_dofs;
    AffineConstraints<double> constraints;

    TrilinosWrappers::BlockSparseMatrix system_matrix;
    TrilinosWrappers::BlockSparseMatrix schur_matrix; // (1,1) block only
    // Near-null space of the viscous block for its AMG.
    std::vector<std::vector<double>> velocity_modes;
    BlockVector                         system_rhs;
    // The direct solver needs the system as one matrix.
    TrilinosWrappers::SparseMatrix monolithic_matrix;
    TrilinosWrappers::MPI::Vector  monolithic_rhs;
    BlockVector                         ghosted_solution;
    BlockVector                         old_displacement;
  };
} // namespace levelsinter
