// Validation of surface diffusion (doc/validation.md, "Surface diffusion"):
//
//   surface_diffusion_validation mullins SCENE.prm LEVELS STEPS [options]
//   surface_diffusion_validation neck SCENE.prm STEPS [--min-neck-growth f]
//                                [--max-volume-change v]
//                                [--max-spread-change s] [--set E=V]
//
// SCENE is a perturbed-particle scene in reduced time (Time unit = reduced,
// reference radius R = the particle's radius), in which mode n decays as
// exp(-n^2 (n^2 - 1) t*) in 2D and as exp(-(n-1) n (n+1) (n+2) t*) in 3D
// (Mullins 1957). Every combination of LEVELS (maximum refinement level)
// and STEPS (steps per e-folding time) is run to one e-folding time; the
// amplitude is measured after every step from the discrete interface and
// the rate fitted by least squares to log(amplitude). Options: --mode n,
// --solver direct|gmres, --csv FILE, and limits --max-rate-error,
// --max-volume-change checked on the last run. The table gives the mean
// iterations and CPU seconds per kappa / v_s solve (steps after the first).
// Exit code 0 only if every check passes.

#include <deal.II/base/mpi.h>
#include <deal.II/base/utilities.h>

#include <levelsinter/level_set/interface_measures.h>
#include <levelsinter/scene/command_line.h>
#include <levelsinter/time/simulation.h>

#include "study_table.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <map>
#include <sstream>
#include <tuple>

using namespace levelsinter;

namespace
{
  // The limits of a run in the form the shared checks take. Errors are
  // checked by magnitude: a rate or area error may have either sign.
  study::Options
  with_limits(const std::map<std::string, double> &limits)
  {
    study::Options options;
    options.limits = limits;
    return options;
  }

  // Mean of one column of a metrics.csv over its rows after the first.
  double
  column_mean(const std::string &file, const std::string &column)
  {
    std::ifstream in(file);
    std::string   line;
    std::getline(in, line);
    const auto names = Utilities::split_string_list(line, ',');
    const auto pos   = std::find(names.begin(), names.end(), column);
    if (pos == names.end())
      return 0;
    const unsigned int index = pos - names.begin();
    double             sum   = 0;
    unsigned int       n     = 0;
    for (unsigned int row = 0; std::getline(in, line); ++row)
      if (row > 0)
        {
          sum += Utilities::string_to_double(
            Utilities::split_string_list(line, ',')[index]);
          ++n;
        }
    return n > 0 ? sum / n : 0;
  }

  // Amplitude of mode n relative to R, from the discrete interface:
  // a_n = (1/pi) int_0^2pi r cos(n theta) dtheta, and dtheta = (N.e_r)/r ds
  // on a star-shaped curve, so a_n = (1/pi) int_Gamma cos(n theta) N.e_r ds.
  // In 3D the Legendre coefficient (2n+1)/2 int r P_n(cos) sin dtheta
  // follows the same way with the solid-angle element (N.e_r)/r^2 dA.
  template <int dim>
  double
  mode_amplitude(const LevelSetField<dim> &alpha,
                 const Point<dim>         &centre,
                 const double              radius,
                 const unsigned int        mode)
  {
    return interface_measures::interface_integral<dim>(
             alpha,
             [&](const Point<dim> &p, const Tensor<1, dim> &normal) {
               const Tensor<1, dim> x = p - centre;
               const double         r = x.norm();
               if constexpr (dim == 2)
                 return std::cos(mode * std::atan2(x[1], x[0])) *
                        (normal * x) / r / M_PI;
               else
                 return std::legendre(mode, x[dim - 1] / r) * (normal * x) /
                        (r * r) * (2 * mode + 1) / (4 * M_PI);
             }) /
           radius;
  }

  double filter_thickness = 0;
  // Run this fraction of the e-folding time (stiffness probes), and the
  // scheme (--coupled 0: kappa then v_s).
  double       time_fraction = 1;
  unsigned int coupled       = 1;
  // Linear solver of the kappa / v_s system (--solver direct|gmres).
  std::string linear_solver = "gmres";

