#include <deal.II/base/function.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/timer.h>
#include <deal.II/base/utilities.h>

#include <levelsinter/analysis/reference_shapes.h>
#include <levelsinter/analysis/scene_postprocessors.h>
#include <levelsinter/grid/box_mesh.h>
#include <levelsinter/io/checkpoint.h>
#include <levelsinter/level_set/cell_size.h>
#include <levelsinter/mechanisms/scene_mechanisms.h>
#include <levelsinter/time/simulation.h>

#include <boost/archive/text_iarchive.hpp>
#include <boost/archive/text_oarchive.hpp>
#include <boost/serialization/map.hpp>
#include <boost/serialization/string.hpp>

#include <algorithm>
#include <cmath>
#include <csignal>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <optional>
#include <sstream>
#include <stdexcept>

namespace levelsinter
{
  namespace
  {
    // The signal that asked the run to stop; see stop_on_signals().
    volatile std::sig_atomic_t stop_signal = 0;
    // When it came (CLOCK_MONOTONIC seconds).
    volatile std::sig_atomic_t stop_signal_time = 0;

    extern "C" void
    record_stop_signal(const int signal)
    {
      // One request often arrives twice: `timeout` and job schedulers
      // signal the process and then its whole process group. A repeat
      // within two seconds is that same request; a later one is a user
      // insisting, and kills as the default action would.
      // (clock_gettime, signal and raise are async-signal-safe.)
      timespec now;
      clock_gettime(CLOCK_MONOTONIC, &now);
      if (stop_signal == 0)
        {
          stop_signal      = signal;
          stop_signal_time = static_cast<std::sig_atomic_t>(now.tv_sec);
        }
      else if (now.tv_sec - stop_signal_time > 2)
        {
          std::signal(signal, SIG_DFL);
          std::raise(signal);
        }
    }

    std::string
    format_seconds(const double s)
    {
      std::ostringstream out;
      if (s < 120)
        out << std::fixed << std::setprecision(1) << s << " s";
      else if (s < 7200)
        out << std::fixed << std::setprecision(1) << s / 60 << " min";
      else
        out << std::fixed << std::setprecision(1) << s / 3600 << " h";
      return out.str();
    }
  } // namespace

  void
  stop_on_signals()
  {
    struct sigaction action = {};
    action.sa_handler       = record_stop_signal;
    action.sa_flags         = 0;
    sigemptyset(&action.sa_mask);
    sigaction(SIGINT, &action, nullptr);
    sigaction(SIGTERM, &action, nullptr);
    // Open MPI's mpirun passes SIGUSR1 on to every rank and then reports
    // their exit code; SIGTERM or SIGINT it answers by exiting 1 and
    // killing the ranks a second later (doc/user_guide.md, "Exit codes").
    sigaction(SIGUSR1, &action, nullptr);
  }

