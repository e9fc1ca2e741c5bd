#pragma once

// Shared by the validation drivers and compare_metrics (compiled once into
// the static library levelsinter_study): the reader of the CSV files the
// runs write (metrics.csv, the drivers' tables) and the cell size of a
// refinement level.

#include <levelsinter/scene/scene_parameters.h>

#include <string>
#include <vector>

namespace levelsinter::study
{
  /**
   * A CSV file with a header row of column names and rows of numbers, as
   * MetricsLog and study::Table write them. Stored by column.
   */
  class CsvTable
  {
  public:
    /** An empty table. */
    CsvTable() = default;

    /** Read @p file_name; throws std::runtime_error naming the file if it
     * cannot be opened or a row has not one value per column. */
    explicit CsvTable(const std::string &file_name);

    const std::vector<std::string> &
    columns() const
    {
      return names;
    }

    unsigned int
    n_rows() const
    {
      return rows;
    }

    bool
    has_column(const std::string &name) const;

    /** The values of column @p name; throws if the file has none. */
    const std::vector<double> &
    column(const std::string &name) const;

  private:
    std::string                      file_name;
    std::vector<std::string>         names;
    std::vector<std::vector<double>> values; // values[column][row]
    unsigned int                     rows = 0;
  };

  /**
   * Edge length of the cells at refinement level @p level of @p scene's
   * box: SceneParameters::band_cell_size() with the maximum level set to
   * @p level. The drivers tie the band, the filter and the step to it.
   */
  double
  cell_size(const SceneParameters &scene, const unsigned int level);
} // namespace levelsinter::study
