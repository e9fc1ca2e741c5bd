// The progress line's ETA (RemainingTime) against the exact wall time left
// for steps of known law, each costing 0.5 s: fixed steps, steps growing
// with t (Time/Relative time step) and a step limit that comes first.
#include <levelsinter/time/remaining_time.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <iostream>
#include <utility>

namespace
{
  using namespace levelsinter;

  // Takes @p n steps of dt(t) from t = 0, then compares the estimate to
  // @p end_time (or the step limit) with @p exact; returns true if within
  // @p tolerance (relative).
  bool
  check(const char                           *name,
        const std::function<double(double)> &step_size,
        const unsigned int                    n,
        const double                          end_time,
        const double                          steps_left,
        const double                          exact,
        const double                          tolerance)
  {
    const double  wall_per_step = 0.5;
    RemainingTime remaining;
    double        t = 0;
    for (unsigned int k = 1; k <= n; ++k)
      {
        const double dt = step_size(t);
        t += dt;
        remaining.add_step(t, dt, k * wall_per_step);
      }
    const double estimate = remaining.estimate(end_time, steps_left);
    const double error    = std::abs(estimate - exact) / exact;
    std::cout << name << ": estimate " << estimate << " s, exact " << exact
              << " s, relative error " << error << "\n";
    return error <= tolerance;
  }
} // namespace

int
main()
{
  bool ok = true;
  // dt = 0.01 to t = 1: after 20 steps 80 remain (40 s), or 10 (5 s) if
  // the step limit comes first; the line fit is exact up to rounding.
  for (const auto &[steps_left, exact] :
       {std::pair{1e300, 80 * 0.5}, std::pair{10., 10 * 0.5}})
    ok = check(steps_left < 1e300 ? "step limit" : "fixed step",
               [](double) { return 0.01; },
               20,
               1.0,
               steps_left,
               exact,
               1e-9) &&
         ok;
  // dt = max(1e-3, 0.1 t) until t >= 0.1 (the window then holds relative
  // steps only), then on to t = 1: the steps grow x 1.1, so ln(1/t)/ln(1.1)
  // of them remain. The fit integrates the continuous law dt = (r/(1+r)) t
  // (each dt is r times the time before it), which counts ln(1/t) (1+r)/r
  // steps: (1+r) ln(1+r)/r = 1.048 times too many (measured 4.8 %), so 6 %
  // is the limit. The former ETA, wall (1 - t/T)/(t/T), says 144 s here
  // (35 steps to t = 0.108) against 11.7 s.
  {
    double       t = 0;
    unsigned int n = 0;
    while (t < 0.1)
      t += std::max(1e-3, 0.1 * t), ++n;
    const double exact = std::log(1.0 / t) / std::log(1.1) * 0.5;
    ok = check("relative step",
               [](double t) { return std::max(1e-3, 0.1 * t); },
               n,
               1.0,
               1e300,
               exact,
               0.06) &&
         ok;
  }
  // A CFL step starting up: dt = 2e-4 + 0.5 t, capped at 1e-3 from
  // t = 1.6e-3 on (as a packing's first steps), 4 steps known, then on to
  // t = 0.06: the fitted line alone would predict a handful of steps; with
  // the cap (0.06 - t)/1e-3 steps remain, to the rounding of the crossing.
  {
    auto         law = [](double t) { return std::min(1e-3, 2e-4 + 0.5 * t); };
    double       t   = 0;
    unsigned int n   = 0;
    while (n < 4)
      t += law(t), ++n;
    double       s = t, exact_steps = 0;
    while (s < 0.06)
      s += law(s), ++exact_steps;
    RemainingTime remaining;
    double        wall = 0;
    s                  = 0;
    for (unsigned int k = 1; k <= n; ++k)
      {
        const double dt = law(s);
        s += dt;
        remaining.add_step(s, dt, wall += 0.5);
      }
    const double estimate = remaining.estimate(0.06, 1e300, 1e-3);
    const double exact    = exact_steps * 0.5;
    std::cout << "capped start-up: estimate " << estimate << " s, exact "
              << exact << " s\n";
    // One step of slack: the last step is spread to end exactly at T.
    ok = std::abs(estimate - exact) <= 0.5 && ok;
  }
  return ok ? 0 : 1;
}
