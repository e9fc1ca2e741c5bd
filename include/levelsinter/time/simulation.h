#pragma once

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/timer.h>

#include <deal.II/distributed/tria.h>

#include <levelsinter/analysis/particle_id_field.h>
#include <levelsinter/analysis/postprocessor.h>
#include <levelsinter/analysis/small_pore_closure.h>
#include <levelsinter/grid/interface_band_refinement.h>
#include <levelsinter/io/field_output.h>
#include <levelsinter/io/metrics_log.h>
#include <levelsinter/level_set/convective_reinitialization.h>
#include <levelsinter/level_set/interface_measures.h>
#include <levelsinter/level_set/level_set_field.h>
#include <levelsinter/level_set/level_set_filter.h>
#include <levelsinter/mechanisms/mechanism.h>
#include <levelsinter/level_set/velocity_field.h>
#include <levelsinter/scene/scene_parameters.h>
#include <levelsinter/time/remaining_time.h>
#include <levelsinter/time/step_interval.h>

#include <chrono>
#include <functional>
#include <memory>
#include <optional>
#include <string>

namespace levelsinter
{
  /**
   * From this call on, SIGINT, SIGTERM and SIGUSR1 make a running
   * Simulation stop after its current step, as if that were the last (its
   * metrics row and fields are written, and a checkpoint), instead of
   * killing the process; the signal is in
   * Summary::stop_signal. The handler only records the signal; a second
   * one more than two seconds later acts as usual (kills at once), an
   * earlier one is taken as the same request. For a program's main.
   */
  void
  stop_on_signals();

  /**
   * One scene from t = 0 to the end time. Each step reads like the physics:
   * interface velocity (the sum over the scene's mechanisms) -> transport
   * with convective reinitialisation -> corrections (v^c) -> adapt the mesh around the interface
   * -> metrics and fields.
   */
  template <int dim>
  class Simulation
  {
  public:
    /** Everything a caller (main or a test) may want after run(). */
    struct Summary
    {
      unsigned int steps                = 0;
      double       time                 = 0;
      double       wall_time            = 0;
      double       cpu_time             = 0; // summed over the ranks
      unsigned int max_cells            = 0;
      unsigned int max_dofs             = 0;
      double       mean_iterations      = 0;
      unsigned int rejected_steps       = 0; // retried with a smaller dt
      /** Steps whose velocity was computed again with a smaller dt because
       *  it came out faster than the CFL step allowed (since this start;
       *  each costs one more velocity computation). */
      unsigned int shortened_steps = 0;
      /** Last time the curvature was under-resolved (-1: never; only for
       *  curvature-driven mechanisms). */
      double curvature_under_resolved_until = -1;
      /** The signal that stopped the run early (stop_on_signals()),
       *  else 0. */
      int stop_signal = 0;
    };

    Simulation(const SceneParameters &scene,
               const MPI_Comm         comm,
               std::ostream          &progress_stream);

    /** Build the mesh and alpha at t = 0 (run() calls it if needed). */
    void
    initialise();

    /**
     * Instead of initialise(): read the mesh, the level set, the mechanisms'
     * state and the counters from a checkpoint folder (checkpoint::newest_verified()),
     * written with any number of ranks; run() then continues from its step,
     * keeping the first rows of metrics.csv and the field series up to it.
     */
    void
    resume(const std::string &checkpoint_folder);

    Summary
    run();

    /**
     * Replace alpha on the current mesh by the interpolant of a (filtered)
     * level set, e.g. a distorted one to test reinitialisation. Call after
     * initialise() and before run().
     */
    void
    set_level_set(const Function<dim> &filtered_level_set);

    /**
     * Called after every step with (step, t, alpha): lets a test measure the
     * interface as it evolves without writing files.
     */
    void
    set_step_observer(
      const std::function<void(unsigned int, double, const LevelSetField<dim> &)>
        &observer)
    {
      step_observer = observer;
    }

    const LevelSetField<dim> &
    level_set() const
    {
      return alpha;
    }

    /** The interface velocity of the last step (the sum over mechanisms). */
    const VelocityField<dim> &
    interface_velocity() const
    {
      return velocity;
    }

    const LevelSetFilter &
    filter() const
    {
      return level_set_filter;
    }

    const parallel::distributed::Triangulation<dim> &
    triangulation() const
    {
      return tria;
    }

    /**
     * Add the mechanisms' fields (Mechanism::add_output_fields()) and
     * particle_id to @p data_out: what the field output writes besides
     * alpha and the velocity, for tests that read them without files.
     */
    void
    add_output_fields(DataOut<dim> &data_out) const;

