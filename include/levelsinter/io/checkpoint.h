#pragma once

#include <deal.II/base/mpi.h>

#include <cstdint>
#include <string>

namespace levelsinter
{
  /**
   * The folders of checkpoints in a run directory:
   * DIRECTORY/checkpoints/step_NNNNNN/. A checkpoint is written into
   * step_NNNNNN.tmp and renamed when complete, so that a run killed while
   * writing leaves the previous checkpoints intact; the newest two are kept.
   * What goes inside is the writer's business (Simulation).
   */
  namespace checkpoint
  {
    /**
     * Create the empty temporary folder for the checkpoint of @p step and
     * return its path (every rank; collective).
     */
    std::string
    begin(const std::string &directory,
          const unsigned int step,
          const MPI_Comm     comm);

    /**
     * Rename the folder begin() returned to its final name and remove all
     * but the newest two checkpoints (collective). Returns the final path.
     */
    std::string
    commit(const std::string &directory,
           const unsigned int step,
           const MPI_Comm     comm);

    /**
     * The newest complete checkpoint in @p directory; throws
     * std::runtime_error if there is none.
     */
    std::string
    newest(const std::string &directory);

    /** The bytes in the files of a checkpoint folder. */
    std::uintmax_t
    size(const std::string &checkpoint_folder);
  } // namespace checkpoint
} // namespace levelsinter
