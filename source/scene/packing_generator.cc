#include <levelsinter/scene/packing_generator.h>
#include <levelsinter/scene/particles.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <map>
#include <random>
#include <sstream>
#include <stdexcept>

namespace levelsinter
{
  namespace packing
  {
    namespace
    {
      using Point = std::array<double, 3>;

      constexpr double pi = 3.14159265358979323846;

      double
      ball_measure(const unsigned int dim, const double r)
      {
        return dim == 2 ? pi * r * r : 4. / 3. * pi * r * r * r;
      }

      std::string
      to_string(const double v)
      {
        std::ostringstream out;
        out << v;
        return out.str();
      }

      /**
       * The container's faces: hard walls, symmetry planes or periodic, and
       * the copies of a particle that its neighbours see across them (a
       * ghost: the particle translated by a period or mirrored in one or
       * more symmetry planes).
       */
      struct Container
      {
        unsigned int        dim;
        std::vector<double> lower, upper;
        bool                periodic;
        std::vector<bool>   symmetry, symmetry_upper;

        double
        plane(const unsigned int d) const
        {
          return symmetry_upper[d] ? upper[d] : lower[d];
        }

        // A hard wall on both faces of axis d, or on the face opposite its
        // symmetry plane.
        bool
        wall(const unsigned int d, const bool upper_face) const
        {
          return !periodic && !(symmetry[d] && symmetry_upper[d] == upper_face);
        }

        // The point about which scaling keeps the container's symmetry
        // planes where they are (and otherwise its centre).
        double
        scaling_origin(const unsigned int d) const
        {
          return symmetry[d] ? plane(d) : 0.5 * (lower[d] + upper[d]);
        }

        void
        scale(const double c)
        {
          for (unsigned int d = 0; d < dim; ++d)
            {
              const double o = scaling_origin(d);
              lower[d]       = o + c * (lower[d] - o);
              upper[d]       = o + c * (upper[d] - o);
            }
        }
      };

      struct Ghost
      {
        Point        x;
        unsigned int owner;
        // Each axis: 0 = unchanged, +-1 = shifted by a period, 2 = mirrored.
        std::array<int, 3> transform;
      };

      // The copies of particle x within @p cutoff of the container (beyond
      // the periodic faces or the symmetry planes), the particle included
      // with an identity transform first.
      void
      add_ghosts(const Container   &box,
                 const Point       &x,
                 const unsigned int owner,
                 const double       cutoff,
                 std::vector<Ghost> &ghosts)
      {
        // Per axis the options: identity, and the periodic shifts or the
        // mirror that land within the cutoff of the container.
        // (transform, coordinate); at most identity and two shifts.
        std::array<std::array<std::pair<int, double>, 3>, 3> options;
        std::array<unsigned int, 3>                           n_options = {{1, 1, 1}};
        for (unsigned int d = 0; d < box.dim; ++d)
          {
            options[d][0] = {0, x[d]};
            if (box.periodic)
              {
                const double period = box.upper[d] - box.lower[d];
                for (const int shift : {-1, 1})
                  {
                    const double y = x[d] + shift * period;
                    if (y >= box.lower[d] - cutoff && y <= box.upper[d] + cutoff)
                      options[d][n_options[d]++] = {shift, y};
                  }
              }
            else if (box.symmetry[d] && std::abs(x[d] - box.plane(d)) <= cutoff)
              options[d][n_options[d]++] = {2, 2 * box.plane(d) - x[d]};
          }
        std::array<unsigned int, 3> index = {{0, 0, 0}};
        while (true)
          {
            Ghost g{{{0, 0, 0}}, owner, {{0, 0, 0}}};
            for (unsigned int d = 0; d < box.dim; ++d)
              {
                g.transform[d] = options[d][index[d]].first;
                g.x[d]         = options[d][index[d]].second;
              }
            ghosts.push_back(g);
            unsigned int d = 0;
            for (; d < box.dim; ++d)
              if (++index[d] < n_options[d])
                break;
              else
                index[d] = 0;
            if (d == box.dim)
              break;
          }
      }

      /**
       * Particles and their ghosts sorted into cells of side >= cutoff over
       * the container widened by the cutoff: the neighbours of a point
       * closer than the cutoff are in its cell and the adjacent ones.
       */
      class CellList
      {
      public:
        CellList(const Container        &box,
                 const std::vector<Point> &x,
                 const double              cutoff)
          : dim(box.dim)
        {
          for (unsigned int i = 0; i < x.size(); ++i)
            add_ghosts(box, x[i], i, cutoff, ghosts);
          unsigned long n_total = 1;
          for (unsigned int d = 0; d < dim; ++d)
            {
              origin[d]  = box.lower[d] - cutoff;
              const double extent = box.upper[d] - box.lower[d] + 2 * cutoff;
              n_cells[d] = std::max(1, static_cast<int>(extent / cutoff));
              // Bounded so that a tiny cutoff cannot ask for a huge grid.
              n_cells[d] = std::min(n_cells[d], 256);
              cell_size[d] = extent / n_cells[d];
              n_total *= n_cells[d];
            }
          // Counting sort: the ghosts of cell c are sorted[start[c]] to
          // sorted[start[c + 1] - 1].
          start.assign(n_total + 1, 0);
          std::vector<unsigned long> cell(ghosts.size());
          for (unsigned int k = 0; k < ghosts.size(); ++k)
            ++start[(cell[k] = cell_index(cell_of(ghosts[k].x))) + 1];
          for (unsigned long c = 0; c < n_total; ++c)
            start[c + 1] += start[c];
          sorted.resize(ghosts.size());
          std::vector<unsigned int> fill(start.begin(), start.end() - 1);
          for (unsigned int k = 0; k < ghosts.size(); ++k)
            sorted[fill[cell[k]]++] = k;
        }

