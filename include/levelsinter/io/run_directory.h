#pragma once

#include <deal.II/base/mpi.h>

#include <string>

namespace levelsinter
{
  /**
   * The output directory of one run of the application. A directory that
   * holds the files of an earlier run (metrics.csv, a field series,
   * parameters.prm) is refused unless the user asks to overwrite it; then
   * exactly those files are removed first, so that two runs never mix in
   * one series. Other files are left alone. Rank 0 does the file-system
   * work and every rank gets the same verdict.
   */
  namespace run_directory
  {
    /**
     * Create @p directory and check that it can be written and holds no
     * earlier run, or, with @p overwrite, remove the earlier run's files.
     * Throws std::runtime_error, before anything is removed, if not.
     */
    void
    prepare(const std::string &directory,
            const bool         overwrite,
            const MPI_Comm     comm);

    /**
     * Write @p directory/parameters.prm: @p header as comment lines, then
     * @p parameters (every entry in deal.II's PRM format), so that the file
     * can be run again as a scene.
     */
    void
    write_parameters(const std::string &directory,
                     const std::string &header,
                     const std::string &parameters,
                     const MPI_Comm     comm);
  } // namespace run_directory
} // namespace levelsinter