    /** The scene's mechanisms, in the order their velocities are summed. */
    const std::vector<std::unique_ptr<Mechanism<dim>>> &
    scene_mechanisms() const
    {
      return mechanisms;
    }

    /** Wall time per phase (assembly, solve, adaptation, metrics, output). */
    TimerOutput &
    timer()
    {
      return timer_output;
    }

  private:
    void
    refine_initial_mesh();
    // Throws if the initial refinement left part of a particle's surface
    // in cells coarser than the maximum level.
    void
    check_particles_refined() const;
    void
    adapt_mesh();
    void
    check_curvature_resolution(const double t);
    double
    choose_time_step(const double t) const;
    double
    speed_near_interface() const;
    // velocity = the sum over the mechanisms of what @p add adds.
    void
    sum_velocities(const std::function<void(Mechanism<dim> &)> &add);
    // The mechanisms' velocities for the trial step t -> t + dt.
    void
    compute_interface_velocity(const double t, const double dt);
    // Their velocities at t before any step, for the first step size
    // (Mechanism::add_probe_velocity()).
    void
    probe_interface_velocity(const double t);
    // Every mechanism drops its trial step (Mechanism::reject_step()).
    void
    reject_trial_step();
    // The trial is taken again with a shorter step
    // (Mechanism::shorten_step()).
    void
    shorten_trial_step();
    unsigned int
    correct_step(const double dt);
    double
    take_step(const double t);
    // By Output/Checkpoint interval or minutes (collective).
    bool
    checkpoint_due(const unsigned int step) const;
    void
    write_checkpoint(const unsigned int step, const double t);

    /** TimerOutput's sections (calls, wall and CPU seconds of this process
     *  run) to OUTPUT_DIR/timing.csv, at each checkpoint and at the end. */
    void
    write_timing() const;
    // Both directions of the checkpoint's counters (boost archives).
    template <class Archive>
    void
    archive_counters(Archive &archive, unsigned int &step, double &t);
    void
    record(const unsigned int step,
           const double       t,
           const double       dt,
           const bool         final_step);

    const SceneParameters                     scene;
    const MPI_Comm                            comm;
    ConditionalOStream                        pcout;
    TimerOutput                               timer_output;
    parallel::distributed::Triangulation<dim> tria;
    LevelSetFilter                            level_set_filter;
    LevelSetField<dim>                        alpha;
    VelocityField<dim>                        velocity;
    VelocityField<dim>                        correction_velocity;
    std::vector<std::unique_ptr<Mechanism<dim>>> mechanisms;
    // Some mechanism is driven by the curvature: its resolution is checked.
    bool curvature_driven;
    std::unique_ptr<Function<dim>>            initial_distance;
    InterfaceBandRefinement<dim>              band_refinement;
    ConvectiveReinitialization<dim>           transport;
    // The metrics.csv columns, in order; the log is made at the first row.
    std::vector<std::unique_ptr<Postprocessor<dim>>> postprocessors;
    std::unique_ptr<MetricsLog>               metrics;
    const StepInterval                        metrics_interval;
    const StepInterval                        field_interval;
    const StepInterval                        progress_interval;
    const StepInterval                        checkpoint_interval;
    // The particle_id output field of a scene of two or more particles.
    std::unique_ptr<ParticleIdField<dim>>     particle_ids;
    FieldOutput<dim>                          field_output;
    double                                    h_min;
    double                                    interface_speed = 0;
    // Interface cells at the finest level that under-resolve the curvature,
    // at the last check (after each adaptation).
    unsigned int under_resolved_cells    = 0;
    bool         resolved_again_reported = false;
    Summary                                   summary;
    unsigned int                              total_iterations = 0;
    unsigned int                              last_iterations  = 0;
    bool                                      initialised      = false;
    // Set by resume(): where run() starts and the metrics rows to keep.
    unsigned int                              first_step = 0;
    double                                    first_time = 0;
    std::optional<unsigned int>               kept_metrics_rows;
    std::chrono::steady_clock::time_point     start;
    std::chrono::steady_clock::time_point     last_checkpoint;
    RemainingTime                             remaining_time;
    std::function<void(unsigned int, double, const LevelSetField<dim> &)>
      step_observer;
    // 'Viscous flow/Pore closure radius' > 0: the rule, one of the
    // postprocessors (its metrics columns and restart state).
    SmallPoreClosure<dim> *small_pores = nullptr;
  };
} // namespace levelsinter
