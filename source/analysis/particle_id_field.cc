#include <levelsinter/analysis/particle_id_field.h>
#include <levelsinter/geometry/grain_boundaries.h>

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
    grain_geometry::cell_grains(level_set, power_cells, ids);
    data_out.add_data_vector(ids,
                             "particle_id",
                             DataOut<dim>::type_cell_data);
  }

  template class ParticleIdField<2>;
  template class ParticleIdField<3>;
} // namespace levelsinter
