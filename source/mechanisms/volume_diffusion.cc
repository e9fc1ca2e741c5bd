#include <deal.II/base/mpi.h>

#include <deal.II/dofs/dof_tools.h>

#include <levelsinter/level_set/cell_size.h>
#include <levelsinter/mechanisms/volume_diffusion.h>

#include <iostream>

namespace levelsinter
{
  namespace
  {
    // c of the explicit limit dt <= c h^3 / ((2/3)(1 + nu) C_v gamma): the
    // largest stable step of the perturbed cylinder R = 0.25 with lambda =
    // 6 cells (study_vd_stiffness_2d, doc/validation.md "Volume diffusion:
    // explicit stability limit"): c = 152, 141, 130 at h = 1/64, 1/128,
    // 1/256 (the first unstable steps 176, 163, 150); the least.
    constexpr double measured_limit = 130;

    // The same c with xi as the boundary flux ('Pressure gradient = flux',
    // the solid pressure with ghost penalty 10): stable dt* = 5.6e-4,
    // unstable 6.5e-4 at h = 1/128 (doc/validation.md, "Volume diffusion:
    // xi as the boundary flux"), c = 16. Read at the interface, xi moves
    // modes up to n ~ R / h that lambda = 6 cells filters out; measured at
    // this h only.
    constexpr double measured_flux_limit = 16;
    // With `Elastic state = total` (ghost penalty 1): stable dt* = 2.05e-4,
    // unstable 2.37e-4 at h = 1/128 (doc/validation.md, "Volume diffusion:
    // the elastic state in the cut cells"), c = 5.9. The incremental
    // form's fading penalty smooths xi over the steps, which this form
    // does not.
    constexpr double measured_total_flux_limit = 5.9;

    // The first dim components of a velocity-pressure vector as one vector
    // field.
    template <int dim>
    class VelocityBlock : public DataPostprocessorVector<dim>
    {
    public:
      explicit VelocityBlock(const std::string &name)
        : DataPostprocessorVector<dim>(name, update_values)
      {}

      void
      evaluate_vector_field(
        const DataPostprocessorInputs::Vector<dim> &inputs,
        std::vector<dealii::Vector<double>>        &computed) const override
      {
        for (unsigned int q = 0; q < computed.size(); ++q)
          for (unsigned int d = 0; d < dim; ++d)
            computed[q](d) = inputs.solution_values[q](d);
      }
    };

    template <int dim>
    typename NormalGradientExtension<dim>::Settings
    extension_settings(const VolumeDiffusionParameters       &p,
                       const std::vector<types::boundary_id> &symmetry_planes)
    {
      typename NormalGradientExtension<dim>::Settings s;
      s.interior_offset      = p.interior_offset;
      s.linear_extrapolation = p.linear_extrapolation;
      s.limited_extrapolation = p.limited_extrapolation;
      s.recovered_gradient   = p.recovered_gradient;
      s.boundary_flux        = p.boundary_flux;
      s.solver_tolerance     = p.solver_tolerance;
      s.max_iterations       = p.max_iterations;
      s.symmetry_boundaries  = symmetry_planes;
      return s;
    }
  } // namespace

  template <int dim>
  VolumeDiffusion<dim>::VolumeDiffusion(
    const VolumeDiffusionParameters       &parameters,
    const double                           seconds_per_time_unit,
    const ViscousFlowParameters           &mechanics,
    const MaterialsParameters             &materials,
    const PhaseLawParameters              &law,
    const std::vector<types::boundary_id> &symmetry_planes,
    const LevelSetFilter                  &filter,
    const unsigned int                     band_level,
    TimerOutput                           &timer)
    : coefficient(parameters.mobility() * seconds_per_time_unit)
    , seconds_per_time_unit(seconds_per_time_unit)
    , settings(TwoPhaseStokes<dim>::Settings::from(mechanics,
                                                   materials,
                                                   symmetry_planes,
                                                   band_level))
    , mechanics_parameters(mechanics)
    , phases(make_phase_law<dim>(law, mechanics, materials))
    , probe_step(materials.fluid_viscosity / (1e-5 * law.shear_modulus))
    , limit_per_h3([&]() {
      const double G = law.shear_modulus, K = law.bulk_modulus;
      const double nu = (3 * K - 2 * G) / (2 * (3 * K + G));
      // s_n = (2/3)(1 + nu) C_v gamma n (n^2 - 1) / R^3 (doc/numerics.md):
      // the decay rate of the finest modes, n ~ R / h, is proportional to
      // (2/3)(1 + nu) C_v gamma / h^3.
      return parameters.time_step_factor *
             (!parameters.boundary_flux        ? measured_limit :
              parameters.total_elastic_state ? measured_total_flux_limit :
                                               measured_flux_limit) /
             (2. / 3 * (1 + nu) * coefficient * materials.surface_tension);
    }())
    , timer(timer)
    , extension(filter,
                extension_settings<dim>(parameters, symmetry_planes),
                timer)
    , solve_interval(parameters.solve_interval)
    , total_elastic_state(parameters.total_elastic_state)
  {
    // The paper's Eq. 108 on {alpha_h = 0}: the Laplace jump stays in the
    // cut cells, clear of the nodes where xi reads grad p.
    settings.form = TwoPhaseStokes<dim>::SurfaceTensionForm::sharp;
    // The atmosphere here only lets the solid's surface move: no stress of
    // its own is read.
    settings.void_atmosphere = true;
  }

