// Convergence studies of the level-set foundation, shared by the CI tests
// (small resolutions) and the long validation runs (doc/validation.md):
//
//   levelsinter_validation measures SCENE.prm PARTICLES LEVELS [options]
//   levelsinter_validation transport SCENE.prm LEVELS [options]
//   levelsinter_validation reinit LEVELS [options]
//
// LEVELS is a comma-separated list of maximum refinement levels. Each case
// prints a table, optionally writes it as CSV (--csv FILE), and checks the
// finest resolution and the observed order against the limits given
// (--max-volume-error, --max-shape-error, --min-order, ...). Exit code 0 only
// if every check passes.

#include <deal.II/base/function.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/utilities.h>

#include <levelsinter/analysis/reference_shapes.h>
#include <levelsinter/scene/command_line.h>
#include <levelsinter/time/simulation.h>

#include "study_support.h"
#include "study_table.h"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <limits>
#include <map>
#include <sstream>

using namespace levelsinter;

namespace
{
  using study::check;
  using study::Table;

  struct Options : study::Options
  {
    std::vector<unsigned int> levels;
  };

  // LEVELS [--csv FILE] [--NAME VALUE ...] from args[first] on.
  Options
  parse_options(const std::vector<std::string> &args, const unsigned int first)
  {
    Options o;
    static_cast<study::Options &>(o) = study::parse_options(args, first + 1);
    o.levels                         = study::parse_levels(args.at(first));
    return o;
  }

  // Resolution-dependent settings: filter, band and step scale with the
  // finest cell so that every level sees the same discrete problem
  // (E = 6 h, band 4 h), unless --filter-thickness / --band-width fix them
  // in length units, which shows convergence at a fixed physical filter.
  std::vector<std::pair<std::string, std::string>>
  resolution_overrides(const SceneParameters &base,
                       const unsigned int     level,
                       const Options         &options = {})
  {
    const auto fixed = [&](const std::string &name, const double scaled) {
      const auto it = options.limits.find(name);
      return std::to_string(it == options.limits.end() ? scaled : it->second);
    };
    const double h = study::cell_size(base, level);
    // Each run writes its metrics to its own directory below the working
    // directory.
    const std::string output = "validation_output/" +
                               std::to_string(base.dimension) + "d_level" +
                               std::to_string(level);
    std::filesystem::create_directories(output);
    return {{"Output/Directory", output},
            {"Mesh refinement/Maximum level", std::to_string(level)},
            {"Mesh refinement/Minimum level", std::to_string(level > 4 ? level - 4 : 0)},
            {"Mesh refinement/Band width", fixed("band-width", 4 * h)},
            {"Mesh refinement/Adapt interval", "2"},
            {"Level set/Filter thickness", fixed("filter-thickness", 6 * h)}};
  }

  template <int dim>
  void
  exact_measures(const SceneParameters &scene, double &volume, double &area)
  {
    if (scene.geometry.shape == GeometryParameters::Shape::slotted_disk)
      {
        // Keep the function alive while the disk is read.
        const auto  distance = make_initial_signed_distance<2>(scene);
        const auto &disk     = dynamic_cast<const SlottedDisk &>(*distance);
        volume               = disk.area();
        area                 = disk.perimeter();
        return;
      }
    // An axisymmetric scene measures the body of revolution: its balls
    // (centred on the axis) are spheres.
    const auto  &p          = scene.geometry.particles;
    const double r          = p[0][dim];
    const bool   revolution = scene.geometry.axisymmetric;
    if (p.size() == 1)
      {
        volume = dim == 2 && !revolution ? M_PI * r * r :
                                           4. / 3. * M_PI * r * r * r;
        area = dim == 2 && !revolution ? 2 * M_PI * r : 4 * M_PI * r * r;
        return;
      }
    double d2 = 0;
    for (unsigned int d = 0; d < dim; ++d)
      d2 += std::pow(p[1][d] - p[0][d], 2);
    volume = revolution ? two_ball_volume<3>(r, std::sqrt(d2)) :
                          two_ball_volume<dim>(r, std::sqrt(d2));
    area   = revolution ? two_ball_surface<3>(r, std::sqrt(d2)) :
                          two_ball_surface<dim>(r, std::sqrt(d2));
  }

  // Transport: run to the end time (where the exact shape is the initial
  // one) and measure volume and shape errors against the exact shape.
  template <int dim>
  void
  transport(const std::string &scene_file, const Options &options)
  {
    const SceneParameters base = read_scene(scene_file, {});
    Table table({"level", "h", "cells", "dofs", "steps", "wall_time", "cpu_time",
                 "volume_error", "shape_error", "shape_error/h",
                 "max_distance/h", "iterations"},
                options.csv);
    for (const unsigned int level : options.levels)
      {
        const auto scene = read_scene(scene_file, resolution_overrides(base, level, options));
        const double h = study::cell_size(scene, level);
        Simulation<dim>     simulation(scene, MPI_COMM_WORLD, std::cout);
        const auto          summary = simulation.run();
        double              volume, area;
        exact_measures<dim>(scene, volume, area);
        const auto measured =
          interface_measures::volume_and_area(simulation.level_set());
        const auto exact_shape = make_initial_signed_distance<dim>(scene);
        const auto shape =
          interface_measures::shape_error(simulation.level_set(), *exact_shape);
        table.add({double(level), h, double(summary.max_cells),
                   double(summary.max_dofs), double(summary.steps),
                   summary.wall_time,
                   summary.cpu_time,
                   std::abs(measured.solid_volume - volume) / volume,
                   shape.symmetric_difference / area,
                   shape.symmetric_difference / area / h,
                   shape.max_distance / h, summary.mean_iterations});
      }
    check("finest relative volume error", table.finest("volume_error"),
          options, "max-volume-error", true);
    check("finest shape error (mean distance)", table.finest("shape_error"),
          options, "max-shape-error", true);
    check("observed order of the shape error", table.order("shape_error"),
          options, "min-order", false);
  }

