// Packing analysis on constructed level sets whose answer is known
// (doc/validation.md, "Packing analysis"):
//
//   pore_analysis holes DIM N_HOLES LEVELS [options]
//     a particle (disc, sphere) of radius 0.3 minus N_HOLES balls of radius
//     0.08: N_HOLES closed pores of exact volume, one open pore outside.
//     With --planes K (1 <= K < DIM) the particle and its holes are centred
//     on the K lower box faces normal to e_1, ..., e_K (the box a quarter
//     or half of the scene, those faces symmetry planes): each closed pore
//     is cut by K planes, its exact volume that of the part in the box,
//     and its sphericity (that of the whole pore the mirrors make) 1.
//   pore_analysis lattice DIM N SPACING RADIUS LEVELS [options]
//     N^DIM balls on a simple cubic lattice centred in the unit box: pores,
//     relative density in the centres' bounding box, necks, coordination.
//     With --spacing-y B the rows are B apart along y (the exact pore and
//     density then do not apply): with 2 RADIUS < B < 2 RADIUS + h the
//     pairs along y are near misses, and the packing's neck_radius must
//     still be the neck of the contacts along x.
//   pore_analysis tracking
//     pore matching between calls on synthetic pore lists.
//
// The mesh is refined around the interface up to each level of LEVELS and
// alpha is the interpolated signed distance. Options: --csv FILE, limits
// --max-volume-error, --max-density-error, --max-neck-error (relative, at
// the finest level; the neck error over the contacts' necks and over the
// smallest of them, the metrics' neck_radius), --min-volume-order, and
// exact counts --closed-pores, --open-pores, --contacts,
// --interior-coordination, --near-misses. Every open pore must have no
// sphericity (NaN: the box faces are not part of its surface). Exit code 0
// only if every check passes.

#include <deal.II/base/function.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/quadrature_lib.h>

#include <deal.II/distributed/tria.h>

#include <levelsinter/analysis/packing_analysis.h>
#include <levelsinter/analysis/pores.h>
#include <levelsinter/analysis/reference_shapes.h>
#include <levelsinter/grid/box_mesh.h>

#include "refined_level_set.h"
#include "study_table.h"

#include <chrono>
#include <iostream>

using namespace levelsinter;

namespace
{
  using study::check;
  using study::Table;

  // The unit box, refined around the interface up to @p level.
  template <int dim>
  void
  build(parallel::distributed::Triangulation<dim> &tria,
        LevelSetField<dim>                        &level_set,
        const Function<dim>                       &phi,
        const unsigned int                         level)
  {
    SceneParameters::Domain domain;
    domain.lower_corner = std::vector<double>(dim, 0.);
    domain.upper_corner = std::vector<double>(dim, 1.);
    domain.subdivisions = std::vector<unsigned int>(dim, 1);
    study::build_refined_level_set(tria, level_set, domain, phi, level);
  }

  void
  check_count(const std::string   &what,
              const double         value,
              const study::Options &options,
              const std::string   &name)
  {
    const auto it = options.limits.find(name);
    if (it == options.limits.end())
      return;
    const bool ok = value == it->second;
    study::failures() += !ok;
    if (study::is_root())
      std::cout << (ok ? "PASS " : "FAIL ") << what << " = " << value
                << " (expected " << it->second << ")\n";
  }

  template <int dim>
  Point<dim>
  uniform_point(const double x)
  {
    Point<dim> p;
    for (unsigned int d = 0; d < dim; ++d)
      p[d] = x;
    return p;
  }

  // ---------------------------------------------------------------------
  // A particle with holes.

  template <int dim>
  class ParticleWithHoles : public Function<dim>
  {
  public:
    ParticleWithHoles(const double                   R,
                      const Point<dim>              &centre,
                      const std::vector<Point<dim>> &holes,
                      const double                   r)
      : R(R)
      , centre(centre)
      , holes(holes)
      , r(r)
    {}

    double
    value(const Point<dim> &p, const unsigned int = 0) const override
    {
      // Solid = particle minus holes: max(d_particle, -d_holes).
      double phi = p.distance(centre) - R;
      for (const auto &c : holes)
        phi = std::max(phi, r - p.distance(c));
      return phi;
    }

  private:
    double                  R;
    Point<dim>              centre;
    std::vector<Point<dim>> holes;
    double                  r;
  };

