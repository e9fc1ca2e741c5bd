#include <deal.II/base/quadrature_lib.h>

#include <deal.II/fe/fe_values.h>

#include <levelsinter/mechanisms/surface_diffusion.h>

#include <cmath>

namespace levelsinter
{
  namespace
  {
    double
    coefficient_in_scene_time(const SceneParameters::SurfaceDiffusion &p)
    {
      if (p.time_unit == "reduced")
        return std::pow(p.reference_radius, 4);
      return p.surface_mobility();
    }
  } // namespace

  template <int dim>
  SurfaceDiffusion<dim>::SurfaceDiffusion(
    const SceneParameters::SurfaceDiffusion &parameters,
    const LevelSetFilter                    &filter,
    TimerOutput                             &timer)
    : mobility(coefficient_in_scene_time(parameters))
    , solver(filter,
             {parameters.coupled, parameters.solver_tolerance, 1000},
             timer)
    , timer(timer)
  {}

  template <int dim>
  void
  SurfaceDiffusion<dim>::setup(const LevelSetField<dim> &alpha)
  {
    solver.setup(alpha);
    // v_s^{n-1} lives on the old mesh; A^n falls back to |grad d| for the
    // first step after a remesh (a second-order change in kappa).
    previous_velocity.clear();
    solved_time = -1;
  }

  template <int dim>
  void
  SurfaceDiffusion<dim>::add_velocity(const LevelSetField<dim> &alpha,
                                      const double              t,
                                      const double              dt,
                                      VelocityField<dim>       &velocity)
  {
    if (solved_time >= 0 && t > solved_time)
      previous_velocity = solver.normal_velocity();
    iterations  = solver.solve(alpha, mobility, dt, previous_velocity);
    solved_time = t;

    TimerOutput::Scope scope(timer, "surface diffusion velocity");
    const auto    &ls_dofs = alpha.dof_handler();
    const auto    &v_dofs  = velocity.dof_handler();
    const MPI_Comm comm    = ls_dofs.get_communicator();

    // Eq. 84: sum the cell normals at each node (the gradient of Q1 at the
    // cell centre), normalise, multiply by the nodal v_s.
    TrilinosWrappers::MPI::Vector normal_sum;
    normal_sum.reinit(velocity.locally_owned(),
                      velocity.locally_relevant(),
                      comm,
                      /*vector_writable=*/true);
    const QMidpoint<dim>        centre;
    FEValues<dim>               fe_values(alpha.fe(), centre, update_gradients);
    std::vector<Tensor<1, dim>> gradient(1);
    auto velocity_cell = [&](const auto &cell) {
      return typename DoFHandler<dim>::active_cell_iterator(
        &ls_dofs.get_triangulation(), cell->level(), cell->index(), &v_dofs);
    };
    for (const auto &cell : ls_dofs.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          fe_values.reinit(cell);
          fe_values.get_function_gradients(alpha.alpha(), gradient);
          const double norm = gradient[0].norm();
          if (norm == 0)
            continue;
          const auto v_cell = velocity_cell(cell);
          for (const unsigned int v : cell->vertex_indices())
            for (unsigned int c = 0; c < dim; ++c)
              normal_sum(v_cell->vertex_dof_index(v, c)) += gradient[0][c] / norm;
        }
    normal_sum.compress(VectorOperation::add);
    TrilinosWrappers::MPI::Vector normals(velocity.locally_owned(),
                                          velocity.locally_relevant(),
                                          comm);
    normals = normal_sum;

    TrilinosWrappers::MPI::Vector increment(velocity.locally_owned(), comm);
    const auto                   &v_s = solver.normal_velocity();
    for (const auto &cell : ls_dofs.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          const auto v_cell = velocity_cell(cell);
          for (const unsigned int v : cell->vertex_indices())
            {
              Tensor<1, dim> N;
              for (unsigned int c = 0; c < dim; ++c)
                N[c] = normals(v_cell->vertex_dof_index(v, c));
              const double norm = N.norm();
              if (norm == 0)
                continue;
              const double speed = v_s(cell->vertex_dof_index(v, 0)) / norm;
              for (unsigned int c = 0; c < dim; ++c)
                {
                  const auto index = v_cell->vertex_dof_index(v, c);
                  if (velocity.locally_owned().is_element(index))
                    increment(index) = speed * N[c];
                }
            }
        }
    increment.compress(VectorOperation::insert);
    velocity.add(increment);
  }

  template <int dim>
  std::vector<std::string>
  SurfaceDiffusion<dim>::metric_names() const
  {
    return {"surface_diffusion_iterations"};
  }

  template <int dim>
  std::vector<double>
  SurfaceDiffusion<dim>::metric_values() const
  {
    return {double(iterations)};
  }

  template class SurfaceDiffusion<2>;
  template class SurfaceDiffusion<3>;
} // namespace levelsinter
