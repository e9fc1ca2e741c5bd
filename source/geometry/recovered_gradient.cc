#include <deal.II/fe/fe_values.h>

#include <levelsinter/geometry/recovered_gradient.h>
#include <levelsinter/level_set/interface_measures.h>
#include <levelsinter/level_set/same_cell.h>

#include <array>
#include <vector>

namespace levelsinter
{
  template <int dim>
  SolidPressureGradient<dim>::SolidPressureGradient(
    const LevelSetField<dim>            &level_set,
    const DoFHandler<dim>               &field_dofs,
    const unsigned int                   component,
    const TrilinosWrappers::MPI::Vector &field)
    : field_dofs(field_dofs)
    , field(field)
    , vertices(level_set.fe().get_unit_support_points())
    , field_values(field_dofs.get_fe(), vertices, update_values)
    , pressure(component)
    , nodal(vertices.size())
  {}

  template <int dim>
  const std::vector<Tensor<1, dim>> &
  SolidPressureGradient<dim>::evaluate(
    const typename DoFHandler<dim>::active_cell_iterator &cell,
    const FEValues<dim>                                  &solid)
  {
    field_values.reinit(same_cell(cell, field_dofs));
    field_values[pressure].get_function_values(field, nodal);
    gradients.assign(solid.n_quadrature_points, Tensor<1, dim>());
    for (unsigned int q = 0; q < solid.n_quadrature_points; ++q)
      for (unsigned int v = 0; v < nodal.size(); ++v)
        gradients[q] += nodal[v] * solid.shape_grad(v, q);
    return gradients;
  }

  template <int dim>
  void
  add_solid_gradient_projection(
    const LevelSetField<dim>                         &level_set,
    const DoFHandler<dim>                            &field_dofs,
    const unsigned int                                component,
    const TrilinosWrappers::MPI::Vector              &field,
    TrilinosWrappers::MPI::Vector                    &mass,
    std::array<TrilinosWrappers::MPI::Vector, dim> &moments)
  {
    SolidPressureGradient<dim> pressure_gradient(level_set,
                                                 field_dofs,
                                                 component,
                                                 field);
    const unsigned int n = level_set.fe().dofs_per_cell;
    std::vector<types::global_dof_index> indices(n);
    // Summed over the cell first, then added once per vector: each element
    // access to a Trilinos vector looks its index up (per quadrature point
    // that was 2 % of a coupled packing step, doc/performance.md).
    std::vector<double>                  cell_mass(n);
    std::array<std::vector<double>, dim> cell_moments;

    interface_measures::RegionIntegrands<dim> integrands;
    integrands.solid_flags = update_values | update_gradients |
                             update_JxW_values;
    integrands.on_solid    = [&](const auto &cell, const FEValues<dim> &solid) {
      const auto &gradients = pressure_gradient.evaluate(cell, solid);
      cell->get_dof_indices(indices);
      cell_mass.assign(n, 0.);
      for (auto &moment : cell_moments)
        moment.assign(n, 0.);
      for (unsigned int q = 0; q < solid.n_quadrature_points; ++q)
        {
          const Tensor<1, dim> &gradient = gradients[q];
          for (unsigned int i = 0; i < n; ++i)
            {
              const double weight = solid.shape_value(i, q) * solid.JxW(q);
              cell_mass[i] += weight;
              for (unsigned int c = 0; c < dim; ++c)
                cell_moments[c][i] += weight * gradient[c];
            }
        }
      mass.add(indices, cell_mass);
      for (unsigned int c = 0; c < dim; ++c)
        moments[c].add(indices, cell_moments[c]);
    };
    interface_measures::integrate_regions(level_set, integrands);
  }

  template class SolidPressureGradient<2>;
  template class SolidPressureGradient<3>;

  template void
  add_solid_gradient_projection<2>(
    const LevelSetField<2> &,
    const DoFHandler<2> &,
    const unsigned int,
    const TrilinosWrappers::MPI::Vector &,
    TrilinosWrappers::MPI::Vector &,
    std::array<TrilinosWrappers::MPI::Vector, 2> &);
  template void
  add_solid_gradient_projection<3>(
    const LevelSetField<3> &,
    const DoFHandler<3> &,
    const unsigned int,
    const TrilinosWrappers::MPI::Vector &,
    TrilinosWrappers::MPI::Vector &,
    std::array<TrilinosWrappers::MPI::Vector, 3> &);
} // namespace levelsinter