  template <int dim>
  void
  holes_case(const unsigned int                n_holes,
             const std::vector<std::string> &args)
  {
    const study::Options options = study::parse_options(args, 5);
    const double       R = 0.3, r = 0.08;
    const auto         planes_option = options.limits.find("planes");
    const unsigned int planes =
      planes_option == options.limits.end() ? 0 : planes_option->second;
    if (planes >= dim)
      throw std::runtime_error("--planes must be below the dimension");
    // The particle's centre: on the symmetry planes x_k = 0, k < planes.
    Point<dim>                      centre = uniform_point<dim>(0.5);
    std::vector<types::boundary_id> symmetry;
    for (unsigned int k = 0; k < planes; ++k)
      {
        centre[k] = 0;
        symmetry.push_back(2 * k);
      }
    std::vector<Point<dim>> holes;
    for (unsigned int k = 0; k < n_holes; ++k)
      {
        Point<dim> c = centre;
        // Off the planes of the mesh, the general case; on the symmetry
        // planes, apart along the last axis.
        const double apart = k == 0 ? -0.12 : 0.12, off = 0.013 * (k + 1);
        if (planes == 0)
          {
            c[0] += apart;
            c[1] += off;
          }
        else
          c[dim - 1] += apart + off;
        holes.push_back(c);
      }
    const double exact =
      (dim == 2 ? M_PI * r * r : 4. / 3 * M_PI * r * r * r) / (1u << planes);
    Table table({"level", "h", "closed_pores", "open_pores", "volume_error",
                 "min_sphericity", "open_volume"},
                options.csv);
    for (const unsigned int level : study::parse_levels(args.at(4)))
      {
        parallel::distributed::Triangulation<dim> tria(MPI_COMM_WORLD);
        LevelSetField<dim>                        level_set(tria);
        build(tria,
              level_set,
              ParticleWithHoles<dim>(R, centre, holes, r),
              level);
        const auto pores = find_pores(level_set, symmetry, BoundingBox<dim>(
                                                       std::make_pair(
                                                         uniform_point<dim>(0),
                                                         uniform_point<dim>(1))));
        unsigned int n_closed = 0, n_open = 0;
        double       error = 0, sphericity = 1, open_volume = 0;
        for (const auto &pore : pores)
          if (pore.open)
            {
              ++n_open;
              open_volume += pore.volume;
              const bool undefined = std::isnan(pore.sphericity());
              study::failures() += !undefined;
              if (study::is_root())
                std::cout << (undefined ? "PASS" : "FAIL")
                          << " open pore sphericity " << pore.sphericity()
                          << " (expected nan)\n";
            }
          else
            {
              ++n_closed;
              error = std::max(error, std::abs(pore.volume - exact) / exact);
              sphericity = std::min(sphericity, pore.sphericity());
            }
        table.add({double(level), std::ldexp(1., -int(level)),
                   double(n_closed), double(n_open), error, sphericity,
                   open_volume});
      }
    check_count("closed pores", table.finest("closed_pores"), options,
                "closed-pores");
    check_count("open pores", table.finest("open_pores"), options,
                "open-pores");
    check("volume error", table.finest("volume_error"), options,
          "max-volume-error");
    check("volume error order", table.order("volume_error"), options,
          "min-volume-order", false);
    check("sphericity error", 1 - table.finest("min_sphericity"), options,
          "max-sphericity-error");
  }

  // ---------------------------------------------------------------------
  // A simple cubic lattice.

  // Volume of the pore at the centre of a lattice cell (the 2^dim balls at
  // its corners, throats closed: R > a/2 in 2D, R > a/sqrt2 in 3D): the pore is star-shaped about the centre,
  // V = (1/dim) int |x(omega)|^dim d omega over the directions, x(omega) the
  // first ball surface along the ray; Gauss-Legendre in cos(theta) and the
  // midpoint rule in the angle, 2 x 10^5 rays (converged to 1e-6).
  template <int dim>
  double
  central_pore_volume(const double a, const double R)
  {
    std::vector<Tensor<1, dim>> corners; // ball centres from the pore centre
    for (unsigned int v = 0; v < (1u << dim); ++v)
      {
        Tensor<1, dim> c;
        for (unsigned int d = 0; d < dim; ++d)
          c[d] = (v & (1u << d)) ? a / 2 : -a / 2;
        corners.push_back(c);
      }
    auto hit = [&](const Tensor<1, dim> &omega) {
      double s = std::numeric_limits<double>::max();
      for (const auto &c : corners)
        {
          const double b = omega * c, disc = b * b - (c * c - R * R);
          if (disc >= 0 && b - std::sqrt(disc) > 0)
            s = std::min(s, b - std::sqrt(disc));
        }
      return s;
    };
    const unsigned int n_angle = dim == 2 ? 200000 : 800;
    double             volume  = 0;
    if constexpr (dim == 2)
      for (unsigned int k = 0; k < n_angle; ++k)
        {
          const double t = 2 * M_PI * (k + 0.5) / n_angle;
          volume += std::pow(hit(Tensor<1, 2>({std::cos(t), std::sin(t)})), 2) /
                    2 * 2 * M_PI / n_angle;
        }
    else
      {
        const QGauss<1> gauss(250);
        for (unsigned int q = 0; q < gauss.size(); ++q)
          {
            const double z = 2 * gauss.point(q)[0] - 1, w = 2 * gauss.weight(q);
            const double s = std::sqrt(1 - z * z);
            for (unsigned int k = 0; k < n_angle; ++k)
              {
                const double t = 2 * M_PI * (k + 0.5) / n_angle;
                volume += std::pow(hit(Tensor<1, 3>(
                                     {s * std::cos(t), s * std::sin(t), z})),
                                   3) /
                          3 * w * 2 * M_PI / n_angle;
              }
          }
      }
    return volume;
  }

