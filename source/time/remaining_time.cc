#include <levelsinter/time/remaining_time.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace levelsinter
{
  double
  RemainingTime::StepLimits::at(const double s) const
  {
    return std::min(cap,
                    first_step > 0 ? std::max(first_step, relative * s) :
                                     std::numeric_limits<double>::infinity());
  }

  void
  RemainingTime::add_step(const double t,
                          const double dt,
                          const double wall,
                          const double dofs)
  {
    sizes.emplace_back(t - dt, dofs);
    if (sizes.size() > size_window)
      sizes.pop_front();
    steps.push_back({t, dt, wall});
    if (steps.size() > window + 1)
      steps.pop_front();
  }

  namespace
  {
    // A step law dt = a + b s of the start time s.
    struct Line
    {
      double a;
      double b;

      double
      operator()(const double s) const
      {
        return a + b * s;
      }
    };

    // Steps from s0 to s1 along a law positive there: each step multiplies
    // dt by 1 + b, so their number is ln(dt(s1)/dt(s0))/ln(1 + b).
    double
    steps_along(const Line &line, const double s0, const double s1)
    {
      if (line.b == 0)
        return (s1 - s0) / line.a;
      return std::log(line(s1) / line(s0)) / std::log1p(line.b);
    }

    // The least-squares line through (s, dt), or the mean if the s are
    // equal.
    Line
    fit(const std::vector<std::pair<double, double>> &points)
    {
      const double n      = points.size();
      double       mean_s = 0, mean_dt = 0;
      for (const auto &[s, dt] : points)
        {
          mean_s += s / n;
          mean_dt += dt / n;
        }
      double covariance = 0, variance = 0;
      for (const auto &[s, dt] : points)
        {
          covariance += (s - mean_s) * (dt - mean_dt);
          variance += (s - mean_s) * (s - mean_s);
        }
      const double b = variance > 0 ? covariance / variance : 0;
      return {mean_dt - b * mean_s, b};
    }
  } // namespace

  double
  RemainingTime::estimate(const double      end_time,
                          const double      steps_left,
                          const StepLimits &limits) const
  {
    if (steps.size() < 2)
      return -1;
    const double t = steps.back().t;
    if (!(t < end_time) || steps_left <= 0)
      return 0;
    const double infinity = std::numeric_limits<double>::infinity();

    // The laws a step can follow: the scene's limits, and the CFL number's
    // where the recent steps stayed below those limits (by more than the
    // last steps' evening out to end at the end time).
    std::vector<Line> laws;
    if (std::isfinite(limits.cap))
      laws.push_back({limits.cap, 0});
    if (limits.first_step > 0)
      laws.push_back({limits.first_step, 0});
    if (limits.first_step > 0 && limits.relative > 0)
      laws.push_back({0, limits.relative});
    std::vector<std::pair<double, double>> below_limits;
    for (const auto &step : steps)
      if (step.dt < 0.98 * limits.at(step.t - step.dt))
        below_limits.emplace_back(step.t - step.dt, step.dt);
    bool cfl = !below_limits.empty();
    Line cfl_law{0, 0};
    if (cfl)
      {
        cfl_law = fit(below_limits);
        // A CFL step that shrinks (an interface that speeds up) is not
        // extrapolated to zero: its present value is kept.
        if (cfl_law.b <= -1 || cfl_law(t) <= 0 || cfl_law(end_time) <= 0)
          cfl_law = {std::max(cfl_law(t), below_limits.back().second), 0};
        laws.push_back(cfl_law);
      }
    const auto step_at = [&](const double s) {
      return std::min(limits.at(s), cfl ? cfl_law(s) : infinity);
    };

    // The step law is piecewise one of the laws, changing where two cross.
    std::vector<double> breaks = {t, end_time};
    for (unsigned int i = 0; i < laws.size(); ++i)
      for (unsigned int j = i + 1; j < laws.size(); ++j)
        if (laws[i].b != laws[j].b)
          {
            const double s = (laws[j].a - laws[i].a) / (laws[i].b - laws[j].b);
            if (s > t && s < end_time)
              breaks.push_back(s);
          }
    std::sort(breaks.begin(), breaks.end());
    double              n_steps = 0;
    std::vector<double> pieces(breaks.size(), 0.); // steps per piece
    for (unsigned int k = 0; k + 1 < breaks.size(); ++k)
      {
        const double s0 = breaks[k], s1 = breaks[k + 1];
        if (!(s1 > s0))
          continue;
        const double dt = step_at((s0 + s1) / 2);
        if (!std::isfinite(dt))
          return -1;
        const Line &law = *std::min_element(
          laws.begin(), laws.end(), [&](const Line &x, const Line &y) {
            return std::abs(x((s0 + s1) / 2) - dt) <
                   std::abs(y((s0 + s1) / 2) - dt);
          });
        pieces[k] = steps_along(law, s0, s1);
        n_steps += pieces[k];
      }
    if (!std::isfinite(n_steps))
      return -1;

    // The cost per step: the recent steps' mean C at their mean start time
    // s_m, changed as the DoFs, (s / s_m)^p with p fitted to the DoFs of
    // the longer history in log-log (a neck, and the refined cells it
    // draws, grow as a power of time; a line in s extrapolated the early
    // growth of the default scene 25 % too high, doc/user_guide.md
    // "Progress"). |p| <= 2: a steeper fit is a start-up, not a trend.
    const double wall_per_step =
      (steps.back().wall - steps.front().wall) / (steps.size() - 1);
    double mean_start = 0;
    for (unsigned int k = 1; k < steps.size(); ++k)
      mean_start += (steps[k].t - steps[k].dt) / (steps.size() - 1);
    double power = 0;
    if (mean_start > 0)
      {
        std::vector<std::pair<double, double>> logs;
        for (const auto &[s, n] : sizes)
          if (s > 0 && n > 0)
            logs.emplace_back(std::log(s), std::log(n));
        if (logs.size() >= window)
          power = std::clamp(fit(logs).b, -2., 2.);
      }
    const auto cost = [&](const double s) {
      return power == 0 ? wall_per_step :
                          wall_per_step * std::pow(s / mean_start, power);
    };
    // A part of a step left is one more step.
    const double all_steps = std::ceil(n_steps - 1e-9);
    if (steps_left < all_steps || power == 0)
      return std::min(all_steps, steps_left) * cost(t);
    // Each piece's steps at the mean cost over its steps, sum cost(s)/dt(s)
    // over sum 1/dt(s) (Simpson's rule); the part step at the end's cost.
    double wall = (all_steps - n_steps) * cost(end_time);
    for (unsigned int k = 0; k + 1 < breaks.size(); ++k)
      {
        const double s0 = breaks[k], s1 = breaks[k + 1];
        if (!(s1 > s0))
          continue;
        double             weighted = 0, weights = 0;
        const unsigned int n        = 16;
        for (unsigned int i = 0; i <= n; ++i)
          {
            const double s = s0 + (s1 - s0) * i / n;
            const double w =
              (i == 0 || i == n ? 1 : (i % 2 ? 4 : 2)) / step_at(s);
            weighted += w * cost(s);
            weights += w;
          }
        wall += pieces[k] * weighted / weights;
      }
    return wall;
  }
} // namespace levelsinter
