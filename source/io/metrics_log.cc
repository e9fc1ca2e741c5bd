#include <levelsinter/io/metrics_log.h>

#include <iomanip>
#include <stdexcept>

namespace levelsinter
{
  MetricsLog::MetricsLog(const std::string              &file_name,
                         const std::vector<std::string> &columns,
                         const MPI_Comm                  comm)
    : column_names(columns)
    , root(dealii::Utilities::MPI::this_mpi_process(comm) == 0)
  {
    if (!root)
      return;
    out.open(file_name);
    if (!out)
      throw std::runtime_error("cannot write '" + file_name + "'");
    for (unsigned int i = 0; i < columns.size(); ++i)
      out << (i ? "," : "") << columns[i];
    out << std::endl;
  }

  void
  MetricsLog::add_row(const std::vector<double> &values)
  {
    if (values.size() != column_names.size())
      throw std::logic_error("metrics row has the wrong number of columns");
    if (!root)
      return;
    out << std::setprecision(12);
    for (unsigned int i = 0; i < values.size(); ++i)
      out << (i ? "," : "") << values[i];
    out << std::endl;
  }
} // namespace levelsinter