  template <int dim>
  Simulation<dim>::Simulation(const SceneParameters &scene,
                              const MPI_Comm         comm,
                              std::ostream          &progress_stream)
    : scene(scene)
    , comm(comm)
    , pcout(progress_stream, Utilities::MPI::this_mpi_process(comm) == 0)
    // CPU per section as well: wall times mean little on shared cores.
    , timer_output(comm,
                   pcout,
                   TimerOutput::never,
                   TimerOutput::cpu_and_wall_times)
    , tria(comm,
           Triangulation<dim>::limit_level_difference_at_vertices)
    , level_set_filter(scene.level_set.filter, scene.level_set.filter_thickness)
    , alpha(tria, SceneMeasure(scene.geometry.axisymmetric))
    , velocity(tria)
    , correction_velocity(tria)
    , mechanisms(make_scene_mechanisms<dim>(scene, timer_output))
    , curvature_driven(
        std::any_of(mechanisms.begin(), mechanisms.end(), [](const auto &m) {
          return m->curvature_driven();
        }))
    , initial_distance(make_initial_signed_distance<dim>(scene))
    , band_refinement(scene.refinement,
                      level_set_filter,
                      scene.domain.symmetry_planes)
    , transport(level_set_filter,
                {scene.level_set.theta,
                 scene.level_set.solver_tolerance,
                 scene.level_set.max_iterations,
                 scene.level_set.reinitialization_strength,
                 scene.level_set.reinitialization_diffusion,
                 scene.level_set.reinitialization_tolerance,
                 scene.level_set.solid_reinitialization_from_band ?
                   scene.band_cell_size() :
                   0.,
                 scene.level_set.reinitialization_pace ==
                   LevelSetParameters::ReinitializationPace::interface_motion},
                timer_output)
    , postprocessors(make_scene_postprocessors<dim>(scene,
                                                    mechanisms,
                                                    curvature_driven,
                                                    comm,
                                                    timer_output))
    , metrics_interval{scene.output.metrics_interval, true, true}
    , field_interval{scene.output.field_interval, true, true}
    , progress_interval{scene.output.progress_interval, false, true}
    , checkpoint_interval{scene.output.checkpoint_interval, false, false}
    , field_output(scene.output.directory,
                   scene.output.write_vtu,
                   scene.output.write_xdmf)
    , h_min(0)
  {
    if (scene.dimension != dim)
      throw std::logic_error("Simulation<dim> built for the wrong dimension");
    first_time = scene.time.start_time;
    for (const auto &warning : scene.warnings)
      pcout << "warning: " << warning << std::endl;
    if (scene.geometry.particles_are_bodies() &&
        scene.geometry.particles.size() >= 2)
      particle_ids =
        std::make_unique<ParticleIdField<dim>>(scene.geometry.particles);
    if (scene.viscous_flow.enabled && scene.viscous_flow.pore_closure_radius > 0)
      {
        Point<dim> lower, upper;
        for (unsigned int d = 0; d < dim; ++d)
          {
            lower[d] = scene.domain.lower_corner[d];
            upper[d] = scene.domain.upper_corner[d];
          }
        auto rule = std::make_unique<SmallPoreClosure<dim>>(
          scene.domain.symmetry_planes,
          BoundingBox<dim>(std::make_pair(lower, upper)),
          level_set_filter,
          scene.viscous_flow.pore_closure_radius,
          scene.materials.surface_tension /
            (2 * scene.viscous_flow.solid_viscosity));
        small_pores = rule.get();
        postprocessors.push_back(std::move(rule));
      }
  }

  template <int dim>
  void
  Simulation<dim>::refine_initial_mesh()
  {
    TimerOutput::Scope scope(timer_output, "mesh adaptation");
    make_box_mesh(tria, scene.domain);
    if (scene.refinement.min_level > 0)
      tria.refine_global(scene.refinement.min_level);
    const ScalarFunctionFromFunctionObject<dim> filtered(
      [this](const Point<dim> &p) {
        return level_set_filter.filter(initial_distance->value(p));
      });
    // Each pass refines the band by one level; the exact initial shape is
    // interpolated again on every new mesh rather than transferred.
    for (unsigned int pass = 0;; ++pass)
      {
        alpha.setup_dofs();
        alpha.interpolate(filtered);
        if (pass > band_refinement.finest_level() - scene.refinement.min_level ||
            !band_refinement.mark_cells(tria, alpha))
          break;
        tria.execute_coarsening_and_refinement();
      }
    check_particles_refined();
  }

