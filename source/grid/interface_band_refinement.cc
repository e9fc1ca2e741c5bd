#include <deal.II/base/mpi.h>
#include <deal.II/base/quadrature_lib.h>

#include <deal.II/fe/fe_values.h>

#include <deal.II/grid/grid_tools.h>

#include <deal.II/lac/vector.h>

#include <levelsinter/geometry/nodal_normals.h>
#include <levelsinter/grid/interface_band_refinement.h>
#include <levelsinter/level_set/cell_size.h>

#include <algorithm>
#include <optional>
#include <cmath>

namespace levelsinter
{
  template <int dim>
  InterfaceBandRefinement<dim>::InterfaceBandRefinement(
    const SceneParameters::Refinement     &settings,
    const LevelSetFilter                  &filter,
    const std::vector<types::boundary_id> &symmetry_boundaries)
    : settings(settings)
    , filter(filter)
    , symmetry_boundaries(symmetry_boundaries)
  {}

  template <int dim>
  unsigned int
  InterfaceBandRefinement<dim>::finest_level() const
  {
    return settings.max_level + settings.curvature_levels;
  }

  template <int dim>
  InterfaceBandRefinement<dim>::CellCurvature::CellCurvature(
    const LevelSetField<dim>             &level_set,
    const LevelSetFilter                 &filter,
    const std::vector<types::boundary_id> &symmetry_boundaries)
    : normals(nodal_normals(level_set,
                            filter,
                            /*from_distance=*/true,
                            symmetry_boundaries))
    , measure(level_set.measure())
    , fe_values(level_set.fe(),
                QMidpoint<dim>(),
                update_values | update_gradients | update_quadrature_points)
    , local_normal(level_set.fe().dofs_per_cell)
  {}

  template <int dim>
  double
  InterfaceBandRefinement<dim>::CellCurvature::operator()(
    const typename DoFHandler<dim>::active_cell_iterator &cell)
  {
    fe_values.reinit(cell);
    Tensor<2, dim> gradient;
    // On a body of revolution grad N has the azimuthal entry N_r / r, the
    // hoop curvature (N_r = 0 on the axis nodes, nodal_normals()).
    double hoop = 0;
    for (unsigned int c = 0; c < dim; ++c)
      {
        cell->get_dof_values(normals[c], local_normal);
        for (unsigned int i = 0; i < local_normal.size(); ++i)
          {
            gradient[c] += local_normal[i] * fe_values.shape_grad(i, 0);
            if (c == 0)
              hoop += local_normal[i] * fe_values.shape_value(i, 0);
          }
      }
    hoop *= measure.inverse_radius(fe_values.quadrature_point(0));
    return std::sqrt(gradient.norm_square() + hoop * hoop);
  }

  template <int dim>
  bool
  InterfaceBandRefinement<dim>::crossed(
    const std::vector<types::global_dof_index> &indices,
    const LevelSetField<dim>                   &level_set)
  {
    bool negative = false, positive = false;
    for (const auto i : indices)
      {
        negative = negative || level_set.alpha()(i) <= 0;
        positive = positive || level_set.alpha()(i) >= 0;
      }
    return negative && positive;
  }

  template <int dim>
  typename InterfaceBandRefinement<dim>::CurvatureResolution
  InterfaceBandRefinement<dim>::curvature_resolution(
    const LevelSetField<dim> &level_set) const
  {
    CellCurvature curvature(level_set, filter, symmetry_boundaries);
    CurvatureResolution                  result;
    std::vector<types::global_dof_index> indices(level_set.fe().dofs_per_cell);
    for (const auto &cell : level_set.dof_handler().active_cell_iterators())
      if (cell->is_locally_owned() && cell->level() >= int(finest_level()))
        {
          cell->get_dof_indices(indices);
          if (!crossed(indices, level_set))
            continue;
          const double h = cell_size(cell);
          const double kh = curvature(cell) * h;
          result.max_curvature_times_h =
            std::max(result.max_curvature_times_h, kh);
          if (kh > 1)
            ++result.under_resolved_cells;
        }
    const MPI_Comm comm = level_set.dof_handler().get_communicator();
    result.under_resolved_cells =
      Utilities::MPI::sum(result.under_resolved_cells, comm);
    result.max_curvature_times_h =
      Utilities::MPI::max(result.max_curvature_times_h, comm);
    return result;
  }

