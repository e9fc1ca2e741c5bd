// Validation of surface diffusion (doc/validation.md, "Surface diffusion"):
//
//   surface_diffusion_validation mullins SCENE.prm LEVELS STEPS [options]
//   surface_diffusion_validation neck SCENE.prm STEPS [options]
//
// mullins: SCENE is a perturbed-particle scene in reduced time (Time unit =
// reduced, reference radius R = the particle's radius), in which mode n
// decays as exp(-n^2 (n^2 - 1) t*) in 2D and as exp(-(n-1) n (n+1) (n+2) t*)
// in 3D (Mullins 1957); with volume diffusion on (2D, elastic) as
// exp(-(2/3)(1 + nu) n (n^2 - 1) t*), t* = C_v gamma t / R^3; with viscous
// flow on (an atmosphere of negligible viscosity) as
// exp(-n gamma t / (2 eta_s R)) for a cylinder and as
// exp(-l (l + 2) (2 l + 1) gamma t / (2 (2 l^2 + 4 l + 3) eta_s R)) for a
// sphere (3D or axisymmetric) in the scene's time (doc/numerics.md and
// doc/validation.md, "Sharp interfaces"; iterations and solve CPU are then
// Stokes'). Every
// combination of LEVELS (maximum refinement level) and STEPS (steps per
// e-folding time) is run to one e-folding time; the amplitude is measured
// after every step from the discrete interface and the rate fitted by
// least squares to log|amplitude|. Settings: --mode n, --time-fraction f
// (run f e-folding times), --coupled 0 (kappa then v_s),
// --filter-thickness E and --band-width W (lower bounds; the defaults are
// 6 h and 4 h), --signs 2 (each case with
// +delta and -delta, rate = their mean), --coarse-levels k (the mesh
// outside the band k levels coarser than LEVEL; 3), --velocity-rate 1
// (print each step's rate; the column velocity_rate_error is the mean
// over the steps of the rate each step's velocity stands for, before
// transport); limits --max-rate-error, --max-volume-change, checked on the
// last run.
//
// neck: SCENE has two grains R1, R2 (2D or 3D), or a packing whose
// overlapping particles are neighbours; it runs STEPS steps (or to its end
// time) and samples every --sample-interval steps (10) the neck x (two
// grains: on the narrowest cross-section between the centres; a packing:
// the smallest over the neighbour pairs), x / Rbar with Rbar =
// 2 R1 R2 / (R1 + R2) (paper Fig. 27; a packing: the mean radius),
// t* = C_s t / Rbar^4 (with volume diffusion on, also coupled: C_v gamma
// t / Rbar^3), the solid-volume change and the change of the
// centre distances read off the level set (rays from each centre away
// from its neighbours, see sample() in neck()) and the change of the
// far-end-to-far-end length (length_change, the exits along the outward
// directions). It fits
// x / Rbar = A t*^(1/n) over the samples with --fit-min <= x / Rbar <=
// --fit-max (0.05, 0.3: the Nichols-Mullins window) and over all samples
// with x / Rbar >= --fit-min, and prints the CPU time of each timer
// section. Limits: --min-neck-growth and --max-neck-growth (x_end / x_0),
// --max-volume-change, --max-centre-shift (|d - d0| / d0),
// --max-length-change (|L - L0| / L0), --max-neck-offset (two grains:
// distance of the initial neck from the plane where the spheres meet,
// relative to Rbar). A grain whose centre lies outside the domain is the
// mirror image of the other across a symmetry plane (an octant scene):
// the neck is then on that plane, and the centre and length measures use
// the grain inside (rays that leave the domain are skipped).
//
// Both modes take --csv FILE and --set "Section/Entry=value" (scene
// overrides for every run). Exit code 0 only if every check passes.

#include <deal.II/base/mpi.h>
#include <deal.II/base/timer.h>
#include <deal.II/base/utilities.h>

