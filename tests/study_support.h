#pragma once

// Shared by the validation drivers and compare_metrics (compiled once into
// the static library levelsinter_study): the reader of the CSV files the
// runs write (metrics.csv, the drivers' tables) and the cell size of a
// refinement level.

#include <levelsinter/scene/scene_parameters.h>

#include <fstream>
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
   * A CSV file a study writes row by row, under the rule of
   * scripts/validation_data.py: a file in a validation_data folder that
   * holds more data rows than this run has written so far is kept, and the
   * run's rows go to FILE.partial, which replaces FILE as soon as it holds
   * as many rows. So an interrupted or shorter rerun of a study leaves the
   * longer history in place (and says so), while a run that gets as far
   * replaces it row by row as before. LEVELSINTER_REPLACE_SHORTER=1
   * replaces it at once; outside a validation_data folder FILE is written
   * directly. Open it on one rank only.
   */
  class CsvFile
  {
  public:
    explicit CsvFile(const std::string &path);

    CsvFile(const CsvFile &) = delete;
    CsvFile &
    operator=(const CsvFile &) = delete;

    /** Says on stderr that the longer history was kept, if it was. */
    ~CsvFile();

    /** Where the header and the rows go. */
    std::ofstream &
    stream()
    {
      return file;
    }

    /** Call after each data row (not after the header). */
    void
    end_row();

    /** One data row of @p values, comma-separated. */
    template <typename... Values>
    void
    row(const Values &...values)
    {
      const char *separator = "";
      ((file << separator << values, separator = ","), ...);
      file << '\n';
      end_row();
    }

  private:
    std::string   path;
    std::string   partial;
    unsigned int  rows     = 0;
    unsigned int  old_rows = 0;
    std::ofstream file;
  };

  /**
   * Edge length of the cells at refinement level @p level of @p scene's
   * box: SceneParameters::band_cell_size() with the maximum level set to
   * @p level. The drivers tie the band, the filter and the step to it.
   */
  double
  cell_size(const SceneParameters &scene, const unsigned int level);
} // namespace levelsinter::study
