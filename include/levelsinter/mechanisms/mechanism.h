#pragma once

#include <deal.II/numerics/data_out.h>

#include <levelsinter/level_set/level_set_field.h>
#include <levelsinter/level_set/state_transfer.h>
#include <levelsinter/level_set/velocity_field.h>

#include <limits>
#include <string>
#include <vector>

namespace levelsinter
{
  /**
   * One physical cause of interface motion (prescribed velocity, viscous
   * flow, surface diffusion, ...). The time loop owns a list of the
   * mechanisms a scene switches on and asks each for its share of the
   * interface velocity; a mechanism a scene does not list is never built, so
   * nothing it needs (a Stokes system, a curvature solve) is assembled.
   *
   * A step is a trial until the time loop decides: add_velocity() (possibly
   * several times for the same t, with a smaller dt each time) -> after the
   * transport check_step() and add_correction_velocity() -> accept_step(),
   * which makes the trial the mechanism's state; or reject_step() at any
   * point, which drops it (shorten_step() before a smaller dt). The state a mesh change or a checkpoint carries
   * (add_state()) is always that of the last accepted step.
   */
  template <int dim>
  class Mechanism
  {
  public:
    virtual ~Mechanism() = default;

    /** What the start-up line calls it, e.g. "viscous flow". */
    virtual std::string
    name() const = 0;

    /**
     * The mesh changed (or t = 0): size matrices and vectors, and distribute
     * the DoFs of the mechanism's own DoFHandlers again (the same objects
     * given to add_state(): their vectors are filled after this call).
     */
    virtual void
    setup(const LevelSetField<dim> &alpha) = 0;

    /**
     * Hand to @p transfer the vectors that must survive a mesh change (a
     * lagged velocity, a displacement or stress history), ghosted, on any
     * DoFHandler of the triangulation. The time loop calls it before
     * adapting the mesh; after setup() the transfer fills them on the new
     * mesh (StateTransfer).
     */
    virtual void
    add_state(const LevelSetField<dim> &, StateTransfer<dim> &)
    {}

    /**
     * Numbers a restart needs besides the fields of add_state() (e.g. a
     * reference volume), as text for the checkpoint; empty: none. The
     * state of the last accepted step.
     */
    virtual std::string
    save() const
    {
      return {};
    }

    /** Read back what save() wrote (a restart). */
    virtual void
    load(const std::string &)
    {}

    /**
     * Add the mechanism's fields (on any DoFHandler of the triangulation,
     * each add_data_vector() naming its DoFHandler) to the field output.
     * Names start with the mechanism's, so that they stay apart when
     * several mechanisms are on; the vectors must live until the output is
     * written.
     */
    virtual void
    add_output_fields(const LevelSetField<dim> &, DataOut<dim> &) const
    {}

    /**
     * Add this mechanism's velocity for the trial step t -> t + dt (dt > 0),
     * computed from the level set at t and the state of the last accepted
     * step, to @p velocity (which holds the sum of the mechanisms before
     * this one).
     */
    virtual void
    add_velocity(const LevelSetField<dim> &alpha,
                 const double              t,
                 const double              dt,
                 VelocityField<dim>       &velocity) = 0;

    /**
     * The speed probe: add the velocity at t before any step is taken (the
     * time loop's first look at the speed, which chooses the first step),
     * with no step size and no step-dependent terms. Changes no state and
     * is neither accepted nor rejected.
     */
    virtual void
    add_probe_velocity(const LevelSetField<dim> &alpha,
                       const double              t,
                       VelocityField<dim>       &velocity) = 0;

    /**
     * After a step has been accepted (check_step()): add to @p velocity a
     * velocity that corrects the new state in a transport of its own over
     * the same dt, as the volume correction of the paper's Algorithm 2
     * does, and return true; false if the mechanism has none.
     */
    virtual bool
    add_correction_velocity(const LevelSetField<dim> &,
                            const double,
                            VelocityField<dim> &)
    {
      return false;
    }

    /**
     * A time-step limit of the mechanism's own (e.g. an explicit capillary
     * or diffusion limit), on top of the CFL limit the time loop applies to
     * the summed velocity. Infinity if none.
     */
    virtual double
    time_step_limit(const LevelSetField<dim> &) const
    {
      return std::numeric_limits<double>::infinity();
    }

    /**
     * Called after the transport of a step with the new level set: throw
     * (std::runtime_error, saying why) to reject the step; the time loop
     * then retries it from the old state with half the step.
     */
    virtual void
    check_step(const LevelSetField<dim> &)
    {}

    /**
     * The trial step has been accepted (check_step() and the corrections
     * passed): what the last add_velocity() advanced becomes the
     * mechanism's state, before the metrics of the step are recorded.
     */
    virtual void
    accept_step(const LevelSetField<dim> &)
    {}

    /**
     * The trial step is dropped (a failed check or solve, or a step chosen
     * again smaller): the state stays that of the last accepted step.
     */
    virtual void
    reject_step()
    {}

    /**
     * The trial step is taken again from the same state with a shorter
     * step (its velocity was too fast for the one chosen): add_velocity()
     * follows with the shorter dt. A mechanism whose expensive part does
     * not depend on the step may keep it; by default the trial is dropped
     * as in reject_step().
     */
    virtual void
    shorten_step()
    {
      reject_step();
    }

    /**
     * True if the velocity is driven by the interface's curvature (surface
     * tension, surface diffusion): the time loop then reports where the
     * mesh under-resolves the curvature.
     */
    virtual bool
    curvature_driven() const
    {
      return false;
    }

    /** Extra metrics.csv columns and their values after the last step. */
    virtual std::vector<std::string>
    metric_names() const
    {
      return {};
    }

    virtual std::vector<double>
    metric_values() const
    {
      return {};
    }

    /**
     * Fields worth reading at a pair's neck (metrics.csv columns "neck_" +
     * name, e.g. the polymer stretch of a viscoelastic melt), and their
     * values at @p point after the last step (collective: every rank calls
     * it with the same point).
     */
    virtual std::vector<std::string>
    point_metric_names() const
    {
      return {};
    }

    virtual std::vector<double>
    point_metric_values(const LevelSetField<dim> &, const Point<dim> &) const
    {
      return {};
    }
  };
} // namespace levelsinter
