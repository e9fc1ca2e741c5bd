#pragma once

#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/base/tensor.h>
#include <deal.II/base/types.h>

#include <deal.II/dofs/dof_handler.h>

#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/fe_values.h>

#include <deal.II/hp/fe_collection.h>
#include <deal.II/hp/mapping_collection.h>

#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/trilinos_parallel_block_vector.h>
#include <deal.II/lac/trilinos_vector.h>
#include <deal.II/lac/vector.h>

#include <deal.II/non_matching/fe_values.h>
#include <deal.II/non_matching/mesh_classifier.h>

#include <levelsinter/level_set/level_set_field.h>
#include <levelsinter/level_set/scene_measure.h>
#include <levelsinter/mechanics/cut_cell_rules.h>
#include <levelsinter/mechanics/phase_law.h>
#include <levelsinter/mechanics/velocity_pressure_operator.h>

#include <memory>
#include <vector>

namespace levelsinter
{
  using namespace dealii;

  /**
   * What the assemblers of the two-phase Stokes operator read on one cell
   * (the scratch of StokesAssembler and StokesFaceAssembler, as Lethe's
   * ScratchData): reinit() gathers everything at the cell's points (shape
   * data, the phase fractions and the phase law's coefficients, its
   * material state and history terms, the ASGS tau, the balanced force,
   * the points of the surface measure, smeared or from the cut-cell
   * quadrature, and the free box faces); the assemblers only consume it,
   * each adding one term of Eq. 93-94 to a CellContribution.
   *
   * Weights are in the scene's measure (SceneMeasure): on an axisymmetric
   * scene JxW and dS carry 2 pi r, and the hoop strain e_thth(w) = w_r / r
   * of each velocity shape function is at hand (hoop(), SurfacePoint::hoop;
   * zero on a plane scene), so each assembler writes its form once for
   * both (doc/numerics.md, "Axisymmetric scenes").
   */
  template <int dim>
  class StokesCellData
  {
  public:
    /** Where the interface measure of the surface terms comes from. */
    enum class SurfaceMeasure
    {
      none,    // no surface term
      smeared, // regularised Dirac, dS -> delta(alpha) |grad alpha| dV
      sharp    // cut-cell quadrature on {alpha_h = 0}
    };

    /** What reinit() reads, fixed for one assembly. */
    struct Inputs
    {
      const LevelSetField<dim> &alpha;
      const PhaseLaw<dim>      &law;
      // u^{n-1} of a law with history (PhaseLaw::material_states()).
      const TrilinosWrappers::MPI::BlockVector &displacement;
      // The balanced force gamma kappa_h grad H_h (csf-curvature): nodal
      // kappa_h and H_h on the level set's DoFs, ghosted; none otherwise.
      // The sharp curvature load (sharp-curvature) reads kappa_h alone, at
      // the sharp surface's points.
      const TrilinosWrappers::MPI::Vector *curvature      = nullptr;
      const TrilinosWrappers::MPI::Vector *solid_fraction = nullptr;
      double                               surface_tension = 0;
      SurfaceMeasure                       surface = SurfaceMeasure::none;
      // E of Eq. 102-104 in cell sizes, at the band's refinement level.
      double       interface_half_width_cells = 1.5;
      unsigned int band_level                 = 0;
      double       stabilisation_constant     = 1; // c_tau of Eq. 99
      // TwoPhaseStokes::Settings::void_atmosphere.
      bool void_atmosphere = false;
      // Gather the free box faces (those off the symmetry planes).
      bool                            free_faces = false;
      std::vector<types::boundary_id> symmetry_boundaries;
      // The extended pressure (ExtendedPressureStokes): the element has
      // one pressure per phase (components dim: solid, dim + 1: fluid),
      // gathered with reinit_cut() and select_phase() instead of
      // reinit(); the surface is then the sharp one.
      bool extended_pressure = false;
    };

