#pragma once

#include <deal.II/base/function.h>
#include <deal.II/base/index_set.h>

#include <deal.II/distributed/tria.h>

#include <deal.II/dofs/dof_handler.h>

#include <deal.II/fe/fe_system.h>

#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/trilinos_vector.h>

#include <functional>

namespace levelsinter
{
  using namespace dealii;

  /**
   * The interface velocity as a continuous Q1 vector field: what the
   * mechanisms produce and the level-set transport consumes. Prescribed
   * velocities are interpolated into it, later mechanisms solve for it.
   */
  template <int dim>
  class VelocityField
  {
  public:
    using Vector = TrilinosWrappers::MPI::Vector;

    explicit VelocityField(const parallel::distributed::Triangulation<dim> &tria);

    void
    setup_dofs();

    /** v = 0: the start of the sum over the mechanisms. */
    void
    set_zero();

    /** v += nodal interpolant of a dim-component function at its time. */
    void
    add(const Function<dim> &velocity);

    /**
     * v += @p increment, a vector over the locally owned DoFs of
     * dof_handler() (a mechanism that solves for its velocity on its own
     * space copies it into this numbering first). Hanging-node values are
     * made consistent here.
     */
    void
    add(const Vector &increment);

    /**
     * v += the vector vertex_value(cell, v) at vertex v of every locally
     * owned cell, where cell is the same mesh cell seen from
     * @p source_dofs: how a mechanism that computes a nodal velocity on its
     * own space on the same mesh hands it over (it reads its vertex DoFs on
     * that cell).
     */
    void
    add_vertex_values(
      const DoFHandler<dim> &source_dofs,
      const std::function<
        Tensor<1, dim>(const typename DoFHandler<dim>::active_cell_iterator &,
                       const unsigned int)> &vertex_value);

    /** Locally owned and locally relevant DoFs of dof_handler(). */
    const IndexSet &
    locally_owned() const
    {
      return owned_dofs;
    }

    const IndexSet &
    locally_relevant() const
    {
      return relevant_dofs;
    }

    /** Hanging-node constraints of the velocity space. */
    const AffineConstraints<double> &
    constraints() const
    {
      return hanging_node_constraints;
    }

    /** max over the nodes of |v| (all processes). */
    double
    max_norm() const;

    /**
     * The velocity at @p point, on every rank (the owner of the cell that
     * holds it evaluates the Q1 field; the value is then shared). Throws if
     * no cell holds the point.
     */
    Tensor<1, dim>
    value(const Point<dim> &point) const;

    /**
     * max of |v| over the nodes of cells where |alpha| is below
     * @p saturation, i.e. near the interface: the speed that limits the
     * time step (far away alpha is constant and any speed is harmless).
     */
    template <typename LevelSetVector>
    double
    max_norm_near_interface(const DoFHandler<dim> &level_set_dofs,
                            const LevelSetVector  &alpha,
                            const double           saturation) const;

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

    const Vector &
    values() const
    {
      return ghosted_velocity;
    }

  private:
    template <typename CellFilter>
    double
    max_norm_over_cells(const CellFilter &use_cell) const;

    FESystem<dim>   finite_element;
    DoFHandler<dim> dofs;
    IndexSet        owned_dofs;
    IndexSet                  relevant_dofs;
    AffineConstraints<double> hanging_node_constraints;
    Vector                    ghosted_velocity;
  };
} // namespace levelsinter
