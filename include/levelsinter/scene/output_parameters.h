#pragma once

#include <deal.II/base/parameter_handler.h>

#include <string>

namespace levelsinter
{
  using namespace dealii;

  /** The `Output` subsection: where and how often to write. */
  struct OutputParameters
  {
    static void
    declare(ParameterHandler &prm);

    /** Read and check; throws std::runtime_error naming the entry. */
    void
    parse(ParameterHandler &prm);

    std::string  directory;
    unsigned int field_interval    = 0;
    bool         write_vtu         = true;
    bool         write_xdmf        = true;
    unsigned int metrics_interval  = 1;
    unsigned int progress_interval = 10;
    // Steps between checkpoints (0: none).
    unsigned int checkpoint_interval = 0;
    // Wall-clock minutes between checkpoints (0: none).
    double checkpoint_minutes = 0;
  };
} // namespace levelsinter
