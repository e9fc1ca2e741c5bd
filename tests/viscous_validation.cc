// Validation of the viscous-flow mechanism (issue 3), shared by the CI tests
// (small resolutions) and the long studies (doc/validation.md):
//
//   levelsinter_viscous_validation bubble SCENE.prm LEVELS FORMS [options]
//   levelsinter_viscous_validation hopper SCENE.prm LEVELS [options]
//   levelsinter_viscous_validation spheres SCENE.prm LEVELS [options]
//   levelsinter_viscous_validation pore SCENE.prm LEVELS [options]
//   levelsinter_viscous_validation coalescence SCENE.prm LEVELS [options]
//   levelsinter_viscous_validation neck-history SCENE.prm LEVELS [options]
//   levelsinter_viscous_validation bubble-time SCENE.prm LEVELS [options]
//
// LEVELS: comma-separated maximum refinement levels (uniform meshes for the
// bubble); FORMS: comma-separated surface-tension forms (csf, sharp,
// csf-curvature, sharp-curvature, and either curvature form with -exact:
// the curvature prescribed, 1/R or 2/R).
// Options: --csv FILE, --set ENTRY=VALUE and limits (--max-pressure-error,
// --max-core-error, --max-C, --max-curvature-error,
// --max-outer-pressure-error (bubble: |p_out - p_ext| / p_exact, p_ext the
// scene's 'External pressure'),
// --max-neck-error, --max-area-drift, --max-mean-stokes-its,
// --max-stokes-its, hopper: --circle-start 1 (keep the scene's circles
// instead of Hopper's shape of their neck), --max-neck-error-from-tau0.2,
// --samples N (the viscoelastic seed's Eq. 44
// error over N samples of the run, column sampled_neck_error, limit
// --max-sampled-neck-error), --max-final-neck-error, --max-rejected,
// --min-rejected, --min-fine-cells (cells above Maximum level after the
// first step), --max-fine-cell-distance (the farthest of them from the
// neck, / R); spheres:
// --min-neck-growth, --max-volume-drift,
// --min-early-slope, --max-early-slope, --max-final-radius-error,
// --min-neck_tau0.5, --min-neck_tau1, --min-neck_tau2 and --max-... (x/a at those
// t gamma/(eta a) from touching); pore:
// --pore-half-width W (required: a square window of half-width W around
// the particles' centroid that holds the pore and solid only),
// --max-closure-time, --max-pore-area-ratio, --max-area-drift; coalescence:
// --max-roundness-error, --max-area-drift; neck-history: --max-trace-c,
// --max-rejected; bubble-time: --max-C, --max-C-growth (largest C over C
// at the first step), --max-area-drift) and for all but the bubbles the
// band and filter thickness in cells (--band-cells, --filter-cells) and a
// fixed step --dt-factor F (dt = F eta_s h / gamma, no CFL or capillary
// limit).
// Exit code 0 only if every check passes.

#include <deal.II/base/mpi.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/base/timer.h>
#include <deal.II/base/utilities.h>

#include <deal.II/fe/fe_values.h>

#include <deal.II/hp/fe_collection.h>

#include <deal.II/non_matching/fe_values.h>
#include <deal.II/non_matching/mesh_classifier.h>

#include <levelsinter/analysis/neck.h>
#include <levelsinter/level_set/interface_measures.h>
#include <levelsinter/mechanisms/viscous_flow.h>
#include <levelsinter/scene/command_line.h>
#include <levelsinter/scene/hopper.h>
#include <levelsinter/time/simulation.h>

