// Shapes of the Geometry section (issue 17; doc/validation.md, "Shapes:
// holes, ellipses, superellipses, implicit functions"):
//
//   shapes measures CASE LEVELS [options]
//     the filtered level set of a shape at t = 0 on the unit box, refined
//     around the interface up to each level of LEVELS, against its exact
//     area (volume) and perimeter (surface): CASE is annulus (a disc with
//     a concentric hole), ellipse, superellipse, implicit (the ellipse
//     given as a parsed function) or ellipsoid (3D). Also the displacement
//     of the discrete zero level set from the exact curve (largest and
//     RMS) and, for the shapes whose distance comes from closest-point
//     projection, the projection against a brute-force distance.
//   shapes hollow SCENE.prm LEVELS [options]
//     a viscous hollow cylinder (one particle minus a concentric pore)
//     closing under surface tension, against the exact Stokes solution
//     (doc/numerics.md): the wall thickness b - a grows at gamma /
//     (2 eta_s) while the area stays; the hole's own area (the atmosphere
//     about its centre) after every step gives the closing time.
//   shapes holes SCENE.prm LEVELS [options]
//     a viscous cylinder (one particle) with holes (Pores, Elliptic
//     pores) closing under surface tension, with the packing analysis on:
//     each hole's area and roundness against time, the times at which its
//     equivalent radius has halved and has reached six finest cells, and
//     the closure time estimated from the latter, against the
//     concentric annulus of the same areas (exact) and, with
//     --single-holes 1, against the same scene with that hole alone.
//
// Options: --csv FILE, --set ENTRY=VALUE (hollow, holes), limits
// --max-area-error, --max-perimeter-error (relative, finest level),
// --min-area-order, --max-displacement (finest level, / h),
// --max-projection-error (/ h); hollow: --max-rate-error,
// --max-radius-error, --max-area-drift, --max-closing-error; holes: --min-closure-ratio,
// --max-closure-ratio (closure estimate), --min-half-time-ratio,
// --max-half-time-ratio (each hole's time against its single-hole run if
// there is one, else against the annulus), --min-roundness-at-half,
// --max-roundness-at-half (4 pi A / P^2 when the equivalent radius has
// halved), --max-area-drift. Exit code 0 only if every check passes.

#include <deal.II/base/mpi.h>

#include <deal.II/distributed/tria.h>

#include <levelsinter/analysis/reference_shapes.h>
#include <levelsinter/grid/box_mesh.h>
#include <levelsinter/level_set/interface_measures.h>
#include <levelsinter/level_set/level_set_filter.h>
#include <levelsinter/scene/command_line.h>
#include <levelsinter/scene/solid_geometry.h>
#include <levelsinter/time/simulation.h>

#include "study_support.h"
#include "study_table.h"

#include <cmath>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <memory>

using namespace levelsinter;

namespace
{
  using study::check;
  using study::Options;
  using study::Table;

  // The exact measures of a shape: area (volume) and perimeter (surface;
  // NaN where not known), and for shapes drawn by closest-point
  // projection a brute-force signed distance to compare it with.
  template <int dim>
  struct ShapeCase
  {
    SceneParameters                             scene;
    double                                      measure = 0;
    double                                      boundary = 0;
    std::function<double(const Point<dim> &)>   brute_force_distance;
  };

  // Points of the superellipse x = a sgn(c)|c|^(2/p), y = b sgn(s)|s|^(2/p)
  // centred at (0.5, 0.5), at n parameter values.
  std::vector<Point<2>>
  superellipse_points(const double a, const double b, const double p,
                      const unsigned int n)
  {
    std::vector<Point<2>> points;
    const auto power = [p](const double w) {
      return (w < 0 ? -1 : 1) * std::pow(std::abs(w), 2 / p);
    };
    for (unsigned int i = 0; i < n; ++i)
      {
        const double t = 2 * M_PI * i / n;
        points.emplace_back(0.5 + a * power(std::cos(t)),
                            0.5 + b * power(std::sin(t)));
      }
    return points;
  }

