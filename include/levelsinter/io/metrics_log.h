#pragma once

#include <deal.II/base/mpi.h>

#include <fstream>
#include <optional>
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
    /**
     * A new file, or with @p kept_rows (a restart) the existing one cut to
     * its header and first @p kept_rows rows and continued; its header must
     * name @p columns.
     */
    MetricsLog(const std::string              &file_name,
               const std::vector<std::string> &columns,
               const MPI_Comm                  comm,
               const std::optional<unsigned int> kept_rows = {});

    void
    add_row(const std::vector<double> &values);

    /** A row whose cells are text (a column that is not a number). */
    void
    add_text_row(const std::vector<std::string> &cells);

    /** A number as add_row() writes it (12 significant digits). */
    static std::string
    format(const double value);

    const std::vector<std::string> &
    columns() const
    {
      return column_names;
    }

    /** Rows in the file so far. */
    unsigned int
    n_rows() const
    {
      return rows;
    }

  private:
    std::vector<std::string> column_names;
    std::ofstream            out;
    bool                     root;
    unsigned int             rows = 0;
  };
} // namespace levelsinter