    /** One point of the surface measure of Gamma: unit normal, weight dS
     * and the gradients of the velocity shape functions there. */
    struct SurfacePoint
    {
      Tensor<1, dim>              normal;
      double                      dS = 0;
      std::vector<Tensor<2, dim>> grad_w;
      // w_r / r per shape function (0 off the axisymmetric case).
      std::vector<double> hoop;
      // w . n per shape function.
      std::vector<double> normal_w;
      // The nodal curvature kappa_h at the point (Inputs::curvature with
      // the sharp surface; 0 without).
      double curvature = 0;

      /** The tangential projector I - n (x) n. */
      Tensor<2, dim>
      projector() const
      {
        return unit_symmetric_tensor<dim>() - outer_product(normal, normal);
      }
    };

    /** One quadrature point of a box face: outer normal, weight and the
     * velocity shape values. */
    struct FacePoint
    {
      Tensor<1, dim>              normal;
      double                      JxW = 0;
      std::vector<Tensor<1, dim>> w;
    };

    /** One free box face of the cell, what a StokesFaceAssembler reads. */
    struct Face
    {
      types::boundary_id     boundary_id = 0;
      std::vector<FacePoint> points;
    };

    /** For the Stokes element @p fe (velocity, then pressure) and the
     * assembly's @p inputs, which must outlive this object. */
    StokesCellData(const FESystem<dim> &fe, const Inputs &inputs);

    /** Gather what the assemblers read on @p cell (locally owned, of the
     * operator's DoFHandler). */
    void
    reinit(const typename DoFHandler<dim>::active_cell_iterator &cell);

    /**
     * The extended pressure: gather on @p cell what does not depend on the
     * phase (cell size, the sharp surface points of the cut cells, the
     * free box faces); then select_phase() for each phase.
     */
    void
    reinit_cut(const typename DoFHandler<dim>::active_cell_iterator &cell);

    /**
     * The extended pressure: the volume data of the part of the cell
     * reinit_cut() was called on that lies in @p phase (the whole cell if
     * it is uncut; cut-cell quadrature on {alpha_h < 0} or {alpha_h > 0}
     * otherwise), with the law's coefficients of the pure phase and
     * pressure_dofs that phase's pressure. Returns false (and gathers
     * nothing) if the cell has no part in @p phase.
     */
    bool
    select_phase(const Phase phase);

    bool
    is_pressure(const unsigned int i) const
    {
      return component[i] >= dim;
    }

    const std::vector<unsigned int> component;
    const unsigned int              n_dofs;
    unsigned int                    n_q = 0;
    double                          h   = 0; // cell size
    // Cell mean of a1 (the Schur weight, doc/numerics.md).
    double a1_cell = 0;

    // Per volume quadrature point k, [k][i] per shape function i.
    // Per quadrature point (sized for the largest rule seen: entries from
    // n_q on are stale).
    std::vector<double>            JxW;
    // 1 / r of the hoop terms (0 off the axisymmetric case).
    std::vector<double>            inverse_radius;
    std::vector<PhaseCoefficients> law;
    std::vector<double>            tau; // ASGS, Eq. 99
    std::vector<HistoryTerms<dim>> history;
    std::vector<Tensor<1, dim>>    balanced_force;
    // Each shape function of the FESystem has one nonzero component
    // (component[i]): its value and gradient per point and shape function.
    // A velocity shape function is w = value e_c, grad w = e_c (x)
    // gradient; a pressure one is q = value, grad q = gradient.
    std::vector<std::vector<double>>         value;
    std::vector<std::vector<Tensor<1, dim>>> gradient;

    std::vector<unsigned int> velocity_dofs;
    std::vector<unsigned int> pressure_dofs;

    /** grad w of velocity shape function @p i at point @p k (zero for a
     * pressure shape function). */
    Tensor<2, dim>
    velocity_gradient(const unsigned int k, const unsigned int i) const
    {
      Tensor<2, dim> grad_w;
      if (!is_pressure(i))
        grad_w[component[i]] = gradient[k][i];
      return grad_w;
    }

    /** The hoop strain w_r / r of shape function @p i at point @p k (0
     * for a pressure shape function, the axial component and on a plane
     * scene). */
    double
    hoop(const unsigned int k, const unsigned int i) const
    {
      return component[i] == 0 ? value[k][i] * inverse_radius[k] : 0.;
    }