  // Brute force: the distance to a polyline of 2^16 points of the curve
  // (its chords lie within (pi a / 2^16)^2 / R of the curve), signed by
  // |x/a|^p + |y/b|^p - 1.
  std::function<double(const Point<2> &)>
  brute_force_superellipse(const double a, const double b, const double p)
  {
    const auto points = std::make_shared<std::vector<Point<2>>>(
      superellipse_points(a, b, p, 1u << 16));
    return [points, a, b, p](const Point<2> &x) {
      double d = std::numeric_limits<double>::max();
      for (unsigned int i = 0; i < points->size(); ++i)
        {
          const Point<2>    &u = (*points)[i];
          const Point<2>    &v = (*points)[(i + 1) % points->size()];
          const Tensor<1, 2> e = v - u;
          const double t = std::clamp((x - u) * e / e.norm_square(), 0., 1.);
          d = std::min(d, x.distance(u + t * e));
        }
      const double f = std::pow(std::abs(x[0] - 0.5) / a, p) +
                       std::pow(std::abs(x[1] - 0.5) / b, p) - 1;
      return f < 0 ? -d : d;
    };
  }

  // Perimeter of the same polyline with 2^20 points (second order: its
  // error is below 1e-10 of the perimeter).
  double
  superellipse_perimeter(const double a, const double b, const double p)
  {
    const auto points = superellipse_points(a, b, p, 1u << 20);
    double     length = 0;
    for (unsigned int i = 0; i < points.size(); ++i)
      length += points[i].distance(points[(i + 1) % points.size()]);
    return length;
  }

  template <int dim>
  ShapeCase<dim>
  make_case(const std::string &name)
  {
    ShapeCase<dim> c;
    auto          &s = c.scene;
    s.dimension      = dim;
    s.geometry.shape = GeometryParameters::Shape::particles;
    s.domain.lower_corner = std::vector<double>(dim, 0.);
    s.domain.upper_corner = std::vector<double>(dim, 1.);
    s.domain.subdivisions = std::vector<unsigned int>(dim, 1);
    auto &g = s.geometry;
    // Semi-axes of the ellipses and superellipses, turned by 30 degrees
    // (any orientation).
    const double a = 0.3, b = 0.15, angle = 30;
    if constexpr (dim == 3)
      {
        if (name != "ellipsoid")
          throw std::runtime_error("unknown case '" + name + "' in 3D");
        const double c3 = 0.2;
        g.superellipses = {{0.5, 0.5, 0.5, a, b, c3, 2, angle, angle, 0}};
        c.measure       = 4 * M_PI * a * b * c3 / 3;
        c.boundary      = std::numeric_limits<double>::quiet_NaN();
      }
    else if (name == "annulus")
      {
        const double R = 0.3, r = 0.12;
        g.particles = {{0.5, 0.5, R}};
        g.pores     = {{0.5, 0.5, r}};
        c.measure   = M_PI * (R * R - r * r);
        c.boundary  = 2 * M_PI * (R + r);
      }
    else if (name == "ellipse" || name == "superellipse")
      {
        const double p  = name == "ellipse" ? 2 : 4;
        g.superellipses = {{0.5, 0.5, a, b, p, angle}};
        c.measure       = 4 * a * b * std::pow(std::tgamma(1 + 1 / p), 2) /
                    std::tgamma(1 + 2 / p);
        c.boundary = superellipse_perimeter(a, b, p);
        // The brute force in the body frame: turn x back by the angle.
        const auto body = brute_force_superellipse(a, b, p);
        c.brute_force_distance = [body, angle](const Point<dim> &x) {
          const double   t = angle * M_PI / 180;
          const double   u = x[0] - 0.5, v = x[1] - 0.5;
          const Point<2> y(0.5 + std::cos(t) * u + std::sin(t) * v,
                           0.5 - std::sin(t) * u + std::cos(t) * v);
          return body(y);
        };
        if (name == "ellipse")
          {
            // Ramanujan's second formula, to 1e-9 here: the numerical
            // perimeter is checked against it.
            const double h = std::pow((a - b) / (a + b), 2);
            const double ramanujan =
              M_PI * (a + b) * (1 + 3 * h / (10 + std::sqrt(4 - 3 * h)));
            if (std::abs(ramanujan / c.boundary - 1) > 1e-8)
              throw std::logic_error("ellipse perimeter: " +
                                     std::to_string(c.boundary) + " against " +
                                     std::to_string(ramanujan));
          }
      }
    else if (name == "implicit")
      {
        g.implicit_function  = "((x-0.5)/a)^2 + ((y-0.5)/b)^2 - 1";
        g.implicit_constants = {{"a", a}, {"b", b}};
        c.measure            = M_PI * a * b;
        c.boundary           = superellipse_perimeter(a, b, 2);
        c.brute_force_distance = brute_force_superellipse(a, b, 2);
      }
    else
      throw std::runtime_error("unknown case '" + name + "' in 2D");
    return c;
  }

