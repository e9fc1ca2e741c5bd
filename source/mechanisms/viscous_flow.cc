#include <deal.II/base/timer.h>

#include <deal.II/fe/fe_values.h>

#include <deal.II/numerics/vector_tools.h>

#include <levelsinter/geometry/redistanced_level_set.h>
#include <levelsinter/level_set/cell_size.h>
#include <levelsinter/level_set/ghosted_vector.h>
#include <levelsinter/level_set/interface_measures.h>
#include <levelsinter/mechanisms/viscous_flow.h>

#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>

namespace levelsinter
{
  template <int dim>
  ViscousFlow<dim>::ViscousFlow(
    const ViscousFlowParameters           &parameters,
    const MaterialsParameters             &materials,
    const std::vector<types::boundary_id> &symmetry_planes,
    const LevelSetFilter                  &filter,
                                const unsigned int           band_level,
                                TimerOutput                 &timer,
                                const PhaseLawParameters    &law)
    : parameters(parameters)
    , materials(materials)
    , symmetry_planes(symmetry_planes)
    , filter(filter)
    , band_level(band_level)
    , timer(timer)
    , viscoelastic(law.is_viscoelastic() ?
                     std::make_unique<ViscoelasticState<dim>>(
                       law, filter, parameters.interface_half_width, band_level) :
                     nullptr)
    , phases(make_phase_law<dim>(law, parameters, materials, viscoelastic.get()))
    , zero_shear_viscosity(parameters.solid_viscosity +
                           (law.is_viscoelastic() ? law.polymer_viscosity : 0))
    , relaxation_time(law.is_viscoelastic() ? law.relaxation_time : 0)
  {
    // SceneParameters refuses the elastic solid with viscous flow.
    if (law.law == PhaseLawParameters::Law::elastic_solid)
      throw std::logic_error("viscous flow with the elastic-solid law");
  }

  template <int dim>
  void
  ViscousFlow<dim>::setup(const LevelSetField<dim> &alpha)
  {
    const auto &tria = alpha.dof_handler().get_triangulation();
    h_min = finest_cell_size(tria);
    const auto settings =
      TwoPhaseStokes<dim>::Settings::from(parameters,
                                          materials,
                                          symmetry_planes,
                                          band_level);
    using Form = typename TwoPhaseStokes<dim>::SurfaceTensionForm;
    // The DoFHandler is tied to the triangulation, which the time loop
    // builds after the mechanisms: create the operator on first use.
    operator_ =
      make_velocity_pressure_operator(tria, settings, *phases, parameters);
    operator_->setup_dofs();
    if (viscoelastic)
      viscoelastic->setup(alpha);

    if (settings.form == Form::csf_curvature ||
        settings.form == Form::sharp_curvature)
      {
        kappa.reinit(alpha.locally_owned(),
                     alpha.locally_relevant(),
                     alpha.dof_handler().get_communicator());
        if (!exact_curvature)
          {
            // kappa only (no surface Laplacian): the decoupled mode with a
            // zero coefficient is one mass-matrix solve.
            typename MixedCurvatureSolver<dim>::Settings curvature_settings;
            curvature_settings.coupled               = false;
            curvature_settings.tolerance             = 1e-10;
            curvature_settings.normals_from_distance = true;
            curvature_settings.symmetry_boundaries   = symmetry_planes;
            curvature_solver = std::make_unique<MixedCurvatureSolver<dim>>(
              filter, curvature_settings, timer);
            curvature_solver->setup(alpha);
          }
      }
  }

