// Elastic inclusion under surface tension (paper Sect. 6.3.2, Table 6):
// an elastic disc (2D, plane strain) or sphere (3D) of radius R in a
// low-viscosity incompressible fluid, p_out = 0 on the free box faces. The
// exact state is uniform: in the disc sigma_rr = sigma_tt = -gamma/R and,
// plane strain (eps_zz = 0), sigma_zz = nu (sigma_rr + sigma_tt), so the
// mean pressure p = -tr(sigma)/3 = (2/3)(1 + nu) gamma/R = 3K/(3K + G)
// gamma/R (Eq. 109); in the sphere the stress is hydrostatic,
// p = 2 gamma/R with no elastic factor. The fluid is at rest at p = 0.
//
//   levelsinter_elastic_inclusion SCENE.prm LEVELS [options]
//
// LEVELS: comma-separated refinement levels (uniform meshes, or the band
// around the interface with --min-level M outside it). Options: --ratios
// r1,r2,... (eta_f / (G dt), default 1e-5), --steps N (rate-form steps,
// default 1), --csv FILE, --set ENTRY=VALUE and limits on the finest
// level, all steps and ratios: --max-l2-in, --max-l2-out (L2 error of p
// relative to p_in over the discrete solid / fluid), --max-undershoot (most
// negative fluid pressure / p_in), --max-drift (largest change of the
// solid's mean pressure from step 1, / p_in), --max-its (FGMRES).
// Exit code 0 only if every check passes.

#include <deal.II/base/mpi.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/base/timer.h>
#include <deal.II/base/utilities.h>

#include <deal.II/grid/grid_tools.h>

#include <deal.II/hp/fe_collection.h>

#include <deal.II/non_matching/fe_values.h>
#include <deal.II/non_matching/mesh_classifier.h>

#include <levelsinter/level_set/same_cell.h>
#include <levelsinter/mechanics/phase_law.h>
#include <levelsinter/mechanics/extended_pressure_stokes.h>
#include <levelsinter/scene/command_line.h>
#include <levelsinter/time/simulation.h>

#include "study_table.h"

#include <cmath>
#include <filesystem>
#include <iostream>

using namespace levelsinter;

namespace
{
  using study::check;
  using study::Options;
  using study::Table;

  struct PressureErrors
  {
    double l2_in      = 0; // ||p - p_in||_{L2(solid)} / (p_in |solid|^1/2)
    double l2_out     = 0; // ||p||_{L2(fluid)} / (p_in |fluid|^1/2)
    double mean_in    = 0;
    double undershoot = 0; // -min p at fluid nodes / p_in
  };

  // Errors over the discrete phases {alpha_h < 0}, {alpha_h > 0} with
  // cut-cell quadrature (4 points per direction: p_h is Q1, its square Q2).
  template <int dim>
  PressureErrors
  pressure_errors(const VelocityPressureOperator<dim> &stokes,
                  const LevelSetField<dim>            &alpha,
                  const double                         p_in)
  {
    NonMatching::MeshClassifier<dim> classifier(alpha.dof_handler(),
                                                alpha.alpha());
    classifier.reclassify();
    NonMatching::RegionUpdateFlags flags;
    flags.inside  = update_values | update_JxW_values;
    flags.outside = update_values | update_JxW_values;
    const hp::FECollection<dim> fe_collection(stokes.fe());
    NonMatching::FEValues<dim>  values(fe_collection,
                                      QGauss<1>(4),
                                      flags,
                                      classifier,
                                      alpha.dof_handler(),
                                      alpha.alpha());
    // Each phase's own pressure (the same where there is one).
    const std::array<FEValuesExtractors::Scalar, 2> pressure = {
      {FEValuesExtractors::Scalar(stokes.pressure_component(Phase::solid)),
       FEValuesExtractors::Scalar(stokes.pressure_component(Phase::fluid))}};
    // int (p - p_exact)^2, int p, volume; solid then fluid.
    std::array<double, 6> sums{{0, 0, 0, 0, 0, 0}};
    std::vector<double>   p;
    double                lowest = 0;
    for (const auto &cell : stokes.dof_handler().active_cell_iterators())
      if (cell->is_locally_owned())
        {
          values.reinit(cell);
          const auto add = [&](const auto &region, const unsigned int k,
                               const double exact) {
            if (!region)
              return;
            p.resize(region->n_quadrature_points);
            (*region)[pressure[k]].get_function_values(stokes.solution(), p);
            for (const unsigned int q : region->quadrature_point_indices())
              {
                sums[3 * k] += std::pow(p[q] - exact, 2) * region->JxW(q);
                sums[3 * k + 1] += p[q] * region->JxW(q);
                sums[3 * k + 2] += region->JxW(q);
              }
          };
          add(values.get_inside_fe_values(), 0, p_in);
          add(values.get_outside_fe_values(), 1, 0.);
          // Nodal fluid pressure.
          const auto ls_cell = same_cell(cell, alpha.dof_handler());
          for (const unsigned int v : cell->vertex_indices())
            if (alpha.alpha()(ls_cell->vertex_dof_index(v, 0)) > 0)
              lowest = std::min(lowest,
                                stokes.solution()(cell->vertex_dof_index(
                                  v, stokes.pressure_component(Phase::fluid))));
        }
    for (auto &s : sums)
      s = Utilities::MPI::sum(s, MPI_COMM_WORLD);
    PressureErrors e;
    e.l2_in      = std::sqrt(sums[0] / sums[2]) / p_in;
    e.mean_in    = sums[1] / sums[2];
    e.l2_out     = std::sqrt(sums[3] / sums[5]) / p_in;
    e.undershoot = -Utilities::MPI::min(lowest, MPI_COMM_WORLD) / p_in;
    return e;
  }

