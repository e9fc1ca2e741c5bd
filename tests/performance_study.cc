// performance_study SCENE STEPS --csv FILE [--set "Section/Entry=value"]...
//
// The cost of a scene per step (doc/performance.md): runs STEPS steps and
// writes one row to FILE with the particle count, the ranks, the mesh, the
// solver iterations and, per phase, the wall and the CPU time per step
// (TimerOutput; CPU summed over the ranks) over steps 2..STEPS, so that
// the set-up, the t = 0 velocity and the first step do not count. The
// packing analysis and the metrics are given per call (they run every
// metrics interval). The machine's load average is written next to the
// times: on shared cores the wall time grows with it, the CPU time less.
#include <deal.II/base/mpi.h>
#include <deal.II/grid/grid_tools.h>

#include <levelsinter/scene/command_line.h>
#include <levelsinter/time/simulation.h>

#include "study_support.h"
#include "study_table.h"

#include <chrono>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <numeric>

using namespace dealii;
using namespace levelsinter;

namespace
{
  // TimerOutput sections summed into the phases of the table.
  const std::map<std::string, std::vector<std::string>> phases = {
    {"transport", {"level set: assembly", "level set: solve"}},
    {"curvature_vs",
     {"curvature assembly",
      "curvature solve",
      "surface diffusion velocity",
      "normal gradient: assembly",
      "normal gradient: solve"}},
    {"elastic",
     {"volume diffusion: elastic set-up",
      "volume diffusion: elastic assembly",
      "volume diffusion: elastic solve"}},
    {"adaptation", {"mesh adaptation", "system setup after adaptation"}},
    {"metrics", {"metrics"}}, // holds the packing analysis
    {"packing_analysis", {"packing analysis"}},
    {"output", {"output"}}};

  double
  phase_time(const std::map<std::string, double> &sections,
             const std::string                   &phase)
  {
    double sum = 0;
    for (const auto &name : phases.at(phase))
      if (const auto it = sections.find(name); it != sections.end())
        sum += it->second;
    return sum;
  }

  double
  load_average()
  {
    std::ifstream in("/proc/loadavg");
    double        load = std::numeric_limits<double>::quiet_NaN();
    in >> load;
    return load;
  }

  template <int dim>
  void
  run(const std::string &scene_file, const unsigned int steps,
      const study::Options &options)
  {
    auto overrides = options.overrides;
    overrides.emplace_back("Time/Maximum steps", std::to_string(steps));
    const SceneParameters scene = read_scene(scene_file, overrides);
    const MPI_Comm        comm  = MPI_COMM_WORLD;
    std::filesystem::create_directories(scene.output.directory);
    Simulation<dim>       simulation(scene, comm, std::cout);
    std::map<std::string, double> wall_1, cpu_1;
    unsigned int                  metrics_calls = 0;
    auto                          wall_start    = std::chrono::steady_clock::now();
    double                        process_cpu_1 = 0;
    const Timer                   process_timer(comm);
    simulation.set_step_observer(
      [&](const unsigned int step, const double, const LevelSetField<dim> &) {
        if (step == 1)
          {
            wall_1 = simulation.timer().get_summary_data(TimerOutput::total_wall_time);
            cpu_1 = simulation.timer().get_summary_data(TimerOutput::total_cpu_time);
            wall_start    = std::chrono::steady_clock::now();
            process_cpu_1 = process_timer.cpu_time();
          }
        else if (step % scene.output.metrics_interval == 0 || step == steps)
          ++metrics_calls;
      });
    const auto summary = simulation.run();
    if (summary.steps != steps || steps < 2)
      throw std::runtime_error("the run stopped after " +
                               std::to_string(summary.steps) + " of " +
                               std::to_string(steps) + " steps (at least 2)");
    const double wall_steps =
      std::chrono::duration<double>(std::chrono::steady_clock::now() -
                                    wall_start)
        .count();
    const double cpu_steps = process_timer.cpu_time() - process_cpu_1;
    const auto   wall = simulation.timer().get_summary_data(TimerOutput::total_wall_time);
    const auto   cpu  = simulation.timer().get_summary_data(TimerOutput::total_cpu_time);

    // Iterations from metrics.csv, steps 2..STEPS.
    const study::CsvTable metrics(scene.output.directory + "/metrics.csv");
    auto mean_after_first = [&](const std::string &column) {
      if (!metrics.has_column(column))
        return std::numeric_limits<double>::quiet_NaN();
      const auto &step   = metrics.column("step");
      const auto &values = metrics.column(column);
      double      sum = 0, n = 0;
      for (unsigned int r = 0; r < values.size(); ++r)
        if (step[r] >= 2)
          {
            sum += values[r];
            ++n;
          }
      return sum / n;
    };
    const auto  &neck = metrics.has_column("neck_radius") ?
                          metrics.column("neck_radius") :
                          std::vector<double>{};
    const double h_min =
      GridTools::minimal_cell_diameter(simulation.triangulation()) /
      std::sqrt(double(dim));
    const double n_particles = scene.geometry.particles.size();
    const double ranks       = Utilities::MPI::n_mpi_processes(comm);
    const double per_step    = 1. / (steps - 1);

    std::vector<std::string> columns = {"particles",
                                        "ranks",
                                        "steps",
                                        "cells",
                                        "dofs",
                                        "dofs_per_particle",
                                        "h_min",
                                        "neck_cells_t0",
                                        "transport_iterations",
                                        "surface_diffusion_iterations",
                                        "wall_per_step",
                                        "cpu_per_step",
                                        "load"};
    std::vector<double> row = {
      n_particles,
      ranks,
      double(steps),
      double(simulation.triangulation().n_global_active_cells()),
      double(simulation.level_set().dof_handler().n_dofs()),
      simulation.level_set().dof_handler().n_dofs() / n_particles,
      h_min,
      neck.empty() ? std::numeric_limits<double>::quiet_NaN() : neck[0] / h_min,
      mean_after_first("transport_iterations"),
      mean_after_first("surface_diffusion_iterations"),
      wall_steps * per_step,
      cpu_steps * per_step,
      load_average()};
    for (const auto &[phase, sections] : phases)
      {
        // Every step but the metrics, given per call.
        const bool   per_call = phase == "metrics" || phase == "packing_analysis";
        const double scale    = per_call ? 1. / std::max(1u, metrics_calls) :
                                           per_step;
        columns.push_back(phase + "_wall");
        columns.push_back(phase + "_cpu");
        row.push_back((phase_time(wall, phase) - phase_time(wall_1, phase)) *
                      scale);
        row.push_back((phase_time(cpu, phase) - phase_time(cpu_1, phase)) *
                      scale);
      }
    study::Table table(columns, options.csv);
    table.add(row);
    simulation.timer().print_summary();
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const std::vector<std::string>   args(argv, argv + argc);
  if (args.size() < 3)
    {
      std::cerr << "usage: performance_study SCENE STEPS --csv FILE "
                   "[--set ...]\n";
      return 1;
    }
  try
    {
      const auto         options = study::parse_options(args, 3);
      const unsigned int steps   = std::stoul(args[2]);
      if (read_scene(args[1], options.overrides).dimension == 2)
        run<2>(args[1], steps, options);
      else
        run<3>(args[1], steps, options);
    }
  catch (const std::exception &e)
    {
      std::cerr << "performance_study: " << e.what() << std::endl;
      return 1;
    }
  return 0;
}
