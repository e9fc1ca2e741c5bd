#pragma once

#include <deal.II/base/mpi.h>

#include <fstream>
#include <string>
#include <vector>

namespace levelsinter
{
  /**
   * metrics.csv: a header naming the columns, then one row per recorded
   * step, flushed at once so that the file can be followed while the run
   * goes on. Only rank 0 writes.
   */
  class MetricsLog
  {
  public:
    MetricsLog(const std::string              &file_name,
               const std::vector<std::string> &columns,
               const MPI_Comm                  comm);

    void
    add_row(const std::vector<double> &values);

    const std::vector<std::string> &
    columns() const
    {
      return column_names;
    }

  private:
    std::vector<std::string> column_names;
    std::ofstream            out;
    bool                     root;
  };
} // namespace levelsinter