  template <int dim>
  void
  Simulation<dim>::check_particles_refined() const
  {
    // The poles of each particle along the axes, where they lie on the
    // solid's surface (not inside another particle or cut away by a pore)
    // and in the box.
    std::vector<Point<dim>> poles;
    double                  smallest_radius = std::numeric_limits<double>::max();
    for (const auto &particle : scene.geometry.particles)
      {
        const double r  = particle[dim];
        smallest_radius = std::min(smallest_radius, r);
        for (unsigned int d = 0; d < dim; ++d)
          for (const double side : {-1., 1.})
            {
              Point<dim> p;
              for (unsigned int e = 0; e < dim; ++e)
                p[e] = particle[e];
              p[d] += side * r;
              bool inside = true;
              for (unsigned int e = 0; e < dim; ++e)
                inside = inside && p[e] > scene.domain.lower_corner[e] &&
                         p[e] < scene.domain.upper_corner[e];
              if (inside && std::abs(initial_distance->value(p)) < 1e-9 * r)
                poles.push_back(p);
            }
      }
    const auto missed = band_refinement.points_in_coarse_cells(tria, poles);
    if (missed.empty())
      return;
    std::ostringstream where;
    where << missed.front();
    throw std::runtime_error(
      "the initial mesh missed particles: " + std::to_string(missed.size()) +
      " of the " + std::to_string(poles.size()) +
      " points sampled on the particles' surfaces (their poles along the "
      "axes) lie in cells coarser than 'Mesh refinement/Maximum level', the "
      "first at (" + where.str() + "). The band is found level by level "
      "from the nodes, and no node of the coarse levels came within the band "
      "width of these particles. Raise 'Mesh refinement/Minimum level' (its "
      "cells are " +
      std::to_string(scene.domain.coarse_cell_size() /
                     std::pow(2., scene.refinement.min_level)) +
      " wide, the smallest particle radius is " +
      std::to_string(smallest_radius) + ") or widen 'Mesh refinement/Band "
      "width'.");
  }

  template <int dim>
  void
  Simulation<dim>::initialise()
  {
    refine_initial_mesh();
    velocity.setup_dofs();
    correction_velocity.setup_dofs();
    for (auto &mechanism : mechanisms)
      mechanism->setup(alpha);
    transport.setup_system(alpha);
    h_min = finest_cell_size(tria);
    initialised = true;
  }

  template <int dim>
  template <class Archive>
  void
  Simulation<dim>::archive_counters(Archive      &archive,
                                    unsigned int &step,
                                    double       &t)
  {
    // The step size comes from t and the last interface speed; the rest
    // continues metrics.csv, the field series and the summary.
    unsigned int metrics_rows = metrics ? metrics->n_rows() : 0;
    archive &step &t &interface_speed &total_iterations &last_iterations;
    archive &under_resolved_cells &resolved_again_reported;
    archive &summary.max_cells &summary.max_dofs &summary.rejected_steps;
    archive &summary.curvature_under_resolved_until;
    archive &metrics_rows &field_output;
    if (Archive::is_loading::value)
      kept_metrics_rows = metrics_rows;
    // The mechanisms' and postprocessors' own numbers (reference volumes,
    // pore tracking, centres, ...) by name.
    std::map<std::string, std::string> states;
    for (const auto &mechanism : mechanisms)
      states["mechanism/" + mechanism->name()] = mechanism->save();
    for (const auto &postprocessor : postprocessors)
      states["postprocessor/" + postprocessor->name()] = postprocessor->save();
    archive &states;
    const auto load = [&states](const std::string &key, auto &object) {
      const auto state = states.find(key);
      if (state != states.end() && !state->second.empty())
        object.load(state->second);
    };
    if (Archive::is_loading::value)
      {
        for (const auto &mechanism : mechanisms)
          load("mechanism/" + mechanism->name(), *mechanism);
        for (const auto &postprocessor : postprocessors)
          load("postprocessor/" + postprocessor->name(), *postprocessor);
      }
  }

  template <int dim>
  void
  Simulation<dim>::write_timing() const
  {
    if (scene.output.directory.empty())
      return;
    const auto wall  = timer_output.get_summary_data(TimerOutput::total_wall_time);
    const auto cpu   = timer_output.get_summary_data(TimerOutput::total_cpu_time);
    const auto calls = timer_output.get_summary_data(TimerOutput::n_calls);
    if (Utilities::MPI::this_mpi_process(comm) != 0)
      return;
    // Replaced whole each time, so a reader never sees half a table.
    const std::string file = scene.output.directory + "/timing.csv";
    {
      std::ofstream out(file + ".tmp");
      out << "section,calls,wall_seconds,cpu_seconds\n";
      for (const auto &[section, seconds] : wall)
        out << '"' << section << "\"," << calls.at(section) << ','
            << seconds << ',' << cpu.at(section) << '\n';
    }
    std::filesystem::rename(file + ".tmp", file);
  }

