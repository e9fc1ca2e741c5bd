#pragma once

#include <deal.II/base/point.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/base/tensor.h>

#include <deal.II/dofs/dof_handler.h>

#include <deal.II/hp/q_collection.h>

#include <deal.II/lac/trilinos_vector.h>

#include <deal.II/non_matching/quadrature_generator.h>

#include <array>
#include <vector>

namespace levelsinter
{
  using namespace dealii;

  /**
   * The integration rules of a cell cut by the zero level set of a Q1
   * field, on the axis-parallel cells of the box meshes, without an
   * FEValues object per cut cell (NonMatching::FEValues builds up to three
   * for each, and that construction, not the quadrature, was most of the
   * cut spaces' assembly: doc/performance.md, "Session 25").
   *
   * - Each part {alpha_h < 0} and {alpha_h > 0} of the cell is integrated
   *   on the cell's fixed tensor Gauss points with moment-fitted weights:
   *   w_q = sum_k W_k L_q(y_k), the generated rule's points y_k and
   *   weights W_k (NonMatching::DiscreteQuadratureGenerator, the same as
   *   NonMatching::FEValues uses) and L_q the tensor Lagrange polynomial
   *   of Gauss point q. With n points per direction this is the generated
   *   rule itself on every polynomial of degree n - 1 per direction. With
   *   n = 3 that holds every integrand of the Q1/Q1 spaces' cell terms
   *   with coefficients constant in each phase (products of Q1 functions
   *   and of their derivatives on an affine cell), so the cell matrices
   *   are the generated rule's to round-off (tests/cut_cell_rules.cc).
   *   An FEValues on those fixed points is reinit() as on any cell.
   * - The surface {alpha_h = 0}: the generated points mapped to the cell
   *   with their real normals and weights dS, and the Q1 shape functions'
   *   values and gradients there, evaluated directly.
   *
   * Plane measure only: the axisymmetric weight 2 pi r and the hoop terms
   * are no polynomials of that degree (those scenes keep
   * NonMatching::FEValues).
   */
  template <int dim>
  class CutCellRules
  {
  public:
    /** A point of the surface: in real space, with the unit normal
     * (pointing into {alpha_h > 0}), the weight dS, and the values and
     * gradients of the 2^dim Q1 shape functions (deal.II's vertex order). */
    struct SurfacePoint
    {
      Point<dim>                                           point;
      Tensor<1, dim>                                       normal;
      double                                               dS = 0;
      std::array<double, GeometryInfo<dim>::vertices_per_cell> value;
      std::array<Tensor<1, dim>, GeometryInfo<dim>::vertices_per_cell>
        gradient;
    };

    /** Rules on the zero level set of @p level_set (ghosted, on the Q1
     * @p dofs), from @p n_points Gauss points per direction. */
    CutCellRules(const DoFHandler<dim>               &dofs,
                 const TrilinosWrappers::MPI::Vector &level_set,
                 const unsigned int                   n_points);

    /** The Gauss points of the whole cell the weights refer to (reinit an
     * FEValues on them). */
    const Quadrature<dim> &
    cell_quadrature() const
    {
      return gauss;
    }

    /** Generate the rules of @p cell, which must be intersected and
     * axis-parallel. */
    void
    generate(const typename Triangulation<dim>::active_cell_iterator &cell);

    /** Whether the last cell has a part on the @p inside (alpha_h < 0)
     * or outside side (false: the generated rule had no point there). */
    bool
    has_part(const bool inside) const
    {
      return !(inside ? inside_weights : outside_weights).empty();
    }

    /** The moment-fitted weights of the part on the unit cell, one per
     * point of cell_quadrature(): multiply by det J (JxW / w_q of the
     * full Gauss rule). */
    const std::vector<double> &
    weights(const bool inside) const
    {
      return inside ? inside_weights : outside_weights;
    }

    const std::vector<SurfacePoint> &
    surface() const
    {
      return surface_points;
    }

  private:
    void
    fit(const Quadrature<dim> &part, std::vector<double> &weights) const;

    const QGauss<1>    gauss_1d;
    const QGauss<dim>  gauss;
    // The generator keeps a pointer to it.
    const hp::QCollection<1>                      q_collection_1d;
    NonMatching::DiscreteQuadratureGenerator<dim> generator;
    // The 1D indices of each point of `gauss`.
    std::vector<std::array<unsigned int, dim>>   tensor_index;
    std::vector<double>                          inside_weights;
    std::vector<double>                          outside_weights;
    std::vector<SurfacePoint>                    surface_points;
  };
} // namespace levelsinter
