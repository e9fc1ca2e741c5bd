// The normal pressure gradient xi of volume diffusion (paper Eq. 110-111,
// doc/numerics.md "Volume diffusion") against analytic pressures:
//
//   normal_gradient_extension field DIM FIELD LEVELS [options]
//   normal_gradient_extension neck LEVEL [options]
//   normal_gradient_extension parameters
//
// field: a circle (sphere) of radius 0.3 in the unit box, uniform meshes
// at each of LEVELS, the pressure FIELD interpolated into the Q1 pressure
// component of a Q1^dim x Q1 system:
//   linear  p = x                 xi = n_x         (exact along the normals)
//   radial  p = r^2               xi = 2 R
//   mode2   p = x^2 - y^2         xi = 2 R cos 2 theta on the equator
//   cubic   p = x^3 - 3 x y^2     xi = 3 R^2 cos 3 theta on the equator
// (r, x, y about the centre). --constant 1: the paper's constant extension
// instead of the linear extrapolation; --limited 1: the linear one with
// its correction bounded (Extrapolation = limited). With --jump J the
// pressure also jumps by J across the interface, smeared over 1.5 h like
// the CSF Laplace jump (doc/numerics.md): xi must not see it. Prints the
// error of xi on the discrete zero level set (cut-cell quadrature), max
// and surface RMS, relative to max |xi_exact|, and the orders between
// levels. Limits:
// --max-error (RMS at the finest level), --max-pointwise-error,
// --min-order (between the last two levels); every case must report no
// unsourced interface cell. --offset sets lambda in cells (3). --band B:
// the mesh is refined to LEVEL only where |d| < B h (h = 2^-LEVEL), two
// levels coarser elsewhere, so that hanging nodes lie inside the filter
// ramp E = 6 h (B < 4.8: inside the extension's band); --filter F sets
// E = F h (6).
//
// neck: two discs of radius 0.15 at x = 0.2 and 0.8 joined by a bar 0.4
// long and 0.08 thick, p = x, on a uniform mesh at LEVEL; --min-unsourced N
// and --max-unsourced N bound the interface cells reported as unsourced
// (the bar is thinner than 2 lambda for h > 1/75), and xi must stay within
// the range of the source values up to --overshoot (a fraction of it).
//
// parameters: the `Volume diffusion` subsection: C_v from the material
// entries, the reduced-time coefficient, and the documented errors.
//
// --csv FILE writes the rows (for the 1-vs-2-ranks comparison).

#include <deal.II/base/function.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/base/timer.h>

#include <deal.II/distributed/tria.h>

#include <deal.II/dofs/dof_handler.h>
#include <deal.II/dofs/dof_tools.h>

#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/mapping_q1.h>

#include <deal.II/grid/grid_generator.h>

#include <deal.II/hp/fe_collection.h>

#include <deal.II/non_matching/fe_values.h>
#include <deal.II/non_matching/mesh_classifier.h>

#include <deal.II/numerics/vector_tools.h>

#include <levelsinter/geometry/normal_gradient_extension.h>
#include <levelsinter/level_set/level_set_field.h>
#include <levelsinter/level_set/level_set_filter.h>
#include <levelsinter/scene/volume_diffusion_parameters.h>

#include <cmath>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

using namespace levelsinter;

namespace
{
  constexpr double radius = 0.3;

  // Off the grid's symmetry lines, so that no error cancels by symmetry.
  template <int dim>
  Point<dim>
  centre()
  {
    Point<dim> c;
    const double offsets[3] = {0.503, 0.497, 0.501};
    for (unsigned int d = 0; d < dim; ++d)
      c[d] = offsets[d];
    return c;
  }

  template <int dim>
  double
  exact_pressure(const std::string &field, const Point<dim> &x)
  {
    const Tensor<1, dim> r = x - centre<dim>();
    if (field == "linear")
      return x[0];
    if (field == "radial")
      return r.norm_square();
    if (field == "cubic")
      return r[0] * r[0] * r[0] - 3 * r[0] * r[1] * r[1];
    return r[0] * r[0] - r[1] * r[1]; // mode2
  }

  template <int dim>
  Tensor<1, dim>
  exact_gradient(const std::string &field, const Point<dim> &x)
  {
    const Tensor<1, dim> r = x - centre<dim>();
    Tensor<1, dim>       g;
    if (field == "linear")
      g[0] = 1;
    else if (field == "radial")
      g = 2 * r;
    else if (field == "cubic")
      {
        g[0] = 3 * (r[0] * r[0] - r[1] * r[1]);
        g[1] = -6 * r[0] * r[1];
      }
    else
      {
        g[0] = 2 * r[0];
        g[1] = -2 * r[1];
      }
    return g;
  }

