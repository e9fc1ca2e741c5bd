#pragma once

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

  /** Copy the upper triangle of the same-type pairs (velocity-velocity,
   * pressure-pressure) of the matrix and the Schur block to the lower. */
  template <int dim>
  void
  symmetrise(const StokesCellData<dim> &data, CellContribution &cell);
} // namespace levelsinter