  // Measures: volume and interface area of the scene's solid at t = 0.
  template <int dim>
  void
  measures(const std::string &scene_file,
           const std::string &particles,
           const Options     &options)
  {
    const SceneParameters base = read_scene(scene_file, {});
    Table table({"level", "h", "cells", "volume_error", "area_error"},
                options.csv);
    for (const unsigned int level : options.levels)
      {
        auto overrides = resolution_overrides(base, level, options);
        overrides.emplace_back("Geometry/Particles", particles);
        // --set entries (e.g. Geometry/Axisymmetric) last.
        overrides.insert(overrides.end(),
                         options.overrides.begin(),
                         options.overrides.end());
        const auto scene = read_scene(scene_file, overrides);
        const double h = study::cell_size(scene, level);
        Simulation<dim> simulation(scene, MPI_COMM_WORLD, std::cout);
        simulation.initialise();
        double volume, area;
        exact_measures<dim>(scene, volume, area);
        const auto m = interface_measures::volume_and_area(simulation.level_set());
        table.add({double(level), h,
                   double(simulation.triangulation().n_global_active_cells()),
                   std::abs(m.solid_volume - volume) / volume,
                   std::abs(m.interface_area - area) / area});
      }
    check("finest relative volume error", table.finest("volume_error"), options,
          "max-volume-error", true);
    check("finest relative area error", table.finest("area_error"), options,
          "max-area-error", true);
    check("observed order of the volume error", table.order("volume_error"),
          options, "min-order", false);
    check("observed order of the area error", table.order("area_error"),
          options, "min-area-order", false);
  }

  // Reinitialisation: start from alpha = filter(2 d), whose gradient is
  // twice the target, run with zero velocity and measure how close
  // |grad alpha| comes to g(alpha) (Eq. 67) and how far alpha = 0 moved.
  void
  reinitialisation(const std::string &scene_file, const Options &options)
  {
    const SceneParameters base = read_scene(scene_file, {});
    Table table({"level", "h", "steps", "grad_rms_before", "grad_rms_after",
                 "grad_max_after", "interface_shift/h"},
                options.csv);
    for (const unsigned int level : options.levels)
      {
        auto overrides = resolution_overrides(base, level, options);
        const double h = study::cell_size(base, level);
        // 40 steps (the default) of lambda dt = 0.25 h move information
        // 10 h, beyond the filter thickness (6 h): enough to reach the
        // target everywhere. --steps N runs longer to show stability.
        const auto   steps = options.limits.find("steps");
        const double n_steps =
          steps == options.limits.end() ? 40. : steps->second;
        overrides.insert(overrides.end(),
                         {{"Velocity/Type", "none"},
                          {"Time/CFL number", "0"},
                          {"Time/Time step", "0.01"},
                          {"Time/End time", std::to_string(0.01 * n_steps)},
                          {"Mesh refinement/Adapt interval", "1000000"}});
        const auto scene = read_scene(scene_file, overrides);
        Simulation<2> simulation(scene, MPI_COMM_WORLD, std::cout);
        simulation.initialise();
        const auto distance = make_initial_signed_distance<2>(scene);
        const LevelSetFilter &filter = simulation.filter();
        simulation.set_level_set(ScalarFunctionFromFunctionObject<2>(
          [&](const Point<2> &p) { return filter.filter(2 * distance->value(p)); }));
        const auto before =
          interface_measures::gradient_norm_error(simulation.level_set(), filter);
        const auto summary = simulation.run();
        const auto after =
          interface_measures::gradient_norm_error(simulation.level_set(), filter);
        const auto shift =
          interface_measures::shape_error(simulation.level_set(), *distance);
        table.add({double(level), h, double(summary.steps), before.rms_error,
                   after.rms_error, after.max_error, shift.max_distance / h});
      }
    check("finest rms |grad alpha| - g(alpha)", table.finest("grad_rms_after"),
          options, "max-gradient-error", true);
    check("finest interface shift / h", table.finest("interface_shift/h"),
          options, "max-shift", true);
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const std::vector<std::string> args(argv, argv + argc);
  try
    {
      if (args.size() < 3)
        throw std::runtime_error("see the comment at the top of validation.cc");
      if (args[1] == "measures")
        {
          // args: measures SCENE PARTICLES LEVELS ...
          const auto scene = read_scene(args[2], {});
          if (scene.dimension == 2)
            measures<2>(args[2], args[3], parse_options(args, 4));
          else
            measures<3>(args[2], args[3], parse_options(args, 4));
        }
      else if (args[1] == "transport")
        {
          const auto scene = read_scene(args[2], {});
          if (scene.dimension == 2)
            transport<2>(args[2], parse_options(args, 3));
          else
            transport<3>(args[2], parse_options(args, 3));
        }
      else if (args[1] == "reinit")
        reinitialisation(args[2], parse_options(args, 3));
      else
        throw std::runtime_error("unknown case " + args[1]);
    }
  catch (const std::exception &e)
    {
      std::cerr << "levelsinter_validation: " << e.what() << "\n";
      return 2;
    }
  return study::failures() == 0 ? 0 : 1;
}