        // Calls f(ghost) for every particle or ghost in the cells around p.
        template <typename F>
        void
        for_each_near(const Point &p, const F &f) const
        {
          const auto c = cell_of(p);
          std::array<int, 3> lo = {{0, 0, 0}}, hi = {{0, 0, 0}};
          for (unsigned int d = 0; d < dim; ++d)
            {
              lo[d] = std::max(0, c[d] - 1);
              hi[d] = std::min(n_cells[d] - 1, c[d] + 1);
            }
          for (int a = lo[0]; a <= hi[0]; ++a)
            for (int b = lo[1]; b <= hi[1]; ++b)
              for (int e = lo[2]; e <= hi[2]; ++e)
                {
                  const unsigned long c = cell_index({{a, b, e}});
                  for (unsigned int k = start[c]; k < start[c + 1]; ++k)
                    f(ghosts[sorted[k]]);
                }
        }

        std::vector<Ghost> ghosts;

      private:
        std::array<int, 3>
        cell_of(const Point &p) const
        {
          std::array<int, 3> c = {{0, 0, 0}};
          for (unsigned int d = 0; d < dim; ++d)
            c[d] = std::clamp(static_cast<int>(
                                std::floor((p[d] - origin[d]) / cell_size[d])),
                              0,
                              n_cells[d] - 1);
          return c;
        }

        unsigned long
        cell_index(const std::array<int, 3> &c) const
        {
          return (static_cast<unsigned long>(c[2]) * n_cells[1] + c[1]) *
                   n_cells[0] +
                 c[0];
        }

        unsigned int                         dim;
        Point                                origin    = {{0, 0, 0}};
        Point                                cell_size = {{1, 1, 1}};
        std::array<int, 3>                   n_cells   = {{1, 1, 1}};
        std::vector<unsigned int>            start, sorted;
      };

      double
      distance(const Point &a, const Point &b, const unsigned int dim)
      {
        double s = 0;
        for (unsigned int d = 0; d < dim; ++d)
          s += (a[d] - b[d]) * (a[d] - b[d]);
        return std::sqrt(s);
      }

      bool
      is_self(const Ghost &g, const unsigned int i)
      {
        return g.owner == i && g.transform == std::array<int, 3>{{0, 0, 0}};
      }

      bool
      is_mirror(const Ghost &g)
      {
        return std::find(g.transform.begin(), g.transform.end(), 2) !=
               g.transform.end();
      }

      std::vector<double>
      sample_radii(const Settings &s, std::mt19937_64 &rng)
      {
        std::vector<double> r(s.n_particles);
        if (s.distribution == RadiusDistribution::constant)
          {
            std::fill(r.begin(), r.end(), s.r_min);
            return r;
          }
        std::uniform_real_distribution<double> uniform(s.r_min, s.r_max);
        std::normal_distribution<double> normal(s.r_mean,
                                                s.r_std > 0 ? s.r_std : 1.);
        // Mean and standard deviation of the radius, not of its logarithm
        // (both positive here: Settings::check).
        const bool   ln = s.distribution == RadiusDistribution::log_normal;
        const double sigma2 =
          ln ? std::log1p(s.r_std * s.r_std / (s.r_mean * s.r_mean)) : 1.;
        std::lognormal_distribution<double> log_normal(
          ln ? std::log(s.r_mean) - 0.5 * sigma2 : 0., std::sqrt(sigma2));
        for (double &v : r)
          for (unsigned int attempt = 0;; ++attempt)
            {
              if (attempt == 1000000)
                throw std::runtime_error(
                  "--radius-mean / --radius-std: a million draws fell outside "
                  "[--radius-min, --radius-max]; widen the bounds");
              v = s.distribution == RadiusDistribution::uniform ? uniform(rng) :
                  s.distribution == RadiusDistribution::normal  ? normal(rng) :
                                                                  log_normal(rng);
              if (v >= s.r_min && v <= s.r_max)
                break;
            }
        return r;
      }

