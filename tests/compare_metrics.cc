// compare_metrics A.csv B.csv TOLERANCE [IGNORED_COLUMN...]
// Exit 0 if the two metrics files have the same columns and rows and every
// value agrees to TOLERANCE, relative to max(|a|, |b|, 1e-12); columns named
// after the tolerance (e.g. wall_time) are skipped, and may be missing from
// one of the files.
#include "study_support.h"

#include <algorithm>
#include <cmath>
#include <iostream>
#include <string>
#include <vector>

using levelsinter::study::CsvTable;

int
main(int argc, char **argv)
{
  if (argc < 4)
    {
      std::cerr << "usage: compare_metrics A.csv B.csv TOLERANCE [COLUMN...]\n";
      return 2;
    }
  try
    {
      const CsvTable a(argv[1]), b(argv[2]);
      const double   tolerance = std::stod(argv[3]);
      const std::vector<std::string> ignored(argv + 4, argv + argc);
      // Ignored columns may be missing from one file (e.g. the metrics a
      // viscoelastic melt adds to a Newtonian run's).
      const auto compared = [&](const CsvTable &table) {
        std::vector<std::string> names;
        for (const auto &name : table.columns())
          if (std::find(ignored.begin(), ignored.end(), name) == ignored.end())
            names.push_back(name);
        return names;
      };
      if (a.n_rows() != b.n_rows() || compared(a) != compared(b))
        {
          std::cerr << "FAIL: the files differ in header or number of rows ("
                    << a.n_rows() + 1 << " vs " << b.n_rows() + 1 << ")\n";
          return 1;
        }
      double worst = 0;
      for (unsigned int r = 0; r < a.n_rows(); ++r)
        for (const auto &name : compared(a))
          {
            const double x = a.column(name)[r], y = b.column(name)[r];
            const double e =
              std::abs(x - y) / std::max({std::abs(x), std::abs(y), 1e-12});
            worst = std::max(worst, e);
            if (e > tolerance)
              {
                std::cerr << "FAIL: row " << r + 1 << " column " << name
                          << ": " << x << " vs " << y << "\n";
                return 1;
              }
          }
      std::cout << "PASS: largest relative difference " << worst << "\n";
      return 0;
    }
  catch (const std::exception &e)
    {
      std::cerr << "FAIL: " << e.what() << "\n";
      return 1;
    }
}