  // Signed distance of the geometry: balls, and in 2D optionally a bar
  // |x - 0.5| <= 0.2, |y - 0.5| <= bar (neck mode).
  template <int dim>
  class Distance : public Function<dim>
  {
  public:
    Distance(const std::vector<Point<dim>> &centres,
             const double                   radius,
             const double                   bar = 0)
      : centres(centres)
      , r(radius)
      , bar(bar)
    {}

    double
    value(const Point<dim> &x, const unsigned int = 0) const override
    {
      double d = 1e10;
      for (const auto &c : centres)
        d = std::min(d, x.distance(c) - r);
      if (bar > 0)
        {
          const double qx = std::abs(x[0] - 0.5) - 0.2,
                       qy = std::abs(x[1] - 0.5) - bar;
          d = std::min(d,
                       std::hypot(std::max(qx, 0.), std::max(qy, 0.)) +
                         std::min(std::max(qx, qy), 0.));
        }
      return d;
    }

    const std::vector<Point<dim>> centres;
    const double                  r, bar;
  };

  template <int dim>
  class Filtered : public Function<dim>
  {
  public:
    Filtered(const Distance<dim> &distance, const LevelSetFilter &filter)
      : distance(distance)
      , filter(filter)
    {}

    double
    value(const Point<dim> &x, const unsigned int = 0) const override
    {
      return filter.filter(distance.value(x));
    }

    const Distance<dim>  &distance;
    const LevelSetFilter &filter;
  };

  // (0, ..., 0, p): the Stokes layout Q1^dim x Q1 with p as component dim.
  // The optional jump J (1 - H(d)) with H the sine-smoothed Heaviside over
  // |d| < w: the CSF pressure jump of a Laplace law.
  template <int dim>
  class Pressure : public Function<dim>
  {
  public:
    Pressure(const std::string   &field,
             const Distance<dim> &distance,
             const double         jump,
             const double         width)
      : Function<dim>(dim + 1)
      , field(field)
      , distance(distance)
      , jump(jump)
      , width(width)
    {}

    double
    value(const Point<dim> &x, const unsigned int component) const override
    {
      if (component < dim)
        return 0;
      const double d = std::clamp(distance.value(x) / width, -1., 1.);
      const double heaviside =
        0.5 * (1 + d + std::sin(numbers::PI * d) / numbers::PI);
      return exact_pressure(field, x) + jump * (1 - heaviside);
    }

    const std::string    field;
    const Distance<dim> &distance;
    const double         jump, width;
  };

  struct Result
  {
    double       max_error = 0, rms_error = 0;
    unsigned int unsourced = 0, iterations = 0;
    double       xi_min = 0, xi_max = 0, source_min = 0, source_max = 0;
  };

  double
  option(const std::map<std::string, double> &options,
         const std::string                   &name,
         const double                         default_value)
  {
    const auto it = options.find(name);
    return it == options.end() ? default_value : it->second;
  }

