#include <levelsinter/scene/parameter_entries.h>
#include <levelsinter/scene/time_parameters.h>

#include <string>

namespace levelsinter
{
  void
  TimeParameters::declare(ParameterHandler &prm)
  {
    prm.enter_subsection("Time");
    {
      prm.declare_entry("Start time",
                        "0",
                        Patterns::Double(0),
                        "Time of the initial shape, in the scene time unit: "
                        "the first row of metrics.csv. A scene that starts "
                        "from a known state of a solution (e.g. Geometry/"
                        "Shape = hopper at t gamma / (eta R) = tau) gives "
                        "its time here, so that its time axis is the "
                        "solution's.");
      prm.declare_entry("End time",
                        "1",
                        Patterns::Double(0),
                        "Simulated time at which the run stops (at least "
                        "the Start time), in the scene time unit (s with material data, or the "
                        "reduced time of Surface diffusion/Time unit).");
      prm.declare_entry("Time step",
                        "0",
                        Patterns::Double(0),
                        "Fixed time step (scene time unit); 0 lets the CFL "
                        "number choose it. When both are given the smaller "
                        "step is used.");
      prm.declare_entry("CFL number",
                        "0.5",
                        Patterns::Double(0),
                        "Courant number max|v| dt / h_min (no unit); 0 "
                        "disables the CFL limit (then 'Time step' must be "
                        "set).");
      prm.declare_entry(
        "Relative time step",
        "0",
        Patterns::Double(0),
        "0 = off. When positive (r, no unit), the step is max('Time step', "
        "r t): once r t exceeds 'Time step', which is then the first and "
        "smallest step, the steps grow in proportion to the time reached "
        "(about 2.3 / r steps per decade of t). For flows whose own time "
        "scale is t, such as an early sintering neck x ~ t^(1/n), which "
        "then grows by the same fraction every step. The CFL number and the "
        "mechanisms' limits still cap the step: set CFL number = 0 where "
        "the largest speed is not the neck's.");
      prm.declare_entry("Maximum steps",
                        "0",
                        Patterns::Integer(0),
                        "Stop after this many steps (0 = no limit).");
    }
    prm.leave_subsection();
  }

  void
  TimeParameters::parse(ParameterHandler &prm)
  {
    prm.enter_subsection("Time");
    start_time         = prm.get_double("Start time");
    end_time           = prm.get_double("End time");
    time_step          = prm.get_double("Time step");
    cfl                = prm.get_double("CFL number");
    max_steps          = prm.get_integer("Maximum steps");
    relative_time_step = prm.get_double("Relative time step");
    prm.leave_subsection();
    if (end_time < start_time)
      fail_entry("Time/End time",
                 "is " + std::to_string(end_time) +
                   ", before the Start time " + std::to_string(start_time));
    if (time_step == 0 && cfl == 0)
      fail_entry("Time/CFL number",
                 "a CFL number or a fixed 'Time step' must be given (both "
                 "are 0)");
    if (relative_time_step > 0 && time_step == 0)
      fail_entry("Time/Time step",
                 "must be positive with a 'Relative time step': it is the "
                 "first step, taken at t = 0 where r t is 0");
  }
} // namespace levelsinter