  // The unit box refined where |d| < the cell diameter up to @p level;
  // alpha = filter(d) with the sine filter of thickness 8 h (the scenes'
  // setting).
  template <int dim>
  void
  build(parallel::distributed::Triangulation<dim> &tria,
        LevelSetField<dim>                        &level_set,
        const SceneParameters                     &scene,
        const Function<dim>                       &distance,
        const unsigned int                         level)
  {
    make_box_mesh(tria, scene.domain);
    tria.refine_global(2);
    for (unsigned int l = 2; l < level; ++l)
      {
        for (const auto &cell : tria.active_cell_iterators())
          if (cell->is_locally_owned() &&
              std::abs(distance.value(cell->center())) < cell->diameter())
            cell->set_refine_flag();
        tria.execute_coarsening_and_refinement();
      }
    const double         h = 1. / (1u << level);
    const LevelSetFilter filter(LevelSetFilter::Type::sine, 8 * h);
    level_set.setup_dofs();
    level_set.interpolate(ScalarFunctionFromFunctionObject<dim>(
      [&](const Point<dim> &p) { return filter.filter(distance.value(p)); }));
  }

  template <int dim>
  void
  measures(const std::string &name, const std::vector<std::string> &args)
  {
    const Options  options = study::parse_options(args, 3);
    ShapeCase<dim> c       = make_case<dim>(name);
    const auto     distance = make_initial_signed_distance<dim>(c.scene);
    Table          table({"level", "h", "area_error", "perimeter_error",
                          "max_displacement_over_h", "rms_displacement_over_h",
                          "projection_error_over_h", "seconds"},
                options.csv);
    for (const unsigned int level : study::parse_levels(args.at(2)))
      {
        const auto start = std::chrono::steady_clock::now();
        parallel::distributed::Triangulation<dim> tria(MPI_COMM_WORLD);
        LevelSetField<dim>                        level_set(tria);
        build(tria, level_set, c.scene, *distance, level);
        const double h = 1. / (1u << level);
        const auto   m = interface_measures::volume_and_area(level_set);
        // The discrete interface's distance from the exact curve, measured
        // by the same distance function (exact for the annulus; converged
        // closest-point projection otherwise, checked below).
        const auto shape = interface_measures::shape_error(level_set, *distance);
        const double square = interface_measures::interface_integral<dim>(
          level_set, [&](const Point<dim> &x, const Tensor<1, dim> &) {
            return std::pow(distance->value(x), 2);
          });
        // The projection against the brute force at the vertices of the
        // cells the interface crosses (rank 0's share).
        double projection_error = 0;
        if (c.brute_force_distance)
          for (const auto &cell : tria.active_cell_iterators())
            if (cell->is_locally_owned() &&
                std::abs(distance->value(cell->center())) < cell->diameter())
              for (const unsigned int v : cell->vertex_indices())
                projection_error =
                  std::max(projection_error,
                           std::abs(distance->value(cell->vertex(v)) -
                                    c.brute_force_distance(cell->vertex(v))));
        projection_error =
          Utilities::MPI::max(projection_error, MPI_COMM_WORLD);
        const double seconds =
          std::chrono::duration<double>(std::chrono::steady_clock::now() -
                                        start)
            .count();
        table.add({double(level),
                   h,
                   std::abs(m.solid_volume / c.measure - 1),
                   std::abs(m.interface_area / c.boundary - 1),
                   shape.max_distance / h,
                   std::sqrt(square / m.interface_area) / h,
                   c.brute_force_distance ?
                     projection_error / h :
                     std::numeric_limits<double>::quiet_NaN(),
                   seconds});
      }
    check("finest relative area (volume) error", table.finest("area_error"),
          options, "max-area-error");
    check("area (volume) error order", table.order("area_error"), options,
          "min-area-order", false);
    check("finest relative perimeter error", table.finest("perimeter_error"),
          options, "max-perimeter-error");
    check("finest largest interface displacement / h",
          table.finest("max_displacement_over_h"), options,
          "max-displacement");
    check("finest projection error / h",
          table.finest("projection_error_over_h"), options,
          "max-projection-error");
  }