  template <int dim>
  void
  mullins(const std::string               &scene_file,
          const std::vector<unsigned int> &levels,
          const std::vector<unsigned int> &steps_per_efold,
          const unsigned int               mode,
          const std::map<std::string, double> &limits,
          const std::string               &csv)
  {
    const SceneParameters base = read_scene(scene_file, {});
    const double exact_rate =
      dim == 2 ? double(mode * mode) * (mode * mode - 1.) :
                 double(mode - 1) * mode * (mode + 1) * (mode + 2);
    const double end_time = time_fraction / exact_rate;
    Point<dim>   centre;
    for (unsigned int d = 0; d < dim; ++d)
      centre[d] = base.geometry.particles[0][d];
    const double radius = base.geometry.particles[0][dim];

    std::ofstream table;
    if (!csv.empty())
      table.open(csv);
    const std::string header =
      "mode,level,h,steps,dt,rate,exact_rate,rate_error,volume_change,"
      "mean_iterations,wall_time,max_amplitude_ratio,solver,dofs,"
      "solve_cpu_time,cpu_time";
    if (table)
      table << header << "\n";
    std::cout << header << "\n";
    double last_error = 0, last_volume = 0;
    for (const unsigned int level : levels)
      for (const unsigned int steps : steps_per_efold)
        {
          const double h =
            (base.domain.upper_corner[0] - base.domain.lower_corner[0]) /
            base.domain.subdivisions[0] / std::pow(2.0, level);
          const std::string output = "validation_output/sd_" +
                                     std::to_string(dim) + "d_n" +
                                     std::to_string(mode) + "_l" +
                                     std::to_string(level) + "_s" +
                                     std::to_string(steps);
          std::filesystem::create_directories(output);
          const auto scene = read_scene(
            scene_file,
            {{"Output/Directory", output},
             {"Output/Field formats", "none"},
             {"Output/Progress interval", "0"},
             {"Geometry/Perturbation mode", std::to_string(mode)},
             {"Mesh refinement/Maximum level", std::to_string(level)},
             {"Mesh refinement/Minimum level",
              std::to_string(level > 3 ? level - 3 : 0)},
             {"Mesh refinement/Band width", std::to_string(4 * h)},
             {"Level set/Filter thickness",
              std::to_string(std::max(6 * h, filter_thickness))},
             {"Time/End time", Utilities::to_string(end_time, 16)},
             {"Time/Time step", Utilities::to_string(end_time / steps, 16)},
             {"Time/CFL number", "0"},
             {"Surface diffusion/Coupled", coupled ? "true" : "false"},
             {"Surface diffusion/Linear solver", linear_solver}});
          Simulation<dim> simulation(scene, MPI_COMM_WORLD, std::cout);
          simulation.initialise();
          std::vector<double> times, logs;
          auto                observe = [&](const double t,
                             const LevelSetField<dim> &alpha) {
            times.push_back(t);
            logs.push_back(
              std::log(mode_amplitude<dim>(alpha, centre, radius, mode)));
          };
          observe(0, simulation.level_set());
          const double volume0 =
            interface_measures::volume_and_area(simulation.level_set())
              .solid_volume;
          simulation.set_step_observer(
            [&](unsigned int, double t, const LevelSetField<dim> &alpha) {
              observe(t, alpha);
            });
          typename Simulation<dim>::Summary summary;
          try
            {
              summary = simulation.run();
            }
          catch (const std::exception &)
            {
              // A blown-up run (solver failure) counts as unstable.
              logs.push_back(std::log(1e10));
              times.push_back(end_time);
            }
          const double volume =
            interface_measures::volume_and_area(simulation.level_set())
              .solid_volume;
          // Least-squares slope of log(amplitude) against t.
          double st = 0, sl = 0, stt = 0, stl = 0;
          const double n = times.size();
          for (unsigned int i = 0; i < times.size(); ++i)
            {
              st += times[i];
              sl += logs[i];
              stt += times[i] * times[i];
              stl += times[i] * logs[i];
            }
          const double rate = -(n * stl - st * sl) / (n * stt - st * st);
          last_error        = (rate - exact_rate) / exact_rate;
          last_volume       = (volume - volume0) / volume0;
          std::ostringstream row;
          row << mode << "," << level << "," << h << "," << steps << ","
              << end_time / steps << "," << rate << "," << exact_rate << ","
              << last_error << "," << last_volume << ","
              << column_mean(output + "/metrics.csv",
                             "surface_diffusion_iterations")
              << "," << summary.wall_time << ","
              << std::exp(*std::max_element(logs.begin(), logs.end()) -
                          logs.front())
              << "," << linear_solver << "," << summary.max_dofs << ","
              << column_mean(output + "/metrics.csv",
                             "surface_diffusion_solve_cpu_time")
              << "," << summary.cpu_time;
          std::cout << row.str() << std::endl;
          if (table)
            table << row.str() << "\n";
        }
    study::check("|relative rate error| (last run)", std::abs(last_error),
                 with_limits(limits), "max-rate-error");
    study::check("|volume change| (last run)", std::abs(last_volume),
                 with_limits(limits), "max-volume-change");
  }
  // Spread of the solid about its centroid along each axis,
  // sqrt(int (x_i - m_i)^2 dV / V): shrinkage (centres approaching) lowers
  // it, surface diffusion (matter moving along the surface into the necks)
  // barely. The volume integrals are interface integrals by the divergence
  // theorem: int x_i^k dV = int x_i^(k+1)/(k+1) n_i dA.
  template <int dim>
  Tensor<1, dim>
  solid_spread(const LevelSetField<dim> &alpha)
  {
    Tensor<1, dim> spread;
    const double   volume =
      interface_measures::volume_and_area(alpha).solid_volume;
    for (unsigned int d = 0; d < dim; ++d)
      {
        const double first = interface_measures::interface_integral<dim>(
          alpha, [d](const Point<dim> &p, const Tensor<1, dim> &n) {
            return p[d] * p[d] / 2 * n[d];
          });
        const double second = interface_measures::interface_integral<dim>(
          alpha, [d](const Point<dim> &p, const Tensor<1, dim> &n) {
            return p[d] * p[d] * p[d] / 3 * n[d];
          });
        const double mean = first / volume;
        spread[d]         = std::sqrt(second / volume - mean * mean);
      }
    return spread;
  }

