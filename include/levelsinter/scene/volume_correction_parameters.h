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

    bool enabled = false;
  };
} // namespace levelsinter
