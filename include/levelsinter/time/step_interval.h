#pragma once

namespace levelsinter
{
  /**
   * When the time loop does something periodic (metrics rows, fields,
   * progress lines, checkpoints): every @p every steps (0: never by count),
   * plus, if asked, at the first step and at the last step of the run.
   */
  struct StepInterval
  {
    unsigned int every    = 0;
    bool         at_start = false;
    bool         at_end   = false;

    bool
    due(const unsigned int step, const bool final_step) const
    {
      return (at_start && step == 0) || (at_end && final_step) ||
             (every > 0 && step % every == 0);
    }
  };
} // namespace levelsinter
