#pragma once

#include <deal.II/base/mpi.h>

#include <cstdint>
#include <ostream>
#include <string>

namespace levelsinter
{
  /**
   * The folders of checkpoints in a run directory:
   * DIRECTORY/checkpoints/step_NNNNNN/. A checkpoint is written into
   * step_NNNNNN.tmp; then its manifest (manifest.txt: the size and CRC-32
   * of every file in it) is written, last and by an atomic rename, the
   * folder is renamed to its final name and verified against the
   * manifest, and only then are all but the newest two removed. A run
   * killed while writing thus keeps the previous checkpoints, and a
   * checkpoint damaged later (a truncated or changed file) is recognised
   * before it is used. What goes inside is the writer's business
   * (Simulation).
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
     * Write the manifest of the folder begin() returned, rename the folder
     * to its final name, verify it, and then remove all but the newest two
     * checkpoints (collective). Throws, removing nothing, if the new
     * checkpoint does not verify. Returns the final path.
     */
    std::string
    commit(const std::string &directory,
           const unsigned int step,
           const MPI_Comm     comm);

    /**
     * The newest checkpoint in @p directory that verifies (collective).
     * Each newer one that does not is reported on @p progress (by rank 0)
     * with what is wrong, and set aside as step_NNNNNN.damaged, so that
     * the resumed run neither uses nor prunes it. Throws
     * std::runtime_error, changing nothing, if no checkpoint verifies.
     */
    std::string
    newest_verified(const std::string &directory,
                    const MPI_Comm     comm,
                    std::ostream      &progress);

    /**
     * What is wrong with @p checkpoint_folder: empty if its manifest is
     * present and whole and every file it lists has the listed size and
     * CRC-32; otherwise one sentence naming the file and the fault.
     */
    std::string
    verify(const std::string &checkpoint_folder);

    /** The bytes in the files of a checkpoint folder. */
    std::uintmax_t
    size(const std::string &checkpoint_folder);
  } // namespace checkpoint
} // namespace levelsinter
