#pragma once

#include <deal.II/fe/fe_interface_values.h>

#include <levelsinter/mechanics/stokes_cell_data.h>

namespace levelsinter
{
  /**
   * One term of the two-phase Stokes operator (TwoPhaseStokes), added to a
   * cell's contribution from the cell data, in the spirit of Lethe's
   * assemblers: the operator keeps a list of them, chosen once from its
   * settings, and calls each on every cell.
   */
  template <int dim>
  class StokesAssembler
  {
  public:
    virtual ~StokesAssembler() = default;

    virtual void
    assemble(const StokesCellData<dim> &data,
             CellContribution          &cell) const = 0;
  };

  /**
   * One term on the free box faces (off the symmetry planes): the operator
   * calls it on every such face of a cell (StokesCellData::free_faces),
   * after the cell's StokesAssemblers.
   */
  template <int dim>
  class StokesFaceAssembler
  {
  public:
    virtual ~StokesFaceAssembler() = default;

    virtual void
    assemble(const StokesCellData<dim>                  &data,
             const typename StokesCellData<dim>::Face &face,
             CellContribution                           &cell) const = 0;
  };

  /**
   * The bulk operator of Eq. 93-94: a1 eps(v):eps(w) - a2 p div w,
   * -q div v - c_p p q, the phase law's history right-hand sides, and the
   * Schur approximation's mass M_{2/a1_K + c_p} (cell-mean a1, Grinevich &
   * Olshanskii 2009; doc/numerics.md).
   */
  template <int dim>
  class BulkAssembler : public StokesAssembler<dim>
  {
  public:
    void
    assemble(const StokesCellData<dim> &data,
             CellContribution          &cell) const override;
  };

  /**
   * ASGS pressure stabilisation (Eq. 98): -tau_K grad p . grad q in the
   * system and +tau_K grad p . grad q in the Schur approximation.
   */
  template <int dim>
  class StabilisationAssembler : public StokesAssembler<dim>
  {
  public:
    void
    assemble(const StokesCellData<dim> &data,
             CellContribution          &cell) const override;
  };

  /**
   * Tensorial surface tension (Eq. 108): -gamma int_Gamma (I - n (x) n) :
   * grad w over the cell's surface measure, smeared (csf) or sharp.
   */
  template <int dim>
  class TensorialSurfaceTensionAssembler : public StokesAssembler<dim>
  {
  public:
    explicit TensorialSurfaceTensionAssembler(const double gamma)
      : gamma(gamma)
    {}

    void
    assemble(const StokesCellData<dim> &data,
             CellContribution          &cell) const override;

  private:
    const double gamma;
  };

  /**
   * Surface tension as a curvature load on the sharp surface (Eq. 100 with
   * the exact Dirac): -gamma int_Gamma kappa_h n . w over {alpha_h = 0},
   * kappa_h the nodal curvature at the cut-cell points (SurfacePoint::
   * curvature). With the extended pressure it is balanced: for a constant
   * kappa_h, v = 0 with the solid pressure gamma kappa_h and the fluid's 0
   * solves the discrete problem, since int_{alpha_h < 0} div w = int_Gamma
   * w . n on the cut cells (the divergence theorem, which the cut-cell
   * quadrature of both keeps to its order; with the 2 pi r weight and the
   * hoop term w_r / r on a body of revolution too), and the ASGS and
   * ghost-penalty terms vanish on a constant.
   */
  template <int dim>
  class CurvatureSurfaceTensionAssembler : public StokesAssembler<dim>
  {
  public:
    explicit CurvatureSurfaceTensionAssembler(const double gamma)
      : gamma(gamma)
    {}

    void
    assemble(const StokesCellData<dim> &data,
             CellContribution          &cell) const override;

  private:
    const double gamma;
  };

