#include <deal.II/base/function.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/timer.h>
#include <deal.II/base/utilities.h>

#include <deal.II/grid/grid_tools.h>

#include <levelsinter/analysis/neck.h>
#include <levelsinter/analysis/packing_analysis.h>
#include <levelsinter/analysis/reference_shapes.h>
#include <levelsinter/grid/box_mesh.h>
#include <levelsinter/io/checkpoint.h>
#include <levelsinter/mechanisms/scene_mechanisms.h>
#include <levelsinter/time/simulation.h>

#include <boost/archive/text_iarchive.hpp>
#include <boost/archive/text_oarchive.hpp>

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
                   0.},
                timer_output)
    , field_output(scene.output.directory,
                   scene.output.write_vtu,
                   scene.output.write_xdmf)
    , h_min(0)
  {
    if (scene.dimension != dim)
      throw std::logic_error("Simulation<dim> built for the wrong dimension");
    for (const auto &warning : scene.warnings)
      pcout << "warning: " << warning << std::endl;
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
    h_min = GridTools::minimal_cell_diameter(tria) / std::sqrt(double(dim));
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
    archive &summary.initial_solid_volume
      &summary.curvature_under_resolved_until;
    archive &metrics_rows &field_output;
    if (Archive::is_loading::value)
      kept_metrics_rows = metrics_rows;
    // resume() creates the analyses before loading.
    if (packing_analysis)
      archive &*packing_analysis;
    if (particle_centres)
      archive &*particle_centres;
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
    if (scene.output.checkpoint_interval > 0 &&
        step % scene.output.checkpoint_interval == 0)
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
    // Their pore tracking and shrinkage and centre references are in the
    // counters.
    const auto &particles = scene.geometry.particles;
    if (scene.analysis.enabled(scene.geometry.shape, particles.size()))
      {
        packing_analysis = std::make_unique<PackingAnalysis<dim>>(scene, comm);
        if (scene.geometry.particles_are_bodies() &&
            particles.size() >= 2)
          particle_centres = std::make_unique<ParticleCentres<dim>>(
            particles, scene.domain, comm);
      }
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
    h_min = GridTools::minimal_cell_diameter(tria) / std::sqrt(double(dim));

    std::ifstream in(checkpoint_folder + "/counters.txt");
    if (!in)
      throw std::runtime_error("cannot read '" + checkpoint_folder +
                               "/counters.txt'");
    boost::archive::text_iarchive archive(in);
    archive_counters(archive, first_step, first_time);
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
    h_min = GridTools::minimal_cell_diameter(tria) / std::sqrt(double(dim));
  }

  template <int dim>
  void
  Simulation<dim>::add_output_fields(DataOut<dim> &data_out) const
  {
    for (const auto &mechanism : mechanisms)
      mechanism->add_output_fields(alpha, data_out);
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
    if (resolution.under_resolved_cells > 0 && first_time)
      pcout << "warning: t = " << t << ": " << resolution.under_resolved_cells
            << " interface cells at the finest level are larger than the "
               "local curvature radius (largest curvature x h = "
            << resolution.max_curvature_times_h
            << "); the curvature-driven speed is too low there. More "
               "'Mesh refinement/Curvature refinement levels' resolve it."
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
  Simulation<dim>::compute_interface_velocity(const double t, const double dt)
  {
    velocity.set_zero();
    for (auto &mechanism : mechanisms)
      mechanism->add_velocity(alpha, t, dt, velocity);
    interface_speed = speed_near_interface();
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
                                   /*reinitialise=*/false) :
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
      remaining_time.add_step(t, dt, wall);

    if (step == 0 || final_step || step % scene.output.metrics_interval == 0)
      {
        TimerOutput::Scope scope(timer_output, "metrics");
        const auto measures = interface_measures::volume_and_area(alpha);
        if (step == 0)
          summary.initial_solid_volume = measures.solid_volume;
        std::vector<double> row = {double(step),
                                   t,
                                   dt,
                                   double(cells),
                                   double(dofs),
                                   measures.solid_volume,
                                   (measures.solid_volume -
                                    summary.initial_solid_volume) /
                                     summary.initial_solid_volume,
                                   measures.interface_area,
                                   velocity.max_norm(),
                                   double(last_iterations),
                                   wall};
        if (curvature_driven)
          row.push_back(under_resolved_cells);
        const std::size_t columns_before_neck = row.size();
        // Pores, density, all necks, coordination, shrinkage (doc/user_guide.md).
        const auto         &particles = scene.geometry.particles;
        std::vector<double> packing_row;
        if (scene.analysis.enabled(scene.geometry.shape, particles.size()))
          {
            TimerOutput::Scope scope(timer_output, "packing analysis");
            if (!packing_analysis)
              packing_analysis =
                std::make_unique<PackingAnalysis<dim>>(scene, comm);
            packing_row = packing_analysis->measure(step, t, alpha);
          }
        // The neck of two particles; in a packing the smallest neck over
        // the pairs that overlap at t = 0 (the packing analysis' necks if
        // it ran: the same pairs).
        if (scene.geometry.particles_are_bodies() &&
            particles.size() >= 2)
          {
            const double neck =
              packing_analysis ?
                neck_measures::smallest_neck_radius(packing_analysis->necks()) :
                neck_measures::smallest_neck_radius(alpha, particles);
            if (!std::isnan(neck))
              row.push_back(neck);
          }
        const bool has_neck = row.size() > columns_before_neck;
        // An equal pair: the curvature of its neck (from a fit over a few
        // finest cells) and the mechanisms' fields at the neck (the
        // viscoelastic seed's Figs. 8, 11, 13), read one finest cell inside
        // the interface: on it the Q1 fields mix the particle's nodes with
        // the atmosphere's.
        const bool has_neck_shape = has_neck && particles.size() == 2 &&
                                    particles[0][dim] == particles[1][dim];
        std::optional<neck_measures::NeckShape<dim>> neck_shape;
        if (has_neck_shape)
          {
            Point<dim> c1, c2;
            for (unsigned int d = 0; d < dim; ++d)
              {
                c1[d] = particles[0][d];
                c2[d] = particles[1][d];
              }
            neck_shape = neck_measures::neck_shape(alpha, c1, c2, h_min);
            row.push_back(neck_shape->curvature);
          }
        for (const auto &mechanism : mechanisms)
          for (const double value : mechanism->metric_values())
            row.push_back(value);
        if (neck_shape)
          for (const auto &mechanism : mechanisms)
            for (const double value :
                 mechanism->point_metric_values(alpha,
                                                neck_shape->inner_point))
              row.push_back(value);
        row.insert(row.end(), packing_row.begin(), packing_row.end());
        // Densification: the approach of the particle centres.
        if (packing_analysis &&
            scene.geometry.particles_are_bodies() &&
            particles.size() >= 2)
          {
            TimerOutput::Scope scope(timer_output, "packing analysis");
            if (!particle_centres)
              particle_centres = std::make_unique<ParticleCentres<dim>>(
                particles, scene.domain, comm);
            for (const double value :
                 particle_centres->measure(alpha, packing_analysis->necks()))
              row.push_back(value);
          }
        if (!metrics)
          {
            std::vector<std::string> columns = {"step",
                                                "time",
                                                "dt",
                                                "cells",
                                                "dofs",
                                                "solid_volume",
                                                "volume_change",
                                                "interface_area",
                                                "max_velocity",
                                                "transport_iterations",
                                                "wall_time"};
            if (curvature_driven)
              columns.push_back("under_resolved_curvature_cells");
            if (has_neck)
              columns.push_back("neck_radius");
            if (has_neck_shape)
              columns.push_back("neck_curvature");
            for (const auto &mechanism : mechanisms)
              for (const auto &name : mechanism->metric_names())
                columns.push_back(name);
            if (has_neck_shape)
              for (const auto &mechanism : mechanisms)
                for (const auto &name : mechanism->point_metric_names())
                  columns.push_back("neck_" + name);
            if (packing_analysis)
              for (const auto &name : packing_analysis->column_names())
                columns.push_back(name);
            if (particle_centres)
              for (const auto &name : particle_centres->column_names())
                columns.push_back(name);
            metrics = std::make_unique<MetricsLog>(scene.output.directory +
                                                     "/metrics.csv",
                                                   columns,
                                                   comm,
                                                   kept_metrics_rows);
          }
        metrics->add_row(row);
      }

    if (step == 0 || final_step ||
        (scene.output.field_interval > 0 &&
         step % scene.output.field_interval == 0))
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

    if ((scene.output.progress_interval > 0 &&
         step % scene.output.progress_interval == 0) ||
        final_step)
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
          // dt comes from the velocity of the previous step; if this
          // step's velocity is much faster, the step is chosen again.
          compute_interface_velocity(t, dt);
          for (unsigned int k = 0; scene.time.cfl > 0 &&
                                   interface_speed * dt >
                                     1.5 * scene.time.cfl * h_min &&
                                   k < 5;
               ++k)
            {
              dt = std::min(dt, choose_time_step(t));
              compute_interface_velocity(t, dt);
            }
          last_iterations = transport.advance(alpha, velocity, dt);
          for (auto &mechanism : mechanisms)
            mechanism->check_step(alpha);
          last_iterations += correct_step(dt);
          for (auto &mechanism : mechanisms)
            mechanism->accept_step(alpha);
          return dt;
        }
      catch (const std::exception &failure)
        {
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
    pcout << (mechanisms.empty() ? "none" : "") << std::endl;

    double       t    = first_time;
    unsigned int step = first_step;
    if (step == 0)
      {
        check_curvature_resolution(t);
        compute_interface_velocity(t, 0);
        record(step, t, 0, scene.time.end_time == 0);
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
            // Stop with a diagnosis and the last accepted state saved
            // (DESIGN.md Sect. 5), from which the run can go on with
            // other settings.
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