#include "study_support.h"
#include "study_table.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <memory>
#include <complex>
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
  bool root = true; // set in main() once MPI is up

  using study::check;
  using study::Options;
  using study::parse_options;
  using study::Table;

  std::string
  output_directory(const std::string &name)
  {
    const std::string dir = "viscous_validation_output/" + name;
    std::filesystem::create_directories(dir);
    return dir;
  }

  // NonMatching FEValues of @p fe for the regions of {alpha_h = 0} that
  // @p flags asks for, 3 Gauss points per direction; owns the classifier
  // the values read.
  template <int dim>
  struct CutCellValues
  {
    CutCellValues(const FiniteElement<dim>             &fe,
                  const LevelSetField<dim>             &alpha,
                  const NonMatching::RegionUpdateFlags &flags)
      : classifier(alpha.dof_handler(), alpha.alpha())
      , fe_collection(fe)
      , values(fe_collection,
               QGauss<1>(3),
               flags,
               classifier,
               alpha.dof_handler(),
               alpha.alpha())
    {
      classifier.reclassify();
    }

    NonMatching::MeshClassifier<dim> classifier;
    const hp::FECollection<dim>      fe_collection;
    NonMatching::FEValues<dim>       values;
  };

  // Mean pressure over the discrete solid {alpha_h < 0} (cut-cell
  // quadrature) and over the pore, and their areas.
  template <int dim>
  std::array<double, 2>
  mean_pressures(const VelocityPressureOperator<dim> &stokes,
                 const LevelSetField<dim>            &alpha)
  {
    NonMatching::RegionUpdateFlags flags;
    const UpdateFlags region =
      update_values | update_JxW_values | update_quadrature_points;
    flags.inside  = region;
    flags.outside = region;
    CutCellValues<dim> cut(stokes.fe(), alpha, flags);
    auto              &values = cut.values;
    std::array<double, 4> sums{{0, 0, 0, 0}};
    std::vector<double>   p;
    for (const auto &cell : stokes.dof_handler().active_cell_iterators())
      if (cell->is_locally_owned())
        {
          values.reinit(cell);
          // Each phase's own pressure (the same where there is one).
          const auto add = [&](const auto &region, const unsigned int k) {
            if (!region)
              return;
            const FEValuesExtractors::Scalar pressure(
              stokes.pressure_component(k == 0 ? Phase::solid : Phase::fluid));
            p.resize(region->n_quadrature_points);
            (*region)[pressure].get_function_values(stokes.solution(), p);
            for (const unsigned int q : region->quadrature_point_indices())
              {
                const double JxW = alpha.measure().JxW(*region, q);
                sums[2 * k] += p[q] * JxW;
                sums[2 * k + 1] += JxW;
              }
          };
          add(values.get_inside_fe_values(), 0);
          add(values.get_outside_fe_values(), 1);
        }
    for (auto &s : sums)
      s = Utilities::MPI::sum(s, MPI_COMM_WORLD);
    return {{sums[0] / sums[1], sums[2] / sums[3]}};
  }

  // Mean pressure over the disc |x - c| < R/2 and over |x - c| > 3R/2, away
  // from the zone the ASGS term smears: separates the smearing from the
  // accuracy of the surface-tension load.
  template <int dim>
  std::array<double, 2>
  core_pressures(const VelocityPressureOperator<dim> &stokes,
                 const SceneMeasure                  &measure,
                 const Point<dim>                    &centre,
                 const double                         R)
  {
    const QGauss<dim>                quadrature(3);
    FEValues<dim>                    values(stokes.fe(),
                         quadrature,
                         update_values | update_quadrature_points |
                           update_JxW_values);
    const std::array<FEValuesExtractors::Scalar, 2> pressure = {
      {FEValuesExtractors::Scalar(stokes.pressure_component(Phase::solid)),
       FEValuesExtractors::Scalar(stokes.pressure_component(Phase::fluid))}};
    std::array<double, 4> sums{{0, 0, 0, 0}};
    std::array<std::vector<double>, 2> p{
      {std::vector<double>(quadrature.size()),
       std::vector<double>(quadrature.size())}};
    for (const auto &cell : stokes.dof_handler().active_cell_iterators())
      if (cell->is_locally_owned())
        {
          values.reinit(cell);
          for (unsigned int k = 0; k < 2; ++k)
            values[pressure[k]].get_function_values(stokes.solution(), p[k]);
          for (const unsigned int q : values.quadrature_point_indices())
            {
              const double r = values.quadrature_point(q).distance(centre);
              const int    k = r < R / 2 ? 0 : (r > 1.5 * R ? 1 : -1);
              if (k >= 0)
                {
                  const double JxW = measure.JxW(values, q);
                  sums[2 * k] += p[k][q] * JxW;
                  sums[2 * k + 1] += JxW;
                }
            }
        }
    for (auto &s : sums)
      s = Utilities::MPI::sum(s, MPI_COMM_WORLD);
    return {{sums[0] / sums[1], sums[2] / sums[3]}};
  }

  // Relative error of the nodal curvature against @p exact at the points
  // of the sharp surface quadrature on {alpha_h = 0}: {rms, max}.
  template <int dim>
  std::array<double, 2>
  curvature_errors(const LevelSetField<dim>            &alpha,
                   const TrilinosWrappers::MPI::Vector &kappa,
                   const double                         exact)
  {
    NonMatching::RegionUpdateFlags flags;
    flags.surface = update_values | update_JxW_values;
    CutCellValues<dim> cut(alpha.fe(), alpha, flags);
    auto              &values = cut.values;
    std::array<double, 3> sums{{0, 0, 0}}; // int e^2, length, max |e|
    std::vector<double>   k;
    for (const auto &cell : alpha.dof_handler().active_cell_iterators())
      if (cell->is_locally_owned())
        {
          values.reinit(cell);
          if (const auto &surface = values.get_surface_fe_values())
            {
              k.resize(surface->n_quadrature_points);
              surface->get_function_values(kappa, k);
              for (const unsigned int q : surface->quadrature_point_indices())
                {
                  const double e = (k[q] - exact) / exact;
                  sums[0] += e * e * surface->JxW(q);
                  sums[1] += surface->JxW(q);
                  sums[2] = std::max(sums[2], std::abs(e));
                }
            }
        }
    return {{std::sqrt(Utilities::MPI::sum(sums[0], MPI_COMM_WORLD) /
                       Utilities::MPI::sum(sums[1], MPI_COMM_WORLD)),
             Utilities::MPI::max(sums[2], MPI_COMM_WORLD)}};
  }

  // Static bubble: one Stokes solve on a uniform mesh; p_in = gamma / R,
  // or 2 gamma / R for the sphere of an axisymmetric scene.
  // FORMS are the scene's surface-tension forms plus csf-curvature-exact
  // and sharp-curvature-exact, those forms with the curvature prescribed
  // (1/R, 2/R).
  void
  bubble(const std::string              &scene_file,
         const std::vector<unsigned int> &levels,
         const std::vector<std::string>  &forms,
         const Options                   &options)
  {
    constexpr int dim = 2;
    const std::vector<std::string> form_ids = {"csf",
                                               "sharp",
                                               "csf-curvature",
                                               "csf-curvature-exact",
                                               "sharp-curvature",
                                               "sharp-curvature-exact"};
    Table table({"level", "h", "form", "dofs", "iterations", "cpu_time",
                 "p_in", "p_out", "pressure_error", "core_error", "C",
                 "kappa_rms_error", "kappa_max_error"},
                options.csv);
    double worst_error = 0, worst_C = 0, worst_core = 0, worst_kappa = 0,
           worst_outer = 0;
    for (const auto &form : forms)
      for (const unsigned int level : levels)
        {
          const auto id = std::find(form_ids.begin(), form_ids.end(), form) -
                          form_ids.begin();
          if (id == int(form_ids.size()))
            throw std::runtime_error("unknown surface-tension form " + form);
          const std::string exact_suffix    = "-exact";
          const bool        exact_curvature =
            form.size() > exact_suffix.size() &&
            form.compare(form.size() - exact_suffix.size(),
                         exact_suffix.size(),
                         exact_suffix) == 0;
          const std::string scene_form =
            exact_curvature ?
              form.substr(0, form.size() - exact_suffix.size()) :
              form;
          const auto base = read_scene(scene_file, options.overrides);
          const double h = study::cell_size(base, level);
          const double band =
            std::max(base.level_set.filter_thickness, 6 * h);
          auto overrides = options.overrides;
          overrides.insert(
            overrides.end(),
            {{"Mesh refinement/Minimum level", std::to_string(level)},
             {"Mesh refinement/Maximum level", std::to_string(level)},
             // The band only matters for moving interfaces; keep the
             // scene's checks satisfied at every level.
             {"Level set/Filter thickness", std::to_string(band)},
             {"Mesh refinement/Band width", std::to_string(band)},
             {"Time/CFL number", "0.1"},
             {"Viscous flow/Surface tension form", scene_form},
             {"Output/Directory", output_directory("bubble")},
             {"Output/Field formats", "none"}});
          const auto      scene = read_scene(scene_file, overrides);
          Simulation<dim> simulation(scene, MPI_COMM_WORLD, std::cout);
          simulation.initialise();
          const auto  &alpha = simulation.level_set();
          const double R     = scene.geometry.particles[0][dim];

          ViscousFlow<dim>   flow(scene.viscous_flow,
                                scene.materials,
                                scene.domain.symmetry_planes,
                                simulation.filter(),
                                scene.refinement.max_level,
                                simulation.timer());
          VelocityField<dim> velocity(simulation.triangulation());
          velocity.setup_dofs();
          velocity.set_zero();
          // 1/R on a circle, 2/R on the sphere of an axisymmetric scene.
          const double kappa_exact =
            (alpha.measure().body_dimension<dim>() - 1.) / R;
          if (exact_curvature)
            flow.prescribe_curvature(
              std::make_shared<Functions::ConstantFunction<dim>>(kappa_exact));
          flow.setup(alpha);
          const Timer cpu_timer(MPI_COMM_WORLD); // CPU summed over the ranks
          flow.add_probe_velocity(alpha, 0, velocity);
          const double cpu_time = cpu_timer.cpu_time();
          const auto   p     = mean_pressures(flow.stokes(), alpha);
          const double gamma = scene.materials.surface_tension;
          const double eta   = scene.viscous_flow.solid_viscosity;
          const double p_exact = gamma * kappa_exact;
          const double error   = std::abs(p[0] - p[1] - p_exact) / p_exact;
          // The traction -p_ext n on the free box faces sets the level.
          const double outer_error =
            std::abs(p[1] - scene.viscous_flow.external_pressure) / p_exact;
          const double C       = velocity.max_norm() * eta / gamma;
          Point<dim>   centre;
          for (unsigned int d = 0; d < dim; ++d)
            centre[d] = scene.geometry.particles[0][d];
          const auto   core =
            core_pressures(flow.stokes(), alpha.measure(), centre, R);
          const double core_error =
            std::abs(core[0] - core[1] - p_exact) / p_exact;
          const auto kappa_error =
            flow.curvature().size() > 0 ?
              curvature_errors(alpha, flow.curvature(), kappa_exact) :
              std::array<double, 2>{{0., 0.}};
          table.add({double(level), h, double(id),
                     double(flow.stokes().dof_handler().n_dofs()),
                     flow.metric_values()[0], cpu_time, p[0], p[1], error,
                     core_error, C, kappa_error[0], kappa_error[1]});
          if (level == levels.back())
            {
              worst_error = std::max(worst_error, error);
              worst_C     = std::max(worst_C, C);
              worst_core  = std::max(worst_core, core_error);
              worst_kappa = std::max(worst_kappa, kappa_error[1]);
              worst_outer = std::max(worst_outer, outer_error);
            }
        }
    if (root)
      std::cout << "(form: 0 = csf, 1 = sharp, 2 = csf-curvature, 3 = "
                   "csf-curvature with the exact kappa, 1/R (2/R "
                   "axisymmetric), 4 = sharp-curvature, 5 = sharp-curvature "
                   "with the exact kappa; pressure_error = |p_in - "
                   "p_out - p_exact| / p_exact, p_exact = gamma/R (2 gamma/R "
                   "axisymmetric); core_error: the same with "
                   "the means over r < R/2 and r > 3R/2; kappa errors "
                   "relative, on alpha_h = 0, curvature forms only)\n";
    check("finest relative mean-pressure error (worst form)", worst_error,
          options, "max-pressure-error");
    check("finest C = v_max eta / gamma (worst form)", worst_C, options,
          "max-C");
    check("finest core pressure-jump error (worst form)", worst_core, options,
          "max-core-error");
    check("finest max relative curvature error on the interface",
          worst_kappa, options, "max-curvature-error");
    check("finest |p_out - p_ext| / p_exact (worst form)", worst_outer,
          options, "max-outer-pressure-error");
  }

  // What the two-particle studies read from one run.
  struct LevelRun
  {
    double                                     h = 0;
    SceneParameters                            scene;
    study::CsvTable                            metrics;
    unsigned int                               steps    = 0;
    unsigned int                               max_dofs = 0;
    double                                     wall_time = 0, cpu_time = 0;
    double       mean_dt        = 0;
    unsigned int rejected_steps = 0; // retried with a smaller dt
    // Per step: mean and largest FGMRES count, mean solve CPU time.
    double mean_its = 0, max_its = 0, mean_solve_cpu = 0;
  };

  // Run the scene with the finest cells at @p level (h =
  // study::cell_size), band and filter thickness tied to h (options
  // --band-cells, default 6, and --filter-cells, default 8);
  // --dt-factor F fixes dt = F eta_s h / gamma (F times the explicit
  // capillary limit at factor 1) with no CFL or capillary limit: the
  // interface then moves up to ~F cells a step, so the defaults become
  // max(6, F + 2) and max(8, F + 4) cells and the mesh is adapted every
  // step.
  // @p initialise(simulation, scene) may replace the initial level set.
  template <int dim, typename Initialise>
  LevelRun
  run_level(const std::string  &scene_file,
            const unsigned int  level,
            const Options      &options,
            const std::string  &name,
            const Initialise   &initialise)
  {
    LevelRun     run;
    const auto   base = read_scene(scene_file, options.overrides);
    run.h      = study::cell_size(base, level);
    const std::string directory =
      output_directory(name + "_level" + std::to_string(level));
    const auto option = [&](const std::string &key, const double fallback) {
      const auto it = options.limits.find(key);
      return it == options.limits.end() ? fallback : it->second;
    };
    const double dt_factor  = option("dt-factor", 0);
    const double band_cells = option("band-cells", std::max(6., dt_factor + 2));
    auto         overrides  = options.overrides;
    overrides.insert(
      overrides.end(),
      {{"Mesh refinement/Maximum level", std::to_string(level)},
       {"Mesh refinement/Band width", std::to_string(band_cells * run.h)},
       {"Level set/Filter thickness",
        std::to_string(option("filter-cells", std::max(8., dt_factor + 4)) *
                       run.h)},
       {"Output/Directory", directory},
       {"Output/Field formats", "none"}});
    if (dt_factor > 0)
      {
        const auto scene = read_scene(scene_file, overrides);
        overrides.insert(
          overrides.end(),
          {{"Time/Time step",
            std::to_string(dt_factor * scene.viscous_flow.solid_viscosity *
                           run.h / scene.materials.surface_tension)},
           {"Time/CFL number", "0"},
           {"Viscous flow/Capillary time step factor", "0"},
           {"Mesh refinement/Adapt interval", "1"}});
      }
    run.scene = read_scene(scene_file, overrides);

    Simulation<dim> simulation(run.scene, MPI_COMM_WORLD, std::cout);
    simulation.initialise();
    initialise(simulation, run.scene);
    const auto summary = simulation.run();
    run.steps          = summary.steps;
    run.max_dofs       = summary.max_dofs;
    run.wall_time      = summary.wall_time;
    run.cpu_time       = summary.cpu_time;
    run.mean_dt        = summary.time / summary.steps;
    run.rejected_steps = summary.rejected_steps;

    run.metrics           = study::CsvTable(directory + "/metrics.csv");
    const auto &its       = run.metrics.column("stokes_iterations");
    const auto &solve_cpu = run.metrics.column("stokes_solve_cpu");
    for (unsigned int i = 0; i < its.size(); ++i)
      {
        run.mean_its += its[i] / its.size();
        run.max_its = std::max(run.max_its, its[i]);
        run.mean_solve_cpu += solve_cpu[i] / its.size();
      }
    return run;
  }

  // Table columns of every two-particle study, then the study's own.
  std::vector<std::string>
  run_columns(const std::vector<std::string> &specific)
  {
    std::vector<std::string> columns = {"level",
                                        "h",
                                        "steps",
                                        "max_dofs",
                                        "wall_time",
                                        "cpu_time",
                                        "solve_cpu_per_step",
                                        "mean_stokes_its",
                                        "max_stokes_its"};
    columns.insert(columns.end(), specific.begin(), specific.end());
    return columns;
  }

  // The values of run_columns() for one run.
  std::vector<double>
  run_row(const unsigned int          level,
          const LevelRun             &run,
          const std::vector<double> &specific)
  {
    std::vector<double> row = {double(level),
                               run.h,
                               double(run.steps),
                               double(run.max_dofs),
                               run.wall_time,
                               run.cpu_time,
                               run.mean_solve_cpu,
                               run.mean_its,
                               run.max_its};
    row.insert(row.end(), specific.begin(), specific.end());
    return row;
  }

  // The neck history of one level as CSV next to the study's table.
  std::unique_ptr<study::CsvFile>
  open_series(const Options     &options,
              const unsigned int level,
              const std::string &header)
  {
    if (!root || options.csv.empty())
      return nullptr;
    auto series = std::make_unique<study::CsvFile>(
      options.csv + ".level" + std::to_string(level) + ".csv");
    series->stream() << header << '\n';
    return series;
  }

  // Column names prefix + tau for the times of a study.
  std::vector<std::string>
  time_columns(const std::string &prefix, const std::vector<double> &times)
  {
    std::vector<std::string> names;
    for (const double tau : times)
      {
        std::ostringstream name;
        name << prefix << tau;
        names.push_back(name.str());
      }
    return names;
  }

  // The samples y(tau) (tau increasing) at each of @p times, interpolated
  // linearly between the samples around it; NaN where the samples do not
  // span it.
  std::vector<double>
  values_at(const std::vector<double> &taus,
            const std::vector<double> &ys,
            const std::vector<double> &times)
  {
    std::vector<double> values(times.size(),
                               std::numeric_limits<double>::quiet_NaN());
    for (unsigned int i = 1; i < taus.size(); ++i)
      for (unsigned int k = 0; k < times.size(); ++k)
        if (taus[i - 1] < times[k] && times[k] <= taus[i])
          {
            const double s = (times[k] - taus[i - 1]) / (taus[i] - taus[i - 1]);
            values[k]      = (1 - s) * ys[i - 1] + s * ys[i];
          }
    return values;
  }

  // Over all levels: the iteration count must not grow as h shrinks.
  void
  check_iterations(const std::vector<LevelRun> &runs, const Options &options)
  {
    double worst_mean = 0, worst_max = 0;
    for (const auto &run : runs)
      {
        worst_mean = std::max(worst_mean, run.mean_its);
        worst_max  = std::max(worst_max, run.max_its);
      }
    check("largest mean FGMRES iterations per step", worst_mean, options,
          "max-mean-stokes-its");
    check("largest FGMRES iterations in one step", worst_max, options,
          "max-stokes-its");
  }

  // The particles' zero-shear viscosity: eta_s, plus eta_p for a
  // viscoelastic melt (the viscoelastic seed's eta_0, Sect. 3.4).
  double
  zero_shear_viscosity(const SceneParameters &scene)
  {
    return scene.viscous_flow.solid_viscosity +
           (scene.phase_law.is_viscoelastic() ?
              scene.phase_law.polymer_viscosity :
              0.);
  }

  // The viscoelastic seed's error of the neck (Eq. 44): the relative l2
  // norm over @p n equally spaced samples from t = 0 to the run's end,
  // the computed neck y(t) interpolated linearly between the rows of
  // metrics.csv, against exact(t).
  template <typename Exact>
  double
  sampled_neck_error(const std::vector<double> &t,
                     const std::vector<double> &y,
                     const unsigned int         n,
                     const Exact               &exact)
  {
    std::vector<double> times;
    for (unsigned int k = 0; k < n; ++k)
      times.push_back(t.back() * k / (n - 1.));
    // values_at() takes the samples after t = 0; the first row is t = 0.
    std::vector<double> computed = values_at(t, y, times);
    computed[0]                  = y[0];
    double error = 0, norm = 0;
    for (unsigned int k = 0; k < n; ++k)
      {
        const double y_exact = exact(times[k]);
        error += std::pow(computed[k] - y_exact, 2);
        norm += y_exact * y_exact;
      }
    return std::sqrt(error / norm);
  }

  // Two cylinders from Hopper's shape at the scene's initial neck: neck
  // radius against the exact one, solid-area drift, Stokes iterations;
  // --samples N adds the seed's Eq. 44 error over N samples of the run.
  void
  hopper(const std::string              &scene_file,
         const std::vector<unsigned int> &levels,
         const Options                   &options)
  {
    constexpr int dim = 2;
    // The early neck, where the band under-resolves it (doc/validation.md,
    // "Curvature refinement near necks").
    const std::vector<double> early_times = {0.05, 0.1, 0.2, 0.5};
    // max_neck_error_from_tau0.2: the largest relative error from
    // t gamma/(eta R) = 0.2 on (issue 17's accuracy target).
    std::vector<std::string>  columns = {"mean_dt", "rejected", "max_neck_error",
                                        "max_neck_error_from_tau0.2",
                                        "final_neck_error", "area_drift"};
    const auto early_columns = time_columns("neck_error_tau", early_times);
    columns.insert(columns.end(), early_columns.begin(), early_columns.end());
    columns.insert(columns.end(),
                   {"fine_cells_step1",
                    "max_fine_cell_distance",
                    "initial_neck_speed_error"});
    const auto samples = options.limits.find("samples");
    const unsigned int n_samples =
      samples == options.limits.end() ? 0 : samples->second;
    if (n_samples > 0)
      columns.emplace_back("sampled_neck_error");
    Table   table(run_columns(columns), options.csv);
    // Hopper's shape with the circles' neck replaces them (Shape = hopper)
    // unless --circle-start 1 keeps the circles (their neck's Hopper time
    // is then t = 0).
    Options hopper_options = options;
    if (options.limits.count("circle-start") == 0)
      hopper_options.overrides.emplace_back("Geometry/Shape", "hopper");
    std::vector<LevelRun> runs;
    for (const unsigned int level : levels)
      {
        double       R = 0, tau0 = 0;
        // The first Stokes solution, on Hopper's exact shape: the speed of
        // the neck point (0, y0) against Hopper's dy/dt, free of transport.
        double initial_neck_speed_error = 0;
        // Cells above the band's level (curvature refinement): how many after
        // the first step, and how far from the neck point (0, y_n) the
        // farthest of them came over the run, relative to R.
        unsigned int fine_cells_step1       = 0;
        double       max_fine_cell_distance = 0;
        const auto   run                    = run_level<dim>(
          scene_file,
          level,
          hopper_options,
          "hopper",
          [&](Simulation<dim> &sim, const SceneParameters &scene) {
            // The scene's overlapping circles fix the initial neck y0.
            const auto      &particles = scene.geometry.particles;
            const HopperPair pair(particles);
            R               = pair.R;
            const Hopper exact(R);
            const double m0 = pair.m();
            tau0            = exact.time(m0);
            const double gamma = scene.materials.surface_tension;
            const double eta   = zero_shear_viscosity(scene);
            const double exact_speed =
              exact.neck_speed(m0) * gamma / (eta * R);
            const Point<dim> initial_neck(0, exact.neck(m0));
            const unsigned int band_level = scene.refinement.max_level;
            sim.set_step_observer([&, band_level, particles, exact_speed, initial_neck](
                                    const unsigned int        step,
                                    double,
                                    const LevelSetField<dim> &alpha) {
              const Point<dim> neck_point(
                0, neck_measures::smallest_neck_radius(alpha, particles));
              unsigned int n_fine   = 0;
              double       farthest = 0;
              for (const auto &cell : alpha.dof_handler().active_cell_iterators())
                if (cell->is_locally_owned() &&
                    cell->level() > int(band_level))
                  {
                    ++n_fine;
                    farthest =
                      std::max(farthest, cell->center().distance(neck_point));
                  }
              const MPI_Comm comm = alpha.dof_handler().get_communicator();
              if (step == 1)
                {
                  fine_cells_step1 = Utilities::MPI::sum(n_fine, comm);
                  initial_neck_speed_error =
                    sim.interface_velocity().value(initial_neck)[1] /
                      exact_speed -
                    1;
                }
              max_fine_cell_distance =
                std::max(max_fine_cell_distance,
                         Utilities::MPI::max(farthest, comm) / R);
            });
          });
        runs.push_back(run);
        const Hopper exact(R);
        const double gamma = run.scene.materials.surface_tension;
        const double eta   = zero_shear_viscosity(run.scene);
        // Time from the start (a scene's Start time may be Hopper's own).
        std::vector<double> t = run.metrics.column("time");
        for (double &t_i : t)
          t_i -= run.scene.time.start_time;
        const auto &neck   = run.metrics.column("neck_radius");
        auto        series = open_series(
          options, level, "t_gamma_over_eta_R,neck_over_R,exact_neck_over_R");
        double max_error = 0, max_error_from_02 = 0, final_error = 0;
        std::vector<double> taus;
        for (unsigned int i = 0; i < t.size(); ++i)
          {
            const double tau     = tau0 + t[i] * gamma / (eta * R);
            const double y_exact = exact.neck(exact.m_of_time(tau));
            final_error          = std::abs(neck[i] - y_exact) / y_exact;
            max_error            = std::max(max_error, final_error);
            if (tau >= 0.2 - 1e-9)
              max_error_from_02 = std::max(max_error_from_02, final_error);
            taus.push_back(tau);
            if (series)
              series->row(tau, neck[i] / R, y_exact / R);
          }
        // Relative neck error at each early time (NaN when the run does
        // not span it).
        std::vector<double> early_errors = values_at(taus, neck, early_times);
        for (unsigned int k = 0; k < early_times.size(); ++k)
          {
            const double y_k = exact.neck(exact.m_of_time(early_times[k]));
            early_errors[k]  = std::abs(early_errors[k] - y_k) / y_k;
          }
        std::vector<double> values = {
          run.mean_dt,
          double(run.rejected_steps),
          max_error,
          max_error_from_02,
          final_error,
          std::abs(run.metrics.column("volume_change").back())};
        values.insert(values.end(), early_errors.begin(), early_errors.end());
        values.insert(values.end(),
                      {double(fine_cells_step1),
                       max_fine_cell_distance,
                       initial_neck_speed_error});
        if (n_samples > 0)
          values.push_back(sampled_neck_error(t, neck, n_samples, [&](double s) {
            return exact.neck(exact.m_of_time(tau0 + s * gamma / (eta * R)));
          }));
        table.add(run_row(level, run, values));
      }
    check("finest max relative neck-radius error", table.finest("max_neck_error"),
          options, "max-neck-error");
    check("finest max relative neck-radius error from t gamma/(eta R) = 0.2",
          table.finest("max_neck_error_from_tau0.2"), options,
          "max-neck-error-from-tau0.2");
    check("finest final relative neck-radius error",
          table.finest("final_neck_error"), options, "max-final-neck-error");
    check("finest solid-area drift", table.finest("area_drift"), options,
          "max-area-drift");
    check("finest rejected steps", table.finest("rejected"), options,
          "max-rejected");
    check("finest rejected steps", table.finest("rejected"), options,
          "min-rejected", false);
    check("finest cells above the band level after step 1",
          table.finest("fine_cells_step1"), options, "min-fine-cells", false);
    check("finest largest distance of those cells from the neck / R",
          table.finest("max_fine_cell_distance"), options,
          "max-fine-cell-distance");
    if (n_samples > 0)
      check("finest Eq. 44 neck error (viscoelastic seed)",
            table.finest("sampled_neck_error"), options,
            "max-sampled-neck-error");
    check("finest |initial neck speed / Hopper's - 1|",
          std::abs(table.finest("initial_neck_speed_error")), options,
          "max-initial-neck-speed-error");
    check_iterations(runs, options);
  }

  // Two equal spheres of radius a from the scene's overlapping pair: neck
  // radius x against Frenkel-Eshelby's early law x/a = (3 gamma t' /
  // (2 eta a))^(1/2), t' counted from touching (the scene's initial neck x0
  // is reached at t'0 = 2 eta a x0^2 / (3 gamma a^2)); the coalesced sphere
  // has radius 2^(1/3) a, which the neck becomes at the end. In 3D or on
  // an axisymmetric 2D scene (the spheres on the axis).
  template <int dim>
  void
  spheres(const std::string              &scene_file,
          const std::vector<unsigned int> &levels,
          const Options                   &options)
  {
    // The early neck x/a at these t gamma/(eta a) from touching, for the
    // comparison across resolutions (doc/validation.md).
    const std::vector<double> early_times = {0.5, 1, 2};
    std::vector<std::string>  columns     = {"neck_growth",
                                             "early_slope",
                                             "final_neck_over_a",
                                             "final_radius_error",
                                             "volume_drift"};
    const auto early_columns = time_columns("neck_tau", early_times);
    columns.insert(columns.end(), early_columns.begin(), early_columns.end());
    Table                 table(run_columns(columns), options.csv);
    std::vector<LevelRun> runs;
    for (const unsigned int level : levels)
      {
        const auto run =
          run_level<dim>(scene_file, level, options, "spheres", [](auto &, auto &) {});
        runs.push_back(run);
        const double a     = run.scene.geometry.particles[0][dim];
        const double gamma = run.scene.materials.surface_tension;
        const double eta   = run.scene.viscous_flow.solid_viscosity;
        const auto  &t     = run.metrics.column("time");
        const auto  &neck  = run.metrics.column("neck_radius");
        const double t0 = 2 * eta * std::pow(neck[0] / a, 2) * a / (3 * gamma);
        auto         series = open_series(
          options, level, "t_gamma_over_eta_a,neck_over_a,frenkel_eshelby");
        // Least-squares slope of log x against log t' while x < 0.3 a,
        // where the law applies; x/a at the early times (NaN when the run
        // does not span them).
        std::vector<double> log_t, log_x, taus;
        for (unsigned int i = 0; i < t.size(); ++i)
          {
            const double tau = (t0 + t[i]) * gamma / (eta * a);
            const double x   = neck[i] / a;
            taus.push_back(tau);
            if (series)
              series->row(tau, x, std::sqrt(1.5 * tau));
            if (x < 0.3)
              {
                log_t.push_back(std::log(tau));
                log_x.push_back(std::log(x));
              }
          }
        std::vector<double> early_necks = values_at(taus, neck, early_times);
        for (double &x : early_necks)
          x /= a;
        const double        slope   = study::least_squares(log_t, log_x).slope;
        const double        final_x = neck.back() / a;
        std::vector<double> values  = {
          neck.back() / neck[0],
          slope,
          final_x,
          std::abs(final_x - std::cbrt(2.)) / std::cbrt(2.),
          std::abs(run.metrics.column("volume_change").back())};
        values.insert(values.end(), early_necks.begin(), early_necks.end());
        table.add(run_row(level, run, values));
      }
    check("finest neck growth x_end / x_0", table.finest("neck_growth"),
          options, "min-neck-growth", false);
    check("finest solid-volume drift", table.finest("volume_drift"), options,
          "max-volume-drift");
    check("finest early log-log slope (>=)", table.finest("early_slope"),
          options, "min-early-slope", false);
    check("finest early log-log slope (<=)", table.finest("early_slope"),
          options, "max-early-slope");
    check("finest final radius error against 2^(1/3) a",
          table.finest("final_radius_error"), options,
          "max-final-radius-error");
    for (const auto &name : columns)
      if (name.rfind("neck_tau", 0) == 0)
        {
          check("finest neck / a at t gamma/(eta a) = " + name.substr(8) +
                  " (>=)",
                table.finest(name),
                options,
                "min-" + name,
                false);
          check("finest neck / a at t gamma/(eta a) = " + name.substr(8) +
                  " (<=)",
                table.finest(name),
                options,
                "max-" + name);
        }
    check_iterations(runs, options);
  }

  // A closed pore among the scene's particles: its area (the atmosphere in
  // a window around the particles' centroid) after every step, the time
  // at which it has closed, and the solid-area drift. Closed means smaller
  // than a hundredth of a finest cell: a symmetric pore ends on a mesh node
  // where the velocity vanishes, and the sub-cell remnant the Q1 level set
  // holds there fades only slowly (doc/validation.md).
  void
  pore(const std::string               &scene_file,
       const std::vector<unsigned int> &levels,
       const Options                   &options)
  {
    constexpr int dim = 2;
    const auto    w   = options.limits.find("pore-half-width");
    if (w == options.limits.end())
      throw std::runtime_error("the pore case needs --pore-half-width");
    Table table(run_columns({"initial_pore_area", "closure_time",
                             "final_pore_area_ratio", "area_drift"}),
                options.csv);
    for (const unsigned int level : levels)
      {
        double        area0 = 0, area = 0;
        std::vector<std::pair<double, double>> history;
        const auto series = open_series(options, level, "time,pore_area");
        const auto    run     = run_level<dim>(
          scene_file,
          level,
          options,
          "pore",
          [&](Simulation<dim> &simulation, const SceneParameters &scene) {
            Point<dim> centroid;
            for (const auto &p : scene.geometry.particles)
              for (unsigned int d = 0; d < dim; ++d)
                centroid[d] += p[d] / scene.geometry.particles.size();
            Tensor<1, dim> half;
            for (unsigned int d = 0; d < dim; ++d)
              half[d] = w->second;
            const BoundingBox<dim> window(
              std::make_pair(Point<dim>(centroid - half), centroid + half));
            area0 = area = interface_measures::atmosphere_volume(
              simulation.level_set(), window);
            if (series)
              series->row(0, area0);
            simulation.set_step_observer(
              [&, window](unsigned int,
                          const double              t,
                          const LevelSetField<dim> &alpha) {
                area = interface_measures::atmosphere_volume(alpha, window);
                history.emplace_back(t, area);
                if (series)
                  series->row(t, area);
              });
          });
        double closure = std::numeric_limits<double>::quiet_NaN();
        for (const auto &[t, a] : history)
          if (a < 1e-2 * run.h * run.h)
            {
              closure = t;
              break;
            }
        table.add(run_row(level,
                          run,
                          {area0,
                           closure,
                           area / area0,
                           std::abs(run.metrics.column("volume_change").back())}));
      }
    check("finest closure time", table.finest("closure_time"), options,
          "max-closure-time");
    check("finest final pore area / initial",
          table.finest("final_pore_area_ratio"), options,
          "max-pore-area-ratio");
    check("finest solid-area drift", table.finest("area_drift"), options,
          "max-area-drift");
  }

  // Particles of any sizes that merge into one: at the end, the interface
  // length against that of the circle with the same area (the shape the
  // pair relaxes to; a half circle per symmetry plane), and the area drift.
  void
  coalescence(const std::string               &scene_file,
              const std::vector<unsigned int> &levels,
              const Options                   &options)
  {
    constexpr int dim = 2;
    Table table(run_columns({"roundness_error", "area_drift"}), options.csv);
    for (const unsigned int level : levels)
      {
        const auto run = run_level<dim>(
          scene_file, level, options, "coalescence", [](auto &, auto &) {});
        const double area   = run.metrics.column("solid_volume").back();
        const double length = run.metrics.column("interface_area").back();
        const double parts =
          std::pow(2., run.scene.domain.symmetry_planes.size());
        const double radius = std::sqrt(parts * area / M_PI);
        table.add(run_row(
          level,
          run,
          {length / (2 * M_PI * radius / parts) - 1,
           std::abs(run.metrics.column("volume_change").back())}));
      }
    check("finest interface length / that of the round shape - 1",
          table.finest("roundness_error"), options, "max-roundness-error");
    check("finest solid-area drift", table.finest("area_drift"), options,
          "max-area-drift");
  }
  // Any two-particle scene's neck against time (the viscoelastic seed's
  // Figs. 10, 11, 13): CSV.levelN.csv with the neck radius, the neck
  // curvature and, for a viscoelastic melt, tr c at the neck and its
  // largest value anywhere; the table has the neck at a few times, the
  // curvature's peak and the largest tr c at the neck.
  template <int dim>
  void
  neck_history(const std::string              &scene_file,
               const std::vector<unsigned int> &levels,
               const Options                   &options)
  {
    const std::vector<double> times = {0.001, 0.01, 0.05, 0.1, 0.2};
    std::vector<std::string>  columns = time_columns("neck_t", times);
    columns.insert(columns.end(),
                   {"max_neck_curvature",
                    "t_max_neck_curvature",
                    "max_neck_trace_c",
                    "max_trace_c",
                    "rejected",
                    "volume_drift"});
    Table table(run_columns(columns), options.csv);
    // The runs' directories are named after the CSV, so that studies of
    // the same driver may run at once.
    const std::string name =
      "neck_history_" +
      std::filesystem::path(options.csv.empty() ? "run" : options.csv)
        .stem()
        .string();
    std::vector<LevelRun> runs;
    for (const unsigned int level : levels)
      {
        const auto run =
          run_level<dim>(scene_file, level, options, name, [](auto &, auto &) {});
        runs.push_back(run);
        const auto &m          = run.metrics;
        const auto &t          = m.column("time");
        const auto &neck       = m.column("neck_radius");
        const auto &curvature  = m.column("neck_curvature");
        const bool  melt       = m.has_column("neck_viscoelastic_trace_c");
        const std::vector<double> none(t.size(),
                                       std::numeric_limits<double>::quiet_NaN());
        const auto &neck_trace =
          melt ? m.column("neck_viscoelastic_trace_c") : none;
        const auto &max_trace =
          melt ? m.column("viscoelastic_max_trace_c") : none;
        auto        series     = open_series(
          options,
          level,
          "time,neck_radius,neck_curvature,neck_trace_c,max_trace_c");
        unsigned int peak = 0;
        for (unsigned int i = 0; i < t.size(); ++i)
          {
            if (series)
              series->row(
                t[i], neck[i], curvature[i], neck_trace[i], max_trace[i]);
            if (curvature[i] > curvature[peak])
              peak = i;
          }
        std::vector<double> values = values_at(t, neck, times);
        values.insert(
          values.end(),
          {curvature[peak],
           t[peak],
           *std::max_element(neck_trace.begin(), neck_trace.end()),
           *std::max_element(max_trace.begin(), max_trace.end()),
           double(run.rejected_steps),
           std::abs(m.column("volume_change").back())});
        table.add(run_row(level, run, values));
      }
    check("finest largest tr c anywhere", table.finest("max_trace_c"), options,
          "max-trace-c");
    check("finest rejected steps", table.finest("rejected"), options,
          "max-rejected");
  }

  // The static bubble over time (the scene's form, time step and number
  // of steps), uniform mesh at each level, filter 6 h: C = |v|_max eta /
  // gamma and the bubble's area error after every step, from metrics.csv. The CSV
  // series FILE.levelL.csv holds both against the step.
  void
  bubble_time(const std::string               &scene_file,
              const std::vector<unsigned int> &levels,
              const Options                   &options)
  {
    constexpr int dim = 2;
    Table table({"level", "h", "R_over_h", "steps", "cpu_time", "C_first",
                 "C_last", "C_max", "area_error_last", "area_error_max"},
                options.csv);
    double worst_C = 0, worst_growth = 0, worst_drift = 0;
    for (const unsigned int level : levels)
      {
        const auto   base = read_scene(scene_file, options.overrides);
        const double h    = study::cell_size(base, level);
        auto overrides    = options.overrides;
        overrides.insert(
          overrides.end(),
          {{"Mesh refinement/Minimum level", std::to_string(level)},
           {"Mesh refinement/Maximum level", std::to_string(level)},
           // Filter and band (the latter only satisfies the scene's
           // checks on a uniform mesh) 6 h, as the scene at level 5.
           {"Level set/Filter thickness", std::to_string(6 * h)},
           {"Mesh refinement/Band width", std::to_string(6 * h)},
           // One directory per CSV: the studies may run at once.
           {"Output/Directory",
            output_directory("bubble_time_" +
                             std::filesystem::path(options.csv).stem().string() +
                             "_level" + std::to_string(level))},
           {"Output/Metrics interval", "1"},
           {"Output/Field formats", "none"}});
        const auto      scene = read_scene(scene_file, overrides);
        Simulation<dim> simulation(scene, MPI_COMM_WORLD, std::cout);
        simulation.initialise();
        const auto summary = simulation.run();

        const study::CsvTable metrics(scene.output.directory + "/metrics.csv");
        const auto &steps = metrics.column("step");
        const auto &v     = metrics.column("max_velocity");
        const auto &area  = metrics.column("volume_change");
        const double scale = scene.viscous_flow.solid_viscosity /
                             scene.materials.surface_tension;
        // Row 0 is t = 0, before the first solve.
        std::vector<double> C;
        double              C_max = 0, area_max = 0;
        for (unsigned int i = 1; i < steps.size(); ++i)
          {
            C.push_back(v[i] * scale);
            C_max    = std::max(C_max, C.back());
            area_max = std::max(area_max, std::abs(area[i]));
          }
        if (C.empty())
          throw std::runtime_error("bubble-time: the run made no step");
        if (root && !options.csv.empty())
          {
            study::CsvFile series(options.csv + ".level" +
                                  std::to_string(level) + ".csv");
            series.stream() << "step,time,C,area_error\n"
                            << std::setprecision(10);
            for (unsigned int i = 1; i < steps.size(); ++i)
              series.row(steps[i], metrics.column("time")[i], C[i - 1],
                         area[i]);
          }
        const double R = scene.geometry.particles[0][dim];
        table.add({double(level), h, R / h, double(summary.steps),
                   summary.cpu_time, C.front(), C.back(), C_max,
                   area.back(), area_max});
        worst_C      = std::max(worst_C, C_max);
        worst_growth = std::max(worst_growth, C_max / C.front());
        worst_drift  = std::max(worst_drift, area_max);
      }
    check("largest C = v_max eta / gamma", worst_C, options, "max-C");
    check("largest C / C at the first step", worst_growth, options,
          "max-C-growth");
    check("largest |area error|", worst_drift, options, "max-area-drift");
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  root = Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0;
  try
    {
      const std::vector<std::string> args(argv + 1, argv + argc);
      if (args.size() < 3)
        throw std::runtime_error("usage: see the head of viscous_validation.cc");
      std::vector<unsigned int> levels;
      for (const int l :
           Utilities::string_to_int(Utilities::split_string_list(args[2], ',')))
        levels.push_back(l);
      if (args[0] == "bubble")
        bubble(args[1],
               levels,
               Utilities::split_string_list(args.at(3), ','),
               parse_options(args, 4));
      else if (args[0] == "hopper")
        hopper(args[1], levels, parse_options(args, 3));
      else if (args[0] == "spheres")
        {
          if (read_scene(args[1], {}).dimension == 2)
            spheres<2>(args[1], levels, parse_options(args, 3));
          else
            spheres<3>(args[1], levels, parse_options(args, 3));
        }
      else if (args[0] == "pore")
        pore(args[1], levels, parse_options(args, 3));
      else if (args[0] == "coalescence")
        coalescence(args[1], levels, parse_options(args, 3));
      else if (args[0] == "neck-history")
        {
          if (read_scene(args[1], {}).dimension == 2)
            neck_history<2>(args[1], levels, parse_options(args, 3));
          else
            neck_history<3>(args[1], levels, parse_options(args, 3));
        }
      else if (args[0] == "bubble-time")
        bubble_time(args[1], levels, parse_options(args, 3));
      else if (args[0] == "hopper-reference")
        {
          // Print the reference for a check against the quoted values.
          const Hopper exact(1.);
          for (const double y : {0.1, 0.5, 1.0})
            std::cout << "y_n/R = " << y << "  t gamma/(eta R) = "
                      << exact.time(exact.m_of_neck(y)) << "\n";
        }
      else
        throw std::runtime_error("unknown case " + args[0]);
    }
  catch (const std::exception &e)
    {
      std::cerr << "error: " << e.what() << std::endl;
      return 1;
    }
  return study::failures() == 0 ? 0 : 1;
}
