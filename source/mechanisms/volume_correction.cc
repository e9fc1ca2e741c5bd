#include <levelsinter/geometry/nodal_normals.h>
#include <levelsinter/level_set/interface_measures.h>
#include <levelsinter/mechanisms/volume_correction.h>

#include <iomanip>
#include <sstream>
#include <stdexcept>

namespace levelsinter
{
  template <int dim>
  VolumeCorrection<dim>::VolumeCorrection(
    const std::vector<types::boundary_id> &symmetry_planes,
    const LevelSetFilter                  &filter)
    : symmetry_planes(symmetry_planes)
    , filter(filter)
  {}

  template <int dim>
  void
  VolumeCorrection<dim>::keep_initial_volume(const LevelSetField<dim> &alpha)
  {
    if (initial_volume < 0)
      initial_volume = interface_measures::volume_and_area(alpha).solid_volume;
  }

  template <int dim>
  void
  VolumeCorrection<dim>::add_velocity(const LevelSetField<dim> &alpha,
                                      const double,
                                      const double,
                                      VelocityField<dim> &)
  {
    // Nothing to add to the step itself: the correction follows it.
    keep_initial_volume(alpha);
  }

  template <int dim>
  void
  VolumeCorrection<dim>::add_probe_velocity(const LevelSetField<dim> &alpha,
                                            const double,
                                            VelocityField<dim> &)
  {
    keep_initial_volume(alpha);
  }

  template <int dim>
  bool
  VolumeCorrection<dim>::add_correction_velocity(
    const LevelSetField<dim> &alpha,
    const double              dt,
    VelocityField<dim>       &velocity)
  {
    const auto measures = interface_measures::volume_and_area(alpha);
    speed = 0;
    if (dt > 0 && measures.interface_area > 0)
      speed = (initial_volume - measures.solid_volume) /
              (dt * measures.interface_area);
    if (speed == 0)
      return false;
    const auto normals = nodal_normals(alpha, filter, true, symmetry_planes);
    velocity.add_vertex_values(alpha.dof_handler(),
                               [&](const auto &cell, const unsigned int v) {
      const auto     i = cell->vertex_dof_index(v, 0);
      Tensor<1, dim> value;
      for (unsigned int c = 0; c < dim; ++c)
        value[c] = speed * normals[c](i);
      return value;
    });
    return true;
  }

  template <int dim>
  std::string
  VolumeCorrection<dim>::save() const
  {
    std::ostringstream out;
    out << std::setprecision(17) << initial_volume;
    return out.str();
  }

  template <int dim>
  void
  VolumeCorrection<dim>::load(const std::string &state)
  {
    std::istringstream in(state);
    if (!(in >> initial_volume))
      throw std::runtime_error("the volume correction's checkpoint state '" +
                               state + "' is not a number");
  }

  template <int dim>
  std::vector<std::string>
  VolumeCorrection<dim>::metric_names() const
  {
    return {"volume_correction_speed"};
  }

  template <int dim>
  std::vector<double>
  VolumeCorrection<dim>::metric_values() const
  {
    return {speed};
  }

  template class VolumeCorrection<2>;
  template class VolumeCorrection<3>;
} // namespace levelsinter