  // Solid fraction of the lattice: per ball its volume minus 2 dim caps of
  // height R - a/2 (valid while only nearest neighbours overlap,
  // R < a / sqrt2); past that the cell minus its closed central pore.
  template <int dim>
  double
  lattice_density(const double a, const double R)
  {
    if (R >= a / std::sqrt(2.))
      return 1 - central_pore_volume<dim>(a, R) / std::pow(a, dim);
    const double h = std::max(0., R - a / 2);
    const double ball = dim == 2 ? M_PI * R * R : 4. / 3 * M_PI * R * R * R;
    const double cap =
      dim == 2 ? R * R * std::acos((R - h) / R) -
                   (R - h) * std::sqrt(std::max(0., 2 * R * h - h * h)) :
                 M_PI * h * h * (3 * R - h) / 3;
    return (ball - 2 * dim * cap) / std::pow(a, dim);
  }

  template <int dim>
  void
  lattice_case(const unsigned int n, const double a, const double R,
               const std::vector<std::string> &args)
  {
    const study::Options options = study::parse_options(args, 7);
    SceneParameters scene;
    scene.dimension       = dim;
    scene.geometry.shape  = GeometryParameters::Shape::particles;
    scene.domain.lower_corner = std::vector<double>(dim, 0.);
    scene.domain.upper_corner = std::vector<double>(dim, 1.);
    scene.domain.subdivisions = std::vector<unsigned int>(dim, 1);
    const double a_y =
      options.limits.count("spacing-y") ? options.limits.at("spacing-y") : a;
    for (unsigned int k = 0; k < std::pow(n, dim); ++k)
      {
        std::vector<double> row;
        for (unsigned int d = 0, rest = k; d < dim; ++d, rest /= n)
          row.push_back(0.5 +
                        (double(rest % n) - (n - 1) / 2.) * (d == 1 ? a_y : a));
        row.push_back(R);
        scene.geometry.particles.push_back(row);
      }
    const UnionOfBalls<dim> balls(scene.geometry.particles);
    // The throats close when the balls cover the cell faces' centres.
    const double closing       = dim == 2 ? a / 2 : a / std::sqrt(2.);
    const double exact_pore    = R > closing ?
                                   central_pore_volume<dim>(a, R) :
                                   std::numeric_limits<double>::quiet_NaN();
    const double exact_density = lattice_density<dim>(a, R);
    const double exact_neck    = std::sqrt(std::max(0., R * R - a * a / 4));
    if (study::is_root())
      std::cout << "exact: central pore " << exact_pore << ", density "
                << exact_density << ", neck " << exact_neck << "\n";

    Table table({"level", "h", "closed_pores", "open_pores",
                 "pore_volume_error", "relative_density", "density_error",
                 "neck_error", "neck_radius_error", "near_misses",
                 "near_miss_gap_min", "contacts", "coordination_number",
                 "interior_coordination_number", "cells",
                 "analysis_seconds"},
                options.csv);
    for (const unsigned int level : study::parse_levels(args.at(6)))
      {
        parallel::distributed::Triangulation<dim> tria(MPI_COMM_WORLD);
        LevelSetField<dim>                        level_set(tria);
        build(tria, level_set, balls, level);
        // Near misses: a gap below one cell of this mesh's band.
        scene.refinement.max_level = level;
        PackingAnalysis<dim> analysis(scene, MPI_COMM_WORLD);
        const auto           start = std::chrono::steady_clock::now();
        const auto           row   = analysis.measure(0, 0, level_set);
        const double         seconds = Utilities::MPI::max(
          std::chrono::duration<double>(std::chrono::steady_clock::now() - start)
            .count(),
          MPI_COMM_WORLD);
        const auto           names = analysis.column_names();
        auto value = [&](const std::string &name) {
          const auto it = std::find(names.begin(), names.end(), name);
          return it == names.end() ? std::numeric_limits<double>::quiet_NaN() :
                                     row[it - names.begin()];
        };
        unsigned int n_open = 0;
        double       pore_error = 0;
        for (const auto &pore : analysis.pores())
          if (pore.open)
            ++n_open;
          else
            pore_error = std::max(pore_error,
                                  std::abs(pore.volume - exact_pore) / exact_pore);
        double neck_error = 0;
        for (const auto &neck : analysis.necks())
          if (neck.contact)
            neck_error =
              std::max(neck_error,
                       std::abs(neck.radius - exact_neck) / exact_neck);
        const double neck_radius_error =
          std::abs(neck_measures::smallest_neck_radius(analysis.necks()) -
                   exact_neck) /
          exact_neck;
        table.add({double(level), std::ldexp(1., -int(level)),
                   value("closed_pores"), double(n_open), pore_error,
                   value("relative_density"),
                   std::abs(value("relative_density") - exact_density) /
                     exact_density,
                   neck_error, neck_radius_error, value("near_misses"),
                   value("near_miss_gap_min"), value("contacts"),
                   value("coordination_number"),
                   value("interior_coordination_number"),
                   double(tria.n_global_active_cells()), seconds});
      }
    check_count("closed pores", table.finest("closed_pores"), options,
                "closed-pores");
    check_count("open pores", table.finest("open_pores"), options,
                "open-pores");
    check_count("contacts", table.finest("contacts"), options, "contacts");
    check_count("interior coordination",
                table.finest("interior_coordination_number"), options,
                "interior-coordination");
    check("pore volume error", table.finest("pore_volume_error"), options,
          "max-volume-error");
    check("density error", table.finest("density_error"), options,
          "max-density-error");
    check_count("near misses", table.finest("near_misses"), options,
                "near-misses");
    check("neck error", table.finest("neck_error"), options, "max-neck-error");
    check("neck_radius error", table.finest("neck_radius_error"), options,
          "max-neck-error");
  }

