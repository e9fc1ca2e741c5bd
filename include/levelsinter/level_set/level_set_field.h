#pragma once

#include <deal.II/base/index_set.h>

#include <deal.II/distributed/tria.h>

#include <deal.II/dofs/dof_handler.h>

#include <deal.II/fe/fe_q.h>

#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/trilinos_sparsity_pattern.h>
#include <deal.II/lac/trilinos_vector.h>

#include <deal.II/non_matching/mesh_classifier.h>

#include <levelsinter/level_set/scene_measure.h>

#include <memory>
#include <optional>

namespace levelsinter
{
  using namespace dealii;

  template <int dim>
  class StateTransfer;

  namespace interface_measures
  {
    /** What interface_measures::volume_and_area() measures. */
    struct VolumeAndArea
    {
      double solid_volume   = 0; // area in 2D
      double interface_area = 0; // length in 2D
    };
  } // namespace interface_measures

  /**
   * The discrete filtered level set alpha_h: Q1 on the distributed mesh,
   * with hanging-node constraints and a ghosted copy for reading across
   * process boundaries. Owns the field, the sparsity pattern its scalar
   * systems share and the measured volume and area of its current alpha;
   * the solvers and measurements act on it.
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
     * the level-set mesh (transport, curvature, the xi extension) is sized
     * with. Built at the first call after setup_dofs() and shared by those
     * systems until the next setup_dofs() (a mesh change).
     */
    const TrilinosWrappers::SparsityPattern &
    sparsity_pattern() const;

    /**
     * Set alpha from @p owned (locally owned entries set; compressed and
     * constrained here).
     */
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
     * The volume and area interface_measures::volume_and_area() measured
     * on the current alpha, if it did: the time loop, the metrics and
     * several mechanisms ask for the same state, and in 3D one cut-cell
     * integration costs seconds. Dropped whenever alpha changes.
     */
    const std::optional<interface_measures::VolumeAndArea> &
    measured_volume_and_area() const
    {
      return volume_and_area;
    }

    /** Keep @p measured as measured_volume_and_area() of the current alpha. */
    void
    keep_volume_and_area(
      const interface_measures::VolumeAndArea &measured) const;

    /**
     * Which cells and faces the interface of the current alpha cuts
     * (NonMatching::MeshClassifier, reclassified). Made at the first call
     * after alpha changed and shared by every cut-cell integration and
     * solver on that alpha: a classification reads alpha on every cell
     * and face, and each of them used to make its own (doc/performance.md,
     * "Session 29"). A holder may keep it past a change of alpha; it then
     * describes the alpha it was made for.
     */
    std::shared_ptr<const NonMatching::MeshClassifier<dim>>
    classifier() const;

  private:
    SceneMeasure              scene_measure;
    FE_Q<dim>                 finite_element;
    DoFHandler<dim>           dofs;
    AffineConstraints<double> hanging_node_constraints;
    IndexSet                  owned_dofs;
    IndexSet                  relevant_dofs;
    Vector                    ghosted_alpha;
    // Both belong to the current DoFs; the pattern also to the constraints.
    mutable std::unique_ptr<TrilinosWrappers::SparsityPattern> pattern;
    // Both kept only for an alpha this class knows of: set through
    // set_from_owned() or written by the StateTransfer it was added to.
    // After setup_dofs() and before that transfer, alpha is not yet set.
    mutable std::optional<interface_measures::VolumeAndArea> volume_and_area;
    mutable std::shared_ptr<const NonMatching::MeshClassifier<dim>>
         mesh_classifier;
    bool may_keep_measurements = false;
  };
} // namespace levelsinter