  // The method and data options (--offset, --jump, --constant, --limited,
  // --flux, --band, --filter) as the head of this file describes them.
  template <int dim>
  Result
  run(const std::string                   &field,
      const std::vector<Point<dim>>       &centres,
      const double                         ball_radius,
      const unsigned int                   level,
      const std::map<std::string, double> &options,
      const double                         bar = 0)
  {
    const double offset    = option(options, "offset", 3);
    const double band      = option(options, "band", 0);
    const double thickness = option(options, "filter", 6);
    const MPI_Comm                            comm = MPI_COMM_WORLD;
    parallel::distributed::Triangulation<dim> tria(comm);
    GridGenerator::hyper_cube(tria);
    const double        h = 1. / (1 << level);
    const Distance<dim> distance(centres, ball_radius, bar);
    if (band > 0)
      {
        tria.refine_global(level - 2);
        for (unsigned int k = 0; k < 2; ++k)
          {
            for (const auto &cell : tria.active_cell_iterators())
              if (cell->is_locally_owned() &&
                  std::abs(distance.value(cell->center())) <
                    band * h + cell->diameter() / 2)
                cell->set_refine_flag();
            tria.execute_coarsening_and_refinement();
          }
      }
    else
      tria.refine_global(level);

    // E = 6 h: the filter keeps a slope to 0.8 E = 4.8 h, beyond lambda.
    const LevelSetFilter filter(LevelSetFilter::Type::sine, thickness * h);
    LevelSetField<dim>   level_set(tria);
    level_set.setup_dofs();
    level_set.interpolate(Filtered<dim>(distance, filter));

    const FESystem<dim> fe(FE_Q<dim>(1), dim, FE_Q<dim>(1), 1);
    DoFHandler<dim>     stokes_dofs(tria);
    stokes_dofs.distribute_dofs(fe);
    const IndexSet owned = stokes_dofs.locally_owned_dofs();
    IndexSet       relevant;
    DoFTools::extract_locally_relevant_dofs(stokes_dofs, relevant);
    TrilinosWrappers::MPI::Vector owned_field(owned, comm),
      field_values(owned, relevant, comm);
    VectorTools::interpolate(stokes_dofs,
                             Pressure<dim>(field,
                                           distance,
                                           option(options, "jump", 0),
                                           1.5 * h),
                             owned_field);
    field_values = owned_field;

    TimerOutput timer(comm, std::cout, TimerOutput::never,
                      TimerOutput::wall_times);
    typename NormalGradientExtension<dim>::Settings settings;
    settings.interior_offset      = offset;
    settings.linear_extrapolation  = option(options, "constant", 0) == 0;
    settings.limited_extrapolation = option(options, "limited", 0) > 0;
    settings.boundary_flux         = option(options, "flux", 0) > 0;
    NormalGradientExtension<dim> extension(filter, settings, timer);
    extension.setup(level_set);
    Result result;
    result.iterations =
      extension.solve(level_set, stokes_dofs, dim, field_values);
    result.unsourced = extension.unsourced_interface_cells();
    const auto &xi   = extension.normal_gradient();

    // Range of xi and of the exact grad p . n over the solid's nodes.
    result.xi_min = result.source_min = 1e10;
    result.xi_max = result.source_max = -1e10;
    std::map<types::global_dof_index, Point<dim>> support;
    DoFTools::map_dofs_to_support_points(MappingQ1<dim>(),
                                         level_set.dof_handler(),
                                         support);
    for (const auto i : level_set.locally_owned())
      {
        result.xi_min = std::min(result.xi_min, double(xi(i)));
        result.xi_max = std::max(result.xi_max, double(xi(i)));
        if (level_set.alpha()(i) < 0)
          {
            Tensor<1, dim> n;
            for (unsigned int c = 0; c < dim; ++c)
              n[c] = extension.nodal_normals()[c](i);
            const double g = exact_gradient(field, support.at(i)) * n;
            result.source_min = std::min(result.source_min, g);
            result.source_max = std::max(result.source_max, g);
          }
      }
    result.xi_min     = Utilities::MPI::min(result.xi_min, comm);
    result.xi_max     = Utilities::MPI::max(result.xi_max, comm);
    result.source_min = Utilities::MPI::min(result.source_min, comm);
    result.source_max = Utilities::MPI::max(result.source_max, comm);

    // Error on {alpha_h = 0}, exact normal (x - c) / |x - c| (one ball).
    const auto &dofs = level_set.dof_handler();
    NonMatching::MeshClassifier<dim> classifier(dofs, level_set.alpha());
    classifier.reclassify();
    NonMatching::RegionUpdateFlags flags;
    flags.surface = update_values | update_quadrature_points | update_JxW_values;
    const hp::FECollection<dim> fe_collection(level_set.fe());
    NonMatching::FEValues<dim>  cut_values(
      fe_collection, QGauss<1>(3), flags, classifier, dofs, level_set.alpha());
    double area = 0, sum2 = 0, scale = 0;
    for (const auto &cell : dofs.active_cell_iterators())
      if (cell->is_locally_owned() &&
          classifier.location_to_level_set(cell) ==
            NonMatching::LocationToLevelSet::intersected)
        {
          cut_values.reinit(cell);
          const auto &surface = cut_values.get_surface_fe_values();
          if (!surface)
            continue;
          std::vector<double> values(surface->n_quadrature_points);
          surface->get_function_values(xi, values);
          for (const unsigned int q : surface->quadrature_point_indices())
            {
              const Point<dim> &x = surface->quadrature_point(q);
              const Tensor<1, dim> n =
                (x - centres[0]) / (x - centres[0]).norm();
              const double exact = exact_gradient(field, x) * n;
              const double error = values[q] - exact;
              result.max_error = std::max(result.max_error, std::abs(error));
              scale            = std::max(scale, std::abs(exact));
              sum2 += error * error * surface->JxW(q);
              area += surface->JxW(q);
            }
        }
    area  = Utilities::MPI::sum(area, comm);
    sum2  = Utilities::MPI::sum(sum2, comm);
    scale = Utilities::MPI::max(scale, comm);
    result.max_error = Utilities::MPI::max(result.max_error, comm) / scale;
    result.rms_error = std::sqrt(sum2 / area) / scale;
    return result;
  }