  // ---------------------------------------------------------------------
  // Tracking: two closed pores, then one moved by less than its radius and
  // one gone, plus a new one far away.

  void
  tracking_case()
  {
    auto pore = [](const double x, const double volume) {
      Pore<2> p;
      p.centroid = Point<2>(x, 0.5);
      p.volume   = volume;
      return p;
    };
    PoreTracker<2>                  tracker;
    std::vector<PoreTracker<2>::Event> events;
    const auto first  = tracker.update({pore(0.2, 1e-2), pore(0.6, 1e-2)}, events);
    const auto second = tracker.update({pore(0.22, 5e-3), pore(0.9, 1e-3)}, events);
    std::string log;
    for (const auto &e : events)
      log += e.name + " " + std::to_string(e.pore) + "; ";
    const std::string expected =
      "closed 1; closed 2; vanished 2; closed 3; ";
    const bool ok = first == std::vector<unsigned int>{1, 2} &&
                    second == std::vector<unsigned int>{1, 3} && log == expected;
    study::failures() += !ok;
    if (study::is_root())
      std::cout << (ok ? "PASS" : "FAIL") << " events: " << log << "(expected "
                << expected << ")\n";
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  try
    {
      const std::vector<std::string> args(argv, argv + argc);
      const std::string              what = args.at(1);
      if (what == "tracking")
        tracking_case();
      else if (what == "holes")
        {
          const unsigned int n = std::stoi(args.at(3));
          if (args.at(2) == "2")
            holes_case<2>(n, args);
          else
            holes_case<3>(n, args);
        }
      else if (what == "lattice")
        {
          const unsigned int n = std::stoi(args.at(3));
          const double       a = std::stod(args.at(4)), R = std::stod(args.at(5));
          if (args.at(2) == "2")
            lattice_case<2>(n, a, R, args);
          else
            lattice_case<3>(n, a, R, args);
        }
      else
        throw std::runtime_error("unknown case '" + what +
                                 "': holes, lattice or tracking");
    }
  catch (const std::exception &e)
    {
      std::cerr << "error: " << e.what() << std::endl;
      return 2;
    }
  return study::failures() == 0 ? 0 : 1;
}
