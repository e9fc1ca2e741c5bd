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

  double
  RemainingTime::estimate(const double end_time, const double steps_left) const
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
    double       n_steps = to_go / mean_dt;
    // Steps left = int_t^T dt'/(a + b t') = (T - t)/dt_now * log1p(x)/x,
    // x = b (T - t)/dt_now; a line that reaches zero before T is not
    // trusted (a shrinking CFL step) and the mean step is used instead.
    if (dt_now > 0 && dt_end > 0)
      {
        const double x = b * to_go / dt_now;
        n_steps = to_go / dt_now * (x == 0 ? 1 : std::log1p(x) / x);
      }
    const double wall_per_step =
      (steps.back().wall - steps.front().wall) / (n - 1);
    return std::min(n_steps, steps_left) * wall_per_step;
  }
} // namespace levelsinter
