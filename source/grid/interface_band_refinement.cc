#include <deal.II/base/mpi.h>

#include <deal.II/grid/grid_generator.h>

#include <levelsinter/grid/interface_band_refinement.h>

#include <algorithm>
#include <cmath>

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

  template <int dim>
  InterfaceBandRefinement<dim>::InterfaceBandRefinement(
    const SceneParameters::Refinement &settings,
    const LevelSetFilter              &filter)
    : settings(settings)
    , filter(filter)
  {}

  template <int dim>
  bool
  InterfaceBandRefinement<dim>::mark_cells(
    parallel::distributed::Triangulation<dim> &tria,
    const LevelSetField<dim>                  &level_set) const
  {
    std::vector<types::global_dof_index> indices(level_set.fe().dofs_per_cell);
    bool                                 any_flag = false;
    for (const auto &cell : level_set.dof_handler().active_cell_iterators())
      if (cell->is_locally_owned())
        {
          cell->get_dof_indices(indices);
          double min_alpha = std::numeric_limits<double>::max();
          double max_alpha = -min_alpha;
          double nearest   = min_alpha;
          for (const auto i : indices)
            {
              const double a = level_set.alpha()(i);
              min_alpha      = std::min(min_alpha, a);
              max_alpha      = std::max(max_alpha, a);
              nearest = std::min(nearest, std::abs(filter.distance(a)));
            }
          const bool in_band = (min_alpha <= 0 && max_alpha >= 0) ||
                               nearest <= settings.band_width;
          const unsigned int level = cell->level();
          auto tria_cell = typename Triangulation<dim>::active_cell_iterator(
            &tria, cell->level(), cell->index());
          if (in_band && level < settings.max_level)
            {
              tria_cell->set_refine_flag();
              any_flag = true;
            }
          else if (!in_band && level > settings.min_level)
            {
              tria_cell->set_coarsen_flag();
              any_flag = true;
            }
          else if (in_band && level > settings.max_level)
            {
              tria_cell->set_coarsen_flag();
              any_flag = true;
            }
        }
    return Utilities::MPI::logical_or(any_flag, tria.get_communicator());
  }

  template void
  make_box_mesh(parallel::distributed::Triangulation<2> &,
                const SceneParameters::Domain &);
  template void
  make_box_mesh(parallel::distributed::Triangulation<3> &,
                const SceneParameters::Domain &);
  template class InterfaceBandRefinement<2>;
  template class InterfaceBandRefinement<3>;
} // namespace levelsinter