  // Grains and packings: run the scene for STEPS steps; the neck (the
  // smallest over the overlapping pairs, as in metrics.csv) must grow, the
  // volume stay and the solid not shrink (solid_spread along every axis).
  template <int dim>
  void
  neck(const std::string   &scene_file,
       const unsigned int   steps,
       const study::Options &options)
  {
    const std::string output =
      "validation_output/sd_neck_" + std::to_string(dim) + "d";
    std::filesystem::create_directories(output);
    auto overrides = options.overrides;
    overrides.insert(overrides.begin(),
                     {{"Output/Directory", output},
                      {"Output/Field formats", "none"},
                      {"Time/Maximum steps", std::to_string(steps)}});
    const auto      scene = read_scene(scene_file, overrides);
    Simulation<dim> simulation(scene, MPI_COMM_WORLD, std::cout);
    simulation.initialise();
    auto measure = [&]() {
      const auto &alpha = simulation.level_set();
      const double neck =
        interface_measures::smallest_neck_radius(alpha,
                                                 scene.geometry.particles);
      const auto measures = interface_measures::volume_and_area(alpha);
      return std::make_tuple(neck,
                             measures.solid_volume,
                             measures.interface_area,
                             solid_spread(alpha));
    };
    const auto [x0, v0, a0, s0] = measure();
    const auto summary          = simulation.run();
    const auto [x1, v1, a1, s1] = measure();
    double spread_change = 0;
    for (unsigned int d = 0; d < dim; ++d)
      spread_change = std::max(spread_change, std::abs(s1[d] - s0[d]) / s0[d]);
    if (study::is_root())
      std::cout << "neck " << x0 << " -> " << x1 << ", volume change "
                << (v1 - v0) / v0 << ", area change " << (a1 - a0) / a0
                << ", spread " << s0 << " -> " << s1 << " (largest change "
                << spread_change << "), " << summary.steps << " steps, "
                << summary.max_dofs << " DoFs, CPU " << summary.cpu_time
                << " s\n";
    study::check("neck growth factor", x1 / x0, options, "min-neck-growth",
                 false);
    study::check("|volume change|", std::abs(v1 - v0) / v0, options,
                 "max-volume-change");
    study::check("largest relative change of the spread", spread_change,
                 options, "max-spread-change");
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const std::vector<std::string>   args(argv, argv + argc);
  try
    {
      if (args.size() >= 4 && args[1] == "neck")
        {
          const auto options = study::parse_options(args, 4);
          if (read_scene(args[2], {}).dimension == 2)
            neck<2>(args[2], std::stoi(args[3]), options);
          else
            neck<3>(args[2], std::stoi(args[3]), options);
          return study::failures() == 0 ? 0 : 1;
        }
      if (args.size() < 5 || args[1] != "mullins")
        throw std::runtime_error(
          "usage: mullins SCENE LEVELS STEPS [--mode n] [--csv FILE] "
          "[--max-rate-error x] [--max-volume-change y]");
      unsigned int                  mode = 2;
      std::string                   csv;
      std::map<std::string, double> limits;
      for (unsigned int i = 5; i + 1 < args.size(); i += 2)
        if (args[i] == "--time-fraction")
          time_fraction = std::stod(args[i + 1]);
        else if (args[i] == "--coupled")
          coupled = std::stoi(args[i + 1]);
        else if (args[i] == "--filter-thickness")
          filter_thickness = std::stod(args[i + 1]);
        else if (args[i] == "--solver")
          linear_solver = args[i + 1];
        else if (args[i] == "--mode")
          mode = std::stoi(args[i + 1]);
        else if (args[i] == "--csv")
          csv = args[i + 1];
        else if (args[i].rfind("--", 0) == 0)
          limits[args[i].substr(2)] = std::stod(args[i + 1]);
        else
          throw std::runtime_error("unexpected argument " + args[i]);
      const auto scene = read_scene(args[2], {});
      if (scene.dimension == 2)
        mullins<2>(args[2], study::parse_levels(args[3]), study::parse_levels(args[4]), mode, limits, csv);
      else
        mullins<3>(args[2], study::parse_levels(args[3]), study::parse_levels(args[4]), mode, limits, csv);
    }
  catch (const std::exception &e)
    {
      std::cerr << "surface_diffusion_validation: " << e.what() << "\n";
      return 2;
    }
  return study::failures() == 0 ? 0 : 1;
}