    std::vector<SurfacePoint> surface;
    std::vector<Face>         free_faces;

  private:
    /** Shape data and weights from @p values (reinit on the cell). */
    void
    reinit_shapes(const FEValues<dim> &values);

    /** The phase coefficients, the law's history and tau at the points
     * (and the cell's size and mean a1). */
    void
    gather_phases(const FEValues<dim> &values,
                  const FEValues<dim> &level_set_values,
                  const double         E);

    void
    gather_smeared_surface(const double E);

    void
    gather_sharp_surface(
      const typename DoFHandler<dim>::active_cell_iterator &cell);

    /** The points of @p cut; with Inputs::curvature, kappa_h from its
     * values at the cell's vertices (vertex_kappa). */
    void
    add_surface_points(const NonMatching::FEImmersedSurfaceValues<dim> &cut);

    /** Shape data and weights of the part of the cell of reinit_cut() in
     * @p phase; the FEValues they come from, or nullptr if the cell has no
     * part there. */
    const FEValues<dim> *
    reinit_part(const Phase phase);

    /** The same from the plane scenes' CutCellRules. */
    void
    add_surface_points(
      const std::vector<typename CutCellRules<dim>::SurfacePoint> &points);

    void
    gather_free_faces(
      const typename DoFHandler<dim>::active_cell_iterator &cell);

    const Inputs       &inputs;
    const SceneMeasure &measure;
    // Three Gauss points per direction in the transition zone, two where
    // the phases are uniform (see reinit()).
    FEValues<dim>     transition_values;
    FEValues<dim>     uniform_values;
    FEValues<dim>     transition_level_set_values;
    FEValues<dim>     uniform_level_set_values;
    FEFaceValues<dim> face_values;
    // Sharp surface measure only.
    const hp::FECollection<dim>                       fe_collection;
    const hp::MappingCollection<dim>                  mapping_collection;
    // The cut cells' rules (NonMatching::FEValues keeps references to
    // them).
    const hp::QCollection<dim> uncut_quadrature;
    const hp::QCollection<1>   cut_quadrature;
    // The extended pressure: each phase's pressure shape functions.
    std::array<std::vector<unsigned int>, 2> phase_pressure_dofs;
    std::shared_ptr<const NonMatching::MeshClassifier<dim>> classifier;
    // The cut cells of the extended pressure: CutCellRules on plane scenes
    // (no FEValues built per cut cell), NonMatching::FEValues on
    // axisymmetric ones and for the sharp surface of the other spaces.
    std::unique_ptr<CutCellRules<dim>>          cut_rules;
    std::unique_ptr<NonMatching::FEValues<dim>> cut_values;
    // The cell of the last reinit_cut() and where it lies.
    typename DoFHandler<dim>::active_cell_iterator cut_cell;
    NonMatching::LocationToLevelSet                cut_location;
    // The Q1 vertex of each shape function (its base element's index).
    std::vector<unsigned int> vertex_of;
    // At the volume points (sized for the largest rule).
    Vector<double>                       vertex_alpha;
    Vector<double>                       vertex_kappa;
    std::vector<double>                  alpha_q;
    std::vector<Tensor<1, dim>>          grad_alpha_q;
    std::vector<double>                  kappa_q;
    std::vector<Tensor<1, dim>>          grad_heaviside_q;
    std::vector<MaterialState<dim>>      states;
  };

  /** A cell's share of the system matrix, the Schur approximation and the
   * right-hand side, and the DoFs it goes to (the copy data of step-32's
   * cell worker / copier split). Same-type pairs (velocity-velocity,
   * pressure-pressure) are filled in the upper triangle only, mirrored by
   * symmetrise(). */
  struct CellContribution
  {
    explicit CellContribution(const unsigned int n)
      : matrix(n, n)
      , schur(n, n)
      , rhs(n)
      , dof_indices(n)
    {}

    void
    reset()
    {
      matrix = 0;
      schur  = 0;
      rhs    = 0;
    }

    FullMatrix<double>                   matrix;
    FullMatrix<double>                   schur;
    Vector<double>                       rhs;
    std::vector<types::global_dof_index> dof_indices;
  };
} // namespace levelsinter
