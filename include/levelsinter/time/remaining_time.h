#pragma once

#include <deque>
#include <limits>

namespace levelsinter
{
  /**
   * The wall time a run still needs, for the progress line's ETA. The
   * fraction of the end time reached, or of the steps taken, misleads when
   * the steps grow (Time/Relative time step: dt = r t, so a step late in
   * the run covers far more time than an early one at the same cost). So
   * over a window of recent steps the step is fitted as a line in t,
   * dt = a + b t (b = 0 for a fixed or steady CFL step, a = 0 for a purely
   * relative one), the number of steps left to the end time follows from
   * integrating dn = dt'/(a + b t'), and each costs the recent wall time per
   * step.
   */
  class RemainingTime
  {
  public:
    /** Call after each step with the time reached, the step and the wall
     *  time since the start. */
    void
    add_step(const double t, const double dt, const double wall);

    /**
     * Wall seconds to reach @p end_time or to take @p steps_left more steps,
     * whichever comes first, with steps of at most @p max_step; negative
     * while fewer than two steps are known.
     */
    double
    estimate(const double end_time,
             const double steps_left,
             const double max_step =
               std::numeric_limits<double>::infinity()) const;

  private:
    struct Step
    {
      double t;
      double dt;
      double wall;
    };
    // Long enough to average over several mesh adaptations (whose steps
    // cost more), short enough to follow a step that changes.
    static constexpr unsigned int window = 20;
    std::deque<Step>              steps;
  };
} // namespace levelsinter
