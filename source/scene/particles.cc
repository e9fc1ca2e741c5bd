#include <deal.II/base/utilities.h>

#include <levelsinter/scene/parameter_entries.h>
#include <levelsinter/scene/particles.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace levelsinter
{
  namespace
  {
    // Parse one particle from a row whose fields hold x, y[, z], r at
    // column[0..dim]; returns an empty string on success, or what is wrong.
    std::string
    parse_particle(const std::string               &text,
                   const std::vector<unsigned int> &column,
                   std::vector<double>             &particle)
    {
      const unsigned int dim    = column.size() - 1;
      const auto fields = dealii::Utilities::split_string_list(text, ',');
      if (fields.size() != dim + 1)
        return "expected " + std::to_string(dim + 1) + " values (" +
               (dim == 2 ? std::string("x, y, r") : "x, y, z, r") +
               "), found " + std::to_string(fields.size()) + " in '" + text +
               "'";
      std::vector<double> values;
      for (const auto &f : fields)
        {
          std::istringstream in(f);
          double             v;
          if (!(in >> v) || !(in >> std::ws).eof() || !std::isfinite(v))
            return "'" + f + "' is not a number";
          values.push_back(v);
        }
      particle.resize(dim + 1);
      for (unsigned int k = 0; k <= dim; ++k)
        particle[k] = values[column[k]];
      if (!(particle.back() > 0))
        return "the radius must be positive, found " + fields[column.back()];
      return "";
    }

    std::vector<unsigned int>
    in_order(const unsigned int dim)
    {
      std::vector<unsigned int> column(dim + 1);
      for (unsigned int k = 0; k <= dim; ++k)
        column[k] = k;
      return column;
    }
  } // namespace

  std::vector<std::vector<double>>
  parse_inline_particles(const std::string &text,
                         const unsigned int dim,
                         const std::string &entry_name,
                         const std::string &item_name)
  {
    std::vector<std::vector<double>> particles;
    unsigned int                     index = 0;
    for (const auto &item : dealii::Utilities::split_string_list(text, ';'))
      {
        ++index;
        if (item.empty())
          continue;
        std::vector<double> p;
        const std::string   error = parse_particle(item, in_order(dim), p);
        if (!error.empty())
          throw std::runtime_error("entry '" + entry_name + "', " +
                                   item_name + " " +
                                   std::to_string(index) + ": " + error);
        particles.push_back(p);
      }
    return particles;
  }

  std::vector<std::vector<double>>
  read_particle_file(const std::string         &file_name,
                     const unsigned int         dim,
                     const std::string         &item_name,
                     std::vector<unsigned int> *lines)
  {
    check_text_file(file_name, item_name + " file");
    std::ifstream in(file_name);
    const std::vector<std::string> names =
      dim == 2 ? std::vector<std::string>{"x", "y", "r"} :
                 std::vector<std::string>{"x", "y", "z", "r"};
    const std::string expected = dim == 2 ? "x,y,r" : "x,y,z,r";
    // column[k]: where the k-th of x, y[, z], r stands in a row.
    std::vector<unsigned int>        column;
    std::vector<std::vector<double>> particles;
    std::string                      line;
    unsigned int                     line_number = 0;
    while (std::getline(in, line))
      {
        ++line_number;
        const std::string trimmed = dealii::Utilities::trim(line);
        if (trimmed.empty() || trimmed[0] == '#')
          continue;
        const auto where = [&]() {
          return item_name + " file '" + file_name + "', line " +
                 std::to_string(line_number) + ": ";
        };
        if (column.empty())
          {
            // The header names the columns; anything else (a numeric first
            // line, other names) is refused rather than guessed.
            auto header = dealii::Utilities::split_string_list(trimmed, ',');
            for (auto &h : header)
              std::transform(h.begin(),
                             h.end(),
                             h.begin(),
                             [](unsigned char c) { return std::tolower(c); });
            for (const auto &name : names)
              {
                const auto at = std::find(header.begin(), header.end(), name);
                if (at == header.end() ||
                    std::count(header.begin(), header.end(), name) != 1)
                  break;
                column.push_back(at - header.begin());
              }
            if (header.size() != names.size() || column.size() != names.size())
              throw std::runtime_error(
                where() + "the header '" + trimmed + "' must name the " +
                std::to_string(dim) + "D columns '" + expected +
                "' (any order, case and spaces ignored)");
            continue;
          }
        std::vector<double> p;
        const std::string   error = parse_particle(trimmed, column, p);
        if (!error.empty())
          throw std::runtime_error(where() + error);
        particles.push_back(p);
        if (lines)
          lines->push_back(line_number);
      }
    if (particles.empty())
      throw std::runtime_error(item_name + " file '" + file_name +
                               "' holds no " + item_name);
    return particles;
  }

  void
  check_particle_pairs(const std::vector<std::vector<double>> &particles,
                       const std::vector<std::string>         &origins,
                       const double                            cell)
  {
    const auto describe = [&](const unsigned int i) {
      const auto        &p   = particles[i];
      const unsigned int dim = p.size() - 1;
      std::ostringstream text;
      text << "particle " << i + 1 << " ("
           << (i < origins.size() ? origins[i] + ": " : "") << "centre ";
      for (unsigned int k = 0; k < dim; ++k)
        text << (k ? ", " : "") << p[k];
      text << ", radius " << p[dim] << ")";
      return text.str();
    };
    for (unsigned int i = 0; i < particles.size(); ++i)
      for (unsigned int j = i + 1; j < particles.size(); ++j)
        {
          const auto  &p = particles[i], &q = particles[j];
          const auto   dim = p.size() - 1;
          double       d2  = 0;
          for (unsigned int k = 0; k < dim; ++k)
            d2 += (p[k] - q[k]) * (p[k] - q[k]);
          const double d = std::sqrt(d2);
          // The smaller one first: it is the one inside.
          const bool         i_smaller = p[dim] <= q[dim];
          const unsigned int small = i_smaller ? i : j, large = i_smaller ? j : i;
          std::ostringstream msg;
          if (d + particles[small][dim] <=
              particles[large][dim] * (1 + 1e-12))
            msg << describe(small) << " lies inside " << describe(large)
                << ": a particle inside another has no surface of its own "
                   "and no neck to sinter; remove it";
          else if (d < cell)
            msg << describe(i) << " and " << describe(j) << " have centres "
                << d << " apart, less than one cell of the interface band ("
                << cell
                << "): the mesh shows them as one particle, with no neck "
                   "or gap between them; remove one (a row given twice?) "
                   "or move them apart";
          else
            continue;
          throw std::runtime_error(msg.str());
        }
  }

  void
  check_particles_in_domain(const std::vector<std::vector<double>> &particles,
                            const std::vector<double> &lower_corner,
                            const std::vector<double> &upper_corner,
                            const std::string         &item_name)
  {
    const unsigned int dim = lower_corner.size();
    // A particle that crosses a face is its own mirror image there if its
    // centre lies on the face, or has one in the list: the scene is then
    // symmetric about the face (e.g. the neck plane of a pair).
    const auto mirrored = [&](const std::vector<double> &p,
                              const unsigned int         d,
                              const double               face,
                              const double               tol) {
      for (const auto &q : particles)
        {
          bool same = std::abs(q[d] - (2 * face - p[d])) <= tol &&
                      std::abs(q[dim] - p[dim]) <= tol;
          for (unsigned int k = 0; k < dim && same; ++k)
            same = k == d || std::abs(q[k] - p[k]) <= tol;
          if (same)
            return true;
        }
      return false;
    };
    for (unsigned int i = 0; i < particles.size(); ++i)
      {
        const auto  &p = particles[i];
        const double r = p[dim];
        for (unsigned int d = 0; d < dim; ++d)
          {
            const double size = upper_corner[d] - lower_corner[d];
            const double tol  = 1e-12 * size;
            const double lo = lower_corner[d], hi = upper_corner[d];
            const bool   crosses_lower = p[d] - r < lo - tol;
            const bool   crosses_upper = p[d] + r > hi + tol;
            if (p[d] + r < lo - tol || p[d] - r > hi + tol ||
                (crosses_lower && !mirrored(p, d, lo, tol)) ||
                (crosses_upper && !mirrored(p, d, hi, tol)))
              {
                std::ostringstream msg;
                msg << item_name << " " << i + 1 << " (centre";
                for (unsigned int k = 0; k < dim; ++k)
                  msg << (k ? ", " : " ") << p[k];
                msg << ", radius " << r
                    << ") is not inside the domain along axis " << d
                    << " [" << lower_corner[d] << ", " << upper_corner[d]
                    << "]; a " << item_name
                    << " may only be cut by a face its centre "
                       "lies on or across which the list holds its mirror "
                       "image (symmetry plane)";
                throw std::runtime_error(msg.str());
              }
          }
      }
  }
} // namespace levelsinter