  template <int dim>
  void
  ViscousFlow<dim>::update_curvature(const LevelSetField<dim> &alpha)
  {
    const MPI_Comm                comm = alpha.dof_handler().get_communicator();
    // H_h reaches ceil(E / h) cell layers from the cut cells, and the
    // normals of its outermost nodes one layer more (doc/numerics.md, "The
    // level set the form reads").
    interface_level_set = redistanced_level_set(
      alpha,
      filter,
      static_cast<unsigned int>(std::ceil(parameters.interface_half_width)) +
        1);
    TrilinosWrappers::MPI::Vector owned(alpha.locally_owned(), comm);
    if (exact_curvature)
      {
        VectorTools::interpolate(alpha.dof_handler(), *exact_curvature, owned);
        kappa = owned;
      }
    else
      {
        // kappa_h = L2 projection of div N_alpha (Eq. 80 at dt = 0, nodal
        // normals Eq. 84) in the band, with the azimuthal N_r / r on a body
        // of revolution. At a node a distance d off the interface that is
        // the curvature of the level set through the node,
        // kappa(d) = kappa_0 / (1 + d kappa_0 / (n - 1)) for a circle or
        // sphere (n = 2, 3 the body's dimension, 3 on a body of
        // revolution); the balanced force needs the interface value kappa_0
        // carried along the normal, so invert that relation.
        curvature_solver->solve(
          alpha, interface_level_set, 0, 0, TrilinosWrappers::MPI::Vector());
        const auto  &projected = curvature_solver->curvature();
        const double principal_curvatures =
          alpha.measure().template body_dimension<dim>() - 1.;
        for (const auto i : alpha.locally_owned())
          {
            const double k = projected(i);
            const double d = filter.distance(interface_level_set(i));
            owned(i) = k / std::max(1 - d * k / principal_curvatures, 0.5);
          }
        kappa = ghosted_from_owned(owned,
                                   alpha.constraints(),
                                   alpha.locally_relevant());
      }
  }

  template <int dim>
  void
  ViscousFlow<dim>::add_velocity(const LevelSetField<dim> &alpha,
                                 const double,
                                 const double        dt,
                                 VelocityField<dim> &velocity)
  {
    if (materials.surface_tension > 0 && parameters.external_pressure == 0 &&
        !step_started)
      {
        measures_at_step_start = interface_measures::volume_and_area(alpha);
        step_started           = true;
      }
    solve_velocity(alpha, dt, velocity);
  }

  template <int dim>
  void
  ViscousFlow<dim>::add_probe_velocity(const LevelSetField<dim> &alpha,
                                       const double,
                                       VelocityField<dim> &velocity)
  {
    solve_velocity(alpha, 0, velocity);
  }

  template <int dim>
  void
  ViscousFlow<dim>::solve_velocity(const LevelSetField<dim> &alpha,
                                   const double              dt,
                                   VelocityField<dim>       &velocity)
  {
    if (kappa.size() > 0)
      {
        TimerOutput::Scope scope(timer, "viscous flow: curvature");
        update_curvature(alpha);
      }
    phases->set_time_step(dt);
    {
      TimerOutput::Scope scope(timer, "viscous flow: assembly");
      operator_->fit_to(alpha);
      operator_->assemble(alpha,
                          kappa,
                          interface_level_set,
                          parameters.semi_implicit_surface_tension ? dt : 0.);
    }
    {
      TimerOutput::Scope scope(timer, "viscous flow: solve");
      Timer cpu_timer(alpha.dof_handler().get_communicator());
      last_iterations = operator_->solve();
      last_solve_cpu  = cpu_timer.cpu_time(); // summed over the ranks
    }
    operator_->remove_rigid_motion(alpha);

    operator_->add_vertex_velocities(velocity);

    // The melt's conformation follows the velocity just solved for (the
    // scene's velocity so far: this and any prescribed one).
    if (viscoelastic && dt > 0)
      {
        TimerOutput::Scope scope(timer, "viscous flow: conformation");
        viscoelastic->advance(alpha, velocity, dt);
      }
  }

  template <int dim>
  void
  ViscousFlow<dim>::accept_step(const LevelSetField<dim> &alpha)
  {
    step_started = false;
    if (viscoelastic)
      viscoelastic->accept(alpha);
  }

  template <int dim>
  void
  ViscousFlow<dim>::reject_step()
  {
    if (viscoelastic)
      viscoelastic->reject();
  }

  template <int dim>
  void
  ViscousFlow<dim>::add_state(const LevelSetField<dim> &,
                              StateTransfer<dim>       &transfer)
  {
    // The committed state: the time loop accepted the last step
    // (accept_step()), or it stops after a failed one.
    if (viscoelastic)
      viscoelastic->add_state(transfer);
  }

  template <int dim>
  std::vector<std::string>
  ViscousFlow<dim>::metric_names() const
  {
    std::vector<std::string> names = {"stokes_iterations", "stokes_solve_cpu"};
    if (viscoelastic)
      for (const auto &name : viscoelastic->metric_names())
        names.push_back(name);
    return names;
  }

  template <int dim>
  std::vector<double>
  ViscousFlow<dim>::metric_values() const
  {
    std::vector<double> values = {double(last_iterations), last_solve_cpu};
    if (viscoelastic)
      for (const double value : viscoelastic->metric_values())
        values.push_back(value);
    return values;
  }

