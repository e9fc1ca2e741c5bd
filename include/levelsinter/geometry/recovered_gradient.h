#pragma once

#include <deal.II/dofs/dof_handler.h>

#include <deal.II/fe/fe_values.h>

#include <deal.II/lac/trilinos_vector.h>

#include <levelsinter/level_set/level_set_field.h>

#include <array>
#include <vector>

namespace levelsinter
{
  using namespace dealii;

  /**
   * grad p of a scalar finite-element field p at the quadrature points of
   * the solid part of a level-set cell: p at the cell's nodes,
   * differentiated with the level set's Q1 shape functions (exact, since p
   * is Q1 on each cell). p is component @p component of @p field on
   * @p field_dofs, a DoFHandler on the level set's mesh; all three must
   * outlive this object.
   */
  template <int dim>
  class SolidPressureGradient
  {
  public:
    SolidPressureGradient(const LevelSetField<dim>            &level_set,
                          const DoFHandler<dim>               &field_dofs,
                          const unsigned int                   component,
                          const TrilinosWrappers::MPI::Vector &field);

    /** grad p at each point of @p solid (with update_gradients) on the
     * level-set cell @p cell. */
    const std::vector<Tensor<1, dim>> &
    evaluate(const typename DoFHandler<dim>::active_cell_iterator &cell,
             const FEValues<dim>                                  &solid);

  private:
    const DoFHandler<dim>               &field_dofs;
    const TrilinosWrappers::MPI::Vector &field;
    const Quadrature<dim>                vertices;
    FEValues<dim>                        field_values;
    const FEValuesExtractors::Scalar     pressure;
    std::vector<double>                  nodal;
    std::vector<Tensor<1, dim>>          gradients;
  };

  /**
   * The gradient of a scalar finite-element field p recovered on the level
   * set's Q1 nodes by a lumped L2 projection over the solid part
   * {alpha_h < 0} only (sharp cut-cell quadrature, deal.II NonMatching):
   *
   *   G_i = int_{solid} phi_i grad p / int_{solid} phi_i,
   *
   * accumulated here as the two integrals: @p mass gets int phi_i and
   * @p moments[c] gets int phi_i dp/dx_c over the locally owned cells
   * (ghosted vectors with writable ghosts; the caller compresses with
   * VectorOperation::add and divides). Every node of a cell that holds
   * solid gets a value, read from the solid alone: the gradient of the
   * atmosphere's side (the Laplace jump of a smeared or an extended
   * pressure) never enters, and the cell's whole gradient, not the edges
   * through one vertex, is averaged, which damps the pressure's cell-scale
   * oscillations next to the interface (doc/numerics.md, "Volume diffusion:
   * a recovered gradient"). p is component @p component of @p field on
   * @p field_dofs, a DoFHandler on the level set's mesh whose component is
   * Q1 on each cell (the continuous pressure, or the solid's own pressure
   * of the extended space).
   */
  template <int dim>
  void
  add_solid_gradient_projection(
    const LevelSetField<dim>                         &level_set,
    const DoFHandler<dim>                            &field_dofs,
    const unsigned int                                component,
    const TrilinosWrappers::MPI::Vector              &field,
    TrilinosWrappers::MPI::Vector                    &mass,
    std::array<TrilinosWrappers::MPI::Vector, dim> &moments);
} // namespace levelsinter
