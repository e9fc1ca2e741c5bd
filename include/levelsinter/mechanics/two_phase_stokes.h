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
#include <levelsinter/mechanics/phase_law.h>

#include <vector>

namespace levelsinter
{
  using namespace dealii;

  /**
   * Velocity-pressure problem on the whole box with phases from the level
   * set (paper Eq. 93-94 with the phase law of PhaseLaw):
   *   int a1 eps(v):eps(w) - a2 p div w = F_gamma(w) - int_free p_ext n.w
   *   -int q div v - int c_p p q - sum_K int_K tau_K grad p . grad q = 0
   * Equal-order Q1/Q1 with ASGS pressure stabilisation (Eq. 98),
   * tau_K = c_tau a2 h_K^2 / a1 (Eq. 99, c_tau = 1 there). Surface tension
   * uses the tensorial form (Eq. 108) with the sign of Laplace's law
   * p_in - p_out = gamma kappa:
   *   F_gamma(w) = -gamma int_Gamma (I - n (x) n) : grad w,
   * over Gamma either smeared with the regularised Dirac (CSF, Eq. 100-104,
   * dS -> delta(alpha) |grad alpha| dV) or sharp on {alpha_h = 0} with
   * NonMatching quadrature. The form is exact for rigid motions (their
   * gradient is skew), so the discrete capillary load has zero net force and
   * torque and pinning rigid modes leaves no reaction.
   */
  template <int dim>
  class TwoPhaseStokes
  {
  public:
    enum class SurfaceTensionForm
    {
      csf,
      sharp
    };

    struct Settings
    {
      double             surface_tension      = 0;
      SurfaceTensionForm form                 = SurfaceTensionForm::sharp;
      double             interface_half_width = 0; // E of Eq. 102-104
      double             stabilisation_constant = 1; // c_tau
      double             external_pressure      = 0; // on the free faces
      /** Box faces (colorized ids 0..2dim-1) with zero normal velocity. */
      std::vector<types::boundary_id> symmetry_boundaries;
      bool                            direct_solver = false;
      double                          tolerance     = 1e-10; // relative
      unsigned int                    max_iterations = 500;
    };

    using BlockVector = TrilinosWrappers::MPI::BlockVector;

    TwoPhaseStokes(const Triangulation<dim> &tria,
                   const Settings           &settings,
                   const PhaseLaw           &phase_law);

    /** Number the DoFs (velocity block, then pressure) for the mesh. */
    void
    setup_dofs();

    /** Assemble matrix and right-hand side for the level set @p alpha. */
    void
    assemble(const LevelSetField<dim> &alpha);

    /** Solve; returns the number of outer iterations (0: direct). */
    unsigned int
    solve();

    /** The ghosted solution (v, p). */
    const BlockVector &
    solution() const
    {
      return ghosted_solution;
    }

    const DoFHandler<dim> &
    dof_handler() const
    {
      return dofs;
    }

    const FESystem<dim> &
    fe() const
    {
      return finite_element;
    }

  private:
    void
    make_constraints();
    void
    pin_rigid_body_modes();
    template <typename MatrixType, typename VectorType>
    void
    assemble_into(const LevelSetField<dim> &alpha,
                  MatrixType               &matrix,
                  VectorType               &rhs);

    Settings                  settings;
    const PhaseLaw           &phase_law;
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
  };
} // namespace levelsinter
