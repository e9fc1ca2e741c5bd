#include <deal.II/fe/fe_values.h>

#include <levelsinter/geometry/boundary_flux.h>
#include <levelsinter/geometry/recovered_gradient.h>
#include <levelsinter/level_set/interface_measures.h>

#include <vector>

namespace levelsinter
{
  template <int dim>
  void
  add_boundary_flux(const LevelSetField<dim>            &level_set,
                    const DoFHandler<dim>               &field_dofs,
                    const unsigned int                   component,
                    const TrilinosWrappers::MPI::Vector &field,
                    InterfaceMoments<dim>               &moments,
                    TrilinosWrappers::MPI::Vector       &flux)
  {
    SolidPressureGradient<dim> pressure_gradient(level_set,
                                                 field_dofs,
                                                 component,
                                                 field);
    std::vector<types::global_dof_index> indices(level_set.fe().dofs_per_cell);
    const SceneMeasure                  &measure = level_set.measure();

    interface_measures::RegionIntegrands<dim> integrands;
    integrands.solid_flags   = update_gradients | update_JxW_values;
    integrands.surface_flags =
      update_values | update_JxW_values | update_normal_vectors |
      update_quadrature_points;
    integrands.on_solid = [&](const auto &cell, const FEValues<dim> &solid) {
      const auto &gradients = pressure_gradient.evaluate(cell, solid);
      cell->get_dof_indices(indices);
      for (unsigned int q = 0; q < solid.n_quadrature_points; ++q)
        {
          const double JxW = measure.JxW(solid, q);
          for (unsigned int i = 0; i < indices.size(); ++i)
            flux(indices[i]) += gradients[q] * solid.shape_grad(i, q) * JxW;
        }
    };
    integrands.on_surface =
      [&](const auto &cell, const NonMatching::FEImmersedSurfaceValues<dim>
                              &surface) {
        cell->get_dof_indices(indices);
        for (unsigned int q = 0; q < surface.n_quadrature_points; ++q)
          {
            const double          JxW    = measure.JxW(surface, q);
            const Tensor<1, dim> &normal = surface.normal_vector(q);
            const Point<dim>     &x      = surface.quadrature_point(q);
            for (unsigned int i = 0; i < indices.size(); ++i)
              {
                const double value = surface.shape_value(i, q) * JxW;
                moments.mass(indices[i]) += value;
                for (unsigned int d = 0; d < dim; ++d)
                  {
                    moments.normal[d](indices[i]) += value * normal[d];
                    moments.position[d](indices[i]) += value * x[d];
                  }
                moments.normal_position(indices[i]) += value * (normal * x);
              }
          }
      };
    interface_measures::integrate_regions(level_set, integrands);
  }

  template void
  add_boundary_flux<2>(const LevelSetField<2> &,
                       const DoFHandler<2> &,
                       const unsigned int,
                       const TrilinosWrappers::MPI::Vector &,
                       InterfaceMoments<2> &,
                       TrilinosWrappers::MPI::Vector &);
  template void
  add_boundary_flux<3>(const LevelSetField<3> &,
                       const DoFHandler<3> &,
                       const unsigned int,
                       const TrilinosWrappers::MPI::Vector &,
                       InterfaceMoments<3> &,
                       TrilinosWrappers::MPI::Vector &);
} // namespace levelsinter