      /**
       * The force-biased densification in the region (see the header). The
       * radii are r_i s; returns the final scale s (the inner scale when
       * jammed, or the one giving the target fraction).
       */
      double
      densify(const Settings            &s,
              const Container           &box,
              const std::vector<double> &r,
              std::vector<Point>        &x,
              Result                    &result)
      {
        const unsigned int dim = s.dim;
        double             volume = 1, solid = 0, r_max = 0;
        for (unsigned int d = 0; d < dim; ++d)
          volume *= box.upper[d] - box.lower[d];
        for (const double v : r)
          {
            solid += ball_measure(dim, v);
            r_max = std::max(r_max, v);
          }
        const auto fraction = [&](const double scale) {
          return std::pow(scale, dim) * solid / volume;
        };
        const auto scale_of = [&](const double phi) {
          return std::pow(phi * volume / solid, 1. / dim);
        };

        // Bezrukov et al. start from the nominal density 1.
        double phi_out = 1;
        // Displacement per step as a fraction of the outer overlap (0.9:
        // measured 2x fewer iterations than 0.5 for the same density).
        const double       push = 0.9;
        std::vector<Point> dx(x.size());
        for (unsigned int it = 0; it < s.max_iterations; ++it)
          {
            const double s_out  = scale_of(phi_out);
            const double cutoff = 2 * s_out * r_max;
            CellList     cells(box, x, cutoff);
            double       s_in = s_out;
            for (unsigned int i = 0; i < x.size(); ++i)
              {
                dx[i] = {{0, 0, 0}};
                cells.for_each_near(x[i], [&](const Ghost &g) {
                  if (is_self(g, i))
                    return;
                  const double dist = distance(x[i], g.x, dim);
                  const double sum  = r[i] + r[g.owner];
                  s_in              = std::min(s_in, dist / sum);
                  const double overlap = s_out * sum - dist;
                  if (overlap <= 0 || dist == 0)
                    return;
                  // The lighter particle moves more; its own mirror image
                  // moves with it, so it takes half.
                  const double w =
                    g.owner == i ?
                      0.5 :
                      std::pow(r[g.owner], dim) /
                        (std::pow(r[i], dim) + std::pow(r[g.owner], dim));
                  for (unsigned int d = 0; d < dim; ++d)
                    dx[i][d] += push * w * overlap * (x[i][d] - g.x[d]) / dist;
                });
                for (unsigned int d = 0; d < dim; ++d)
                  for (const bool upper : {false, true})
                    if (box.wall(d, upper))
                      {
                        const double gap = upper ? box.upper[d] - x[i][d] :
                                                   x[i][d] - box.lower[d];
                        s_in             = std::min(s_in, gap / r[i]);
                        const double overlap = s_out * r[i] - gap;
                        if (overlap > 0)
                          dx[i][d] += (upper ? -1 : 1) * push * overlap;
                      }
              }
            s_in              = std::max(s_in, 0.);
            result.iterations = it + 1;
            const double phi_in = fraction(s_in);
            if (s.target_fraction > 0 && phi_in >= s.target_fraction)
              {
                result.converged = true;
                return scale_of(s.target_fraction);
              }
            const double gap = phi_out - phi_in;
            // Jammed: the outer and inner densities meet (1e-4: the radii
            // then differ by 5e-5 relative, far below the contact gap).
            if (gap < 1e-4)
              {
                if (s.target_fraction > 0)
                  throw std::runtime_error(
                    "--fraction " + to_string(s.target_fraction) +
                    ": not reached: the packing jammed at solid fraction " +
                    to_string(phi_in) +
                    " (as dense as it gets with these radii and walls, "
                    "after " +
                    std::to_string(it + 1) +
                    " iterations); lower --fraction, or leave it out to "
                    "write the jammed packing");
                result.converged = true;
                return s_in;
              }
            // The contraction of the outer radius (Jodrey & Tory 1985;
            // Bezrukov et al. 2002): slower as the densities approach.
            const int j = static_cast<int>(std::floor(-std::log10(gap)));
            phi_out -= std::pow(0.5, std::max(j, 0)) * gap / s.contraction;
            for (unsigned int i = 0; i < x.size(); ++i)
              for (unsigned int d = 0; d < dim; ++d)
                {
                  double &y = x[i][d];
                  y += dx[i][d];
                  const double period = box.upper[d] - box.lower[d];
                  if (box.periodic)
                    y -= period * std::floor((y - box.lower[d]) / period);
                  else
                    y = std::clamp(y, box.lower[d], box.upper[d]);
                }
          }
        // Not jammed within the iterations: the inner packing is still
        // valid, only looser.
        CellList cells(box, x, 2 * scale_of(phi_out) * r_max);
        double   s_in = scale_of(phi_out);
        for (unsigned int i = 0; i < x.size(); ++i)
          {
            cells.for_each_near(x[i], [&](const Ghost &g) {
              if (!is_self(g, i))
                s_in = std::min(s_in,
                                distance(x[i], g.x, dim) / (r[i] + r[g.owner]));
            });
            for (unsigned int d = 0; d < dim; ++d)
              {
                if (box.wall(d, false))
                  s_in = std::min(s_in, (x[i][d] - box.lower[d]) / r[i]);
                if (box.wall(d, true))
                  s_in = std::min(s_in, (box.upper[d] - x[i][d]) / r[i]);
              }
          }
        if (s.target_fraction > 0)
          throw std::runtime_error(
            "--fraction " + to_string(s.target_fraction) +
            ": not reached in --max-iterations " +
            std::to_string(s.max_iterations) + " (solid fraction " +
            to_string(fraction(s_in)) + ")");
        return s_in;
      }

      // Centre distance at which spheres r1, r2 have the neck x = nu R.
      double
      neck_distance(const double nu, const double r1, const double r2)
      {
        const double x = nu * 2 * r1 * r2 / (r1 + r2);
        return std::sqrt(r1 * r1 - x * x) + std::sqrt(r2 * r2 - x * x);
      }

      struct Pair
      {
        unsigned int       i, j;
        std::array<int, 3> transform;
        double             target;
      };

