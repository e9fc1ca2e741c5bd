#pragma once

#include <levelsinter/level_set/level_set_field.h>
#include <levelsinter/level_set/velocity_field.h>

#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace levelsinter
{
  /** What the time loop knows after a step, handed to every postprocessor. */
  template <int dim>
  struct StepRecord
  {
    unsigned int              step;
    double                    time;
    double                    dt;
    const LevelSetField<dim> &level_set;
    // The interface velocity of the step (the sum over the mechanisms).
    const VelocityField<dim> &velocity;
    double                    h_min;
    unsigned int              transport_iterations;
    double                    wall_time;
    // Interface cells at the finest level larger than the curvature radius
    // (Simulation::check_curvature_resolution()).
    unsigned int under_resolved_curvature_cells;
  };

  /**
   * One measurement of a run that writes columns of metrics.csv (as
   * ASPECT's postprocessors do): it names its columns, computes their
   * values from a StepRecord, and keeps whatever state a restart needs. A
   * new measurement is one class added to make_scene_postprocessors().
   *
   * A postprocessor that reads another's result gets it at construction
   * and calls its values(), which measures at most once per step whatever
   * the order of the calls.
   */
  template <int dim>
  class Postprocessor
  {
  public:
    virtual ~Postprocessor() = default;

    /** Unique in a run: the key of its state in a checkpoint. */
    virtual std::string
    name() const = 0;

    /** Its metrics.csv columns; fixed from the first values() on. */
    virtual std::vector<std::string>
    column_names() const = 0;

    /** Its columns' values at @p record (collective: every rank calls it). */
    const std::vector<double> &
    values(const StepRecord<dim> &record)
    {
      const std::pair<unsigned int, double> now(record.step, record.time);
      if (measured_at != now)
        {
          last_values = measure(record);
          measured_at = now;
        }
      return last_values;
    }

    /** The state a restart needs, as text (empty: none). */
    virtual std::string
    save() const
    {
      return {};
    }

    /** Read back what save() wrote. */
    virtual void
    load(const std::string &)
    {}

  protected:
    virtual std::vector<double>
    measure(const StepRecord<dim> &record) = 0;

  private:
    std::optional<std::pair<unsigned int, double>> measured_at;
    std::vector<double>                            last_values;
  };
} // namespace levelsinter
