#pragma once

#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/base/tensor.h>

#include <deal.II/fe/fe_values.h>

#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>

#include <levelsinter/level_set/scene_measure.h>
#include <levelsinter/mechanics/phase_law.h>

#include <vector>

namespace levelsinter
{
  using namespace dealii;

  /**
   * What the assemblers of the two-phase Stokes operator read on one cell
   * (the scratch of StokesAssembler): shape data and phase coefficients at
   * the volume quadrature points, the points of the surface measure and the
   * points on free box faces. TwoPhaseStokes fills it per cell; each
   * assembler adds one term of Eq. 93-94 to a CellContribution.
   *
   * Weights are in the scene's measure (SceneMeasure): on an axisymmetric
   * scene JxW and dS carry 2 pi r, and the hoop strain e_thth(w) = w_r / r
   * of each velocity shape function is at hand (hoop(), SurfacePoint::hoop;
   * zero on a plane scene), so each assembler writes its form once for
   * both (doc/numerics.md, "Axisymmetric scenes").
   */
  template <int dim>
  struct StokesCellData
  {
    /** One point of the surface measure of Gamma: unit normal, weight dS
     * and the gradients of the velocity shape functions there. */
    struct SurfacePoint
    {
      Tensor<1, dim>              normal;
      double                      dS = 0;
      std::vector<Tensor<2, dim>> grad_w;
      // w_r / r per shape function (0 off the axisymmetric case).
      std::vector<double> hoop;

      /** The tangential projector I - n (x) n. */
      Tensor<2, dim>
      projector() const
      {
        return unit_symmetric_tensor<dim>() - outer_product(normal, normal);
      }
    };

    /** One quadrature point of a free box face: outer normal, weight and
     * the velocity shape values. */
    struct FacePoint
    {
      Tensor<1, dim>              normal;
      double                      JxW = 0;
      std::vector<Tensor<1, dim>> w;
    };

    /** Size for @p n_dofs shape functions; @p component[i] is the vector
     * component of shape function i (dim: pressure). */
    explicit StokesCellData(const std::vector<unsigned int> &component);

    /** Shape data from @p values (reinit on the cell, with its
     * quadrature points), weights in @p measure; resets the surface and
     * face points. */
    void
    reinit(const FEValues<dim> &values, const SceneMeasure &measure);

    bool
    is_pressure(const unsigned int i) const
    {
      return component[i] == dim;
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
    std::vector<FacePoint>    free_faces;
  };

  /** A cell's share of the system matrix, the Schur approximation and the
   * right-hand side. Same-type pairs (velocity-velocity, pressure-pressure)
   * are filled in the upper triangle only, mirrored by symmetrise(). */
  struct CellContribution
  {
    explicit CellContribution(const unsigned int n)
      : matrix(n, n)
      , schur(n, n)
      , rhs(n)
    {}

    void
    reset()
    {
      matrix = 0;
      schur  = 0;
      rhs    = 0;
    }

    FullMatrix<double> matrix;
    FullMatrix<double> schur;
    Vector<double>     rhs;
  };
} // namespace levelsinter