  template <int dim>
  std::vector<Point<dim>>
  InterfaceBandRefinement<dim>::points_in_coarse_cells(
    const parallel::distributed::Triangulation<dim> &tria,
    const std::vector<Point<dim>>                   &interface_points) const
  {
    // Down the refinement tree from the coarse cells: a point in another
    // rank's cells is then not searched for among all cells, as
    // GridTools::find_active_cell_around_point() does (minutes for the 154
    // particles' 924 points on 0.7 M cells). The cells are boxes.
    std::vector<Point<dim>> coarse;
    for (const auto &p : interface_points)
      for (auto cell : tria.cell_iterators_on_level(0))
        if (cell->bounding_box().point_inside(p, 1e-12))
          {
            while (cell->has_children())
              {
                const auto child = std::find_if(
                  cell->child_iterators().begin(),
                  cell->child_iterators().end(),
                  [&](const auto &c) {
                    return c->bounding_box().point_inside(p, 1e-12);
                  });
                if (child == cell->child_iterators().end())
                  break;
                cell = *child;
              }
            if (cell->is_active() && cell->is_locally_owned() &&
                cell->level() < int(settings.max_level))
              coarse.push_back(p);
            break;
          }
    std::vector<Point<dim>> all;
    for (const auto &part :
         Utilities::MPI::all_gather(tria.get_communicator(), coarse))
      all.insert(all.end(), part.begin(), part.end());
    return all;
  }

  template <int dim>
  bool
  InterfaceBandRefinement<dim>::mark_cells(
    parallel::distributed::Triangulation<dim> &tria,
    const LevelSetField<dim>                  &level_set) const
  {
    const unsigned int extra_levels = settings.curvature_levels;
    std::optional<CellCurvature> curvature;
    if (extra_levels > 0)
      curvature.emplace(level_set, filter, symmetry_boundaries);

    std::vector<types::global_dof_index> indices(level_set.fe().dofs_per_cell);
    bool                                 any_flag = false;
    for (const auto &cell : level_set.dof_handler().active_cell_iterators())
      if (cell->is_locally_owned())
        {
          cell->get_dof_indices(indices);
          double nearest = std::numeric_limits<double>::max();
          for (const auto i : indices)
            nearest = std::min(nearest,
                               std::abs(filter.distance(level_set.alpha()(i))));
          const bool cut     = crossed(indices, level_set);
          const bool in_band = cut || nearest <= settings.band_width;
          const unsigned int level = cell->level();
          auto tria_cell = typename Triangulation<dim>::active_cell_iterator(
            &tria, cell->level(), cell->index());
          bool refine = false, coarsen = false;
          if (in_band && extra_levels > 0 && level >= settings.max_level)
            {
              // Extra level j only within band_width / 2^j of the interface.
              const double distance  = cut ? 0. : nearest;
              unsigned int max_extra = 0;
              while (max_extra < extra_levels &&
                     distance <=
                       settings.band_width / std::pow(2., max_extra + 1))
                ++max_extra;
              const unsigned int extra = level - settings.max_level;
              const double       h = cell_size(cell);
              const double       resolution =
                settings.cells_per_curvature_radius * (*curvature)(cell) * h;
              refine  = extra < max_extra && resolution > 1;
              coarsen = extra > 0 && (extra > max_extra || 4 * resolution <= 1);
            }
          else
            {
              refine  = in_band && level < settings.max_level;
              coarsen = (!in_band && level > settings.min_level) ||
                        (in_band && level > settings.max_level);
            }
          if (refine)
            tria_cell->set_refine_flag();
          else if (coarsen)
            tria_cell->set_coarsen_flag();
          any_flag = any_flag || refine || coarsen;
        }
    return Utilities::MPI::logical_or(any_flag, tria.get_communicator());
  }

  template class InterfaceBandRefinement<2>;
  template class InterfaceBandRefinement<3>;
} // namespace levelsinter
