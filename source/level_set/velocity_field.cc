#include <deal.II/base/mpi.h>

#include <deal.II/dofs/dof_tools.h>

#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_values.h>

#include <deal.II/numerics/vector_tools.h>

#include <levelsinter/level_set/ghosted_vector.h>
#include <levelsinter/level_set/point_value.h>
#include <levelsinter/level_set/same_cell.h>
#include <levelsinter/level_set/velocity_field.h>

#include <cmath>

namespace levelsinter
{
  template <int dim>
  VelocityField<dim>::VelocityField(
    const parallel::distributed::Triangulation<dim> &tria)
    : finite_element(FE_Q<dim>(1), dim)
    , dofs(tria)
  {}

  template <int dim>
  void
  VelocityField<dim>::setup_dofs()
  {
    dofs.distribute_dofs(finite_element);
    owned_dofs = dofs.locally_owned_dofs();
    DoFTools::extract_locally_relevant_dofs(dofs, relevant_dofs);
    ghosted_velocity.reinit(owned_dofs, relevant_dofs, dofs.get_communicator());
    // Hanging nodes must follow their parents so that the field is
    // continuous; built once per mesh, used at every interpolation.
    hanging_node_constraints.clear();
    hanging_node_constraints.reinit(relevant_dofs);
    DoFTools::make_hanging_node_constraints(dofs, hanging_node_constraints);
    hanging_node_constraints.close();
  }

  template <int dim>
  void
  VelocityField<dim>::set_zero()
  {
    ghosted_velocity = 0;
  }

  template <int dim>
  void
  VelocityField<dim>::add(const Function<dim> &velocity)
  {
    Vector owned(owned_dofs, dofs.get_communicator());
    VectorTools::interpolate(dofs, velocity, owned);
    add(owned);
  }

  template <int dim>
  void
  VelocityField<dim>::add(const Vector &increment)
  {
    Vector owned(owned_dofs, dofs.get_communicator());
    owned = ghosted_velocity;
    owned += increment;
    ghosted_velocity =
      ghosted_from_owned(owned, hanging_node_constraints, relevant_dofs);
  }

  template <int dim>
  void
  VelocityField<dim>::add_vertex_values(
    const DoFHandler<dim> &source_dofs,
    const std::function<
      Tensor<1, dim>(const typename DoFHandler<dim>::active_cell_iterator &,
                     const unsigned int)> &vertex_value)
  {
    Vector increment(owned_dofs, dofs.get_communicator());
    for (const auto &cell : dofs.active_cell_iterators())
      if (cell->is_locally_owned())
        for (const unsigned int v : cell->vertex_indices())
          {
            const auto source_cell = same_cell(cell, source_dofs);
            const Tensor<1, dim> value = vertex_value(source_cell, v);
            for (unsigned int c = 0; c < dim; ++c)
              {
                const auto index = cell->vertex_dof_index(v, c);
                if (owned_dofs.is_element(index))
                  increment(index) = value[c];
              }
          }
    increment.compress(VectorOperation::insert);
    add(increment);
  }

  template <int dim>
  double
  VelocityField<dim>::max_norm() const
  {
    return max_norm_over_cells([](const auto &) { return true; });
  }

  template <int dim>
  template <typename LevelSetVector>
  double
  VelocityField<dim>::max_norm_near_interface(
    const DoFHandler<dim> &level_set_dofs,
    const LevelSetVector  &alpha,
    const double           saturation) const
  {
    std::vector<types::global_dof_index> indices(
      level_set_dofs.get_fe().dofs_per_cell);
    return max_norm_over_cells([&](const auto &cell) {
      const auto ls_cell = same_cell(cell, level_set_dofs);
      ls_cell->get_dof_indices(indices);
      for (const auto i : indices)
        if (std::abs(alpha(i)) < saturation)
          return true;
      return false;
    });
  }

  template <int dim>
  Tensor<1, dim>
  VelocityField<dim>::value(const Point<dim> &point) const
  {
    return value_at_point<Tensor<1, dim>>(
      dofs, point, "velocity", [&](const auto &cell, const Point<dim> &unit) {
        FEValues<dim> values(finite_element,
                             Quadrature<dim>(unit),
                             update_values);
        values.reinit(cell);
        std::vector<Tensor<1, dim>> v(1);
        values[FEValuesExtractors::Vector(0)].get_function_values(
          ghosted_velocity, v);
        return v[0];
      });
  }

  template <int dim>
  template <typename CellFilter>
  double
  VelocityField<dim>::max_norm_over_cells(const CellFilter &use_cell) const
  {
    // Nodal values of each support point are stored component by component;
    // walk the cells so that components of one node are combined.
    double                               local_max = 0;
    std::vector<types::global_dof_index> indices(finite_element.dofs_per_cell);
    for (const auto &cell : dofs.active_cell_iterators())
      if (cell->is_locally_owned() && use_cell(cell))
        {
          cell->get_dof_indices(indices);
          for (unsigned int v = 0; v < GeometryInfo<dim>::vertices_per_cell;
               ++v)
            {
              double norm2 = 0;
              for (unsigned int c = 0; c < dim; ++c)
                {
                  const double value = ghosted_velocity(
                    indices[finite_element.component_to_system_index(c, v)]);
                  norm2 += value * value;
                }
              local_max = std::max(local_max, norm2);
            }
        }
    return std::sqrt(Utilities::MPI::max(local_max, dofs.get_communicator()));
  }

  template class VelocityField<2>;
  template class VelocityField<3>;
  template double
  VelocityField<2>::max_norm_near_interface(
    const DoFHandler<2> &,
    const TrilinosWrappers::MPI::Vector &,
    const double) const;
  template double
  VelocityField<3>::max_norm_near_interface(
    const DoFHandler<3> &,
    const TrilinosWrappers::MPI::Vector &,
    const double) const;
} // namespace levelsinter
