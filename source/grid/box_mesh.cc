#include <deal.II/grid/grid_generator.h>

#include <levelsinter/grid/box_mesh.h>

namespace levelsinter
{
  template <int dim>
  void
  make_box_mesh(parallel::distributed::Triangulation<dim> &tria,
                const SceneParameters::Domain             &domain)
  {
    Point<dim>                lower, upper;
    std::vector<unsigned int> repetitions(dim);
    for (unsigned int d = 0; d < dim; ++d)
      {
        lower[d]       = domain.lower_corner[d];
        upper[d]       = domain.upper_corner[d];
        repetitions[d] = domain.subdivisions[d];
      }
    GridGenerator::subdivided_hyper_rectangle(
      tria, repetitions, lower, upper, /*colorize=*/true);
  }

  template void
  make_box_mesh(parallel::distributed::Triangulation<2> &,
                const SceneParameters::Domain &);
  template void
  make_box_mesh(parallel::distributed::Triangulation<3> &,
                const SceneParameters::Domain &);
} // namespace levelsinter
