#pragma once

#include <deal.II/base/index_set.h>

#include <deal.II/distributed/tria.h>

#include <deal.II/dofs/dof_handler.h>

#include <deal.II/fe/fe_q.h>

#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/trilinos_vector.h>

#include <levelsinter/level_set/scene_measure.h>

#include <cstdint>

namespace levelsinter
{
  using namespace dealii;

  template <int dim>
  class StateTransfer;

  /**
   * The discrete filtered level set alpha_h: Q1 on the distributed mesh,
   * with hanging-node constraints and a ghosted copy for reading across
   * process boundaries. Owns nothing but the field; the solvers and
   * measurements act on it.
   */
  template <int dim>
  class LevelSetField
  {
  public:
    using Vector = TrilinosWrappers::MPI::Vector;

    /** @p measure: the measure of the scene's volumes and areas (an
     * axisymmetric scene's are those of the body of revolution). */
    explicit LevelSetField(
      const parallel::distributed::Triangulation<dim> &tria,
      const SceneMeasure                              &measure = SceneMeasure());
    ~LevelSetField();

    /** Distribute DoFs and size the vectors for the current mesh. */
    void
    setup_dofs();

    /** alpha = filter(distance(x)), interpolated at the nodes. */
    void
    interpolate(const Function<dim> &filtered_level_set);

    /**
     * Keep alpha across the next mesh change: after it, setup_dofs() comes
     * before StateTransfer::interpolate().
     */
    void
    add_to(StateTransfer<dim> &transfer);

    /**
     * The sparsity pattern of a matrix on these DoFs with these
     * constraints, distributed over the ranks: what every scalar system on
     * the level-set mesh (transport, curvature) is sized with.
     */
    DynamicSparsityPattern
    sparsity_pattern() const;

    /** Set the ghosted vector from an owned-only one, applying constraints. */
    void
    set_from_owned(Vector &owned);

    const DoFHandler<dim> &
    dof_handler() const
    {
      return dofs;
    }

    const AffineConstraints<double> &
    constraints() const
    {
      return hanging_node_constraints;
    }

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

    /** alpha with ghost entries, for assembly, measurements and output. */
    const Vector &
    alpha() const
    {
      return ghosted_alpha;
    }

    const FE_Q<dim> &
    fe() const
    {
      return finite_element;
    }

    /** The measure every integral over this field's regions uses. */
    const SceneMeasure &
    measure() const
    {
      return scene_measure;
    }

    /**
     * A number that identifies the current values of alpha among all
     * states of all level-set fields of the run: a measurement of one
     * state (interface_measures::volume_and_area) is taken once and reused.
     */
    std::uint64_t
    state_id() const
    {
      return state;
    }

  private:
    SceneMeasure              scene_measure;
    FE_Q<dim>                 finite_element;
    DoFHandler<dim>           dofs;
    AffineConstraints<double> hanging_node_constraints;
    IndexSet                  owned_dofs;
    IndexSet                  relevant_dofs;
    Vector                    ghosted_alpha;
    std::uint64_t             state = 0;
  };
} // namespace levelsinter
