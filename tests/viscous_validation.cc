// Validation of the viscous-flow mechanism (issue 3), shared by the CI tests
// (small resolutions) and the long studies (doc/validation.md):
//
//   levelsinter_viscous_validation bubble SCENE.prm LEVELS FORMS [options]
//   levelsinter_viscous_validation hopper SCENE.prm LEVELS [options]
//
// LEVELS: comma-separated maximum refinement levels (uniform meshes for the
// bubble); FORMS: comma-separated surface-tension forms (csf, sharp).
// Options: --csv FILE and limits (--max-pressure-error, --max-C,
// --max-neck-error, --max-area-drift). Exit code 0 only if every check
// passes.

#include <deal.II/base/mpi.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/base/utilities.h>

#include <deal.II/fe/fe_values.h>

#include <deal.II/hp/fe_collection.h>

#include <deal.II/non_matching/fe_values.h>
#include <deal.II/non_matching/mesh_classifier.h>

#include <levelsinter/level_set/interface_measures.h>
#include <levelsinter/mechanisms/viscous_flow.h>
#include <levelsinter/scene/command_line.h>
#include <levelsinter/time/simulation.h>

#include <chrono>
#include <cmath>
#include <complex>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <map>
#include <sstream>

using namespace levelsinter;

namespace
{
  bool root = true; // set in main() once MPI is up

  struct Options
  {
    std::map<std::string, double> limits;
    std::string                   csv;
    // --set "Section/Entry=value": scene overrides for every run.
    std::vector<std::pair<std::string, std::string>> overrides;
  };

  Options
  parse_options(const std::vector<std::string> &args, const unsigned int first)
  {
    Options o;
    for (unsigned int i = first; i + 1 < args.size(); i += 2)
      {
        if (args[i] == "--csv")
          o.csv = args[i + 1];
        else if (args[i] == "--set")
          {
            const auto eq = args[i + 1].find('=');
            o.overrides.emplace_back(args[i + 1].substr(0, eq),
                                     args[i + 1].substr(eq + 1));
          }
        else if (args[i].rfind("--", 0) == 0)
          o.limits[args[i].substr(2)] = std::stod(args[i + 1]);
        else
          throw std::runtime_error("unexpected argument " + args[i]);
      }
    return o;
  }

  unsigned int failures = 0;

  void
  check(const std::string &what,
        const double       value,
        const Options     &options,
        const std::string &limit_name)
  {
    const auto it = options.limits.find(limit_name);
    if (it == options.limits.end())
      return;
    const bool ok = value <= it->second && std::isfinite(value);
    failures += !ok;
    if (root)
      std::cout << (ok ? "PASS " : "FAIL ") << what << " = " << value
                << " <= " << it->second << "\n";
  }

  // Rows to stdout and, optionally, CSV.
  class Table
  {
  public:
    Table(const std::vector<std::string> &columns, const std::string &csv)
    {
      if (!root)
        return;
      if (!csv.empty())
        {
          file.open(csv);
          for (unsigned int i = 0; i < columns.size(); ++i)
            file << (i ? "," : "") << columns[i];
          file << "\n";
        }
      for (const auto &c : columns)
        std::cout << std::setw(std::max<int>(12, c.size() + 2)) << c;
      std::cout << "\n";
      widths.clear();
      for (const auto &c : columns)
        widths.push_back(std::max<int>(12, c.size() + 2));
    }

    void
    add(const std::vector<double> &row)
    {
      if (!root)
        return;
      for (unsigned int i = 0; i < row.size(); ++i)
        {
          std::cout << std::setw(widths[i]) << std::setprecision(4) << row[i];
          if (file.is_open())
            file << (i ? "," : "") << std::setprecision(10) << row[i];
        }
      std::cout << std::endl;
      if (file.is_open())
        file << "\n";
    }

  private:
    std::vector<int> widths;
    std::ofstream    file;
  };

  std::string
  output_directory(const std::string &name)
  {
    const std::string dir = "viscous_validation_output/" + name;
    std::filesystem::create_directories(dir);
    return dir;
  }

