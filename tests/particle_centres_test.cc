// Particle centres (analysis/particle_centres.h) on cases whose answer is
// exact (doc/validation.md, "Densification (centre distance)"):
//
//   particle_centres_test shift DIM LEVEL [--mirror 1] [--csv FILE]
//     two balls of radius 0.15 at x = 0.5 -/+ (0.2 + s), s = 0 ... 0.05,
//     the level set the interpolated signed distance on a mesh refined
//     around the interface to LEVEL: the centroid distance must grow by
//     exactly 2 s. With --mirror 1 the box is x in [0.5, 1] with the
//     symmetry plane x- (the left ball is the right one's image).
//   particle_centres_test run METRICS SPEED LIMIT
//     metrics.csv of a run whose two particles move apart at SPEED each:
//     centre_distance(t) - centre_distance(0) against 2 SPEED t.
//   particle_centres_test ids SCENE.prm
//     the particle_id output field of a 2D scene of particles, read from
//     the patches of Simulation::add_output_fields() at t = 0: on every
//     cell with a vertex alpha <= 0 the particle whose power cell holds
//     the cell's centre (computed here from the scene's list), -1 on the
//     others; each particle and -1 must occur.
//
// The bound of the shift case: the centroid of a solid whose boundary
// lies within delta of the exact one moves by at most
// (1/V) int_Gamma delta |x - c| <= dim delta for a ball (area / volume x
// radius = dim), so each distance is off by at most 2 dim delta, the
// change by 2 dim (delta_0 + delta_s), delta the largest interface
// distance measured by interface_measures::shape_error. Exit code 0 only
// if every check passes.

#include <deal.II/base/mpi.h>

#include <deal.II/distributed/tria.h>

#include <levelsinter/analysis/particle_centres.h>
#include <levelsinter/analysis/reference_shapes.h>
#include <levelsinter/level_set/interface_measures.h>
#include <levelsinter/scene/command_line.h>
#include <levelsinter/time/simulation.h>

#include "refined_level_set.h"
#include "study_support.h"
#include "study_table.h"

#include <algorithm>
#include <iostream>
#include <limits>

using namespace levelsinter;

namespace
{
  using study::check;
  using study::Table;

  template <int dim>
  void
  shift_study(const unsigned int level, const study::Options &options)
  {
    const bool       mirror = options.limits.count("mirror") &&
                        options.limits.at("mirror") > 0;
    DomainParameters domain;
    domain.lower_corner = std::vector<double>(dim, 0.);
    domain.upper_corner = std::vector<double>(dim, 1.);
    domain.subdivisions = std::vector<unsigned int>(dim, 1);
    if (mirror)
      {
        domain.lower_corner[0] = 0.5;
        domain.subdivisions    = std::vector<unsigned int>(dim, 2);
        domain.subdivisions[0] = 1;
        domain.symmetry_planes = {0};
      }
    const double radius = 0.15, gap = 0.2;
    const auto   particles = [&](const double s) {
      std::vector<std::vector<double>> p(2, std::vector<double>(dim + 1, 0.5));
      p[0][0]   = 0.5 - gap - s;
      p[1][0]   = 0.5 + gap + s;
      p[0][dim] = p[1][dim] = radius;
      return p;
    };
    ParticleCentres<dim> centres(particles(0), domain, MPI_COMM_WORLD);
    Table table({"shift", "h", "distance_change", "error", "bound"},
                options.csv);
    double worst = 0, delta_0 = 0;
    for (const double s : {0., 0.01, 0.025, 0.05})
      {
        const UnionOfBalls<dim> phi(particles(s));
        parallel::distributed::Triangulation<dim> tria(MPI_COMM_WORLD);
        LevelSetField<dim>                        level_set(tria);
        study::build_refined_level_set(tria, level_set, domain, phi, level);
        const double delta =
          interface_measures::shape_error(level_set, phi).max_distance;
        if (s == 0)
          delta_0 = delta;
        // measure(): the distance and its change relative to the first.
        const std::vector<double> row = centres.measure(level_set, {});
        const double d_0 = row[0] / (1 + row[1]);
        const double error = std::abs(row[0] - d_0 - 2 * s);
        const double bound = 2 * dim * (delta_0 + delta);
        const double h =
          (domain.upper_corner[1] - domain.lower_corner[1]) /
          domain.subdivisions[1] / std::pow(2., level);
        worst = std::max(worst, error / bound);
        table.add({s, h, row[0] - d_0, error, bound});
      }
    check("largest error / bound", worst, options, "max-bound-ratio");
  }