  template <int dim>
  std::vector<std::string>
  ViscousFlow<dim>::point_metric_names() const
  {
    if (viscoelastic)
      return viscoelastic->point_metric_names();
    return {};
  }

  template <int dim>
  std::vector<double>
  ViscousFlow<dim>::point_metric_values(const LevelSetField<dim> &alpha,
                                        const Point<dim>         &point) const
  {
    if (viscoelastic)
      return viscoelastic->point_metric_values(alpha, point);
    return {};
  }

  template <int dim>
  void
  ViscousFlow<dim>::add_output_fields(const LevelSetField<dim> &alpha,
                                      DataOut<dim>             &data_out) const
  {
    std::vector<std::string> names(dim, "viscous_flow_velocity");
    std::vector<DataComponentInterpretation::DataComponentInterpretation>
      interpretation(dim,
                     DataComponentInterpretation::component_is_part_of_vector);
    for (const auto &name : operator_->pressure_names("viscous_flow"))
      {
        names.push_back(name);
        interpretation.push_back(
          DataComponentInterpretation::component_is_scalar);
      }
    data_out.add_data_vector(operator_->dof_handler(),
                             operator_->solution(),
                             names,
                             interpretation);
    if (kappa.size() > 0)
      data_out.add_data_vector(alpha.dof_handler(),
                               kappa,
                               "viscous_flow_curvature");
    if (viscoelastic)
      viscoelastic->add_output_fields(alpha, data_out);
  }

  template <int dim>
  void
  ViscousFlow<dim>::check_step(const LevelSetField<dim> &alpha)
  {
    if (measures_at_step_start.interface_area == 0)
      return;
    // 0.1 %: stable steps never raise the measure, an unstable one raises
    // it by about 1 % (doc/numerics.md, "Step rejection by surface
    // energy"). A step that also gained volume (the volume correction moves
    // the interface outwards) may grow the measure legitimately: it is
    // rejected only if the scale-free measure S / V^((dim-1)/dim), which a
    // uniform normal offset of a sphere leaves unchanged, grew as well.
    const auto   start    = measures_at_step_start;
    const auto   end      = interface_measures::volume_and_area(alpha);
    const double body_dim = alpha.measure().template body_dimension<dim>();
    const double exponent = (body_dim - 1) / body_dim;
    const auto   scale_free = [exponent](const auto &m) {
      return m.interface_area / std::pow(m.solid_volume, exponent);
    };
    const double area = end.interface_area;
    if (area > (1 + 1e-3) * start.interface_area &&
        scale_free(end) > (1 + 1e-3) * scale_free(start))
      {
        std::ostringstream message;
        message << "viscous flow: the interface measure grew from "
                << start.interface_area << " to " << area
                << " in one step, also relative to the solid volume, but a "
                << "capillary Stokes flow only lowers "
                << "the surface energy: the explicit surface tension is "
                << "unstable at this dt (lower 'Capillary time step factor' "
                << "or use 'Surface tension time integration = "
                << "semi-implicit')";
        throw std::runtime_error(message.str());
      }
  }

  template <int dim>
  double
  ViscousFlow<dim>::time_step_limit(const LevelSetField<dim> &) const
  {
    if (parameters.capillary_time_step_factor == 0 ||
        materials.surface_tension == 0 ||
        parameters.semi_implicit_surface_tension)
      return std::numeric_limits<double>::infinity();
    const double a = parameters.capillary_time_step_factor * h_min /
                     materials.surface_tension;
    if (relaxation_time == 0)
      return a * zero_shear_viscosity;
    // A viscoelastic melt resists a step dt with the viscosity of its
    // implicit polymer stress, eta_s + eta_p dt / (lambda + dt), not eta_0
    // (doc/numerics.md, "Capillary time-step limit"): the largest
    // dt <= a (eta_s + eta_p dt / (lambda + dt)) is the positive root of
    // dt^2 + b dt - a eta_s lambda with b = lambda - a eta_0 (eta_0 as
    // lambda -> 0, a eta_s for lambda >> a eta_0).
    const double eta_s = parameters.solid_viscosity;
    const double b     = relaxation_time - a * zero_shear_viscosity;
    const double c     = 4 * a * eta_s * relaxation_time;
    return b > 0 ? 2 * a * eta_s * relaxation_time / (b + std::sqrt(b * b + c)) :
                   (-b + std::sqrt(b * b + c)) / 2;
  }

  template class ViscousFlow<2>;
  template class ViscousFlow<3>;
} // namespace levelsinter