  template <int dim>
  bool
  field_study(const std::string                   &field,
              const std::vector<unsigned int>     &levels,
              const std::map<std::string, double> &options,
              std::ostream                        *csv)
  {
    const bool root = Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0;
    const double offset = option(options, "offset", 3);
    const double jump   = option(options, "jump", 0);
    bool         ok     = true;
    std::vector<double> rms;
    if (root)
      std::cout << dim << "D, p = " << field << ", lambda = " << offset
                << " h, jump " << jump
                << (option(options, "constant", 0) > 0 ? ", constant" : "")
                << (option(options, "limited", 0) > 0 ? ", limited" : "")
                << (option(options, "flux", 0) > 0 ? ", boundary flux" : "")
                << "\n"
                << " level  R/h   max error   rms error  order  unsourced"
                   "  GMRES\n";
    if (csv && root)
      *csv << "level,max_error,rms_error,unsourced\n";
    for (const unsigned int level : levels)
      {
        const Result r =
          run<dim>(field, {centre<dim>()}, radius, level, options);
        rms.push_back(r.rms_error);
        const double order =
          rms.size() > 1 ? std::log2(rms[rms.size() - 2] / rms.back()) : 0;
        if (root)
          {
            std::cout << std::setw(6) << level << std::setw(6)
                      << radius * (1 << level) << std::scientific
                      << std::setprecision(3) << std::setw(12) << r.max_error
                      << std::setw(12) << r.rms_error << std::fixed
                      << std::setprecision(2) << std::setw(7) << order
                      << std::setw(11) << r.unsourced << std::setw(7)
                      << r.iterations << "\n";
            if (csv)
              *csv << level << "," << std::setprecision(10) << r.max_error
                   << "," << r.rms_error << "," << r.unsourced << "\n";
          }
        if (r.unsourced > 0)
          {
            ok = false;
            if (root)
              std::cout << "FAIL: unsourced interface cells on a ball\n";
          }
        if (level == levels.back())
          {
            if (r.rms_error > option(options, "max-error", 1e10) ||
                r.max_error > option(options, "max-pointwise-error", 1e10))
              {
                ok = false;
                if (root)
                  std::cout << "FAIL: error above the limit\n";
              }
            if (rms.size() > 1 && order < option(options, "min-order", -1e10))
              {
                ok = false;
                if (root)
                  std::cout << "FAIL: order below the limit\n";
              }
          }
      }
    return ok;
  }

  bool
  neck_study(const unsigned int                   level,
             const std::map<std::string, double> &options)
  {
    const bool root = Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0;
    const Result r  = run<2>("linear",
                            {Point<2>(0.2, 0.5), Point<2>(0.8, 0.5)},
                            0.15,
                            level,
                            options,
                            0.04);
    if (root)
      std::cout << "two discs joined by a bar 0.08 thick, h = 1/" << (1 << level)
                << ": " << r.unsourced << " unsourced interface cells; xi in ["
                << r.xi_min << ", " << r.xi_max << "], grad p . N in the solid in ["
                << r.source_min << ", " << r.source_max << "]\n";
    // The reaction only damps, but where characteristics from two sides
    // meet (the concave corners) SUPG over- and undershoots.
    const double slack =
      option(options, "overshoot", 0) * (r.source_max - r.source_min);
    const bool ok =
      r.unsourced >= option(options, "min-unsourced", 0) &&
      r.unsourced <= option(options, "max-unsourced", 1e9) &&
      r.xi_min >= r.source_min - slack && r.xi_max <= r.source_max + slack;
    if (!ok && root)
      std::cout << "FAIL\n";
    return ok;
  }

