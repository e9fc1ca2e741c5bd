#include <deal.II/base/utilities.h>

#include "study_support.h"

#include <algorithm>
#include <fstream>
#include <stdexcept>

namespace levelsinter::study
{
  CsvTable::CsvTable(const std::string &file_name)
    : file_name(file_name)
  {
    std::ifstream in(file_name);
    std::string   line;
    if (!in || !std::getline(in, line))
      throw std::runtime_error("cannot read a header line from '" +
                               file_name + "'");
    names = Utilities::split_string_list(line, ',');
    values.resize(names.size());
    while (std::getline(in, line))
      {
        const auto fields = Utilities::split_string_list(line, ',');
        if (fields.size() != names.size())
          throw std::runtime_error(
            "'" + file_name + "', line " + std::to_string(rows + 2) +
            ": " + std::to_string(fields.size()) + " values for " +
            std::to_string(names.size()) + " columns");
        for (unsigned int c = 0; c < names.size(); ++c)
          values[c].push_back(std::stod(fields[c]));
        ++rows;
      }
  }

  bool
  CsvTable::has_column(const std::string &name) const
  {
    return std::find(names.begin(), names.end(), name) != names.end();
  }

  const std::vector<double> &
  CsvTable::column(const std::string &name) const
  {
    const auto it = std::find(names.begin(), names.end(), name);
    if (it == names.end())
      throw std::runtime_error("'" + file_name + "' has no column " + name);
    return values[it - names.begin()];
  }

  double
  cell_size(const SceneParameters &scene, const unsigned int level)
  {
    SceneParameters at_level      = scene;
    at_level.refinement.max_level = level;
    return at_level.band_cell_size();
  }
} // namespace levelsinter::study