#include <levelsinter/analysis/neck.h>
#include <levelsinter/level_set/interface_measures.h>
#include <levelsinter/level_set/same_cell.h>
#include <levelsinter/scene/command_line.h>
#include <levelsinter/time/simulation.h>

#include "study_support.h"
#include "study_table.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <functional>
#include <fstream>
#include <iostream>
#include <limits>
#include <numeric>

using namespace levelsinter;

namespace
{
  // ctest -j runs tests of the same mode, level and steps but other
  // settings side by side: a hash of the settings keeps their run
  // directories apart (they shared one and read each other's metrics).
  std::string
  settings_tag(const study::Options &options)
  {
    std::string all;
    for (const auto &[key, value] : options.overrides)
      all += key + '=' + value + ';';
    for (const auto &[name, value] : options.limits)
      all += name + '=' + std::to_string(value) + ';';
    return "_" + std::to_string(std::hash<std::string>{}(all));
  }

  // A numeric setting given as --name value, or its default.
  double
  setting(const study::Options &options,
          const std::string    &name,
          const double          default_value)
  {
    const auto it = options.limits.find(name);
    return it == options.limits.end() ? default_value : it->second;
  }

  // Mean of one column of a metrics.csv over its rows after the first
  // (the first row is the initial state); 0 if the column is absent.
  double
  column_mean(const std::string &file, const std::string &column)
  {
    const study::CsvTable metrics(file);
    if (!metrics.has_column(column) || metrics.n_rows() < 2)
      return 0;
    const auto &values = metrics.column(column);
    double      sum    = 0;
    for (unsigned int row = 1; row < values.size(); ++row)
      sum += values[row];
    return sum / (values.size() - 1);
  }

  // Amplitude of mode n relative to R, from the discrete interface:
  // a_n = (1/pi) int_0^2pi r cos(n theta) dtheta, and dtheta = (N.e_r)/r ds
  // on a star-shaped curve, so a_n = (1/pi) int_Gamma cos(n theta) N.e_r ds.
  // In 3D the Legendre coefficient (2n+1)/2 int r P_n(cos) sin dtheta
  // follows the same way with the solid-angle element (N.e_r)/r^2 dA; on
  // an axisymmetric 2D scene too (dA is the body's, theta from the axis).
  template <int dim>
  bool
  planar(const LevelSetField<dim> &alpha)
  {
    return dim == 2 && !alpha.measure().is_axisymmetric();
  }