  // DataOut's per-component names, as the writers label the patches.
  struct NamedDataOut : DataOut<2>
  {
    using DataOut<2>::get_dataset_names;
  };

  void
  id_check(const std::string &scene_file)
  {
    const SceneParameters scene = read_scene(scene_file, {});
    Simulation<2>         simulation(scene, MPI_COMM_WORLD, std::cout);
    simulation.initialise();
    NamedDataOut data_out;
    data_out.attach_dof_handler(simulation.level_set().dof_handler());
    data_out.add_data_vector(simulation.level_set().alpha(), "alpha");
    simulation.add_output_fields(data_out);
    data_out.build_patches();
    const auto  names = data_out.get_dataset_names();
    const auto  index = [&](const std::string &name) {
      const auto it = std::find(names.begin(), names.end(), name);
      if (it == names.end())
        throw std::runtime_error("no output field " + name);
      return it - names.begin();
    };
    const auto  alpha = index("alpha"), id = index("particle_id");
    const auto &particles = scene.geometry.particles;
    std::vector<unsigned int> seen(particles.size() + 1, 0);
    unsigned int              wrong = 0, cells = 0;
    for (const auto &patch : data_out.get_patches())
      {
        Point<2> centre;
        bool     solid = false;
        for (unsigned int v = 0; v < 4; ++v)
          {
            centre += patch.vertices[v] / 4.;
            solid = solid || patch.data(alpha, v) <= 0;
          }
        int expected = -1;
        if (solid)
          {
            double power = std::numeric_limits<double>::max();
            for (unsigned int i = 0; i < particles.size(); ++i)
              if (const double p =
                    centre.distance_square(Point<2>(particles[i][0],
                                                    particles[i][1])) -
                    particles[i][2] * particles[i][2];
                  p < power)
                {
                  power    = p;
                  expected = i;
                }
          }
        ++cells;
        wrong += patch.data(id, 0) != expected;
        ++seen[expected + 1];
      }
    wrong = Utilities::MPI::sum(wrong, MPI_COMM_WORLD);
    cells = Utilities::MPI::sum(cells, MPI_COMM_WORLD);
    Utilities::MPI::sum(seen, MPI_COMM_WORLD, seen);
    const bool all_seen =
      std::find(seen.begin(), seen.end(), 0u) == seen.end();
    study::failures() += wrong > 0 || !all_seen;
    if (study::is_root())
      {
        std::cout << "cells per id from -1:";
        for (const unsigned int n : seen)
          std::cout << " " << n;
        std::cout << "\n"
                  << (wrong == 0 ? "PASS" : "FAIL") << " particle_id: "
                  << wrong << " of " << cells << " cells wrong\n"
                  << (all_seen ? "PASS" : "FAIL")
                  << " every particle and -1 occur\n";
      }
  }

  void
  run_check(const std::string &file, const double speed, const double limit)
  {
    const study::CsvTable metrics(file);
    const auto &t = metrics.column("time");
    const auto &d = metrics.column("centre_distance");
    double      worst = 0;
    for (unsigned int r = 0; r < metrics.n_rows(); ++r)
      worst = std::max(worst, std::abs(d[r] - d[0] - 2 * speed * t[r]));
    study::Options options;
    options.limits["max-error"] = limit;
    std::cout << "centre distance " << d[0] << " -> " << d.back()
              << ", exact change " << 2 * speed * t.back() << "\n";
    check("largest |change - 2 U t|", worst, options, "max-error");
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  try
    {
      const std::vector<std::string> args(argv, argv + argc);
      if (args.size() >= 4 && args[1] == "shift")
        {
          const auto options = study::parse_options(args, 4);
          if (args[2] == "2")
            shift_study<2>(std::stoi(args[3]), options);
          else
            shift_study<3>(std::stoi(args[3]), options);
        }
      else if (args.size() == 5 && args[1] == "run")
        run_check(args[2], std::stod(args[3]), std::stod(args[4]));
      else if (args.size() == 3 && args[1] == "ids")
        id_check(args[2]);
      else
        throw std::runtime_error(
          "usage: particle_centres_test shift DIM LEVEL [options] | run "
          "METRICS SPEED LIMIT | ids SCENE.prm");
    }
  catch (const std::exception &e)
    {
      std::cerr << "FAIL: " << e.what() << std::endl;
      return 1;
    }
  return study::failures() > 0;
}