  bool
  parameter_check()
  {
    bool ok     = true;
    auto expect = [&](const bool condition, const std::string &what) {
      if (!condition)
        {
          std::cout << "FAIL: " << what << "\n";
          ok = false;
        }
    };
    auto parse = [](const std::string &text) {
      ParameterHandler prm;
      VolumeDiffusionParameters::declare(prm);
      prm.parse_input_from_string("subsection Volume diffusion\n" + text +
                                  "end\n");
      VolumeDiffusionParameters p;
      p.parse(prm);
      return p;
    };
    auto error_of = [&](const std::string &text) -> std::string {
      try
        {
          parse(text);
        }
      catch (const std::runtime_error &e)
        {
          return e.what();
        }
      return "";
    };
    // Omega = 8.5e-30 m^3, D_v = 1e-17 m^2/s, kT = 1.9e-20 J, f = 0.4.
    const auto p = parse("set Enabled = true\n"
                         "set Atomic volume = 8.5e-30\n"
                         "set Volume diffusivity = 1e-17\n"
                         "set Thermal energy = 1.9e-20\n"
                         "set Vacancy volume fraction = 0.4\n"
                         "set Time unit = reduced\n"
                         "set Reference radius = 2e-7\n"
                         "set Extrapolation = constant\n");
    expect(!p.linear_extrapolation && !p.limited_extrapolation &&
             p.interior_offset == 6,
           "Extrapolation = constant, default Interior offset");
    const auto limited = parse("set Enabled = true\n"
                               "set Coefficient = 1\n"
                               "set Extrapolation = limited\n");
    expect(limited.linear_extrapolation && limited.limited_extrapolation,
           "Extrapolation = limited: linear with the bound");
    expect(p.time_step_factor == 0.5, "default Time step factor");
    expect(error_of("set Enabled = true\nset Coefficient = 1\n"
                    "set Time step factor = 2\n")
               .find("'Volume diffusion/Time step factor'") !=
             std::string::npos,
           "a time step factor above 1");
    const double expected = 0.6 * 8.5e-30 * 1e-17 / 1.9e-20;
    expect(std::abs(p.mobility() / expected - 1) < 1e-14,
           "C_v = (1 - f) Omega D_v / kT");
    expect(std::abs(p.mobility() * p.reduced_time_scale(2e-7, 0.9) /
                      (8e-21 / 0.9) -
                    1) < 1e-14,
           "reduced time: C_v per unit t* = R^3 / gamma");
    expect(parse("set Enabled = true\nset Coefficient = 0.013\n")
               .mobility() == 0.013,
           "a given C_v");
    expect(error_of("set Enabled = true\n").find(
             "entry 'Volume diffusion/Coefficient'") == 0,
           "no coefficient and no material entries");
    expect(error_of("set Enabled = true\nset Coefficient = 1\n"
                    "set Time unit = reduced\n")
               .find("'Volume diffusion/Reference radius'") !=
             std::string::npos,
           "reduced time without a radius");
    expect(error_of("set Enabled = true\nset Coefficient = 1\n"
                    "set Vacancy volume fraction = 1\n")
               .find("'Volume diffusion/Vacancy volume fraction'") !=
             std::string::npos,
           "f = 1");
    std::cout << (ok ? "parameters: all checks pass\n" : "");
    return ok;
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  try
    {
      const std::vector<std::string> args(argv + 1, argv + argc);
      std::vector<std::string>       positional;
      std::map<std::string, double>  options;
      std::string                    csv_name;
      for (unsigned int i = 0; i < args.size(); ++i)
        if (args[i] == "--csv" && i + 1 < args.size())
          csv_name = args[++i];
        else if (args[i].rfind("--", 0) == 0 && i + 1 < args.size())
          {
            options[args[i].substr(2)] = std::stod(args[i + 1]);
            ++i;
          }
        else
          positional.push_back(args[i]);
      if (positional.empty())
        throw std::runtime_error("usage: see the head of "
                                 "tests/normal_gradient_extension.cc");
      std::ofstream csv;
      if (!csv_name.empty() &&
          Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
        csv.open(csv_name);
      std::ostream *csv_stream = csv_name.empty() ? nullptr : &csv;
      bool          ok         = false;
      if (positional[0] == "parameters")
        ok = parameter_check();
      else if (positional[0] == "neck" && positional.size() == 2)
        ok = neck_study(std::stoi(positional[1]), options);
      else if (positional[0] == "field" && positional.size() == 4)
        {
          std::vector<unsigned int> levels;
          std::stringstream         list(positional[3]);
          std::string               item;
          while (std::getline(list, item, ','))
            levels.push_back(std::stoi(item));
          ok = positional[1] == "2" ?
                 field_study<2>(positional[2], levels, options, csv_stream) :
                 field_study<3>(positional[2], levels, options, csv_stream);
        }
      else
        throw std::runtime_error("unknown mode or wrong number of arguments");
      return ok ? 0 : 1;
    }
  catch (const std::exception &e)
    {
      std::cerr << "error: " << e.what() << std::endl;
      return 2;
    }
}
