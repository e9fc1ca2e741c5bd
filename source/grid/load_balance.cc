#include <deal.II/base/mpi.h>

#include <deal.II/lac/vector.h>

#include <levelsinter/grid/load_balance.h>

#include <algorithm>
#include <array>

namespace levelsinter
{
  template <int dim>
  LoadBalance<dim>::LoadBalance(
    parallel::distributed::Triangulation<dim> &tria,
    const Weights                             &weights)
    : tria(tria)
    , weights(weights)
  {
    // Equal weights leave p4est's partition by cells as it is.
    if (weights.void_cell == weights.solid_cell &&
        weights.solid_cell == weights.cut_cell)
      return;
    weight_connection = tria.signals.weight.connect(
      [this](const typename Triangulation<dim>::cell_iterator &cell,
             const typename Triangulation<dim>::CellStatus     status) {
        return weight(cell, status);
      });
    // The weight signal runs inside the mesh change, any_change after it:
    // the classes of the old mesh are gone by the next one.
    change_connection =
      tria.signals.any_change.connect([this]() { cell_classes.clear(); });
  }

  template <int dim>
  std::vector<typename LoadBalance<dim>::CellClass>
  LoadBalance<dim>::classes(const LevelSetField<dim> &alpha)
  {
    const auto &dofs = alpha.dof_handler();
    std::vector<CellClass> result(dofs.get_triangulation().n_active_cells(),
                                  void_cell);
    Vector<double>         values(dofs.get_fe().n_dofs_per_cell());
    for (const auto &cell : dofs.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          cell->get_dof_values(alpha.alpha(), values);
          const auto [low, high] =
            std::minmax_element(values.begin(), values.end());
          // Solid where alpha < 0 (Q1: the cell's extremes are nodal).
          result[cell->active_cell_index()] =
            *high <= 0 ? solid_cell : (*low < 0 ? cut_cell : void_cell);
        }
    return result;
  }

  template <int dim>
  void
  LoadBalance<dim>::classify(const LevelSetField<dim> &alpha)
  {
    cell_classes = classes(alpha);
  }

  template <int dim>
  unsigned int
  LoadBalance<dim>::weight_of(const CellClass cell_class) const
  {
    return cell_class == cut_cell   ? weights.cut_cell :
           cell_class == solid_cell ? weights.solid_cell :
                                      weights.void_cell;
  }

  template <int dim>
  unsigned int
  LoadBalance<dim>::weight(
    const typename Triangulation<dim>::cell_iterator &cell,
    const typename Triangulation<dim>::CellStatus     status) const
  {
    if (cell_classes.empty())
      return 1;
    // A cell to be refined is active now and passes its class to each
    // child; children to be coarsened give their parent the most costly
    // of their classes.
    if (status != Triangulation<dim>::CELL_COARSEN)
      return weight_of(cell_classes[cell->active_cell_index()]);
    CellClass most = void_cell;
    for (const auto &child : cell->child_iterators())
      most = std::max(most, cell_classes[child->active_cell_index()]);
    return weight_of(most);
  }

  template <int dim>
  typename LoadBalance<dim>::Imbalance
  LoadBalance<dim>::imbalance(const LevelSetField<dim> &alpha) const
  {
    std::array<double, 4> local{}; // cells, solid, cut, work
    const auto cells = classes(alpha);
    for (const auto &cell : alpha.dof_handler().active_cell_iterators())
      if (cell->is_locally_owned())
        {
          const CellClass cell_class = cells[cell->active_cell_index()];
          local[0] += 1;
          local[1] += cell_class != void_cell;
          local[2] += cell_class == cut_cell;
          local[3] += weight_of(cell_class);
        }
    const MPI_Comm comm = tria.get_communicator();
    std::array<double, 4> ratio{};
    for (unsigned int k = 0; k < local.size(); ++k)
      {
        const auto stats = Utilities::MPI::min_max_avg(local[k], comm);
        ratio[k]         = stats.avg > 0 ? stats.max / stats.avg : 1.;
      }
    return {ratio[0], ratio[1], ratio[2], ratio[3]};
  }

  template class LoadBalance<2>;
  template class LoadBalance<3>;
} // namespace levelsinter