      // Position of the partner x_j of x_i seen through the transform of a
      // ghost; in a periodic box the image nearest to x_i (the transform's
      // shift changes when a particle is wrapped back into the box).
      Point
      partner(const Container          &box,
              const Point              &xi,
              const Point              &xj,
              const std::array<int, 3> &t)
      {
        Point y = xj;
        for (unsigned int d = 0; d < box.dim; ++d)
          if (box.periodic)
            {
              const double period = box.upper[d] - box.lower[d];
              y[d] -= period * std::round((y[d] - xi[d]) / period);
            }
          else if (t[d] == 2)
            y[d] = 2 * box.plane(d) - xj[d];
        return y;
      }

      // The pairs (j > i, or i's own mirror image) closer than
      // factor (r_i + r_j).
      std::vector<Pair>
      close_pairs(const Container           &box,
                  const std::vector<Point>  &x,
                  const std::vector<double> &r,
                  const double               factor)
      {
        const double r_max  = *std::max_element(r.begin(), r.end());
        CellList     cells(box, x, 2 * r_max * factor);
        std::vector<Pair> pairs;
        for (unsigned int i = 0; i < x.size(); ++i)
          cells.for_each_near(x[i], [&](const Ghost &g) {
            if (g.owner < i || is_self(g, i) ||
                (g.owner == i && !is_mirror(g)))
              return;
            if (distance(x[i], g.x, box.dim) < factor * (r[i] + r[g.owner]))
              pairs.push_back({i, g.owner, g.transform, 0});
          });
        return pairs;
      }

      /**
       * Bring every contacting pair to the centre distance of neck
       * x0/R = nu and keep every other pair at least that far apart:
       * scale the packing (about the container's centre or its symmetry
       * planes) by the mean ratio, then project the pair distances in
       * Gauss-Seidel sweeps, keeping the particles off the walls.
       */
      double
      make_necks(const Settings            &s,
                 Container                 &box,
                 const std::vector<double> &r,
                 std::vector<Point>        &x,
                 std::vector<Pair>         &contacts)
      {
        const unsigned int dim = s.dim;
        if (contacts.empty())
          return 0;
        double ratio = 0;
        for (auto &p : contacts)
          {
            p.target = neck_distance(s.neck_ratio, r[p.i], r[p.j]);
            ratio += p.target /
                     distance(x[p.i], partner(box, x[p.i], x[p.j], p.transform), dim);
          }
        ratio /= contacts.size();
        for (auto &y : x)
          for (unsigned int d = 0; d < dim; ++d)
            y[d] = box.scaling_origin(d) + ratio * (y[d] - box.scaling_origin(d));
        // A periodic box shrinks with its contents; walls stay.
        if (box.periodic)
          box.scale(ratio);

        // Pairs that may come closer than their neck distance meanwhile.
        std::vector<Pair> others = close_pairs(box, x, r, 1.1);
        for (auto &p : others)
          p.target = neck_distance(s.neck_ratio, r[p.i], r[p.j]);

        const double r_min = *std::min_element(r.begin(), r.end());
        const auto   project = [&](const Pair &p, const bool equality) {
          const Point  y    = partner(box, x[p.i], x[p.j], p.transform);
          const double dist = distance(x[p.i], y, dim);
          const double err  = dist - p.target;
          if ((!equality && err >= 0) || dist == 0)
            return 0.;
          Point n;
          for (unsigned int d = 0; d < dim; ++d)
            n[d] = (x[p.i][d] - y[d]) / dist;
          if (p.i == p.j)
            {
              // The particle and its mirror image move together.
              for (unsigned int d = 0; d < dim; ++d)
                x[p.i][d] -= 0.5 * err * n[d];
              return std::abs(err);
            }
          const double mi = std::pow(r[p.i], dim), mj = std::pow(r[p.j], dim);
          const double wi = mj / (mi + mj), wj = mi / (mi + mj);
          for (unsigned int d = 0; d < dim; ++d)
            {
              x[p.i][d] -= wi * err * n[d];
              // j moves by the inverse transform of +wj err n: mirrored
              // axes flip, shifts do not matter.
              x[p.j][d] += (p.transform[d] == 2 ? -1 : 1) * wj * err * n[d];
            }
          return std::abs(err);
        };
        double residual = 0;
        for (unsigned int sweep = 0; sweep < 10000; ++sweep)
          {
            residual = 0;
            for (const auto &p : contacts)
              residual = std::max(residual, project(p, true));
            for (const auto &p : others)
              residual = std::max(residual, project(p, false));
            for (unsigned int i = 0; i < x.size(); ++i)
              for (unsigned int d = 0; d < dim; ++d)
                {
                  const double lo = box.wall(d, false) ? box.lower[d] + r[i] :
                                                         box.lower[d];
                  const double hi = box.wall(d, true) ? box.upper[d] - r[i] :
                                                        box.upper[d];
                  if (!box.periodic)
                    {
                      residual = std::max(
                        {residual, lo - x[i][d], x[i][d] - hi});
                      x[i][d] = std::clamp(x[i][d], lo, hi);
                    }
                }
            if (residual < 1e-10 * r_min)
              break;
          }
        if (box.periodic)
          for (auto &y : x)
            for (unsigned int d = 0; d < dim; ++d)
              {
                const double period = box.upper[d] - box.lower[d];
                y[d] -= period * std::floor((y[d] - box.lower[d]) / period);
              }
        return residual / r_min;
      }

