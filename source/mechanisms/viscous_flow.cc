#include <deal.II/base/mpi.h>

#include <deal.II/grid/grid_tools.h>

#include <levelsinter/mechanisms/viscous_flow.h>

#include <cmath>
#include <ctime>
#include <limits>

namespace levelsinter
{
  template <int dim>
  ViscousFlow<dim>::ViscousFlow(const ViscousFlowParameters &parameters,
                                TimerOutput                 &timer)
    : parameters(parameters)
    , timer(timer)
    , phases(parameters.solid_viscosity,
             parameters.fluid_viscosity,
             parameters.fluid_compressibility)
  {}

  template <int dim>
  void
  ViscousFlow<dim>::setup(const LevelSetField<dim> &alpha)
  {
    const auto &tria = alpha.dof_handler().get_triangulation();
    h_min = GridTools::minimal_cell_diameter(tria) / std::sqrt(double(dim));
    typename TwoPhaseStokes<dim>::Settings settings;
    settings.surface_tension = parameters.surface_tension;
    settings.form =
      parameters.surface_tension_form == "csf" ?
        TwoPhaseStokes<dim>::SurfaceTensionForm::csf :
        TwoPhaseStokes<dim>::SurfaceTensionForm::sharp;
    settings.interface_half_width   = parameters.interface_half_width * h_min;
    settings.stabilisation_constant = parameters.stabilisation_constant;
    settings.external_pressure      = parameters.external_pressure;
    settings.symmetry_boundaries    = parameters.symmetry_boundaries;
    settings.direct_solver          = parameters.direct_solver;
    settings.tolerance              = parameters.solver_tolerance;
    settings.max_iterations         = parameters.max_iterations;
    // The DoFHandler is tied to the triangulation, which the time loop
    // builds after the mechanisms: create the operator on first use.
    operator_ = std::make_unique<TwoPhaseStokes<dim>>(tria, settings, phases);
    operator_->setup_dofs();
  }

  template <int dim>
  void
  ViscousFlow<dim>::add_velocity(const LevelSetField<dim> &alpha,
                                 const double,
                                 const double,
                                 VelocityField<dim> &velocity)
  {
    {
      TimerOutput::Scope scope(timer, "viscous flow: assembly");
      operator_->assemble(alpha);
    }
    {
      TimerOutput::Scope scope(timer, "viscous flow: solve");
      const std::clock_t start = std::clock();
      last_iterations          = operator_->solve();
      last_solve_cpu           = Utilities::MPI::sum(
        double(std::clock() - start) / CLOCKS_PER_SEC,
        alpha.dof_handler().get_communicator());
    }

    // Same mesh, Q1 in both spaces: hand the nodal velocity over vertex by
    // vertex (the first dim vertex DoFs of the Stokes element are the
    // velocity components).
    const auto &stokes_dofs = operator_->dof_handler();
    const auto &solution    = operator_->solution();
    velocity.add_vertex_values([&](const auto &velocity_cell,
                                   const unsigned int v) {
      const typename DoFHandler<dim>::active_cell_iterator cell(
        &velocity_cell->get_triangulation(),
        velocity_cell->level(),
        velocity_cell->index(),
        &stokes_dofs);
      Tensor<1, dim> value;
      for (unsigned int c = 0; c < dim; ++c)
        value[c] = solution(cell->vertex_dof_index(v, c));
      return value;
    });
  }

  template <int dim>
  double
  ViscousFlow<dim>::time_step_limit(const LevelSetField<dim> &) const
  {
    if (parameters.capillary_time_step_factor == 0 ||
        parameters.surface_tension == 0)
      return std::numeric_limits<double>::infinity();
    return parameters.capillary_time_step_factor *
           parameters.solid_viscosity * h_min / parameters.surface_tension;
  }

  template class ViscousFlow<2>;
  template class ViscousFlow<3>;
} // namespace levelsinter