  // The hollow cylinder: one particle of radius b minus a concentric pore
  // of radius a. With area A = pi (b^2 - a^2) and perimeter P = 2 pi (a +
  // b) (whole cylinder; the symmetry planes' parts scale both), the wall
  // thickness is w = b - a = 2A/P and a = (P / (2 pi) - w) / 2; exact:
  // w(t) = w0 + gamma t / (2 eta_s), a(t) = ((b0^2 - a0^2) / w - w) / 2.
  void
  hollow(const std::string &scene_file, const std::vector<std::string> &args)
  {
    constexpr int dim     = 2;
    const Options options = study::parse_options(args, 3);
    Table         table({"level", "h", "steps", "cpu_time", "rate_error",
                         "max_radius_error", "area_drift", "final_a_over_a0",
                         "closing_time", "closing_time_exact",
                         "closing_error", "pore_closure_volume"},
                options.csv);
    for (const unsigned int level : study::parse_levels(args.at(2)))
      {
        const auto   base = read_scene(scene_file, options.overrides);
        const double h    = study::cell_size(base, level);
        const std::string directory =
          "shapes_output/hollow_level" + std::to_string(level);
        std::filesystem::create_directories(directory);
        auto overrides = options.overrides;
        overrides.insert(
          overrides.end(),
          {{"Mesh refinement/Maximum level", std::to_string(level)},
           {"Mesh refinement/Band width", std::to_string(6 * h)},
           {"Level set/Filter thickness", std::to_string(8 * h)},
           {"Output/Directory", directory},
           {"Output/Metrics interval", "1"},
           {"Output/Field formats", "none"}});
        const auto scene = read_scene(scene_file, overrides);
        const auto &g    = scene.geometry;
        if (g.particles.size() != 1 || g.pores.size() != 1)
          throw std::runtime_error("the hollow case needs one particle and "
                                   "one pore");
        const double b0 = g.particles[0][dim], a0 = g.pores[0][dim];
        const double gamma = scene.materials.surface_tension;
        const double eta   = scene.viscous_flow.solid_viscosity;
        // The hole's own area: the atmosphere in the cells whose centre
        // lies within a0 + h/4 of the centre along each axis, which hold
        // the hole (it only shrinks; at the start its edge lies on cell
        // faces in the scenes measured) and no atmosphere outside: b stays
        // above sqrt(b0^2 - a0^2).
        const double parts = std::pow(2., scene.domain.symmetry_planes.size());
        const double half_width = a0 + h / 4;
        if (std::sqrt(2.) * (half_width + h / 2) >
            std::sqrt(b0 * b0 - a0 * a0))
          throw std::runtime_error("the hollow case needs a wall of a few "
                                   "cells between the hole and the outside");
        const Point<dim> centre(g.pores[0][0], g.pores[0][1]);
        const Tensor<1, dim> half({half_width, half_width});
        const BoundingBox<dim> window(
          std::make_pair(Point<dim>(centre - half), Point<dim>(centre + half)));
        std::vector<double> hole_time, hole_area;
        Simulation<dim> simulation(scene, MPI_COMM_WORLD, std::cout);
        simulation.initialise();
        const auto observe = [&](const double time,
                                 const LevelSetField<dim> &alpha) {
          hole_time.push_back(time);
          hole_area.push_back(
            parts * interface_measures::atmosphere_volume(alpha, window));
        };
        observe(0, simulation.level_set());
        simulation.set_step_observer(
          [&](unsigned int, const double time, const LevelSetField<dim> &alpha) {
            observe(time, alpha);
          });
        const auto summary = simulation.run();

        const study::CsvTable metrics(directory + "/metrics.csv");
        const auto &t = metrics.column("time");
        const auto &A = metrics.column("solid_volume");
        const auto &P = metrics.column("interface_area");
        const auto   a_of  = [&](const unsigned int i) {
          const double w = 2 * A[i] / P[i];
          return (parts * P[i] / (2 * M_PI) - w) / 2;
        };
        // 0 from the closing time on.
        const auto exact_a = [&](const double time) {
          const double w = b0 - a0 + gamma * time / (2 * eta);
          return std::max(((b0 * b0 - a0 * a0) / w - w) / 2, 0.);
        };
        const double exact_closing =
          2 * eta / gamma * (std::sqrt(b0 * b0 - a0 * a0) - (b0 - a0));
        // The closing time: the hole's radius extrapolated linearly to
        // zero from the last two samples that hold a hole (the radius
        // falls linearly near the end; the sample after it has none).
        double closing = std::numeric_limits<double>::quiet_NaN();
        for (unsigned int i = 2; i < hole_area.size(); ++i)
          if (hole_area[i] < 1e-10 * h * h && hole_area[i - 1] >= 1e-10 * h * h)
            {
              const double r1 = std::sqrt(hole_area[i - 2] / M_PI),
                           r2 = std::sqrt(hole_area[i - 1] / M_PI);
              closing = hole_time[i - 1] + r2 * (hole_time[i - 1] -
                                                 hole_time[i - 2]) /
                                             (r1 - r2);
              break;
            }
        double max_error = 0;
        std::unique_ptr<study::CsvFile> series;
        if (study::is_root() && !options.csv.empty())
          {
            series = std::make_unique<study::CsvFile>(
              options.csv + ".level" + std::to_string(level) + ".csv");
            series->stream() << "time,a,a_exact,hole_radius\n";
          }
        for (unsigned int i = 0; i < t.size(); ++i)
          {
            max_error =
              std::max(max_error, std::abs(a_of(i) - exact_a(t[i])) / a0);
            if (series)
              series->row(t[i],
                          a_of(i),
                          exact_a(t[i]),
                          std::sqrt(std::max(hole_area.at(i), 0.) / M_PI));
          }
        const unsigned int last = t.size() - 1;
        table.add({double(level),
                   h,
                   double(summary.steps),
                   summary.cpu_time,
                   (a_of(last) - a_of(0)) / (exact_a(t[last]) - a0) - 1,
                   max_error,
                   std::abs(metrics.column("volume_change").back()),
                   a_of(last) / a0,
                   closing,
                   exact_closing,
                   closing / exact_closing - 1,
                   metrics.has_column("pore_closure_volume") ?
                     parts * metrics.column("pore_closure_volume").back() :
                     0.});
      }
    check("finest |mean inner-radius rate / exact - 1|",
          std::abs(table.finest("rate_error")), options, "max-rate-error");
    check("finest largest |a - a_exact| / a0", table.finest("max_radius_error"),
          options, "max-radius-error");
    check("finest solid-area drift", table.finest("area_drift"), options,
          "max-area-drift");
    // NaN (the hole has not closed) fails.
    check("finest |closing time / exact - 1|",
          std::abs(table.finest("closing_error")), options,
          "max-closing-error");
  }

