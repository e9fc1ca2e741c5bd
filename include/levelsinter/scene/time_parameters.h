#pragma once

#include <deal.II/base/parameter_handler.h>

namespace levelsinter
{
  using namespace dealii;

  /** The `Time` subsection: start, end, step and its limits. */
  struct TimeParameters
  {
    static void
    declare(ParameterHandler &prm);

    /** Read and check; throws std::runtime_error naming the entry. */
    void
    parse(ParameterHandler &prm);

    double       start_time = 0; // the time of the initial shape
    double       end_time  = 0;
    double       time_step = 0; // 0: from the CFL number
    double       cfl       = 0.5;
    unsigned int max_steps = 0; // 0: unlimited
    // r > 0: the step is max(time_step, r t) (before the caps).
    double relative_time_step = 0;
  };
} // namespace levelsinter
