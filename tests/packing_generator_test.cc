// Checks of levelsinter-pack's generator (scene/packing_generator.h), run
// through the library with the generator's own options:
//   packing_generator_test CHECK [levelsinter-pack options]
// CHECK is one of
//   rcp:PHI_MIN:PHI_MAX:Z_MIN:Z_MAX:SEEDS  solid fraction and mean
//       coordination of SEEDS packings (seeds 1..SEEDS), each within bounds
//   bounds           every radius within [--radius-min, --radius-max]
//   symmetry         the file's particles are mirror-symmetric about the
//                    --symmetry planes and fit the container as the scene
//                    reader wants
//   neck:TOL         every contacting pair has x0/R = --neck within TOL
// Exit code 1 with the reason if a check fails.
#include <levelsinter/scene/packing_generator.h>
#include <levelsinter/scene/particles.h>

#include <chrono>
#include <cmath>
#include <iostream>
#include <sstream>
#include <stdexcept>

using namespace levelsinter;

namespace
{
  std::vector<std::string>
  split(const std::string &text)
  {
    std::vector<std::string> items;
    std::istringstream       in(text);
    std::string              item;
    while (std::getline(in, item, ':'))
      items.push_back(item);
    return items;
  }

  void
  require(const bool ok, const std::string &what)
  {
    if (!ok)
      throw std::runtime_error("FAILED: " + what);
  }

  void
  check_rcp(const std::vector<std::string> &spec, packing::Settings s)
  {
    require(spec.size() == 6, "rcp:PHI_MIN:PHI_MAX:Z_MIN:Z_MAX:SEEDS");
    const double phi_min = std::stod(spec[1]), phi_max = std::stod(spec[2]);
    const double z_min = std::stod(spec[3]), z_max = std::stod(spec[4]);
    const unsigned int n_seeds = std::stoul(spec[5]);
    for (unsigned int seed = 1; seed <= n_seeds; ++seed)
      {
        s.seed          = seed;
        const auto t0   = std::chrono::steady_clock::now();
        const auto r    = packing::generate(s);
        const double dt = std::chrono::duration<double>(
                            std::chrono::steady_clock::now() - t0)
                            .count();
        // Periodic: the nominal fraction is exact; with walls the interior
        // one (sampled) is the bulk value.
        const double phi =
          s.periodic ? r.nominal_fraction : r.interior_fraction;
        const double z = s.periodic ? r.coordination : r.interior_coordination;
        std::cout << "seed " << seed << ": solid fraction " << phi
                  << ", mean coordination " << z << ", " << r.iterations
                  << " iterations, " << dt << " s" << std::endl;
        require(r.converged, "not converged");
        require(phi >= phi_min && phi <= phi_max,
                "solid fraction outside [" + spec[1] + ", " + spec[2] + "]");
        require(z >= z_min && z <= z_max,
                "coordination outside [" + spec[3] + ", " + spec[4] + "]");
      }
  }

  void
  check_bounds(const packing::Settings &s)
  {
    const auto r = packing::generate(s);
    double     lo = 1e300, hi = 0;
    for (const auto &p : r.particles)
      {
        lo = std::min(lo, p.back());
        hi = std::max(hi, p.back());
      }
    std::cout << "radii in [" << lo << ", " << hi << "], bounds [" << s.r_min
              << ", " << s.r_max << "]" << std::endl;
    require(lo >= s.r_min && hi <= s.r_max, "a radius outside the bounds");
    // The draws must spread over the bounds, not sit at one value.
    require(hi - lo > 0.5 * (s.r_max - s.r_min), "radii do not spread");
  }

  void
  check_symmetry(const packing::Settings &s)
  {
    const auto         r   = packing::generate(s);
    const unsigned int dim = s.dim;
    std::cout << r.particles.size() - r.n_images << " particles, "
              << r.n_images << " images" << std::endl;
    require(r.n_images > 0, "no particle crosses a symmetry plane");
    // The reader's own check: a particle may cross a face only if its
    // mirror image is listed.
    check_particles_in_domain(r.particles, r.container_lower, r.container_upper);
    // Every particle crossing a plane has its image; none crosses a wall.
    for (unsigned int i = 0; i < r.particles.size() - r.n_images; ++i)
      for (unsigned int d = 0; d < dim; ++d)
        if (s.symmetry[d])
          {
            const auto  &p     = r.particles[i];
            const double plane = s.symmetry_upper[d] ? r.container_upper[d] :
                                                       r.container_lower[d];
            if (std::abs(p[d] - plane) >= p[dim])
              continue;
            bool found = false;
            for (const auto &q : r.particles)
              {
                bool same = std::abs(q[d] - (2 * plane - p[d])) < 1e-12 &&
                            q[dim] == p[dim];
                for (unsigned int k = 0; k < dim; ++k)
                  same = same && (k == d || std::abs(q[k] - p[k]) < 1e-12);
                found = found || same;
              }
            require(found, "particle " + std::to_string(i + 1) +
                             " crosses a symmetry plane without its image");
          }
    require(r.coordination > 0, "no contacts");
  }

  void
  check_neck(const std::vector<std::string> &spec, const packing::Settings &s)
  {
    require(spec.size() == 2, "neck:TOL");
    const double tol = std::stod(spec[1]);
    const auto   r   = packing::generate(s);
    std::cout << r.n_contacts << " contacts, x0/R min " << r.neck_min
              << ", mean " << r.neck_mean << ", max " << r.neck_max
              << "; other overlaps " << r.n_other_overlaps << " (largest x0/R "
              << r.other_overlap_neck_max << ")" << std::endl;
    require(r.n_contacts > 0, "no contacts");
    require(std::abs(r.neck_min - s.neck_ratio) <= tol &&
              std::abs(r.neck_max - s.neck_ratio) <= tol,
            "x0/R of the contacting pairs off by more than " + spec[1]);
    require(r.other_overlap_neck_max <= s.neck_ratio + tol,
            "another pair overlaps more than the contacts");
  }
} // namespace

int
main(int argc, char **argv)
{
  try
    {
      if (argc < 2)
        throw std::runtime_error("usage: packing_generator_test CHECK "
                                 "[levelsinter-pack options]");
      std::vector<std::string> arguments(argv + 2, argv + argc);
      arguments.push_back("--output");
      arguments.push_back("unused.csv");
      std::string  unused;
      bool         overwrite;
      const auto   settings =
        packing::parse_arguments(arguments, unused, overwrite);
      const auto   spec     = split(argv[1]);
      if (spec[0] == "rcp")
        check_rcp(spec, settings);
      else if (spec[0] == "bounds")
        check_bounds(settings);
      else if (spec[0] == "symmetry")
        check_symmetry(settings);
      else if (spec[0] == "neck")
        check_neck(spec, settings);
      else
        throw std::runtime_error("unknown check '" + spec[0] + "'");
    }
  catch (const std::exception &e)
    {
      std::cerr << e.what() << std::endl;
      return 1;
    }
  return 0;
}