      // Fraction of the box [lo, hi] covered by the particles and their
      // ghosts, sampled at cell centres of spacing h.
      double
      sampled_fraction(const Container           &box,
                       const std::vector<Point>  &x,
                       const std::vector<double> &r,
                       const std::vector<double> &lo,
                       const std::vector<double> &hi,
                       const double               h)
      {
        const double r_max = *std::max_element(r.begin(), r.end());
        CellList     cells(box, x, 2 * r_max);
        std::array<unsigned int, 3> n = {{1, 1, 1}};
        for (unsigned int d = 0; d < box.dim; ++d)
          n[d] = std::max(1u, static_cast<unsigned int>(
                                std::ceil((hi[d] - lo[d]) / h)));
        unsigned long inside = 0;
        Point         p      = {{0, 0, 0}};
        for (unsigned int c = 0; c < n[2]; ++c)
          for (unsigned int b = 0; b < n[1]; ++b)
            for (unsigned int a = 0; a < n[0]; ++a)
              {
                const std::array<unsigned int, 3> k = {{a, b, c}};
                for (unsigned int d = 0; d < box.dim; ++d)
                  p[d] = lo[d] + (k[d] + 0.5) * (hi[d] - lo[d]) / n[d];
                bool covered = false;
                cells.for_each_near(p, [&](const Ghost &g) {
                  covered = covered || distance(p, g.x, box.dim) < r[g.owner];
                });
                inside += covered;
              }
        return static_cast<double>(inside) / (1. * n[0] * n[1] * n[2]);
      }

      double
      parse_number(const std::string &name, const std::string &text)
      {
        std::istringstream in(text);
        double             v;
        if (!(in >> v) || !(in >> std::ws).eof() || !std::isfinite(v))
          throw std::runtime_error(name + ": '" + text + "' is not a number");
        return v;
      }

      // "x0,y0[,z0]:x1,y1[,z1]" into two corners.
      void
      parse_box(const std::string   &name,
                const std::string   &text,
                std::vector<double> &lower,
                std::vector<double> &upper)
      {
        const auto colon = text.find(':');
        if (colon == std::string::npos)
          throw std::runtime_error(name + ": expected 'x0,y0[,z0]:x1,y1[,z1]'"
                                          ", found '" + text + "'");
        for (const bool second : {false, true})
          {
            auto &corner = second ? upper : lower;
            corner.clear();
            std::istringstream in(second ? text.substr(colon + 1) :
                                           text.substr(0, colon));
            std::string        item;
            while (std::getline(in, item, ','))
              corner.push_back(parse_number(name, item));
          }
      }
    } // namespace

    double
    neck_ratio(const double distance, const double r1, const double r2)
    {
      if (distance >= r1 + r2)
        return 0;
      // Distance from centre 1 to the plane of the intersection circle.
      const double a = (distance * distance + r1 * r1 - r2 * r2) / (2 * distance);
      return std::sqrt(std::max(r1 * r1 - a * a, 0.)) /
             (2 * r1 * r2 / (r1 + r2));
    }

    void
    Settings::check() const
    {
      if (dim != 2 && dim != 3)
        throw std::runtime_error("--dim: expected 2 or 3, found " +
                                 std::to_string(dim));
      if (n_particles == 0)
        throw std::runtime_error("--particles: expected a positive number");
      if (!(r_min > 0) || !(r_max >= r_min))
        throw std::runtime_error(
          "radii: expected 0 < --radius-min <= --radius-max (or --radius), "
          "found " + to_string(r_min) + " and " + to_string(r_max));
      if ((distribution == RadiusDistribution::normal ||
           distribution == RadiusDistribution::log_normal) &&
          (!(r_mean >= r_min && r_mean <= r_max) || !(r_std > 0)))
        throw std::runtime_error(
          "--radius-distribution normal / log-normal: expected --radius-mean "
          "within [--radius-min, --radius-max] and --radius-std > 0, found " +
          to_string(r_mean) + " and " + to_string(r_std));
      if (region_lower.size() != dim || region_upper.size() != dim)
        throw std::runtime_error("--region: expected " + std::to_string(dim) +
                                 " coordinates per corner for --dim " +
                                 std::to_string(dim));
      for (unsigned int d = 0; d < dim; ++d)
        if (!(region_upper[d] > region_lower[d]))
          throw std::runtime_error("--region: the upper corner must exceed "
                                   "the lower one along every axis");
      if (!domain_lower.empty() &&
          (domain_lower.size() != dim || domain_upper.size() != dim))
        throw std::runtime_error("--domain: expected " + std::to_string(dim) +
                                 " coordinates per corner for --dim " +
                                 std::to_string(dim));
      if (symmetry.size() != dim || symmetry_upper.size() != dim)
        throw std::runtime_error("--symmetry: internal size mismatch");
      if (periodic &&
          std::find(symmetry.begin(), symmetry.end(), true) != symmetry.end())
        throw std::runtime_error(
          "--symmetry cannot be combined with --periodic");
      if (!(target_fraction >= 0 && target_fraction < 1))
        throw std::runtime_error("--fraction: expected a value in (0, 1), "
                                 "found " + to_string(target_fraction));
      if (!(neck_ratio >= 0 && neck_ratio < 1))
        throw std::runtime_error("--neck: expected x0/R in [0, 1), found " +
                                 to_string(neck_ratio));
      if (!(contact_gap >= 0 && contact_gap < 0.1))
        throw std::runtime_error("--contact-gap: expected a value in [0, "
                                 "0.1), found " + to_string(contact_gap));
      if (!(interior_margin >= 0))
        throw std::runtime_error("--interior-margin: expected a value >= 0");
      if (!(contraction >= 1))
        throw std::runtime_error("--contraction: expected a value >= 1, "
                                 "found " + to_string(contraction));
      if (max_iterations == 0)
        throw std::runtime_error("--max-iterations: expected a positive "
                                 "number");
    }