  /**
   * Balanced-force surface tension (Eq. 100 as f = gamma kappa_h grad H_h,
   * the cell data's balanced_force): f . w in the momentum rows and the
   * consistent residual term -tau_K f . grad q in the pressure rows.
   */
  template <int dim>
  class BalancedForceAssembler : public StokesAssembler<dim>
  {
  public:
    void
    assemble(const StokesCellData<dim> &data,
             CellContribution          &cell) const override;
  };

  /**
   * Semi-implicit surface tension (Baensch 2001): the Laplace-Beltrami
   * form at x + dt v, dt gamma int_Gamma grad_Gamma v : grad_Gamma w, on
   * the cell's surface measure.
   */
  template <int dim>
  class LaplaceBeltramiAssembler : public StokesAssembler<dim>
  {
  public:
    LaplaceBeltramiAssembler(const double gamma, const double dt)
      : weight(gamma * dt)
    {}

    void
    assemble(const StokesCellData<dim> &data,
             CellContribution          &cell) const override;

  private:
    const double weight;
  };

  /**
   * A drag c_d (v, w) with c_d = @p relative a1 at each point, for the
   * solid-only problem (SolidElasticStokes): without an atmosphere each
   * connected body is free to move rigidly, and the drag makes the system
   * regular, as the atmosphere's viscosity did (its stress on a body is
   * c_d L^2 / a1 = @p relative L^2 of the solid's; doc/mechanics_operator.md).
   */
  template <int dim>
  class DragAssembler : public StokesAssembler<dim>
  {
  public:
    explicit DragAssembler(const double relative)
      : relative(relative)
    {}

    void
    assemble(const StokesCellData<dim> &data,
             CellContribution          &cell) const override;

  private:
    const double relative;
  };

  /** External pressure on the free box faces: traction -p_ext n. */
  template <int dim>
  class TractionAssembler : public StokesFaceAssembler<dim>
  {
  public:
    explicit TractionAssembler(const double external_pressure)
      : p_ext(external_pressure)
    {}

    void
    assemble(const StokesCellData<dim>                  &data,
             const typename StokesCellData<dim>::Face &face,
             CellContribution                           &cell) const override;

  private:
    const double p_ext;
  };

  /**
   * Pressure ghost penalty of the extended pressure (ExtendedPressureStokes;
   * Burman & Hansbo 2014, Massing et al. 2014): on an interior face of a
   * cut cell whose two cells both hold phase P,
   *   g (a2 / a1)_P h^3 int_F [grad p_P . n][grad q_P . n],
   * with the phase's coefficients (the scaling of the ASGS tau of Eq. 99,
   * without its constant) and h the cell size. A phase's part
   * of a cut cell can be arbitrarily small, and the ASGS term alone then
   * controls the pressure there only as much as the part is large; the
   * face term extends the control of the neighbours into it, so the
   * pressure (and the system's conditioning) stays bounded however the
   * interface cuts the cell. Q1 has no higher normal derivatives to jump,
   * and the exact pressure is smooth within a phase, so the term is
   * consistent to O(h^2). It belongs to -C (the sign of the ASGS term in
   * the system, the opposite in the Schur approximation).
   */
  template <int dim>
  class GhostPenaltyAssembler
  {
  public:
    explicit GhostPenaltyAssembler(const double constant)
      : constant(constant)
    {}

    /** The penalty of the pressure in component @p component of the
     * element, with @p weight = (a2 / a1)_P h^3, on the face @p values was reinit
     * on; @p matrix and @p schur are sized to its interface DoFs. */
    void
    assemble(const FEInterfaceValues<dim> &values,
             const SceneMeasure           &measure,
             const unsigned int            component,
             const double                  weight,
             FullMatrix<double>           &matrix,
             FullMatrix<double>           &schur) const;

  private:
    const double constant;
  };

  /** Copy the upper triangle of the same-type pairs (velocity-velocity,
   * pressure-pressure) of the matrix and the Schur block to the lower. */
  template <int dim>
  void
  symmetrise(const StokesCellData<dim> &data, CellContribution &cell);
} // namespace levelsinter
