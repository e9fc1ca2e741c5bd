// compare_metrics A.csv B.csv TOLERANCE [IGNORED_COLUMN...]
// Exit 0 if the two metrics files have the same columns and rows and every
// value agrees to TOLERANCE, relative to max(|a|, |b|, 1e-12); columns named
// after the tolerance (e.g. wall_time) are skipped.
#include <algorithm>
#include <cmath>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

static std::vector<std::vector<std::string>>
read_csv(const char *name)
{
  std::ifstream                         in(name);
  std::vector<std::vector<std::string>> rows;
  std::string                           line;
  while (std::getline(in, line))
    {
      std::vector<std::string> fields;
      std::stringstream        ss(line);
      std::string              f;
      while (std::getline(ss, f, ','))
        fields.push_back(f);
      rows.push_back(fields);
    }
  return rows;
}

int
main(int argc, char **argv)
{
  if (argc < 4)
    {
      std::cerr << "usage: compare_metrics A.csv B.csv TOLERANCE [COLUMN...]\n";
      return 2;
    }
  const auto                     a = read_csv(argv[1]), b = read_csv(argv[2]);
  const double                   tolerance = std::stod(argv[3]);
  const std::vector<std::string> ignored(argv + 4, argv + argc);
  if (a.empty() || a.size() != b.size() || a[0] != b[0])
    {
      std::cerr << "FAIL: the files differ in header or number of rows ("
                << a.size() << " vs " << b.size() << ")\n";
      return 1;
    }
  double worst = 0;
  for (std::size_t r = 1; r < a.size(); ++r)
    for (std::size_t c = 0; c < a[0].size(); ++c)
      {
        if (std::find(ignored.begin(), ignored.end(), a[0][c]) != ignored.end())
          continue;
        const double x = std::stod(a[r][c]), y = std::stod(b[r][c]);
        const double e =
          std::abs(x - y) / std::max({std::abs(x), std::abs(y), 1e-12});
        if (e > worst)
          worst = e;
        if (e > tolerance)
          {
            std::cerr << "FAIL: row " << r << " column " << a[0][c] << ": "
                      << x << " vs " << y << "\n";
            return 1;
          }
      }
  std::cout << "PASS: largest relative difference " << worst << "\n";
  return 0;
}