    Result
    generate(const Settings &s)
    {
      s.check();
      const unsigned int dim = s.dim;
      std::mt19937_64    rng(s.seed);
      const auto         r = sample_radii(s, rng);

      Container box{dim,
                    s.region_lower,
                    s.region_upper,
                    s.periodic,
                    s.symmetry,
                    s.symmetry_upper};
      std::vector<Point> x(s.n_particles, Point{{0, 0, 0}});
      for (auto &y : x)
        for (unsigned int d = 0; d < dim; ++d)
          y[d] = std::uniform_real_distribution<double>(box.lower[d],
                                                        box.upper[d])(rng);

      Result       result;
      const double scale = densify(s, box, r, x, result);

      // Back to the sampled radii: positions and container grow by 1/scale
      // about the container's centre or its symmetry planes.
      for (auto &y : x)
        for (unsigned int d = 0; d < dim; ++d)
          y[d] = box.scaling_origin(d) +
                 (y[d] - box.scaling_origin(d)) / scale;
      box.scale(1 / scale);

      double solid = 0, volume = 1;
      for (const double v : r)
        solid += ball_measure(dim, v);
      for (unsigned int d = 0; d < dim; ++d)
        volume *= box.upper[d] - box.lower[d];
      result.nominal_fraction = solid / volume;

      auto contacts = close_pairs(box, x, r, 1 + s.contact_gap);
      if (s.neck_ratio > 0)
        result.neck_residual = make_necks(s, box, r, x, contacts);

      // Statistics of what is written.
      const unsigned int n = s.n_particles;
      const double r_max   = *std::max_element(r.begin(), r.end());
      const double r_min   = *std::min_element(r.begin(), r.end());
      result.container_lower = box.lower;
      result.container_upper = box.upper;
      result.interior_lower  = box.lower;
      result.interior_upper  = box.upper;
      bool interior_empty    = false;
      for (unsigned int d = 0; d < dim; ++d)
        {
          const double margin = s.interior_margin * 2 * r_max;
          if (box.wall(d, false))
            result.interior_lower[d] += margin;
          if (box.wall(d, true))
            result.interior_upper[d] -= margin;
          interior_empty = interior_empty || result.interior_upper[d] <=
                                               result.interior_lower[d];
        }
      const auto in_interior = [&](const Point &y) {
        for (unsigned int d = 0; d < dim; ++d)
          if (y[d] < result.interior_lower[d] || y[d] > result.interior_upper[d])
            return false;
        return true;
      };

      std::vector<unsigned int> z(n, 0);
      result.n_contacts = contacts.size();
      result.neck_min   = contacts.empty() ? 0 : 1;
      for (const auto &p : contacts)
        {
          ++z[p.i];
          if (p.j != p.i)
            ++z[p.j];
          const double nu = neck_ratio(
            distance(x[p.i], partner(box, x[p.i], x[p.j], p.transform), dim),
            r[p.i],
            r[p.j]);
          result.neck_min = std::min(result.neck_min, nu);
          result.neck_max = std::max(result.neck_max, nu);
          result.neck_mean += nu / contacts.size();
        }
      for (const auto &p : close_pairs(box, x, r, 1))
        {
          const bool contact =
            std::any_of(contacts.begin(), contacts.end(), [&](const Pair &c) {
              return c.i == p.i && c.j == p.j &&
                     (box.periodic || c.transform == p.transform);
            });
          if (contact)
            continue;
          ++result.n_other_overlaps;
          result.other_overlap_neck_max = std::max(
            result.other_overlap_neck_max,
            neck_ratio(distance(x[p.i],
                                partner(box, x[p.i], x[p.j], p.transform),
                                dim),
                       r[p.i],
                       r[p.j]));
        }
      unsigned int n_interior = 0, z_interior = 0, z_all = 0;
      for (unsigned int i = 0; i < n; ++i)
        {
          z_all += z[i];
          if (in_interior(x[i]))
            {
              ++n_interior;
              z_interior += z[i];
            }
        }
      result.coordination = static_cast<double>(z_all) / n;
      result.interior_coordination =
        n_interior ? static_cast<double>(z_interior) / n_interior :
                     std::numeric_limits<double>::quiet_NaN();

      // Sampling: at least 6 points per smallest radius, at most ~4 million
      // points in all.
      double container_volume = 1;
      for (unsigned int d = 0; d < dim; ++d)
        container_volume *= box.upper[d] - box.lower[d];
      result.sample_spacing =
        std::max(r_min / 6, std::pow(container_volume / 4e6, 1. / dim));
      result.fraction = sampled_fraction(
        box, x, r, box.lower, box.upper, result.sample_spacing);
      result.interior_fraction =
        interior_empty ? std::numeric_limits<double>::quiet_NaN() :
                         sampled_fraction(box,
                                          x,
                                          r,
                                          result.interior_lower,
                                          result.interior_upper,
                                          result.sample_spacing);

      // The particles, then the images of those crossing symmetry planes.
      for (unsigned int i = 0; i < n; ++i)
        {
          std::vector<double> row(x[i].begin(), x[i].begin() + dim);
          row.push_back(r[i]);
          result.particles.push_back(row);
        }
      if (!s.periodic)
        for (unsigned int i = 0; i < n; ++i)
          {
            std::vector<Ghost> copies;
            // Ghosts within r of a plane are the images of a particle that
            // crosses it (its centre is on the domain side).
            add_ghosts(box, x[i], i, r[i] * (1 - 1e-12), copies);
            for (const auto &g : copies)
              if (is_mirror(g))
                {
                  std::vector<double> row(g.x.begin(), g.x.begin() + dim);
                  row.push_back(r[i]);
                  result.particles.push_back(row);
                  ++result.n_images;
                }
          }
      if (!s.domain_lower.empty())
        {
          for (unsigned int d = 0; d < dim; ++d)
            if (box.lower[d] < s.domain_lower[d] - 1e-12 ||
                box.upper[d] > s.domain_upper[d] + 1e-12)
              {
                std::ostringstream msg;
                msg << "--domain: the container along axis " << d << " ["
                    << box.lower[d] << ", " << box.upper[d]
                    << "] is not inside the domain [" << s.domain_lower[d]
                    << ", " << s.domain_upper[d]
                    << "]; enlarge the domain or lower the solid fraction";
                throw std::runtime_error(msg.str());
              }
          check_particles_in_domain(result.particles,
                                    s.domain_lower,
                                    s.domain_upper);
        }
      return result;
    }