  // The concentric annulus b, a0 closing (doc/numerics.md, "Hollow
  // cylinder"): the time at which the inner radius has fallen to a. The
  // wall w grows as w0 + gamma t / (2 eta_s) at constant area b(t)^2 -
  // a(t)^2 = b^2 - a0^2, so at radius a: w^2 + 2 a w - (b^2 - a0^2) = 0.
  double
  annulus_time(const double b,
               const double a0,
               const double a,
               const double gamma,
               const double eta)
  {
    const double w = -a + std::sqrt(a * a + b * b - a0 * a0);
    return 2 * eta / gamma * (w - (b - a0));
  }

  // One hole of a holes run: its series and the times it reached.
  struct HoleRun
  {
    Point<2>            centre;
    double              radius = 0; // of the circle of the same area
    std::vector<double> area;       // whole hole, 0 once closed
    std::vector<double> roundness;  // 4 pi A / P^2, NaN once closed
    // The equivalent radius at half its initial value, at six finest
    // cells (below, the hole falls behind: doc/validation.md) and zero.
    double half_time     = std::numeric_limits<double>::quiet_NaN();
    double six_cell_time = std::numeric_limits<double>::quiet_NaN();
    double vanish_time   = std::numeric_limits<double>::quiet_NaN();
  };

  struct HolesRun
  {
    std::vector<double>  time;
    std::vector<double>  area_change; // solid, relative
    std::vector<HoleRun> holes;
    unsigned int         steps    = 0;
    double               cpu_time = 0;
  };