  // Mean pressure over the discrete solid {alpha_h < 0} (cut-cell
  // quadrature) and over the pore, and their areas.
  template <int dim>
  std::array<double, 2>
  mean_pressures(const TwoPhaseStokes<dim> &stokes,
                 const LevelSetField<dim>  &alpha)
  {
    NonMatching::MeshClassifier<dim> classifier(alpha.dof_handler(),
                                                alpha.alpha());
    classifier.reclassify();
    NonMatching::RegionUpdateFlags flags;
    flags.inside  = update_values | update_JxW_values;
    flags.outside = update_values | update_JxW_values;
    const hp::FECollection<dim> fe_collection(stokes.fe());
    NonMatching::FEValues<dim>  values(fe_collection,
                                      QGauss<1>(3),
                                      flags,
                                      classifier,
                                      alpha.dof_handler(),
                                      alpha.alpha());
    const FEValuesExtractors::Scalar pressure(dim);
    std::array<double, 4>            sums{{0, 0, 0, 0}};
    std::vector<double>              p;
    for (const auto &cell : stokes.dof_handler().active_cell_iterators())
      if (cell->is_locally_owned())
        {
          values.reinit(cell);
          const auto add = [&](const auto &region, const unsigned int k) {
            if (!region)
              return;
            p.resize(region->n_quadrature_points);
            (*region)[pressure].get_function_values(stokes.solution(), p);
            for (const unsigned int q : region->quadrature_point_indices())
              {
                sums[2 * k] += p[q] * region->JxW(q);
                sums[2 * k + 1] += region->JxW(q);
              }
          };
          add(values.get_inside_fe_values(), 0);
          add(values.get_outside_fe_values(), 1);
        }
    for (auto &s : sums)
      s = Utilities::MPI::sum(s, MPI_COMM_WORLD);
    return {{sums[0] / sums[1], sums[2] / sums[3]}};
  }

  // Static bubble: one Stokes solve on a uniform mesh; p_in = gamma / R.
  void
  bubble(const std::string              &scene_file,
         const std::vector<unsigned int> &levels,
         const std::vector<std::string>  &forms,
         const Options                   &options)
  {
    constexpr int dim = 2;
    Table table({"level", "h", "form", "dofs", "iterations", "solve_time",
                 "p_in", "p_out", "pressure_error", "C"},
                options.csv);
    double worst_error = 0, worst_C = 0;
    for (const auto &form : forms)
      for (const unsigned int level : levels)
        {
          const auto base = read_scene(scene_file, options.overrides);
          const double L =
            base.domain.upper_corner[0] - base.domain.lower_corner[0];
          const double h = L / base.domain.subdivisions[0] / std::pow(2., level);
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
             {"Viscous flow/Surface tension form", form},
             {"Output/Directory", output_directory("bubble")},
             {"Output/Field formats", "none"}});
          const auto      scene = read_scene(scene_file, overrides);
          Simulation<dim> simulation(scene, MPI_COMM_WORLD, std::cout);
          simulation.initialise();
          const auto &alpha = simulation.level_set();

          ViscousFlow<dim>   flow(scene.viscous_flow);
          VelocityField<dim> velocity(simulation.triangulation());
          velocity.setup_dofs();
          velocity.set_zero();
          flow.setup(alpha);
          const auto start = std::chrono::steady_clock::now();
          flow.add_velocity(alpha, 0, 0, velocity);
          const double solve_time =
            std::chrono::duration<double>(std::chrono::steady_clock::now() -
                                          start)
              .count();
          const auto   p     = mean_pressures(flow.stokes(), alpha);
          const double R     = scene.geometry.particles[0][dim];
          const double gamma = scene.viscous_flow.surface_tension;
          const double eta   = scene.viscous_flow.solid_viscosity;
          const double p_exact = gamma / R;
          const double error   = std::abs(p[0] - p[1] - p_exact) / p_exact;
          const double C       = velocity.max_norm() * eta / gamma;
          table.add({double(level), h, form == "csf" ? 0. : 1.,
                     double(flow.stokes().dof_handler().n_dofs()),
                     flow.metric_values()[0], solve_time, p[0], p[1], error,
                     C});
          if (level == levels.back())
            {
              worst_error = std::max(worst_error, error);
              worst_C     = std::max(worst_C, C);
            }
        }
    if (root)
      std::cout << "(form: 0 = csf, 1 = sharp; pressure_error = |p_in - p_out "
                   "- gamma/R| / (gamma/R))\n";
    check("finest relative mean-pressure error (worst form)", worst_error,
          options, "max-pressure-error");
    check("finest C = v_max eta / gamma (worst form)", worst_C, options,
          "max-C");
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
      else
        throw std::runtime_error("unknown case " + args[0]);
    }
  catch (const std::exception &e)
    {
      std::cerr << "error: " << e.what() << std::endl;
      return 1;
    }
  return failures == 0 ? 0 : 1;
}