    std::string
    usage()
    {
      return "Usage: levelsinter-pack --particles N --output FILE.csv "
             "[options]\n"
             "Writes a random packing of N spheres (discs in 2D) as the "
             "particle CSV the scenes read\n"
             "(header x,y,z,r or x,y,r), preceded by '#' lines with its "
             "statistics and the command line.\n"
             "Densification: the force-biased algorithm (Moscinski et al. "
             "1989; Bezrukov, Bargiel & Stoyan 2002).\n"
             "The container is --region scaled about its centre (or its "
             "symmetry planes) so that the particles\n"
             "keep their radii at the solid fraction reached.\n"
             "\n"
             "  --dim 2|3                 dimension (3)\n"
             "  --particles N             number of particles (required)\n"
             "  --radius R                constant radius\n"
             "  --radius-distribution D   constant, uniform, normal or "
             "log-normal (constant)\n"
             "  --radius-min A --radius-max B   bounds of the radii "
             "(uniform, normal, log-normal)\n"
             "  --radius-mean M --radius-std S  mean and standard deviation "
             "of the radius (normal, log-normal;\n"
             "                            draws outside [A, B] are redrawn)\n"
             "  --region LO:HI            shape and centre of the container, "
             "e.g. 0,0,0:1,1,1 (the unit box)\n"
             "  --domain LO:HI            the scene's box: check that the "
             "container and particles fit in it\n"
             "  --fraction PHI            stop at this solid fraction; an "
             "error (nothing written) if the\n"
             "                            packing jams below it, naming the "
             "fraction reached\n"
             "  --dense                   as dense as it gets (the default)\n"
             "  --periodic                periodic container (default: "
             "hard walls)\n"
             "  --symmetry FACES          symmetry planes among x-,x+,y-,"
             "y+,z-,z+ (one per axis): the packing\n"
             "                            is mirror-symmetric there; the "
             "file lists the images of the particles\n"
             "                            that cross a plane\n"
             "  --neck X0R                neck x0/R of the contacting pairs "
             "(R = 2 r_i r_j/(r_i + r_j));\n"
             "                            0 leaves them nearly tangent (0)\n"
             "  --contact-gap G           pairs closer than (r_i + r_j)(1 + "
             "G) are in contact (1e-3)\n"
             "  --interior-margin M       interior control volume: the "
             "container minus M largest diameters\n"
             "                            at each wall (1)\n"
             "  --contraction TAU         contraction rate parameter "
             "(1000; larger is slower and denser)\n"
             "  --max-iterations K        (200000)\n"
             "  --seed S                  random seed (1)\n"
             "  --output FILE             the CSV to write (required); an "
             "existing file is refused\n"
             "  --overwrite               replace an existing --output file\n"
             "  --help\n";
    }