  // The first time at which @p values falls to @p level, linear between
  // the samples; NaN if it never does.
  double
  crossing_time(const std::vector<double> &time,
                const std::vector<double> &values,
                const double               level)
  {
    for (unsigned int i = 1; i < values.size(); ++i)
      if (values[i] <= level && values[i - 1] > level)
        return time[i - 1] + (time[i] - time[i - 1]) *
                               (values[i - 1] - level) /
                               (values[i - 1] - values[i]);
    return std::numeric_limits<double>::quiet_NaN();
  }

  // Runs the scene with @p overrides into @p directory and follows each of
  // its holes through pores.csv: the closed pore whose centroid is nearest
  // the hole's centre at the first step, by its tracking id. A hole cut by
  // a symmetry plane through its centre is seen as a half (a quarter by
  // two planes): its area is scaled back and its roundness divided by the
  // same factor (4 pi A / P^2 of the part).
  HolesRun
  run_holes(const std::string                                      &scene_file,
            const std::vector<std::pair<std::string, std::string>> &overrides,
            const std::string                                      &directory,
            const double                                            h_min)
  {
    constexpr int dim = 2;
    std::filesystem::create_directories(directory);
    auto all = overrides;
    all.insert(all.end(),
               {{"Output/Directory", directory},
                {"Output/Metrics interval", "1"},
                {"Output/Field formats", "none"},
                {"Analysis/Packing analysis", "true"}});
    const auto scene = read_scene(scene_file, all);
    const auto &g    = scene.geometry;
    HolesRun    run;
    for (const auto &p : g.pores)
      run.holes.push_back({Point<2>(p[0], p[1]), p[2], {}, {}});
    for (const auto &e : g.elliptic_pores)
      run.holes.push_back(
        {Point<2>(e[0], e[1]), std::sqrt(e[2] * e[3]), {}, {}});
    if (g.particles.size() != 1 || run.holes.empty())
      throw std::runtime_error("the holes case needs one particle and at "
                               "least one pore");
    Simulation<dim> simulation(scene, MPI_COMM_WORLD, std::cout);
    simulation.initialise();
    const auto summary = simulation.run();
    run.steps    = summary.steps;
    run.cpu_time = summary.cpu_time;

    const study::CsvTable metrics(directory + "/metrics.csv");
    run.time        = metrics.column("time");
    run.area_change = metrics.column("volume_change");
    const auto &steps = metrics.column("step");
    const study::CsvTable pores(directory + "/pores.csv");
    const auto &pore_step = pores.column("step");
    const auto &id        = pores.column("pore");
    const auto &volume    = pores.column("volume");
    const auto &length    = pores.column("area");
    const auto &x         = pores.column("centroid_x");
    const auto &y         = pores.column("centroid_y");
    for (auto &hole : run.holes)
      {
        double parts = 1;
        for (const auto plane : scene.domain.symmetry_planes)
          {
            const unsigned int axis = plane / 2;
            const double       wall = plane % 2 == 0 ?
                                        scene.domain.lower_corner[axis] :
                                        scene.domain.upper_corner[axis];
            if (std::abs(hole.centre[axis] - wall) < 1e-12)
              parts *= 2;
          }
        double       nearest = std::numeric_limits<double>::max();
        unsigned int pore    = 0;
        for (unsigned int r = 0; r < pores.n_rows() && pore_step[r] == steps[0];
             ++r)
          if (id[r] > 0 && hole.centre.distance(Point<2>(x[r], y[r])) < nearest)
            {
              nearest = hole.centre.distance(Point<2>(x[r], y[r]));
              pore    = id[r];
            }
        if (pore == 0)
          throw std::runtime_error("no closed pore at the first step near the "
                                   "hole at " +
                                   std::to_string(hole.centre[0]) + ", " +
                                   std::to_string(hole.centre[1]));
        for (const double step : steps)
          {
            hole.area.push_back(0);
            hole.roundness.push_back(std::numeric_limits<double>::quiet_NaN());
            for (unsigned int r = 0; r < pores.n_rows(); ++r)
              if (pore_step[r] == step && id[r] == pore)
                {
                  hole.area.back() = parts * volume[r];
                  hole.roundness.back() =
                    4 * M_PI * volume[r] / (parts * length[r] * length[r]);
                }
          }
        std::vector<double> radius;
        for (const double a : hole.area)
          radius.push_back(std::sqrt(a / M_PI));
        hole.half_time     = crossing_time(run.time, radius, radius[0] / 2);
        hole.six_cell_time = crossing_time(run.time, radius, 6 * h_min);
        for (unsigned int i = 0; i < run.time.size(); ++i)
          if (hole.area[i] == 0)
            {
              hole.vanish_time = run.time[i];
              break;
            }
      }
    return run;
  }