  template <int dim>
  void
  run(const std::string               &scene_file,
      const std::vector<unsigned int> &levels,
      const std::vector<double>       &ratios,
      const unsigned int               n_steps,
      const int                        min_level,
      const Options                   &options)
  {
    Table table({"level", "h", "R_over_h", "ratio", "step", "dofs",
                 "iterations", "wall_time", "p_in_exact", "p_in_mean",
                 "l2_in", "l2_out", "undershoot", "v_max"},
                options.csv);
    double worst_in = 0, worst_out = 0, worst_under = 0, worst_drift = 0,
           worst_its = 0;
    for (const double ratio : ratios)
      for (const unsigned int level : levels)
        {
          const auto   base = read_scene(scene_file, options.overrides);
          const double h_level = (base.domain.upper_corner[0] -
                                  base.domain.lower_corner[0]) /
                                 base.domain.subdivisions[0] /
                                 std::pow(2., level);
          // A band of 6 cells inside a filter of 8.
          const double band   = std::max(base.refinement.band_width,
                                       6 * h_level);
          const double filter = std::max(base.level_set.filter_thickness,
                                         8 * h_level);
          auto overrides = options.overrides;
          overrides.insert(
            overrides.end(),
            {// The interface does not move: only the scene's band checks.
             {"Level set/Filter thickness", std::to_string(filter)},
             {"Mesh refinement/Band width", std::to_string(band)},
             {"Time/CFL number", "0.1"},
             {"Mesh refinement/Minimum level",
              std::to_string(min_level < 0 ? level : unsigned(min_level))},
             {"Mesh refinement/Maximum level", std::to_string(level)},
             {"Output/Directory", "elastic_inclusion_output"},
             {"Output/Field formats", "none"}});
          std::filesystem::create_directories("elastic_inclusion_output");
          const auto      scene = read_scene(scene_file, overrides);
          Simulation<dim> simulation(scene, MPI_COMM_WORLD, std::cout);
          simulation.initialise();
          const auto  &alpha = simulation.level_set();
          const auto  &flow  = scene.viscous_flow;
          const auto  &atmosphere = scene.materials;
          const double R     = scene.geometry.particles[0][dim];
          const double G = scene.phase_law.shear_modulus,
                       K = scene.phase_law.bulk_modulus;
          const double nu = (3 * K - 2 * G) / (2 * (3 * K + G));
          const double p_in =
            dim == 2 ? 2. / 3 * (1 + nu) * atmosphere.surface_tension / R :
                       2 * atmosphere.surface_tension / R;
          const double dt = atmosphere.fluid_viscosity / (G * ratio);
          const double h  = GridTools::minimal_cell_diameter(
                             simulation.triangulation()) /
                           std::sqrt(double(dim));

          ElasticSolidFluid<dim> law(G,
                                     K,
                                     atmosphere.fluid_viscosity,
                                     atmosphere.fluid_compressibility);
          law.set_time_step(dt);
          // Sharp surface tension (Eq. 108 on {alpha_h = 0}) whatever the
          // scene says, in the scene's pressure space.
          auto settings = TwoPhaseStokes<dim>::Settings::from(
            flow,
            atmosphere,
            scene.domain.symmetry_planes,
            scene.refinement.max_level);
          settings.form = TwoPhaseStokes<dim>::SurfaceTensionForm::sharp;
          const auto operator_ = make_velocity_pressure_operator(
            simulation.triangulation(), settings, law, flow);
          auto &stokes = *operator_;
          stokes.setup_dofs();

          double first_mean = 0;
          for (unsigned int step = 1; step <= n_steps; ++step)
            {
              Timer wall(MPI_COMM_WORLD, true);
              stokes.fit_to(alpha);
              stokes.assemble(alpha,
                              TrilinosWrappers::MPI::Vector(),
                              TrilinosWrappers::MPI::Vector(),
                              0);
              const unsigned int its = stokes.solve();
              wall.stop();
              stokes.remove_rigid_motion(alpha);
              stokes.advance_displacement(dt);
              const auto e = pressure_errors(stokes, alpha, p_in);
              if (step == 1)
                first_mean = e.mean_in;
              const double v_max =
                stokes.solution().block(0).linfty_norm();
              table.add({double(level), h, R / h, ratio, double(step),
                         double(stokes.dof_handler().n_dofs()), double(its),
                         wall.wall_time(), p_in, e.mean_in, e.l2_in,
                         e.l2_out, e.undershoot, v_max});
              worst_its = std::max(worst_its, double(its));
              worst_drift =
                std::max(worst_drift, std::abs(e.mean_in - first_mean) / p_in);
              if (level == levels.back())
                {
                  worst_in    = std::max(worst_in, e.l2_in);
                  worst_out   = std::max(worst_out, e.l2_out);
                  worst_under = std::max(worst_under, e.undershoot);
                }
            }
        }
    if (study::is_root())
      std::cout << "(ratio = eta_f / (G dt); l2_in, l2_out: L2 error of p "
                   "over the discrete solid / fluid relative to p_in; "
                   "undershoot = -min fluid nodal p / p_in; v_max: largest "
                   "nodal velocity component)\n";
    check("finest L2 error of p in the solid / p_in", worst_in, options,
          "max-l2-in");
    check("finest L2 error of p in the fluid / p_in", worst_out, options,
          "max-l2-out");
    check("finest fluid undershoot / p_in", worst_under, options,
          "max-undershoot");
    check("drift of the solid's mean p over the steps / p_in", worst_drift,
          options, "max-drift");
    check("FGMRES iterations (worst solve)", worst_its, options, "max-its");
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  try
    {
      std::vector<std::string> args(argv + 1, argv + argc);
      if (args.size() < 2)
        throw std::runtime_error(
          "usage: levelsinter_elastic_inclusion SCENE.prm LEVELS [options]");
      std::vector<double> ratios = {1e-5};
      unsigned int        steps  = 1;
      int                 min_level = -1; // uniform meshes
      std::vector<std::string> rest;
      for (unsigned int i = 2; i < args.size(); ++i)
        if (args[i] == "--ratios" && i + 1 < args.size())
          ratios = Utilities::string_to_double(
            Utilities::split_string_list(args[++i], ','));
        else if (args[i] == "--steps" && i + 1 < args.size())
          steps = std::stoi(args[++i]);
        else if (args[i] == "--min-level" && i + 1 < args.size())
          min_level = std::stoi(args[++i]);
        else
          rest.push_back(args[i]);
      rest.insert(rest.begin(), args.begin(), args.begin() + 2);
      const auto options = study::parse_options(rest, 2);
      const auto levels  = study::parse_levels(args[1]);
      const auto scene   = read_scene(args[0], options.overrides);
      if (scene.dimension == 2)
        run<2>(args[0], levels, ratios, steps, min_level, options);
      else
        run<3>(args[0], levels, ratios, steps, min_level, options);
    }
  catch (const std::exception &e)
    {
      std::cerr << "error: " << e.what() << "\n";
      return 2;
    }
  return study::failures() == 0 ? 0 : 1;
}
