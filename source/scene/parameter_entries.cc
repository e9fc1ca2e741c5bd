#include <deal.II/base/utilities.h>

#include <levelsinter/scene/parameter_entries.h>

#include <cmath>
#include <stdexcept>

namespace levelsinter
{
  void
  fail_entry(const std::string &entry, const std::string &what)
  {
    throw std::runtime_error("entry '" + entry + "': " + what);
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