  // Viscous cylinders with holes (see the head of this file).
  void
  holes(const std::string &scene_file, const std::vector<std::string> &args)
  {
    const Options options = study::parse_options(args, 3);
    const auto    single  = options.limits.find("single-holes");
    const bool    with_single_runs =
      single != options.limits.end() && single->second != 0;
    const auto   &overrides = options.overrides;
    Table table({"level", "h", "hole", "x", "y", "radius", "steps",
                 "cpu_time", "half_time", "half_time_annulus",
                 "half_time_single", "six_cell_time",
                 "six_cell_time_annulus", "six_cell_time_single",
                 "closure_estimate", "closure_time_annulus", "vanish_time",
                 "roundness_initial", "roundness_at_half", "area_drift",
                 "max_area_drift"},
                options.csv);
    double worst_low_closure = std::numeric_limits<double>::max(),
           worst_high_closure = 0, worst_low_half = worst_low_closure,
           worst_high_half = 0, worst_low_roundness = 1,
           worst_high_roundness = 0, worst_drift = 0;
    const auto levels = study::parse_levels(args.at(2));
    for (const unsigned int level : levels)
      {
        const auto   base = read_scene(scene_file, overrides);
        const double h    = study::cell_size(base, level);
        const double b    = base.geometry.particles.at(0).at(2);
        const double gamma = base.materials.surface_tension;
        const double eta   = base.viscous_flow.solid_viscosity;
        // One directory per scene and CSV: the studies may run at once.
        const std::string stem =
          "shapes_output/holes_" +
          std::filesystem::path(scene_file).stem().string() + "_" +
          std::filesystem::path(options.csv).stem().string() + "_level" +
          std::to_string(level);
        auto at_level = overrides;
        at_level.insert(
          at_level.end(),
          {{"Mesh refinement/Maximum level", std::to_string(level)},
           {"Mesh refinement/Band width", std::to_string(6 * h)},
           {"Level set/Filter thickness", std::to_string(8 * h)}});
        // Cells of the finest level (curvature refinement adds levels
        // below the band's).
        const double h_min =
          h / (1u << read_scene(scene_file, at_level).refinement.curvature_levels);
        const HolesRun run = run_holes(scene_file, at_level, stem, h_min);

        // Each hole alone (circular holes: one entry of Pores).
        std::vector<HoleRun> alone(run.holes.size());
        if (with_single_runs)
          for (unsigned int k = 0; k < run.holes.size(); ++k)
            {
              const auto &hole = run.holes[k];
              if (k >= base.geometry.pores.size())
                throw std::runtime_error("--single-holes: circular holes only");
              auto one = at_level;
              one.insert(one.end(),
                         {{"Geometry/Pores",
                           std::to_string(hole.centre[0]) + ", " +
                             std::to_string(hole.centre[1]) + ", " +
                             std::to_string(hole.radius)},
                          {"Geometry/Elliptic pores", ""}});
              alone[k] = run_holes(scene_file,
                                   one,
                                   stem + "_hole" + std::to_string(k + 1),
                                   h_min)
                           .holes[0];
            }

        if (study::is_root() && !options.csv.empty())
          {
            study::CsvFile series(options.csv + ".level" +
                                  std::to_string(level) + ".csv");
            auto          &out = series.stream();
            out << "time,area_change";
            for (unsigned int k = 1; k <= run.holes.size(); ++k)
              out << ",area_" << k << ",roundness_" << k;
            out << '\n' << std::setprecision(10);
            for (unsigned int i = 0; i < run.time.size(); ++i)
              {
                out << run.time[i] << ',' << run.area_change[i];
                for (const auto &hole : run.holes)
                  out << ',' << hole.area[i] << ',' << hole.roundness[i];
                out << '\n';
                series.end_row();
              }
          }
        double max_drift = 0;
        for (const double change : run.area_change)
          max_drift = std::max(max_drift, std::abs(change));
        for (unsigned int k = 0; k < run.holes.size(); ++k)
          {
            const auto  &hole = run.holes[k];
            const double half_annulus =
              annulus_time(b, hole.radius, hole.radius / 2, gamma, eta);
            const double closure_annulus =
              annulus_time(b, hole.radius, 0, gamma, eta);
            const double six_cell_annulus =
              annulus_time(b, hole.radius, 6 * h_min, gamma, eta);
            // Below six cells the annulus' remaining time: a hole that
            // small closes as in a large body, at nearly gamma / (2 eta_s).
            const auto closure_estimate = [&](const HoleRun &run) {
              return run.six_cell_time + closure_annulus - six_cell_annulus;
            };
            const double roundness_at_half =
              hole.roundness[std::lower_bound(run.time.begin(),
                                              run.time.end(),
                                              hole.half_time) -
                             run.time.begin()];
            table.add({double(level),
                       h,
                       double(k + 1),
                       hole.centre[0],
                       hole.centre[1],
                       hole.radius,
                       double(run.steps),
                       run.cpu_time,
                       hole.half_time,
                       half_annulus,
                       alone[k].half_time,
                       hole.six_cell_time,
                       six_cell_annulus,
                       alone[k].six_cell_time,
                       closure_estimate(hole),
                       closure_annulus,
                       hole.vanish_time,
                       hole.roundness[0],
                       roundness_at_half,
                       std::abs(run.area_change.back()),
                       max_drift});
            if (level != levels.back())
              continue;
            const double closure_ratio =
              closure_estimate(hole) / (with_single_runs ?
                                          closure_estimate(alone[k]) :
                                          closure_annulus);
            const double half_ratio =
              hole.half_time /
              (with_single_runs ? alone[k].half_time : half_annulus);
            // NaN (not closed) must fail the checks below.
            const auto low = [](const double worst, const double value) {
              return std::isnan(value) ? value : std::min(worst, value);
            };
            const auto high = [](const double worst, const double value) {
              return std::isnan(value) ? value : std::max(worst, value);
            };
            worst_low_closure  = low(worst_low_closure, closure_ratio);
            worst_high_closure = high(worst_high_closure, closure_ratio);
            worst_low_half     = low(worst_low_half, half_ratio);
            worst_high_half    = high(worst_high_half, half_ratio);
            worst_low_roundness  = low(worst_low_roundness, roundness_at_half);
            worst_high_roundness = high(worst_high_roundness, roundness_at_half);
          }
        worst_drift = max_drift;
      }
    check("finest smallest closure time ratio", worst_low_closure, options,
          "min-closure-ratio", false);
    check("finest largest closure time ratio", worst_high_closure, options,
          "max-closure-ratio");
    check("finest smallest half-radius time ratio", worst_low_half, options,
          "min-half-time-ratio", false);
    check("finest largest half-radius time ratio", worst_high_half, options,
          "max-half-time-ratio");
    check("finest smallest roundness at half radius", worst_low_roundness,
          options, "min-roundness-at-half", false);
    check("finest largest roundness at half radius", worst_high_roundness,
          options, "max-roundness-at-half");
    check("finest largest solid-area drift", worst_drift, options,
          "max-area-drift");
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  try
    {
      const std::vector<std::string> args(argv + 1, argv + argc);
      if (args.size() < 3)
        throw std::runtime_error("usage: see the head of shapes.cc");
      if (args[0] == "measures")
        {
          if (args[1] == "ellipsoid")
            measures<3>(args[1], args);
          else
            measures<2>(args[1], args);
        }
      else if (args[0] == "hollow")
        hollow(args[1], args);
      else if (args[0] == "holes")
        holes(args[1], args);
      else
        throw std::runtime_error("unknown mode " + args[0]);
    }
  catch (const std::exception &e)
    {
      std::cerr << "error: " << e.what() << std::endl;
      return 2;
    }
  return study::failures() == 0 ? 0 : 1;
}