  template <int dim>
  void
  Simulation<dim>::write_checkpoint(const unsigned int step, const double t)
  {
    TimerOutput::Scope scope(timer_output, "checkpoint");
    const auto         begin = std::chrono::steady_clock::now();
    const std::string  folder =
      checkpoint::begin(scene.output.directory, step, comm);
    // alpha and the mechanisms' history, in the order resume() reads them.
    StateTransfer<dim> state;
    alpha.add_to(state);
    for (auto &mechanism : mechanisms)
      mechanism->add_state(alpha, state);
    state.prepare_for_serialization();
    tria.save(folder + "/mesh");
    if (Utilities::MPI::this_mpi_process(comm) == 0)
      {
        std::ofstream                 out(folder + "/counters.txt");
        boost::archive::text_oarchive archive(out);
        unsigned int                  s    = step;
        double                        time = t;
        archive_counters(archive, s, time);
        if (!out)
          throw std::runtime_error("cannot write '" + folder +
                                   "/counters.txt'");
      }
    const std::string final_folder =
      checkpoint::commit(scene.output.directory, step, comm);
    last_checkpoint = std::chrono::steady_clock::now();
    const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - begin)
        .count();
    if (Utilities::MPI::this_mpi_process(comm) == 0)
      pcout << "checkpoint " << final_folder << ": "
            << std::setprecision(3)
            << checkpoint::size(final_folder) / 1048576. << " MiB in "
            << seconds << " s" << std::endl;
  }

  template <int dim>
  bool
  Simulation<dim>::checkpoint_due(const unsigned int step) const
  {
    if (checkpoint_interval.due(step, false))
      return true;
    if (scene.output.checkpoint_minutes == 0)
      return false;
    // The slowest rank's clock, so that all ranks decide alike.
    const double seconds = Utilities::MPI::max(
      std::chrono::duration<double>(std::chrono::steady_clock::now() -
                                    last_checkpoint)
        .count(),
      comm);
    return seconds >= 60 * scene.output.checkpoint_minutes;
  }

  template <int dim>
  void
  Simulation<dim>::resume(const std::string &checkpoint_folder)
  {
    // Triangulation::load() wants the coarse mesh of the run.
    make_box_mesh(tria, scene.domain);
    tria.load(checkpoint_folder + "/mesh");
    alpha.setup_dofs();
    velocity.setup_dofs();
    correction_velocity.setup_dofs();
    for (auto &mechanism : mechanisms)
      mechanism->setup(alpha);
    transport.setup_system(alpha);
    StateTransfer<dim> state;
    alpha.add_to(state);
    for (auto &mechanism : mechanisms)
      mechanism->add_state(alpha, state);
    state.deserialize();
    h_min = finest_cell_size(tria);

    const std::string counters = checkpoint_folder + "/counters.txt";
    std::ifstream     in(counters);
    if (!in)
      throw std::runtime_error("cannot read '" + counters + "'");
    // boost names no file ("input stream error"); a checkpoint that
    // verified holds what was written, so this is a format mismatch.
    try
      {
        boost::archive::text_iarchive archive(in);
        archive_counters(archive, first_step, first_time);
      }
    catch (const std::exception &e)
      {
        throw std::runtime_error("cannot read '" + counters + "' (" +
                                 e.what() +
                                 "): it is not the counters of a "
                                 "levelsinter checkpoint of this version");
      }
    initialised = true;
  }

  template <int dim>
  void
  Simulation<dim>::set_level_set(const Function<dim> &filtered_level_set)
  {
    if (!initialised)
      initialise();
    alpha.interpolate(filtered_level_set);
  }

  template <int dim>
  void
  Simulation<dim>::adapt_mesh()
  {
    // alpha and the mechanisms' history, each on its own DoFHandler.
    StateTransfer<dim> state;
    {
      TimerOutput::Scope scope(timer_output, "mesh adaptation");
      if (!band_refinement.mark_cells(tria, alpha))
        return;
      alpha.add_to(state);
      for (auto &mechanism : mechanisms)
        mechanism->add_state(alpha, state);
      state.prepare_for_coarsening_and_refinement();
      tria.execute_coarsening_and_refinement();
      alpha.setup_dofs();
    }
    {
      // Reported apart: on large meshes building the sparsity patterns and
      // matrices costs more than refining and transferring.
      TimerOutput::Scope scope(timer_output, "system setup after adaptation");
      velocity.setup_dofs();
      correction_velocity.setup_dofs();
      for (auto &mechanism : mechanisms)
        mechanism->setup(alpha);
      transport.setup_system(alpha);
    }
    {
      TimerOutput::Scope scope(timer_output, "mesh adaptation");
      state.interpolate();
    }
    // Curvature refinement makes the finest cells come and go with the necks.
    h_min = finest_cell_size(tria);
  }

  template <int dim>
  void
  Simulation<dim>::add_output_fields(DataOut<dim> &data_out) const
  {
    for (const auto &mechanism : mechanisms)
      mechanism->add_output_fields(alpha, data_out);
    if (particle_ids)
      particle_ids->add_to(alpha, data_out);
  }

  template <int dim>
  void
  Simulation<dim>::check_curvature_resolution(const double t)
  {
    if (!curvature_driven)
      return;
    const auto resolution = band_refinement.curvature_resolution(alpha);
    // Said once each way: near the threshold the count can flicker between
    // adaptations; metrics.csv and the summary keep the whole history.
    const bool first_time = summary.curvature_under_resolved_until < 0;
    // The cost quoted is measured on two_grains_surface_diffusion_2d
    // (doc/user_guide.md, "Mesh refinement"); a corner (overlapping
    // particles) reads as curvature x h ~ 1.2 at any level, so only the
    // time it takes to round off can be shortened.
    if (resolution.under_resolved_cells > 0 && first_time)
      pcout << "warning: t = " << t << ": " << resolution.under_resolved_cells
            << " interface cells at the finest level are larger than the "
               "local curvature radius (largest curvature x h = "
            << resolution.max_curvature_times_h
            << "): the curvature-driven speed is too low there until the "
               "shape rounds off (a line says when; a corner where "
               "particles overlap is never resolved at the start). "
               "Measured at two grains' initial neck: 14 % smaller after "
               "20 steps without curvature levels than with 4; 'Mesh "
               "refinement/Curvature refinement levels' shorten this phase "
               "(doc/user_guide.md, \"Mesh refinement\")."
            << std::endl;
    else if (resolution.under_resolved_cells == 0 && under_resolved_cells > 0 &&
             !resolved_again_reported)
      {
        pcout << "t = " << t << ": the interface curvature is resolved again."
              << std::endl;
        resolved_again_reported = true;
      }
    if (resolution.under_resolved_cells > 0)
      summary.curvature_under_resolved_until = t;
    under_resolved_cells = resolution.under_resolved_cells;
  }

  template <int dim>
  double
  Simulation<dim>::speed_near_interface() const
  {
    // The CFL limit concerns the interface and the filter ramp around it;
    // far away alpha is saturated and constant.
    return velocity.max_norm_near_interface(alpha.dof_handler(),
                                            alpha.alpha(),
                                            0.999 *
                                              level_set_filter.saturation());
  }

  template <int dim>
  void
  Simulation<dim>::sum_velocities(
    const std::function<void(Mechanism<dim> &)> &add)
  {
    velocity.set_zero();
    for (auto &mechanism : mechanisms)
      add(*mechanism);
    interface_speed = speed_near_interface();
  }

  template <int dim>
  void
  Simulation<dim>::compute_interface_velocity(const double t, const double dt)
  {
    sum_velocities([&](Mechanism<dim> &mechanism) {
      mechanism.add_velocity(alpha, t, dt, velocity);
    });
  }

  template <int dim>
  void
  Simulation<dim>::probe_interface_velocity(const double t)
  {
    sum_velocities([&](Mechanism<dim> &mechanism) {
      mechanism.add_probe_velocity(alpha, t, velocity);
    });
  }

  template <int dim>
  void
  Simulation<dim>::reject_trial_step()
  {
    for (auto &mechanism : mechanisms)
      mechanism->reject_step();
  }

  template <int dim>
  void
  Simulation<dim>::shorten_trial_step()
  {
    for (auto &mechanism : mechanisms)
      mechanism->shorten_step();
  }

  template <int dim>
  unsigned int
  Simulation<dim>::correct_step(const double dt)
  {
    correction_velocity.set_zero();
    bool any = false;
    for (auto &mechanism : mechanisms)
      any = mechanism->add_correction_velocity(alpha, dt, correction_velocity) ||
            any;
    return any ? transport.advance(alpha,
                                   correction_velocity,
                                   dt,
                                   /*share=*/0.) :
                 0;
  }

  template <int dim>
  double
  Simulation<dim>::choose_time_step(const double t) const
  {
    double dt = std::numeric_limits<double>::max();
    // A relative step r grows the step with t: a neck x ~ t^(1/n) has no
    // time scale but t itself, so a fixed step is too coarse early and
    // wasteful late.
    if (scene.time.time_step > 0)
      dt = std::max(scene.time.time_step, scene.time.relative_time_step * t);
    for (const auto &mechanism : mechanisms)
      dt = std::min(dt, mechanism->time_step_limit(alpha));
    // The speed of the last velocity computed: the previous step's.
    const double v_max = interface_speed;
    if (scene.time.cfl > 0 && v_max > 0)
      dt = std::min(dt, scene.time.cfl * h_min / v_max);
    if (dt == std::numeric_limits<double>::max())
      throw std::runtime_error(
        "the velocity is zero everywhere at t = " + std::to_string(t) +
        " near the interface, so the CFL number cannot choose a time step: "
        "set Time/Time step");
    // Spread the remaining time evenly so that the run ends exactly at the
    // end time without a sliver of a last step.
    const double remaining = scene.time.end_time - t;
    const double n_steps   = std::ceil(remaining / dt - 1e-9);
    return remaining / std::max(1.0, n_steps);
  }

  template <int dim>
  void
  Simulation<dim>::record(const unsigned int step,
                          const double       t,
                          const double       dt,
                          const bool         final_step)
  {
    const unsigned int cells = tria.n_global_active_cells();
    const unsigned int dofs  = alpha.dof_handler().n_dofs();
    summary.max_cells        = std::max(summary.max_cells, cells);
    summary.max_dofs         = std::max(summary.max_dofs, dofs);
    const double wall =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start)
        .count();
    if (step > 0)
      remaining_time.add_step(t, dt, wall, dofs);

    if (metrics_interval.due(step, final_step))
      {
        TimerOutput::Scope    scope(timer_output, "metrics");
        const StepRecord<dim> step_record{step,
                                          t,
                                          dt,
                                          alpha,
                                          velocity,
                                          h_min,
                                          last_iterations,
                                          wall,
                                          under_resolved_cells};
        std::vector<double> row;
        for (const auto &postprocessor : postprocessors)
          {
            const auto &values = postprocessor->values(step_record);
            row.insert(row.end(), values.begin(), values.end());
          }
        if (!metrics)
          {
            std::vector<std::string> columns;
            for (const auto &postprocessor : postprocessors)
              for (const auto &name : postprocessor->column_names())
                columns.push_back(name);
            metrics = std::make_unique<MetricsLog>(scene.output.directory +
                                                     "/metrics.csv",
                                                   columns,
                                                   comm,
                                                   kept_metrics_rows);
          }
        metrics->add_row(row);
      }

    if (field_interval.due(step, final_step))
      {
        TimerOutput::Scope scope(timer_output, "output");
        field_output.write(step,
                           t,
                           alpha,
                           velocity,
                           [this](DataOut<dim> &data_out) {
                             add_output_fields(data_out);
                           });
      }

    if (progress_interval.due(step, final_step))
      {
        // The run ends at the end time or after the step limit, whichever
        // comes first.
        const double steps_left =
          scene.time.max_steps > 0 ? double(scene.time.max_steps) - step :
                                     std::numeric_limits<double>::max();
        // The step's limits as choose_time_step() applies them; the CFL
        // part is extrapolated from the recent steps.
        RemainingTime::StepLimits limits{scene.time.time_step,
                                         scene.time.relative_time_step};
        for (const auto &mechanism : mechanisms)
          limits.cap = std::min(limits.cap, mechanism->time_step_limit(alpha));
        const double eta =
          final_step ? 0. :
                       remaining_time.estimate(scene.time.end_time,
                                               steps_left,
                                               limits);
        pcout << "step " << std::setw(6) << step << "  t = " << std::setw(11)
              << std::setprecision(5) << t << " / " << scene.time.end_time
              << "  dt = " << std::setw(10) << std::setprecision(3) << dt
              << "  cells " << std::setw(8) << cells << "  dofs "
              << std::setw(8) << dofs << "  GMRES " << std::setw(3)
              << last_iterations << "  wall " << format_seconds(wall)
              << "  ETA " << (eta < 0 ? "-" : format_seconds(eta))
              << std::endl;
      }
  }

  template <int dim>
  double
  Simulation<dim>::take_step(const double t)
  {
    // A step that fails (a solver that does not converge, a non-finite
    // field) is taken again from the same alpha with half the step, up to
    // three times; then the run stops with the last diagnosis.
    const unsigned int            max_retries = 3;
    TrilinosWrappers::MPI::Vector start_of_step(alpha.locally_owned(), comm);
    start_of_step = alpha.alpha();
    double dt     = choose_time_step(t);
    for (unsigned int retry = 0;; ++retry)
      try
        {
          if (small_pores)
            small_pores->begin_step(alpha);
          // dt comes from the velocity of the previous step; if this
          // step's velocity is much faster, the step is chosen again.
          compute_interface_velocity(t, dt);
          for (unsigned int k = 0; scene.time.cfl > 0 &&
                                   interface_speed * dt >
                                     1.5 * scene.time.cfl * h_min &&
                                   k < 5;
               ++k)
            {
              shorten_trial_step();
              ++summary.shortened_steps;
              dt = std::min(dt, choose_time_step(t));
              compute_interface_velocity(t, dt);
            }
          last_iterations = transport.advance(
            alpha,
            velocity,
            dt,
            transport.reinitialisation_share(dt, interface_speed));
          for (auto &mechanism : mechanisms)
            mechanism->check_step(alpha);
          last_iterations += correct_step(dt);
          if (small_pores)
            small_pores->end_step(alpha, dt, h_min);
          for (auto &mechanism : mechanisms)
            mechanism->accept_step(alpha);
          return dt;
        }
      catch (const std::exception &failure)
        {
          reject_trial_step();
          if (retry == max_retries)
            {
              // Back to the last accepted state, which run() saves.
              TrilinosWrappers::MPI::Vector copy(start_of_step);
              alpha.set_from_owned(copy);
              throw std::runtime_error(
                "the step from t = " + std::to_string(t) + " failed " +
                std::to_string(max_retries + 1) +
                " times, the last time with dt = " + std::to_string(dt) +
                ": " + failure.what());
            }
          ++summary.rejected_steps;
          pcout << "step from t = " << t << " with dt = " << dt
                << " failed; retrying with dt = " << dt / 2 << ". Reason: "
                << failure.what() << std::endl;
          TrilinosWrappers::MPI::Vector copy(start_of_step);
          alpha.set_from_owned(copy);
          dt /= 2;
        }
  }

  template <int dim>
  typename Simulation<dim>::Summary
  Simulation<dim>::run()
  {
    start                  = std::chrono::steady_clock::now();
    last_checkpoint        = start;
    // CPU time summed over the ranks: unlike the wall time it does not grow
    // when other jobs share the cores.
    const Timer cpu_timer(comm);
    if (!initialised)
      initialise();

    pcout << "levelsinter: " << dim << "D scene, "
          << Utilities::MPI::n_mpi_processes(comm) << " MPI rank(s), "
          << tria.n_global_active_cells() << " cells, "
          << alpha.dof_handler().n_dofs() << " level-set DoFs, h_min = "
          << h_min << "; mechanisms: ";
    for (unsigned int i = 0; i < mechanisms.size(); ++i)
      pcout << (i > 0 ? ", " : "") << mechanisms[i]->name();
    pcout << (mechanisms.empty() ? "none (nothing moves the interface: each "
                                   "step only reinitialises the level set)" :
                                   "")
          << std::endl;

    double       t    = first_time;
    unsigned int step = first_step;
    if (step == 0)
      {
        check_curvature_resolution(t);
        probe_interface_velocity(t);
        record(step, t, 0, scene.time.end_time == scene.time.start_time);
      }
    else
      pcout << "resumed at step " << step << ", t = " << t << std::endl;

    const double end_time = scene.time.end_time;
    while (t < end_time * (1 - 1e-12) &&
           (scene.time.max_steps == 0 || step < scene.time.max_steps))
      {
        // 0. Keep the refined band on the interface.
        if (step > 0 && step % scene.refinement.adapt_interval == 0)
          {
            adapt_mesh();
            check_curvature_resolution(t);
          }

        // 1.-2. Interface velocity, transport with convective
        //       reinitialisation (Eq. 68), corrections (v^c, Eq. 113-116);
        //       a failed step is retried.
        double dt = 0;
        try
          {
            dt = take_step(t);
          }
        catch (const std::exception &failure)
          {
            // Stop with a diagnosis and the last accepted state saved, from
            // which the run can go on with other settings (doc/user_guide.md,
            // "Checkpoint and restart").
            write_checkpoint(step, t);
            throw std::runtime_error(
              std::string(failure.what()) + "; the last accepted state (step " +
              std::to_string(step) + ", t = " + std::to_string(t) +
              ") is in a checkpoint: 'levelsinter --resume " +
              scene.output.directory + "' continues from it");
          }
        total_iterations += last_iterations;
        t += dt;
        ++step;

        // 3. Metrics, fields, progress. A stop signal makes this step the
        //    last on every rank alike, whichever rank received it.
        const bool reached_end = !(t < end_time * (1 - 1e-12));
        const bool step_limit  = !reached_end && scene.time.max_steps > 0 &&
                                step >= scene.time.max_steps;
        const bool finished    = reached_end || step_limit;
        const int  signal =
          finished ? 0 : Utilities::MPI::max(int(stop_signal), comm);
        record(step, t, dt, finished || signal != 0);
        if (step_observer)
          step_observer(step, t, alpha);
        // A run stopped by 'Maximum steps' before its end time is one
        // sitting of a longer run: with checkpoints on, it leaves its last
        // step to resume from.
        const bool checkpoints_on = scene.output.checkpoint_interval > 0 ||
                                    scene.output.checkpoint_minutes > 0;
        if (signal != 0 || (step_limit && checkpoints_on) ||
            (!finished && checkpoint_due(step)))
          {
            write_checkpoint(step, t);
            write_timing();
          }
        if (signal != 0)
          {
            summary.stop_signal = signal;
            break;
          }
      }

    write_timing();
    summary.steps = step;
    summary.time  = t;
    summary.wall_time =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start)
        .count();
    summary.cpu_time = cpu_timer.cpu_time();
    summary.mean_iterations = step > 0 ? double(total_iterations) / step : 0;
    if (summary.curvature_under_resolved_until >= 0)
      pcout << "note: the interface curvature was under-resolved at the "
               "finest level until t = "
            << summary.curvature_under_resolved_until
            << " (metrics.csv: under_resolved_curvature_cells)." << std::endl;
    return summary;
  }

  template class Simulation<2>;
  template class Simulation<3>;
} // namespace levelsinter