    Settings
    parse_arguments(const std::vector<std::string> &arguments,
                    std::string                     &output_file,
                    bool                            &overwrite)
    {
      Settings      s;
      std::string   region, domain, symmetry;
      std::string   distribution = "constant";
      double        radius       = 0;
      unsigned long dim = s.dim, n_particles = 0, max_iterations = s.max_iterations;
      bool          dense = false;
      std::vector<std::string> seen;
      overwrite = false;
      const std::map<std::string, bool *> flags = {{"--periodic", &s.periodic},
                                                   {"--dense", &dense},
                                                   {"--overwrite", &overwrite}};
      const std::map<std::string, double *> numbers = {
        {"--radius", &radius},
        {"--radius-min", &s.r_min},
        {"--radius-max", &s.r_max},
        {"--radius-mean", &s.r_mean},
        {"--radius-std", &s.r_std},
        {"--fraction", &s.target_fraction},
        {"--neck", &s.neck_ratio},
        {"--contact-gap", &s.contact_gap},
        {"--interior-margin", &s.interior_margin},
        {"--contraction", &s.contraction}};
      const std::map<std::string, unsigned long *> integers = {
        {"--dim", &dim},
        {"--particles", &n_particles},
        {"--max-iterations", &max_iterations},
        {"--seed", &s.seed}};
      const std::map<std::string, std::string *> texts = {
        {"--radius-distribution", &distribution},
        {"--region", &region},
        {"--domain", &domain},
        {"--symmetry", &symmetry},
        {"--output", &output_file}};
      for (unsigned int k = 0; k < arguments.size(); ++k)
        {
          const std::string &name = arguments[k];
          if (std::find(seen.begin(), seen.end(), name) != seen.end())
            throw std::runtime_error(name + " given twice");
          seen.push_back(name);
          if (flags.count(name))
            {
              *flags.at(name) = true;
              continue;
            }
          if (!numbers.count(name) && !integers.count(name) &&
              !texts.count(name))
            throw std::runtime_error("unknown option '" + name +
                                     "' (see levelsinter-pack --help)");
          if (k + 1 >= arguments.size())
            throw std::runtime_error(name + " needs a value");
          const std::string &v = arguments[++k];
          if (numbers.count(name))
            *numbers.at(name) = parse_number(name, v);
          else if (texts.count(name))
            *texts.at(name) = v;
          else
            {
              const double d = parse_number(name, v);
              if (d < 0 || d != std::floor(d) || d > 4e9)
                throw std::runtime_error(name + ": expected a non-negative "
                                                "integer, found '" + v + "'");
              *integers.at(name) = static_cast<unsigned long>(d);
            }
        }
      s.dim            = dim;
      s.n_particles    = n_particles;
      s.max_iterations = max_iterations;
      const auto given = [&](const std::string &name) {
        return std::find(seen.begin(), seen.end(), name) != seen.end();
      };
      if (given("--fraction") && !(s.target_fraction > 0))
        throw std::runtime_error("--fraction: expected a value in (0, 1), "
                                 "found " + to_string(s.target_fraction));
      if (output_file.empty())
        throw std::runtime_error("--output: no output file given");
      if (dense && s.target_fraction > 0)
        throw std::runtime_error("--dense and --fraction exclude each other");
      if (distribution == "constant")
        {
          if (given("--radius-min") || given("--radius-max") ||
              given("--radius-mean") || given("--radius-std"))
            throw std::runtime_error(
              "--radius-distribution constant takes --radius only");
          if (!given("--radius"))
            throw std::runtime_error("--radius: no radius given (or choose "
                                     "--radius-distribution uniform, normal "
                                     "or log-normal)");
          s.r_min = s.r_max = radius;
        }
      else
        {
          if (given("--radius"))
            throw std::runtime_error(
              "--radius is for --radius-distribution constant; give "
              "--radius-min and --radius-max");
          if (distribution == "uniform")
            s.distribution = RadiusDistribution::uniform;
          else if (distribution == "normal")
            s.distribution = RadiusDistribution::normal;
          else if (distribution == "log-normal")
            s.distribution = RadiusDistribution::log_normal;
          else
            throw std::runtime_error("--radius-distribution: expected "
                                     "constant, uniform, normal or "
                                     "log-normal, found '" + distribution +
                                     "'");
          if (!given("--radius-min") || !given("--radius-max"))
            throw std::runtime_error("--radius-distribution " + distribution +
                                     " needs --radius-min and --radius-max");
          if (s.distribution == RadiusDistribution::uniform &&
              (given("--radius-mean") || given("--radius-std")))
            throw std::runtime_error("--radius-distribution uniform takes no "
                                     "--radius-mean or --radius-std");
          if (s.distribution != RadiusDistribution::uniform &&
              (!given("--radius-mean") || !given("--radius-std")))
            throw std::runtime_error("--radius-distribution " + distribution +
                                     " needs --radius-mean and --radius-std");
        }
      if (region.empty())
        {
          s.region_lower.assign(s.dim, 0.);
          s.region_upper.assign(s.dim, 1.);
        }
      else
        parse_box("--region", region, s.region_lower, s.region_upper);
      if (!domain.empty())
        parse_box("--domain", domain, s.domain_lower, s.domain_upper);
      s.symmetry.assign(s.dim, false);
      s.symmetry_upper.assign(s.dim, false);
      std::istringstream faces(symmetry);
      std::string        face;
      while (std::getline(faces, face, ','))
        {
          const std::string axes = s.dim == 2 ? "xy" : "xyz";
          const auto        d    = face.size() == 2 ? axes.find(face[0]) :
                                                      std::string::npos;
          if (d == std::string::npos || (face[1] != '-' && face[1] != '+'))
            throw std::runtime_error(
              "--symmetry: expected faces among " +
              std::string(s.dim == 2 ? "x-, x+, y-, y+" :
                                       "x-, x+, y-, y+, z-, z+") +
              " separated by commas, found '" + face + "'");
          if (s.symmetry[d])
            throw std::runtime_error("--symmetry: at most one plane per "
                                     "axis, found two along " +
                                     face.substr(0, 1));
          s.symmetry[d]       = true;
          s.symmetry_upper[d] = face[1] == '+';
        }
      s.check();
      return s;
    }
  } // namespace packing
} // namespace levelsinter
