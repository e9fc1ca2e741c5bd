#pragma once

// Shared by the validation drivers: the options of a study (limits, CSV
// file, scene overrides), a table printed on rank 0 and optionally written
// as CSV (CsvFile's rule for doc/validation_data), and the checks of
// measured values against limits.

#include <deal.II/base/mpi.h>
#include <deal.II/base/utilities.h>

#include "study_support.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <limits>
#include <map>
#include <memory>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace levelsinter::study
{
  inline bool
  is_root()
  {
    return dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0;
  }

  // Least-squares line y = intercept + slope x.
  struct Line
  {
    double slope     = std::numeric_limits<double>::quiet_NaN();
    double intercept = std::numeric_limits<double>::quiet_NaN();
    unsigned int points = 0;
  };

  inline Line
  least_squares(const std::vector<double> &x, const std::vector<double> &y)
  {
    Line         line;
    const double n = x.size();
    line.points    = x.size();
    if (x.size() < 2)
      return line;
    double sx = 0, sy = 0, sxx = 0, sxy = 0;
    for (unsigned int i = 0; i < x.size(); ++i)
      {
        sx += x[i];
        sy += y[i];
        sxx += x[i] * x[i];
        sxy += x[i] * y[i];
      }
    line.slope     = (n * sxy - sx * sy) / (n * sxx - sx * sx);
    line.intercept = (sy - line.slope * sx) / n;
    return line;
  }

  struct Options
  {
    // --max-volume-error 1e-3 ...: limits and numeric settings by name.
    std::map<std::string, double> limits;
    std::string                   csv;
    // --set "Section/Entry=value": scene overrides for every run.
    std::vector<std::pair<std::string, std::string>> overrides;
  };

  /** Comma-separated refinement levels, e.g. "4,5,6". */
  inline std::vector<unsigned int>
  parse_levels(const std::string &list)
  {
    std::vector<unsigned int> levels;
    for (const auto v : dealii::Utilities::string_to_int(
           dealii::Utilities::split_string_list(list, ',')))
      levels.push_back(v);
    return levels;
  }

  /** Pairs "--csv FILE", "--set ENTRY=VALUE", "--NAME NUMBER" from first. */
  inline Options
  parse_options(const std::vector<std::string> &args, const unsigned int first)
  {
    Options o;
    for (unsigned int i = first; i < args.size(); i += 2)
      {
        if (i + 1 == args.size())
          throw std::runtime_error("option " + args[i] + " needs a value");
        if (args[i] == "--csv")
          o.csv = args[i + 1];
        else if (args[i] == "--set")
          {
            const auto eq = args[i + 1].find('=');
            if (eq == std::string::npos)
              throw std::runtime_error("--set needs ENTRY=VALUE, got " +
                                       args[i + 1]);
            o.overrides.emplace_back(args[i + 1].substr(0, eq),
                                     args[i + 1].substr(eq + 1));
          }
        else if (args[i].rfind("--", 0) == 0)
          o.limits[args[i].substr(2)] = std::stod(args[i + 1]);
        else
          throw std::runtime_error("unexpected argument " + args[i]);
      }
    return o;
  }

  /** Number of failed checks so far: the drivers' exit code. */
  inline unsigned int &
  failures()
  {
    static unsigned int n = 0;
    return n;
  }

  /**
   * Compare a measured value with the limit @p limit_name if the options
   * give one, print the verdict, count a failure (a NaN always fails).
   */
  inline void
  check(const std::string &what,
        const double       value,
        const Options     &options,
        const std::string &limit_name,
        const bool         is_upper_bound = true)
  {
    const auto it = options.limits.find(limit_name);
    if (it == options.limits.end())
      return;
    const bool ok = std::isfinite(value) &&
                    (is_upper_bound ? value <= it->second : value >= it->second);
    failures() += !ok;
    if (is_root())
      std::cout << (ok ? "PASS " : "FAIL ") << what << " = " << value
                << (is_upper_bound ? " <= " : " >= ") << it->second << "\n";
  }

  /** Rows printed on rank 0 as they come and, optionally, written as CSV. */
  class Table
  {
  public:
    Table(const std::vector<std::string> &columns, const std::string &csv)
      : columns(columns)
    {
      for (const auto &c : columns)
        widths.push_back(std::max<int>(12, c.size() + 2));
      if (!is_root())
        return;
      if (!csv.empty())
        {
          file = std::make_unique<CsvFile>(csv);
          for (unsigned int i = 0; i < columns.size(); ++i)
            file->stream() << (i ? "," : "") << columns[i];
          file->stream() << "\n";
        }
      for (unsigned int i = 0; i < columns.size(); ++i)
        std::cout << std::setw(widths[i]) << columns[i];
      std::cout << "\n";
    }

    void
    add(const std::vector<double> &row)
    {
      rows.push_back(row);
      if (!is_root())
        return;
      for (unsigned int i = 0; i < row.size(); ++i)
        {
          std::cout << std::setw(widths[i]) << std::setprecision(5) << row[i];
          if (file)
            file->stream() << (i ? "," : "") << std::setprecision(10)
                           << row[i];
        }
      std::cout << std::endl;
      if (file)
        {
          file->stream() << "\n";
          file->end_row();
        }
    }

    /**
     * Observed order between the two last rows of column @p c against
     * column "h"; NaN with a single row (a check on it then fails).
     */
    double
    order(const std::string &c) const
    {
      if (rows.size() < 2)
        return std::numeric_limits<double>::quiet_NaN();
      const unsigned int k = index(c), h = index("h");
      const auto        &a = rows[rows.size() - 2];
      const auto        &b = rows.back();
      return std::log(a[k] / b[k]) / std::log(a[h] / b[h]);
    }

    /** Value of column @p c in the last row. */
    double
    finest(const std::string &c) const
    {
      return rows.back()[index(c)];
    }

  private:
    unsigned int
    index(const std::string &c) const
    {
      const auto it = std::find(columns.begin(), columns.end(), c);
      if (it == columns.end())
        throw std::logic_error("no column " + c);
      return it - columns.begin();
    }

    std::vector<std::string>         columns;
    std::vector<int>                 widths;
    std::vector<std::vector<double>> rows;
    std::unique_ptr<CsvFile>         file;
  };
} // namespace levelsinter::study
