#include <levelsinter/io/metrics_log.h>

#include <cstdio>
#include <iomanip>
#include <sstream>
#include <stdexcept>

namespace levelsinter
{
  MetricsLog::MetricsLog(const std::string              &file_name,
                         const std::vector<std::string> &columns,
                         const MPI_Comm                  comm,
                         const std::optional<unsigned int> kept_rows)
    : column_names(columns)
    , root(dealii::Utilities::MPI::this_mpi_process(comm) == 0)
    , rows(kept_rows.value_or(0))
  {
    if (!root)
      return;
    std::string header;
    for (unsigned int i = 0; i < columns.size(); ++i)
      header += (i ? "," : "") + columns[i];
    if (kept_rows)
      {
        // The rows after the checkpoint are written again by the resumed
        // run.
        std::ifstream      in(file_name);
        std::ostringstream kept;
        std::string        line;
        if (!std::getline(in, line) || line != header)
          throw std::runtime_error("'" + file_name +
                                   "' is missing or its header does not "
                                   "name the columns of this run: " +
                                   header);
        kept << line << '\n';
        for (unsigned int r = 0; r < *kept_rows; ++r)
          {
            if (!std::getline(in, line))
              throw std::runtime_error("'" + file_name + "' has fewer than " +
                                       std::to_string(*kept_rows) +
                                       " rows, the checkpoint's count");
            kept << line << '\n';
          }
        in.close();
        out.open(file_name + ".tmp");
        out << kept.str();
        out.close();
        std::rename((file_name + ".tmp").c_str(), file_name.c_str());
        out.open(file_name, std::ios::app);
        if (!out)
          throw std::runtime_error("cannot write '" + file_name + "'");
        return;
      }
    out.open(file_name);
    if (!out)
      throw std::runtime_error("cannot write '" + file_name + "'");
    out << header << std::endl;
  }

  void
  MetricsLog::add_row(const std::vector<double> &values)
  {
    std::vector<std::string> cells;
    for (const double value : values)
      cells.push_back(format(value));
    add_text_row(cells);
  }

  void
  MetricsLog::add_text_row(const std::vector<std::string> &cells)
  {
    if (cells.size() != column_names.size())
      throw std::logic_error("metrics row has the wrong number of columns");
    ++rows;
    if (!root)
      return;
    for (unsigned int i = 0; i < cells.size(); ++i)
      out << (i ? "," : "") << cells[i];
    out << std::endl;
  }

  std::string
  MetricsLog::format(const double value)
  {
    std::ostringstream text;
    text << std::setprecision(12) << value;
    return text.str();
  }
} // namespace levelsinter
