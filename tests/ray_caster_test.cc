// RayCaster (level_set/interface_measures.h) on rays that run along mesh
// faces (doc/validation.md, "Grain boundaries and densification"):
//
//   ray_caster_test DIM LEVEL
//     a ball of radius 0.3 about the centre of the unit box, the level set
//     its interpolated signed distance refined to LEVEL. Rays start on mesh
//     faces (the box's mid-planes and planes k h off them, so on faces of
//     refined cells too) and run along an axis, exactly or tilted by
//     1e-16 ... 1e-9 rad towards another axis (the rounding of a computed
//     direction), outwards and inwards. Each exit must lie within the
//     interpolation error of the ball's surface: |exit - exact| <= h^2 / R
//     (Q1 interpolation of the distance: 0.02 h at level 6 in 2D); a lost
//     ray gives +infinity. Exit code 0 only if every ray passes.

#include <deal.II/base/mpi.h>

#include <deal.II/base/function.h>

#include <deal.II/distributed/tria.h>

#include <levelsinter/level_set/interface_measures.h>

#include "refined_level_set.h"

#include <cmath>
#include <iostream>

using namespace levelsinter;

namespace
{
  template <int dim>
  unsigned int
  cast(const unsigned int level)
  {
    const double radius = 0.3;
    DomainParameters domain;
    domain.lower_corner = std::vector<double>(dim, 0.);
    domain.upper_corner = std::vector<double>(dim, 1.);
    domain.subdivisions = std::vector<unsigned int>(dim, 1);
    Point<dim> centre;
    for (unsigned int d = 0; d < dim; ++d)
      centre[d] = 0.5;
    const ScalarFunctionFromFunctionObject<dim> phi(
      [&](const Point<dim> &x) { return x.distance(centre) - radius; });
    parallel::distributed::Triangulation<dim> tria(MPI_COMM_WORLD);
    LevelSetField<dim>                        level_set(tria);
    study::build_refined_level_set(tria, level_set, domain, phi, level);
    const double h = 1. / std::pow(2., level);
    std::vector<interface_measures::Ray<dim>> rays;
    std::vector<double>                       exact;
    // Origins on the mid-planes and on planes 1 and 3 finest cells off
    // them (faces of the finest cells near the axis); directions along
    // axis a, tilted towards axis b (the axis whose coordinate puts the
    // origin on a face).
    for (unsigned int a = 0; a < dim; ++a)
      for (unsigned int b = 0; b < dim; ++b)
        if (b != a)
          for (const double offset : {0., h, 3 * h})
            for (const double tilt :
                 {0., 1e-16, -1e-16, 1e-15, -1e-15, 1e-13, -1e-13, 1e-11, 1e-9})
              for (const double sign : {1., -1.})
                for (const double side : {1., -1.})
                  for (const int ulps : {0, 1, -1})
                  {
                    Point<dim> origin = centre;
                    origin[b] += side * offset;
                    // One unit in the last place off the face: the
                    // rounding of a computed origin.
                    for (int k = 0; k < std::abs(ulps); ++k)
                      origin[b] = std::nextafter(origin[b], ulps * 2.);
                    Tensor<1, dim> direction;
                    direction[a] = sign * std::cos(tilt);
                    direction[b] = std::sin(tilt);
                    // The exact exit from the ball (origin inside).
                    const Tensor<1, dim> o = origin - centre;
                    const double         p = o * direction;
                    const double         s =
                      -p + std::sqrt(p * p - o.norm_square() + radius * radius);
                    rays.push_back({origin, direction});
                    exact.push_back(s);
                  }
    const std::vector<double> exits =
      interface_measures::RayCaster<dim>(level_set).exit_distances(rays);
    unsigned int failed = 0;
    double       worst  = 0;
    for (unsigned int r = 0; r < rays.size(); ++r)
      {
        const double error = std::abs(exits[r] - exact[r]);
        worst              = std::max(worst, error);
        if (!(error <= h * h / radius))
          {
            ++failed;
            if (Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
              std::cout << "ray from " << rays[r].origin << " along "
                        << rays[r].direction << ": exit " << exits[r]
                        << ", exact " << exact[r] << '\n';
          }
      }
    if (Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
      std::cout << dim << "D, level " << level << ": " << rays.size()
                << " rays, " << failed << " failed, largest error " << worst
                << " (limit h^2 / R = " << h * h / radius << ")" << std::endl;
    return failed;
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  if (argc != 3)
    {
      std::cerr << "usage: ray_caster_test DIM LEVEL" << std::endl;
      return 1;
    }
  const unsigned int level  = std::stoi(argv[2]);
  const unsigned int failed = std::string(argv[1]) == "2" ? cast<2>(level) :
                                                            cast<3>(level);
  return failed > 0;
}
