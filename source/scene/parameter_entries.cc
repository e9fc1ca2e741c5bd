#include <deal.II/base/utilities.h>

#include <levelsinter/scene/parameter_entries.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <stdexcept>

namespace levelsinter
{
  void
  fail_entry(const std::string &entry, const std::string &what)
  {
    throw std::runtime_error("entry '" + entry + "': " + what);
  }

  void
  check_text_file(const std::string &file_name, const std::string &what)
  {
    const std::string named = what + " '" + file_name + "'";
    if (std::filesystem::is_directory(file_name))
      throw std::runtime_error(named + " is a directory, not a file");
    std::ifstream in(file_name, std::ios::binary);
    if (!in)
      throw std::runtime_error(named + " cannot be opened for reading");
    const std::string text((std::istreambuf_iterator<char>(in)),
                           std::istreambuf_iterator<char>());
    const auto binary = std::find_if(text.begin(), text.end(), [](char c) {
      const auto u = static_cast<unsigned char>(c);
      return (u < 0x20 && std::string("\t\n\r\f\v").find(c) ==
                            std::string::npos) ||
             u == 0x7f;
    });
    if (binary != text.end())
      throw std::runtime_error(
        named + " is not a text file (a binary byte on line " +
        std::to_string(std::count(text.begin(), binary, '\n') + 1) +
        "): give a text file");
  }

  std::vector<double>
  read_coordinates(ParameterHandler  &prm,
                   const std::string &section,
                   const std::string &entry,
                   const unsigned int n)
  {
    const std::string   text = prm.get(entry);
    std::vector<double> values;
    try
      {
        values =
          Utilities::string_to_double(Utilities::split_string_list(text, ','));
      }
    catch (...)
      {
        fail_entry(section + "/" + entry,
                   "'" + text + "' is not a comma-separated list of numbers");
      }
    if (values.size() != n)
      fail_entry(section + "/" + entry,
                 "needs " + std::to_string(n) +
                   " comma-separated numbers (one per coordinate), got '" +
                   text + "'");
    for (const double v : values)
      if (!std::isfinite(v))
        fail_entry(section + "/" + entry, "contains a non-finite number");
    return values;
  }
} // namespace levelsinter