  template <int dim>
  void
  VolumeDiffusion<dim>::setup(const LevelSetField<dim> &alpha)
  {
    // The DoFHandler is tied to the triangulation, which the time loop
    // builds after the mechanisms: create the problem on first use and
    // keep it (and its DoFHandler, which the state transfer refers to).
    if (!operator_)
      operator_ = make_velocity_pressure_operator(
        alpha.dof_handler().get_triangulation(),
        settings,
        *phases,
        mechanics_parameters);
    operator_->setup_dofs();
    must_solve = true;
    extension.setup(alpha);
    h_min = finest_cell_size(alpha.dof_handler().get_triangulation());
  }

  template <int dim>
  void
  VolumeDiffusion<dim>::accept_step(const LevelSetField<dim> &)
  {
    // Delta u = dt v of the solve the step used, also when a shorter step
    // kept it (shorten_step()); once per solve. With the total state u
    // stays 0: in linear elasticity with the surface traction alone the
    // stress is that of the current shape whatever the path, and the ghost
    // penalty then holds the whole displacement, not only its last
    // increment (doc/numerics.md).
    if (solved_in_step && !total_elastic_state)
      operator_->advance_displacement(solved_step);
    solved_in_step = false;
    ++steps_since_solve;
  }

  template <int dim>
  void
  VolumeDiffusion<dim>::reject_step()
  {
    keep_solve     = false;
    solved_in_step = false;
    must_solve     = true;
  }

  template <int dim>
  void
  VolumeDiffusion<dim>::shorten_step()
  {
    keep_solve = phases->pressure_independent_of_step();
  }

  template <int dim>
  void
  VolumeDiffusion<dim>::add_state(const LevelSetField<dim> &,
                                  StateTransfer<dim>       &transfer)
  {
    transfer.add(operator_->dof_handler(), {&operator_->displacement()});
  }

  template <int dim>
  void
  VolumeDiffusion<dim>::add_velocity(const LevelSetField<dim> &alpha,
                                     const double              t,
                                     const double              dt,
                                     VelocityField<dim>       &velocity)
  {
    if (!keep_solve && (must_solve || steps_since_solve >= solve_interval))
      {
        solved_step = dt * seconds_per_time_unit;
        solve(alpha, t, solved_step);
        solved_in_step    = true;
        steps_since_solve = 0;
        must_solve        = false;
      }
    keep_solve = false;
    add_diffusion_velocity(alpha, velocity);
  }

  template <int dim>
  void
  VolumeDiffusion<dim>::add_probe_velocity(const LevelSetField<dim> &alpha,
                                           const double              t,
                                           VelocityField<dim> &velocity)
  {
    keep_solve = false;
    must_solve = true;
    solve(alpha, t, probe_step);
    add_diffusion_velocity(alpha, velocity);
  }

