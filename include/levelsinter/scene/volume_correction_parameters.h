#pragma once

#include <deal.II/base/parameter_handler.h>

namespace levelsinter
{
  using namespace dealii;

  /** The `Volume correction` subsection: v^c (Eq. 113-116), a mechanism of
   * its own on top of the others (VolumeCorrection). */
  struct VolumeCorrectionParameters
  {
    static void
    declare(ParameterHandler &prm);

    void
    parse(ParameterHandler &prm);

    enum class Choice
    {
      automatic, // on with a tensorial surface-tension form
      on,
      off
    };
    Choice choice = Choice::automatic;
    // The choice with 'auto' resolved from the mechanisms
    // (SceneParameters::check_across_sections()).
    bool enabled = false;
  };
} // namespace levelsinter
