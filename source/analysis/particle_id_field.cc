#include <levelsinter/analysis/particle_id_field.h>

namespace levelsinter
{
  template <int dim>
  ParticleIdField<dim>::ParticleIdField(
    const std::vector<std::vector<double>> &particles)
    : power_cells(particles)
  {}

  template <int dim>
  void
  ParticleIdField<dim>::add_to(const LevelSetField<dim> &level_set,
                               DataOut<dim>             &data_out)
  {
    const auto &dofs = level_set.dof_handler();
    ids.reinit(dofs.get_triangulation().n_active_cells());
    std::vector<types::global_dof_index> indices(dofs.get_fe().n_dofs_per_cell());
    for (const auto &cell : dofs.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          // Q1 takes its minimum at a vertex: solid in the cell iff a
          // vertex value is <= 0.
          cell->get_dof_indices(indices);
          bool solid = false;
          for (const auto i : indices)
            solid = solid || level_set.alpha()(i) <= 0;
          ids(cell->active_cell_index()) =
            solid ? float(power_cells.owner(cell->center())) : -1.f;
        }
    data_out.add_data_vector(ids,
                             "particle_id",
                             DataOut<dim>::type_cell_data);
  }

  template class ParticleIdField<2>;
  template class ParticleIdField<3>;
} // namespace levelsinter