  template <int dim>
  void
  VolumeDiffusion<dim>::solve(const LevelSetField<dim> &alpha,
                              const double              t,
                              const double              step_seconds)
  {
    phases->set_time_step(step_seconds);
    {
      TimerOutput::Scope scope(timer, "volume diffusion: elastic set-up");
      operator_->fit_to(alpha);
    }
    {
      TimerOutput::Scope scope(timer, "volume diffusion: elastic assembly");
      operator_->assemble(alpha,
                          TrilinosWrappers::MPI::Vector(),
                          TrilinosWrappers::MPI::Vector(),
                          0);
    }
    {
      TimerOutput::Scope scope(timer, "volume diffusion: elastic solve");
      mechanics_iterations = operator_->solve();
    }

    const unsigned int unsourced_before = extension.unsourced_interface_cells();
    // The solid's pressure (its own where each phase has one).
    xi_iterations =
      extension.solve(alpha,
                      operator_->dof_handler(),
                      operator_->pressure_component(Phase::solid),
                      operator_->plain_solution());
    const unsigned int unsourced = extension.unsourced_interface_cells();
    if (unsourced > 0 && unsourced_before == 0 && !warned_unsourced)
      {
        warned_unsourced = true;
        if (Utilities::MPI::this_mpi_process(
              alpha.dof_handler().get_communicator()) == 0)
          std::cout
            << "warning: t = " << t << ": " << unsourced
            << " interface cells have no node deep enough in the solid to "
            << "read xi from (the solid, or the refined band on its side, "
            << "is thinner than about 2 lambda); volume diffusion is off "
            << "there. Measured on 8 spheres like the 154 packing: such "
            << "cells grow to 4 % of the interface by t = 0.01 s and cost "
            << "0.37 % of the relative density; refine there, widen "
            << "'Level set/Filter thickness' and 'Mesh refinement/Band "
            << "width', or lower 'Volume diffusion/Interior offset' "
            << "(doc/validation.md, \"Packings: interface cells without a "
            << "xi source\")" << std::endl;
      }
  }

  template <int dim>
  void
  VolumeDiffusion<dim>::add_diffusion_velocity(
    const LevelSetField<dim> &alpha,
    VelocityField<dim>       &velocity) const
  {
    TimerOutput::Scope scope(timer, "volume diffusion velocity");
    // Eq. 112 at each level-set node.
    velocity.add_vertex_values(alpha.dof_handler(),
                               [&](const auto &cell, const unsigned int v) {
      return extension.velocity(cell->vertex_dof_index(v, 0), coefficient);
    });
  }

  template <int dim>
  double
  VolumeDiffusion<dim>::time_step_limit(const LevelSetField<dim> &) const
  {
    if (limit_per_h3 == 0)
      return std::numeric_limits<double>::infinity();
    return limit_per_h3 * h_min * h_min * h_min;
  }

  template <int dim>
  void
  VolumeDiffusion<dim>::add_output_fields(const LevelSetField<dim> &alpha,
                                          DataOut<dim> &data_out) const
  {
    using Interpretation =
      DataComponentInterpretation::DataComponentInterpretation;
    std::vector<Interpretation> interpretation(
      dim, DataComponentInterpretation::component_is_part_of_vector);

    // The elastic velocity rate and the pressure of the last solve.
    std::vector<std::string> names(dim, "volume_diffusion_elastic_velocity");
    for (const auto &name : operator_->pressure_names("volume_diffusion"))
      {
        names.push_back(name);
        interpretation.push_back(
          DataComponentInterpretation::component_is_scalar);
      }
    data_out.add_data_vector(operator_->dof_handler(),
                             operator_->solution(),
                             names,
                             interpretation);
    // u^{n-1}.
    output_displacement =
      std::make_unique<VelocityBlock<dim>>("volume_diffusion_displacement");
    data_out.add_data_vector(operator_->dof_handler(),
                             operator_->displacement(),
                             *output_displacement);
    data_out.add_data_vector(alpha.dof_handler(),
                             extension.normal_gradient(),
                             "volume_diffusion_xi");
    // v = -C_v xi N (Eq. 112) as add_velocity() hands it over, before the
    // volume correction; DataOut reads it when it builds the patches.
    output_velocity = std::make_unique<VelocityField<dim>>(
      dynamic_cast<const parallel::distributed::Triangulation<dim> &>(
        alpha.dof_handler().get_triangulation()));
    output_velocity->setup_dofs();
    output_velocity->add_vertex_values(
      alpha.dof_handler(), [&](const auto &cell, const unsigned int v) {
        return extension.velocity(cell->vertex_dof_index(v, 0), coefficient);
      });
    data_out.add_data_vector(
      output_velocity->dof_handler(),
      output_velocity->values(),
      std::vector<std::string>(dim, "volume_diffusion_velocity"),
      std::vector<Interpretation>(
        dim, DataComponentInterpretation::component_is_part_of_vector));
  }

  template class VolumeDiffusion<2>;
  template class VolumeDiffusion<3>;
} // namespace levelsinter
