#include <deal.II/base/utilities.h>

#include "study_support.h"

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
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

  namespace
  {
    // The data rows (non-empty lines after the header) of a CSV file; 0 if
    // it cannot be read.
    unsigned int
    data_rows(const std::string &path)
    {
      std::ifstream in(path);
      std::string   line;
      unsigned int  lines = 0;
      while (std::getline(in, line))
        lines += !line.empty();
      return lines > 0 ? lines - 1 : 0;
    }
  } // namespace

  CsvFile::CsvFile(const std::string &path)
    : path(path)
  {
    namespace fs = std::filesystem;
    const fs::path folder =
      fs::weakly_canonical(fs::absolute(path)).parent_path();
    const bool guarded =
      std::find(folder.begin(), folder.end(), "validation_data") !=
        folder.end() &&
      fs::is_regular_file(path);
    const char *replace = std::getenv("LEVELSINTER_REPLACE_SHORTER");
    if (guarded && !(replace && std::string(replace) == "1"))
      old_rows = data_rows(path);
    if (old_rows == 0)
      {
        file.open(path);
        return;
      }
    partial = path + ".partial";
    file.open(partial);
    std::cout << "'" << path << "' holds " << old_rows
              << " rows: this run's rows go to '" << partial
              << "' and replace it once they are as many (set "
              << "LEVELSINTER_REPLACE_SHORTER=1 to replace it at once)"
              << std::endl;
  }

  void
  CsvFile::end_row()
  {
    file << std::flush;
    ++rows;
    // Renaming keeps the open stream: the next rows go to the new name.
    if (!partial.empty() && rows >= old_rows)
      {
        std::filesystem::rename(partial, path);
        partial.clear();
      }
  }

  CsvFile::~CsvFile()
  {
    if (!partial.empty())
      std::cerr << "'" << path << "' kept: it holds " << old_rows
                << " rows, this run gave " << rows << " (in '" << partial
                << "'). A shorter history does not replace a longer one; "
                << "set LEVELSINTER_REPLACE_SHORTER=1 to replace it."
                << std::endl;
  }

  double
  cell_size(const SceneParameters &scene, const unsigned int level)
  {
    SceneParameters at_level      = scene;
    at_level.refinement.max_level = level;
    return at_level.band_cell_size();
  }
} // namespace levelsinter::study