  // The weight of mode n at x (relative to the centre) in the amplitude:
  // cos(n theta) / pi on a planar curve, (2n+1)/(4 pi) P_n / r on a surface
  // (the 1/r of the solid-angle element's 1/r^2 that N.e_r leaves).
  template <int dim>
  double
  mode_weight(const LevelSetField<dim> &alpha,
              const Tensor<1, dim>     &x,
              const unsigned int        mode)
  {
    const double r = x.norm();
    if (planar(alpha))
      return std::cos(mode * std::atan2(x[1], x[0])) / M_PI;
    return std::legendre(mode, x[dim - 1] / r) * (2 * mode + 1) /
           (4 * M_PI * r);
  }

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
               return mode_weight(alpha, x, mode) * (normal * x) / x.norm();
             }) /
           radius;
  }

  // The rate of change of mode_amplitude() that the velocity v on the
  // interface gives: r moves at v.N / (N.e_r), so the amplitude's
  // integrand N.e_r turns into v.N / r. Divided by the amplitude, minus
  // this is the rate the step's velocity stands for, before the level set
  // transports it (--velocity-rate 1).
  template <int dim>
  double
  mode_velocity(const LevelSetField<dim> &alpha,
                const VelocityField<dim> &velocity,
                const Point<dim>         &centre,
                const double              radius,
                const unsigned int        mode)
  {
    interface_measures::RegionIntegrands<dim> integrands;
    integrands.surface_flags = update_values | update_JxW_values |
                               update_quadrature_points |
                               update_normal_vectors;
    const FiniteElement<dim>            &fe = velocity.fe();
    std::vector<types::global_dof_index> indices(fe.dofs_per_cell);
    double                               result = 0;
    integrands.on_surface = [&](const auto &cell, const auto &values) {
      same_cell(cell, velocity.dof_handler())->get_dof_indices(indices);
      for (const unsigned int q : values.quadrature_point_indices())
        {
          // The velocity is Q1^dim, the level set Q1: the level set's
          // shape values interpolate each component's vertex values.
          Tensor<1, dim> v;
          for (unsigned int k = 0; k < fe.dofs_per_cell; ++k)
            {
              const auto [component, i] = fe.system_to_component_index(k);
              v[component] +=
                values.shape_value(i, q) * velocity.values()[indices[k]];
            }
          const Tensor<1, dim> x = values.quadrature_point(q) - centre;
          result += mode_weight(alpha, x, mode) * (v * values.normal_vector(q)) /
                    x.norm() * alpha.measure().JxW(values, q);
        }
    };
    interface_measures::integrate_regions(alpha, integrands);
    return Utilities::MPI::sum(result,
                               alpha.dof_handler().get_communicator()) /
           radius;
  }

  template <int dim>
  void
  mullins(const std::string               &scene_file,
          const std::vector<unsigned int> &levels,
          const std::vector<unsigned int> &steps_per_efold,
          const study::Options            &options)
  {
    const unsigned int mode          = setting(options, "mode", 2);
    const double       time_fraction = setting(options, "time-fraction", 1);
    const bool         coupled       = setting(options, "coupled", 1) != 0;
    const double filter_thickness = setting(options, "filter-thickness", 0);
    const double band_width       = setting(options, "band-width", 0);
    // --signs 2: every case also with -delta, and the rate is the mean of
    // the two. In 3D P_2^2 has a P_2 part, so the mode drives itself at
    // second order and the rate of +delta is off by O(delta) (measured
    // -4 % at delta = 0.05, doc/validation.md); the mean cancels that term.
    const bool both_signs = setting(options, "signs", 1) == 2;
    // --velocity-rate 1: print each step's rate from the amplitudes and
    // from the velocity (mode_velocity()).
    const bool print_series = setting(options, "velocity-rate", 0) != 0;
    // --coarse-levels k: the mesh away from the band is k levels coarser
    // than LEVEL (3).
    const unsigned int coarse_levels = setting(options, "coarse-levels", 3);

    const SceneParameters base = read_scene(scene_file, options.overrides);
    // Volume diffusion of an elastic cylinder (plane strain, 2D only):
    // s_n = (2/3)(1 + nu) n (n^2 - 1) in t* = C_v gamma t / R^3
    // (doc/numerics.md, "Volume diffusion").
    const double G = base.phase_law.shear_modulus,
                 K = base.phase_law.bulk_modulus;
    const double nu = (3 * K - 2 * G) / (2 * (3 * K + G));
    const bool viscous = base.viscous_flow.enabled;
    const bool planar_scene = dim == 2 && !base.geometry.axisymmetric;
    const double radius = base.geometry.particles[0][dim];
    // Viscous flow: s_n = n gamma / (2 eta R) for a cylinder and
    // l (l + 2) (2 l + 1) gamma / (2 (2 l^2 + 4 l + 3) eta R) for a sphere
    // (3D or a body of revolution; doc/validation.md, "Sharp interfaces:
    // shape modes", scripts/viscous_shape_mode_rates.py).
    const double n             = mode;
    const double viscous_scale = base.materials.surface_tension /
                                 (base.viscous_flow.solid_viscosity * radius);
    const double exact_rate =
      viscous ? (planar_scene ?
                   n / 2 * viscous_scale :
                   n * (n + 2) * (2 * n + 1) / (2 * (2 * n * n + 4 * n + 3)) *
                     viscous_scale) :
      base.volume_diffusion.enabled ?
        2. / 3 * (1 + nu) * mode * (mode * mode - 1.) :
      planar_scene ? double(mode * mode) * (mode * mode - 1.) :
        double(mode - 1) * mode * (mode + 1) * (mode + 2);
    const double end_time = time_fraction / exact_rate;
    Point<dim>   centre;
    for (unsigned int d = 0; d < dim; ++d)
      centre[d] = base.geometry.particles[0][d];

    study::Table table({"mode", "level", "h", "steps", "dt", "max_dofs",
                        "rate", "exact_rate", "rate_error", "volume_change",
                        "mean_iterations", "mean_solve_cpu", "wall_time",
                        "cpu_time", "max_amplitude_ratio",
                        "velocity_rate_error"},
                       options.csv);
    for (const unsigned int level : levels)
      for (const unsigned int steps : steps_per_efold)
        {
          const double h = study::cell_size(base, level);
          double rate = 0, volume_change = 0, wall_time = 0, cpu_time = 0,
                 iterations = 0, solve_cpu = 0, amplitude_ratio = 0,
                 velocity_rate = 0;
          unsigned int max_dofs = 0;
          for (const double sign : both_signs ? std::vector<double>{1, -1} :
                                                std::vector<double>{1})
            {
              const std::string output =
                std::string("validation_output/") +
                (viscous ? base.viscous_flow.pressure_space ==
                               ViscousFlowParameters::PressureSpace::extended ?
                             "vf_extended_" :
                             "vf_" :
                           "sd_") +
                std::to_string(dim) + "d_n" +
                std::to_string(mode) + "_l" + std::to_string(level) + "_s" +
                std::to_string(steps) +
                (base.volume_correction.enabled ? "_vc" : "") +
                (sign < 0 ? "_minus" : "") + settings_tag(options);
              std::filesystem::create_directories(output);
              auto overrides = options.overrides;
              overrides.insert(
                overrides.end(),
                {{"Output/Directory", output},
                 {"Geometry/Perturbation amplitude",
                  Utilities::to_string(sign *
                                         base.geometry.perturbation_amplitude,
                                       16)},
                 {"Output/Field formats", "none"},
                 {"Output/Progress interval", "0"},
                 {"Geometry/Perturbation mode", std::to_string(mode)},
                 {"Mesh refinement/Maximum level", std::to_string(level)},
                 {"Mesh refinement/Minimum level",
                  std::to_string(level > coarse_levels ?
                                   level - coarse_levels :
                                   0)},
                 {"Mesh refinement/Band width",
                  std::to_string(std::max(4 * h, band_width))},
                 {"Level set/Filter thickness",
                  std::to_string(std::max(6 * h, filter_thickness))},
                 {"Time/End time", Utilities::to_string(end_time, 16)},
                 {"Time/Time step", Utilities::to_string(end_time / steps, 16)},
                 {"Time/CFL number", "0"},
                 {"Surface diffusion/Coupled", coupled ? "true" : "false"}});
              const auto scene = read_scene(scene_file, overrides);
              Simulation<dim> simulation(scene, MPI_COMM_WORLD, std::cout);
              simulation.initialise();
              std::vector<double> times, logs, velocity_rates;
              double              amplitude = 0;
              auto                observe = [&](const double              t,
                                 const LevelSetField<dim> &alpha) {
                const double now =
                  mode_amplitude<dim>(alpha, centre, radius, mode);
                if (!times.empty())
                  {
                    // The step's velocity against the amplitude it was
                    // computed for (the start of the step).
                    velocity_rates.push_back(
                      -mode_velocity<dim>(alpha,
                                          simulation.interface_velocity(),
                                          centre,
                                          radius,
                                          mode) /
                      amplitude);
                    if (print_series && study::is_root())
                      std::cout << "series t " << t << " rate "
                                << (logs.back() - std::log(std::abs(now))) /
                                     (t - times.back())
                                << " velocity_rate " << velocity_rates.back()
                                << "\n";
                  }
                amplitude = now;
                times.push_back(t);
                logs.push_back(std::log(std::abs(amplitude)));
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
              // Means over the signs; the volume change of the larger drift.
              const double n_signs   = both_signs ? 2 : 1;
              const double this_rate =
                -study::least_squares(times, logs).slope;
              if (both_signs && study::is_root())
                std::cout << "delta = "
                          << sign * base.geometry.perturbation_amplitude
                          << ": rate " << this_rate << "\n";
              rate += this_rate / n_signs;
              if (!velocity_rates.empty())
                velocity_rate += std::accumulate(velocity_rates.begin(),
                                                 velocity_rates.end(),
                                                 0.) /
                                 velocity_rates.size() / n_signs;
              const double change = (volume - volume0) / volume0;
              if (std::abs(change) > std::abs(volume_change))
                volume_change = change;
              iterations += column_mean(output + "/metrics.csv",
                                        viscous ?
                                          "stokes_iterations" :
                                          "surface_diffusion_iterations") /
                            n_signs;
              solve_cpu += column_mean(output + "/metrics.csv",
                                       viscous ?
                                         "stokes_solve_cpu" :
                                         "surface_diffusion_solve_cpu_time") /
                           n_signs;
              wall_time += summary.wall_time;
              cpu_time += summary.cpu_time;
              max_dofs = std::max(max_dofs, summary.max_dofs);
              amplitude_ratio = std::max(
                amplitude_ratio,
                std::exp(*std::max_element(logs.begin(), logs.end()) -
                         logs.front()));
            }
          table.add({double(mode),
                     double(level),
                     h,
                     double(steps),
                     end_time / steps,
                     double(max_dofs),
                     rate,
                     exact_rate,
                     (rate - exact_rate) / exact_rate,
                     volume_change,
                     iterations,
                     solve_cpu,
                     wall_time,
                     cpu_time,
                     amplitude_ratio,
                     (velocity_rate - exact_rate) / exact_rate});
        }
    // Errors are checked by magnitude: a rate or area error may have
    // either sign.
    study::check("|relative rate error| (last run)",
                 std::abs(table.finest("rate_error")),
                 options,
                 "max-rate-error");
    study::check("|volume change| (last run)",
                 std::abs(table.finest("volume_change")),
                 options,
                 "max-volume-change");
  }

  // Directions for a particle's centre shift, from its centre c (see
  // neck()): first the outward one u, away from its neighbours, then
  // directions across u that also point away from them: the projections
  // of -a_k (a_k towards neighbour k) on the plane normal to u, or, with a
  // single neighbour, the 2 (dim - 1) directions normal to the axis. Empty
  // when the neighbours surround c (no free outward direction).
  template <int dim>
  std::vector<Tensor<1, dim>>
  shift_directions(const Point<dim>              &c,
                   const std::vector<Point<dim>> &neighbours)
  {
    Tensor<1, dim>              sum;
    std::vector<Tensor<1, dim>> away;
    for (const auto &n : neighbours)
      {
        away.push_back((c - n) / (c - n).norm());
        sum += away.back();
      }
    if (sum.norm() < 1e-6 * neighbours.size())
      return {};
    const Tensor<1, dim>        u = sum / sum.norm();
    std::vector<Tensor<1, dim>> directions{u};
    if (neighbours.size() == 1)
      {
        // An orthonormal pair (2D: one vector) normal to u, both signs.
        Tensor<1, dim> e1;
        e1[0] = -u[1];
        e1[1] = u[0];
        if constexpr (dim == 3)
          {
            const Tensor<1, 3> axis =
              std::abs(u[2]) < 0.9 ? Tensor<1, 3>({0, 0, 1}) :
                                     Tensor<1, 3>({1, 0, 0});
            e1 = cross_product_3d(u, axis);
            e1 /= e1.norm();
            const Tensor<1, dim> e2 = cross_product_3d(u, e1);
            directions.insert(directions.end(), {e2, -e2});
          }
        directions.insert(directions.end(), {e1, -e1});
      }
    else
      for (const auto &a : away)
        {
          const Tensor<1, dim> w = a - (a * u) * u;
          if (w.norm() > 1e-6)
            directions.push_back(w / w.norm());
        }
    return directions;
  }

  // Neck growth against t* for two grains or a packing, solid volume and
  // centre distances (surface diffusion moves matter along the surface
  // only: no volume change, no shrinkage).
  template <int dim>
  void
  neck(const std::string    &scene_file,
       const unsigned int    steps,
       const study::Options &options)
  {
    const unsigned int sample_interval =
      setting(options, "sample-interval", 10);
    const double fit_min = setting(options, "fit-min", 0.05);
    const double fit_max = setting(options, "fit-max", 0.3);

    const std::string output =
      "validation_output/sd_neck_" +
      (options.csv.empty() ? std::filesystem::path(scene_file).stem() :
                             std::filesystem::path(options.csv).stem())
        .string() +
      settings_tag(options);
    std::filesystem::create_directories(output);
    auto overrides = options.overrides;
    overrides.insert(overrides.end(),
                     {{"Output/Directory", output},
                      {"Output/Field formats", "none"},
                      {"Time/Maximum steps", std::to_string(steps)}});
    const auto  scene     = read_scene(scene_file, overrides);
    const auto &particles = scene.geometry.particles;
    if (particles.size() < 2)
      throw std::runtime_error(scene_file + ": the neck study needs at least "
                               "two particles (Geometry/Particles or "
                               "Geometry/Particle file)");
    std::vector<Point<dim>> centres(particles.size());
    for (unsigned int i = 0; i < particles.size(); ++i)
      for (unsigned int d = 0; d < dim; ++d)
        centres[i][d] = particles[i][d];
    const bool   pair = particles.size() == 2;
    std::vector<bool> inside(particles.size(), true);
    for (unsigned int i = 0; i < particles.size(); ++i)
      for (unsigned int d = 0; d < dim; ++d)
        inside[i] = inside[i] && centres[i][d] >= scene.domain.lower_corner[d] &&
                    centres[i][d] <= scene.domain.upper_corner[d];
    const bool mirrored_pair = pair && !(inside[0] && inside[1]);
    const unsigned int n_inside =
      std::count(inside.begin(), inside.end(), true);
    const double r1 = particles[0][dim], r2 = particles[1][dim];
    // Two grains: Rbar = 2 R1 R2 / (R1 + R2) (paper Fig. 27); a packing:
    // the mean radius.
    double r_bar = 2 * r1 * r2 / (r1 + r2);
    if (!pair)
      {
        r_bar = 0;
        for (const auto &p : particles)
          r_bar += p[dim] / particles.size();
      }
    // Neighbours as smallest_neck_radius() pairs them: the two grains, or
    // the overlapping pairs of a packing. d0: the smallest centre distance.
    std::vector<std::vector<Point<dim>>> neighbours(particles.size());
    double d0 = std::numeric_limits<double>::max();
    for (unsigned int i = 0; i < particles.size(); ++i)
      for (unsigned int j = 0; j < particles.size(); ++j)
        if (j != i && (pair || centres[i].distance(centres[j]) <
                                 particles[i][dim] + particles[j][dim]))
          {
            neighbours[i].push_back(centres[j]);
            d0 = std::min(d0, centres[i].distance(centres[j]));
          }
    std::vector<std::vector<Tensor<1, dim>>> directions(particles.size());
    for (unsigned int i = 0; i < particles.size(); ++i)
      if (!neighbours[i].empty() && inside[i])
        directions[i] = shift_directions(centres[i], neighbours[i]);
    // t* = C_s t / Rbar^4 (volume diffusion, alone or with surface
    // diffusion: C_v gamma t / Rbar^3), whatever time unit the scene runs
    // in.
    const auto  &sd = scene.surface_diffusion;
    const auto  &vd = scene.volume_diffusion;
    const double gamma = scene.materials.surface_tension;
    const double t_star_per_t =
      scene.seconds_per_time_unit() /
      (vd.enabled ? vd.reduced_time_scale(r_bar, gamma) :
                    sd.reduced_time_scale(r_bar));

    study::Table table({"step", "t", "t_star", "dofs", "neck", "neck_over_R",
                        "neck_position", "volume_change",
                        "centre_distance_change", "length_change",
                        "cpu_time"},
                       options.csv);
    Simulation<dim> simulation(scene, MPI_COMM_WORLD, std::cout);
    simulation.initialise();
    const Timer cpu_timer(MPI_COMM_WORLD); // CPU summed over the ranks
    double      volume0 = 0, shift0 = 0, length0 = 0;
    std::vector<double> log_t, log_x, x_over_r;
    unsigned int        last_sample = 0;
    auto sample = [&](const unsigned int step, const double t,
                      const LevelSetField<dim> &alpha) {
      last_sample = step;
      const auto neck =
        mirrored_pair ?
          neck_measures::Neck{neck_measures::neck_radius(alpha,
                                                         centres[0],
                                                         centres[1]),
                              0.5} :
        pair ? neck_measures::narrowest_neck(alpha, centres[0],
                                                  centres[1]) :
               neck_measures::Neck{
                 neck_measures::smallest_neck_radius(alpha, particles),
                 std::numeric_limits<double>::quiet_NaN()};
      const double volume =
        interface_measures::volume_and_area(alpha).solid_volume;
      // Centre shift of each particle from the level set: if a particle of
      // radius r is still a sphere but its centre moved by delta, the ray
      // from the scene's centre along a unit u leaves it at r + delta.u
      // to first order, whatever r became (v^c grows r uniformly). The
      // inward shift is the mean exit across u minus the exit along u
      // (shift_directions()); all these rays stay away from the necks.
      // Two grains: their approach -(shift1 + shift2) / d0 is the change
      // of the centre distance; a packing: -2 (mean shift) / d0, the
      // change of a pair's distance if both moved along its axis.
      // The far ends alone (the exits along u) give the length of a pair
      // from far end to far end, d + e1 + e2 (a packing: d0 + 2 mean e).
      // It needs no assumption on the shape near the necks, but reads any
      // change of the radius: measured with v^c, which holds it.
      double shift = 0, far_end = 0;
      unsigned int n_free = 0;
      for (unsigned int i = 0; i < particles.size(); ++i)
        if (!directions[i].empty())
          {
            const auto exits = interface_measures::exit_distances(
              alpha, centres[i], directions[i]);
            // Rays that leave the domain first (symmetry planes) are
            // skipped: the mirror image of their exit is one kept.
            double       across   = 0;
            unsigned int n_across = 0;
            for (unsigned int e = 1; e < exits.size(); ++e)
              if (std::isfinite(exits[e]))
                {
                  across += exits[e];
                  ++n_across;
                }
            across /= std::max(n_across, 1u);
            shift += (across - exits[0]) *
                     (pair ? 2. / n_inside : 2. / particles.size());
            far_end += exits[0];
            ++n_free;
          }
      const double length = d0 + 2 * far_end / std::max(n_free, 1u);
      if (step == 0)
        {
          volume0 = volume;
          shift0  = shift;
          length0 = length;
        }
      const double t_star = t * t_star_per_t;
      if (t_star > 0)
        {
          log_t.push_back(std::log(t_star));
          log_x.push_back(std::log(neck.radius / r_bar));
          x_over_r.push_back(neck.radius / r_bar);
        }
      table.add({double(step),
                 t,
                 t_star,
                 double(alpha.dof_handler().n_dofs()),
                 neck.radius,
                 neck.radius / r_bar,
                 neck.position,
                 (volume - volume0) / volume0,
                 -(shift - shift0) / d0,
                 (length - length0) / length0,
                 cpu_timer.cpu_time()});
    };
    sample(0, 0, simulation.level_set());
    const double x0 = table.finest("neck");
    // Two grains: where their circles meet, as a fraction of c1 -> c2.
    const double junction =
      (d0 * d0 + r1 * r1 - r2 * r2) / (2 * d0 * d0);
    const double offset0 =
      pair ? std::abs(table.finest("neck_position") - junction) * d0 / r_bar :
             0.;
    simulation.set_step_observer(
      [&](unsigned int step, double t, const LevelSetField<dim> &alpha) {
        if (step % sample_interval == 0)
          sample(step, t, alpha);
      });
    const auto summary = simulation.run();
    if (last_sample != summary.steps)
      sample(summary.steps, summary.time, simulation.level_set());

    // x / Rbar = A t*^(1/n): a line in log-log.
    auto fit = [&](const double lo, const double hi, const std::string &name) {
      std::vector<double> x, y;
      for (unsigned int i = 0; i < log_t.size(); ++i)
        if (x_over_r[i] >= lo && x_over_r[i] <= hi)
          {
            x.push_back(log_t[i]);
            y.push_back(log_x[i]);
          }
      const study::Line line = study::least_squares(x, y);
      if (study::is_root())
        std::cout << "fit " << name << " (" << line.points << " samples, "
                  << lo << " <= x/Rbar"
                  << (hi < std::numeric_limits<double>::max() ?
                        " <= " + std::to_string(hi) :
                        std::string())
                  << "): x/Rbar = " << std::exp(line.intercept)
                  << " t*^(1/" << 1 / line.slope << ")\n";
    };
    fit(fit_min, fit_max, "window");
    fit(fit_min, std::numeric_limits<double>::max(), "all");
    const double x1 = table.finest("neck");
    if (study::is_root())
      std::cout << "Rbar = " << r_bar << ", neck " << x0 << " -> " << x1
                << " (initial offset from the junction plane "
                << offset0 << " Rbar), " << summary.steps << " steps, "
                << summary.max_dofs << " DoFs at most, mean GMRES "
                << "iterations " << summary.mean_iterations << ", cpu "
                << summary.cpu_time << " s\n";
    // Where the run spent its time (kappa / v_s assembly and solve,
    // transport, adaptation, metrics, output).
    simulation.timer().print_summary();
    study::check("neck growth factor", x1 / x0, options, "min-neck-growth",
                 false);
    study::check("neck growth factor", x1 / x0, options, "max-neck-growth");
    study::check("|volume change|", std::abs(table.finest("volume_change")),
                 options, "max-volume-change");
    study::check("|centre distance change| / d0",
                 std::abs(table.finest("centre_distance_change")), options,
                 "max-centre-shift");
    study::check("|length change| / L0",
                 std::abs(table.finest("length_change")), options,
                 "max-length-change");
    study::check("initial neck offset from the junction plane / Rbar",
                 offset0, options, "max-neck-offset");
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
          if (read_scene(args[2], options.overrides).dimension == 2)
            neck<2>(args[2], std::stoi(args[3]), options);
          else
            neck<3>(args[2], std::stoi(args[3]), options);
        }
      else if (args.size() >= 5 && args[1] == "mullins")
        {
          const auto options = study::parse_options(args, 5);
          const auto levels  = study::parse_levels(args[3]);
          const auto steps   = study::parse_levels(args[4]);
          if (read_scene(args[2], options.overrides).dimension == 2)
            mullins<2>(args[2], levels, steps, options);
          else
            mullins<3>(args[2], levels, steps, options);
        }
      else
        throw std::runtime_error(
          "usage: mullins SCENE LEVELS STEPS [options] | neck SCENE STEPS "
          "[options] (see the head of tests/surface_diffusion_validation.cc)");
    }
  catch (const std::exception &e)
    {
      std::cerr << "surface_diffusion_validation: " << e.what() << "\n";
      return 2;
    }
  return study::failures() == 0 ? 0 : 1;
}
