#include <deal.II/base/utilities.h>

#include <levelsinter/scene/particles.h>

#include <cmath>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace levelsinter
{
  namespace
  {
    // Parse one particle "x, y[, z], r"; returns an empty string on success,
    // or what is wrong.
    std::string
    parse_particle(const std::string   &text,
                   const unsigned int   dim,
                   std::vector<double> &particle)
    {
      const auto fields = dealii::Utilities::split_string_list(text, ',');
      if (fields.size() != dim + 1)
        return "expected " + std::to_string(dim + 1) + " values (" +
               (dim == 2 ? std::string("x, y, r") : "x, y, z, r") +
               "), found " + std::to_string(fields.size()) + " in '" + text +
               "'";
      particle.clear();
      for (const auto &f : fields)
        {
          std::istringstream in(f);
          double             v;
          if (!(in >> v) || !(in >> std::ws).eof() || !std::isfinite(v))
            return "'" + f + "' is not a number";
          particle.push_back(v);
        }
      if (!(particle.back() > 0))
        return "the radius must be positive, found " + fields.back();
      return "";
    }
  } // namespace

  std::vector<std::vector<double>>
  parse_inline_particles(const std::string &text,
                         const unsigned int dim,
                         const std::string &entry_name)
  {
    std::vector<std::vector<double>> particles;
    unsigned int                     index = 0;
    for (const auto &item : dealii::Utilities::split_string_list(text, ';'))
      {
        ++index;
        if (item.empty())
          continue;
        std::vector<double> p;
        const std::string   error = parse_particle(item, dim, p);
        if (!error.empty())
          throw std::runtime_error("entry '" + entry_name + "', particle " +
                                   std::to_string(index) + ": " + error);
        particles.push_back(p);
      }
    return particles;
  }

  std::vector<std::vector<double>>
  read_particle_file(const std::string &file_name, const unsigned int dim)
  {
    std::ifstream in(file_name);
    if (!in)
      throw std::runtime_error("particle file '" + file_name +
                               "' cannot be opened for reading");
    std::vector<std::vector<double>> particles;
    std::string                      line;
    unsigned int                     line_number = 0;
    bool                             header_seen = false;
    while (std::getline(in, line))
      {
        ++line_number;
        const std::string trimmed = dealii::Utilities::trim(line);
        if (trimmed.empty() || trimmed[0] == '#')
          continue;
        if (!header_seen)
          {
            // The header names the columns; a numeric first line means the
            // header is missing, which we refuse rather than guess.
            std::istringstream probe(trimmed);
            double             v;
            if (probe >> v)
              throw std::runtime_error(
                "particle file '" + file_name + "', line " +
                std::to_string(line_number) +
                ": expected a header line such as '" +
                (dim == 2 ? std::string("x,y,r") : "x,y,z,r") +
                "' before the data");
            header_seen = true;
            continue;
          }
        std::vector<double> p;
        const std::string   error = parse_particle(trimmed, dim, p);
        if (!error.empty())
          throw std::runtime_error("particle file '" + file_name +
                                   "', line " + std::to_string(line_number) +
                                   ": " + error);
        particles.push_back(p);
      }
    if (particles.empty())
      throw std::runtime_error("particle file '" + file_name +
                               "' holds no particle");
    return particles;
  }

  void
  check_particles_in_domain(const std::vector<std::vector<double>> &particles,
                            const std::vector<double> &lower_corner,
                            const std::vector<double> &upper_corner)
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
                msg << "particle " << i + 1 << " (centre";
                for (unsigned int k = 0; k < dim; ++k)
                  msg << (k ? ", " : " ") << p[k];
                msg << ", radius " << r
                    << ") is not inside the domain along axis " << d
                    << " [" << lower_corner[d] << ", " << upper_corner[d]
                    << "]; a particle may only be cut by a face its centre "
                       "lies on or across which the list holds its mirror "
                       "image (symmetry plane)";
                throw std::runtime_error(msg.str());
              }
          }
      }
  }
} // namespace levelsinter
