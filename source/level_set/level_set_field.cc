#include <deal.II/dofs/dof_tools.h>

#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/sparsity_tools.h>

#include <deal.II/numerics/vector_tools.h>

#include <levelsinter/level_set/ghosted_vector.h>
#include <levelsinter/level_set/level_set_field.h>
#include <levelsinter/level_set/state_transfer.h>

namespace levelsinter
{
  template <int dim>
  LevelSetField<dim>::LevelSetField(
    const parallel::distributed::Triangulation<dim> &tria,
    const SceneMeasure                              &measure)
    : scene_measure(measure)
    , finite_element(1)
    , dofs(tria)
  {}

  template <int dim>
  LevelSetField<dim>::~LevelSetField() = default;

  template <int dim>
  void
  LevelSetField<dim>::setup_dofs()
  {
    dofs.distribute_dofs(finite_element);
    owned_dofs = dofs.locally_owned_dofs();
    DoFTools::extract_locally_relevant_dofs(dofs, relevant_dofs);
    hanging_node_constraints.clear();
    hanging_node_constraints.reinit(relevant_dofs);
    DoFTools::make_hanging_node_constraints(dofs, hanging_node_constraints);
    hanging_node_constraints.close();
    ghosted_alpha.reinit(owned_dofs,
                         relevant_dofs,
                         dofs.get_communicator());
    pattern.reset();
    volume_and_area.reset();
    mesh_classifier.reset();
    may_keep_measurements = false;
  }

  template <int dim>
  void
  LevelSetField<dim>::interpolate(const Function<dim> &filtered_level_set)
  {
    Vector owned(owned_dofs, dofs.get_communicator());
    VectorTools::interpolate(dofs, filtered_level_set, owned);
    set_from_owned(owned);
  }

  template <int dim>
  const TrilinosWrappers::SparsityPattern &
  LevelSetField<dim>::sparsity_pattern() const
  {
    if (!pattern)
      {
        DynamicSparsityPattern dsp(relevant_dofs);
        DoFTools::make_sparsity_pattern(dofs,
                                        dsp,
                                        hanging_node_constraints,
                                        false);
        SparsityTools::distribute_sparsity_pattern(dsp,
                                                   owned_dofs,
                                                   dofs.get_communicator(),
                                                   relevant_dofs);
        pattern = std::make_unique<TrilinosWrappers::SparsityPattern>();
        pattern->reinit(owned_dofs, owned_dofs, dsp, dofs.get_communicator());
      }
    return *pattern;
  }

  template <int dim>
  void
  LevelSetField<dim>::set_from_owned(Vector &owned)
  {
    ghosted_alpha =
      ghosted_from_owned(owned, hanging_node_constraints, relevant_dofs);
    volume_and_area.reset();
    mesh_classifier.reset();
    may_keep_measurements = true;
  }

  template <int dim>
  void
  LevelSetField<dim>::keep_volume_and_area(
    const interface_measures::VolumeAndArea &measured) const
  {
    if (may_keep_measurements)
      volume_and_area = measured;
  }

  template <int dim>
  std::shared_ptr<const NonMatching::MeshClassifier<dim>>
  LevelSetField<dim>::classifier() const
  {
    if (mesh_classifier)
      return mesh_classifier;
    auto made =
      std::make_shared<NonMatching::MeshClassifier<dim>>(dofs, ghosted_alpha);
    made->reclassify();
    if (may_keep_measurements)
      mesh_classifier = made;
    return made;
  }

  template <int dim>
  void
  LevelSetField<dim>::add_to(StateTransfer<dim> &transfer)
  {
    transfer.add(dofs, {&ghosted_alpha}, [this]() {
      may_keep_measurements = true;
    });
  }

  template class LevelSetField<2>;
  template class LevelSetField<3>;
} // namespace levelsinter
