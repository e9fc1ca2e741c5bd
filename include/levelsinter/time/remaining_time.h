#pragma once

#include <deque>
#include <limits>

namespace levelsinter
{
  /**
   * The wall time a run still needs, for the progress line's ETA. The
   * fraction of the end time reached, or of the steps taken, misleads when
   * the steps grow: a relative step (dt = r t) or a CFL step whose speed
   * falls covers far more time late in the run than early at the same
   * cost. So the steps left are counted along the step's own law: the
   * limits the scene sets (a fixed or relative step, the mechanisms'
   * limits) are known; the CFL part, where it limits the recent steps, is
   * fitted as a line in the step's start time, dt = a + b s. On a piece
   * where one such law dt = a + b s decides, each step multiplies dt by
   * 1 + b, so the count from s0 to s1 is exact:
   * ln(dt(s1)/dt(s0)) / ln(1 + b), or (s1 - s0)/a for b = 0. A step
   * costs the mean wall time of the recent steps, changed in proportion to
   * the mesh: its DoFs, as a power of the start time fitted to a longer
   * history (a neck that grows draws more refined cells, and each step
   * costs more). The trend is read from the DoFs, not from the wall
   * times: those also follow the machine's load, and a power fitted to a
   * load that rose over a short span (a run resumed beside other jobs)
   * put the 154-particle run's ETA at 344 h instead of about 30 h.
   */
  class RemainingTime
  {
  public:
    /**
     * What limits a step besides the CFL number, as Simulation chooses it:
     * max(first_step, relative t) if first_step > 0 (Time/Time step,
     * Time/Relative time step), and at most cap (the mechanisms' limits).
     */
    struct StepLimits
    {
      double first_step = 0;
      double relative   = 0;
      double cap        = std::numeric_limits<double>::infinity();

      /** The largest step from time @p s; infinite if nothing limits it. */
      double
      at(const double s) const;
    };

    /** Call after each step with the time reached, the step, the wall
     *  time since the start and the DoFs the step was computed on. */
    void
    add_step(const double t,
             const double dt,
             const double wall,
             const double dofs);

    /**
     * Wall seconds to reach @p end_time or to take @p steps_left more steps,
     * whichever comes first, with steps limited by @p limits and, where the
     * recent steps were below those limits (the CFL number), by the fitted
     * trend of those steps; negative while it cannot be estimated (fewer
     * than two steps known, or no law that reaches the end time).
     */
    double
    estimate(const double        end_time,
             const double        steps_left,
             const StepLimits   &limits) const;

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
    // The mesh's trend is fitted over more steps: 20 steps see a few
    // adaptations only.
    static constexpr unsigned int size_window = 100;
    // (start time, DoFs) of the last size_window steps.
    std::deque<std::pair<double, double>> sizes;
  };
} // namespace levelsinter
