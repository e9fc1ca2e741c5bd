#include <levelsinter/mechanisms/surface_diffusion.h>

namespace levelsinter
{
  namespace
  {
    template <int dim>
    typename MixedCurvatureSolver<dim>::Settings
    solver_settings(const SceneParameters::SurfaceDiffusion &parameters,
                    const std::vector<types::boundary_id>   &symmetry_planes)
    {
      typename MixedCurvatureSolver<dim>::Settings settings;
      settings.coupled = parameters.coupled;
      settings.direct  = parameters.linear_solver ==
                        SurfaceDiffusionParameters::LinearSolver::direct;
      settings.tolerance           = parameters.solver_tolerance;
      settings.max_iterations      = 1000;
      settings.symmetry_boundaries = symmetry_planes;
      return settings;
    }
  } // namespace

  template <int dim>
  SurfaceDiffusion<dim>::SurfaceDiffusion(
    const SceneParameters::SurfaceDiffusion &parameters,
    const double                             seconds_per_time_unit,
    const std::vector<types::boundary_id>   &symmetry_planes,
    const LevelSetFilter                    &filter,
    TimerOutput                             &timer)
    : mobility(parameters.surface_mobility() * seconds_per_time_unit)
    , solver(filter, solver_settings<dim>(parameters, symmetry_planes), timer)
    , timer(timer)
  {}

  template <int dim>
  void
  SurfaceDiffusion<dim>::setup(const LevelSetField<dim> &alpha)
  {
    solver.setup(alpha);
  }

  template <int dim>
  void
  SurfaceDiffusion<dim>::add_state(const LevelSetField<dim> &alpha,
                                   StateTransfer<dim>       &transfer)
  {
    if (previous_velocity.size() != alpha.dof_handler().n_dofs())
      // Before the first step, or a restart: the checkpoint's v_s^{n-1} is
      // read into it.
      previous_velocity.reinit(alpha.locally_owned(),
                               alpha.locally_relevant(),
                               alpha.dof_handler().get_communicator());
    transfer.add(alpha.dof_handler(), {&previous_velocity});
  }

  template <int dim>
  void
  SurfaceDiffusion<dim>::add_output_fields(const LevelSetField<dim> &alpha,
                                          DataOut<dim> &data_out) const
  {
    // Both on the level set's DoFs.
    const auto &dofs = alpha.dof_handler();
    data_out.add_data_vector(dofs,
                             solver.curvature(),
                             "surface_diffusion_curvature");
    data_out.add_data_vector(dofs,
                             solver.normal_velocity(),
                             "surface_diffusion_v_s");
  }

  template <int dim>
  void
  SurfaceDiffusion<dim>::add_velocity(const LevelSetField<dim> &alpha,
                                      const double,
                                      const double        dt,
                                      VelocityField<dim> &velocity)
  {
    update_sources(alpha);
    iterations = solver.solve(alpha, mobility, dt, previous_velocity);
    add_normal_velocity(alpha, velocity);
  }

  template <int dim>
  void
  SurfaceDiffusion<dim>::add_probe_velocity(const LevelSetField<dim> &alpha,
                                            const double,
                                            VelocityField<dim> &velocity)
  {
    update_sources(alpha);
    iterations = solver.solve(alpha, mobility, 0, previous_velocity);
    add_normal_velocity(alpha, velocity);
  }

  template <int dim>
  void
  SurfaceDiffusion<dim>::update_sources(const LevelSetField<dim> &alpha)
  {
    const MPI_Comm comm = alpha.dof_handler().get_communicator();
    // Each source writes its owned entries; the solver reads them ghosted.
    const auto update = [&](const auto &source, auto &vector) {
      TrilinosWrappers::MPI::Vector owned(alpha.locally_owned(), comm);
      source(alpha, owned);
      vector.reinit(alpha.locally_owned(), alpha.locally_relevant(), comm);
      vector = owned;
    };
    if (potential_source)
      {
        update(potential_source, potential);
        solver.set_potential(&potential);
      }
    if (mobility_source)
      {
        update(mobility_source, mobility_factor);
        solver.set_mobility(&mobility_factor);
      }
  }

  template <int dim>
  void
  SurfaceDiffusion<dim>::accept_step(const LevelSetField<dim> &)
  {
    lag_of_last_step.swap(previous_velocity);
    previous_velocity = solver.normal_velocity();
  }

  template <int dim>
  void
  SurfaceDiffusion<dim>::add_normal_velocity(const LevelSetField<dim> &alpha,
                                             VelocityField<dim> &velocity) const
  {
    TimerOutput::Scope scope(timer, "surface diffusion velocity");
    // Eq. 84: v = v_s N_alpha at each node. Both live on the level set's
    // vertices; the velocity space numbers them its own way.
    const auto &normals = solver.nodal_normals();
    const auto &v_s     = solver.normal_velocity();
    velocity.add_vertex_values(alpha.dof_handler(),
                               [&](const auto &cell, const unsigned int v) {
      const auto     i = cell->vertex_dof_index(v, 0);
      Tensor<1, dim> value;
      for (unsigned int c = 0; c < dim; ++c)
        value[c] = v_s(i) * normals[c](i);
      return value;
    });
  }

  template <int dim>
  std::vector<std::string>
  SurfaceDiffusion<dim>::metric_names() const
  {
    return {"surface_diffusion_iterations",
            "surface_diffusion_solve_cpu_time"};
  }

  template <int dim>
  std::vector<double>
  SurfaceDiffusion<dim>::metric_values() const
  {
    return {double(iterations), solver.solve_cpu_time};
  }

  template class SurfaceDiffusion<2>;
  template class SurfaceDiffusion<3>;
} // namespace levelsinter
