#pragma once

#include <deal.II/dofs/dof_handler.h>

namespace levelsinter
{
  using namespace dealii;

  /**
   * The cell @p cell of the shared triangulation seen through another
   * DoFHandler @p dofs (the level set's, the velocity's, the Stokes
   * system's all live on one mesh).
   */
  template <int dim, typename CellIterator>
  typename DoFHandler<dim>::active_cell_iterator
  same_cell(const CellIterator &cell, const DoFHandler<dim> &dofs)
  {
    return typename DoFHandler<dim>::active_cell_iterator(
      &dofs.get_triangulation(), cell->level(), cell->index(), &dofs);
  }
} // namespace levelsinter
