#include <levelsinter/time/remaining_time.h>

#include <algorithm>
#include <cmath>

namespace levelsinter
{
  void
  RemainingTime::add_step(const double t, const double dt, const double wall)
  {
    steps.push_back({t, dt, wall});
    if (steps.size() > window + 1)
      steps.pop_front();
  }

  namespace
  {
    // Steps from t0 to t1 along the line dt = dt0 + b (t - t0), positive on
    // [t0, t1]: int dt'/(dt0 + b (t' - t0)) = (t1 - t0)/dt0 log1p(x)/x,
    // x = b (t1 - t0)/dt0.
    double
    steps_along_line(const double t0,
                     const double t1,
                     const double dt0,
                     const double b)
    {
      const double x = b * (t1 - t0) / dt0;
      return (t1 - t0) / dt0 * (x == 0 ? 1 : std::log1p(x) / x);
    }
  } // namespace

  double
  RemainingTime::estimate(const double end_time,
                          const double steps_left,
                          const double max_step) const
  {
    if (steps.size() < 2)
      return -1;
    const double n = steps.size();
    // Least-squares line dt = a + b t through the window.
    double mean_t = 0, mean_dt = 0;
    for (const auto &s : steps)
      {
        mean_t += s.t / n;
        mean_dt += s.dt / n;
      }
    double covariance = 0, variance = 0;
    for (const auto &s : steps)
      {
        covariance += (s.t - mean_t) * (s.dt - mean_dt);
        variance += (s.t - mean_t) * (s.t - mean_t);
      }
    const double b       = variance > 0 ? covariance / variance : 0;
    const double t       = steps.back().t;
    const double dt_now  = mean_dt + b * (t - mean_t);
    const double dt_end  = mean_dt + b * (end_time - mean_t);
    const double to_go   = std::max(0., end_time - t);
    double       n_steps = to_go / std::min(mean_dt, max_step);
    // A line that reaches zero before T is not trusted (a shrinking CFL
    // step): the mean step is used instead. Otherwise the line is followed
    // up to the step cap (Time/Time step with a CFL number), e.g. the
    // start-up of a CFL step whose first steps grow fast, and the capped
    // part counts its length / cap.
    if (dt_now > 0 && dt_end > 0)
      {
        // Where the line crosses the cap, if it moves towards it.
        const bool capped_first = dt_now >= max_step;
        double     crossing     = end_time;
        if (capped_first ? b < 0 : b > 0 && std::isfinite(max_step))
          crossing = std::clamp(t + (max_step - dt_now) / b, t, end_time);
        const double line_from  = capped_first ? crossing : t;
        const double line_to    = capped_first ? end_time : crossing;
        n_steps = (to_go - (line_to - line_from)) / max_step;
        if (line_to > line_from)
          n_steps += steps_along_line(line_from,
                                      line_to,
                                      dt_now + b * (line_from - t),
                                      b);
      }
    const double wall_per_step =
      (steps.back().wall - steps.front().wall) / (n - 1);
    return std::min(n_steps, steps_left) * wall_per_step;
  }
} // namespace levelsinter
