#pragma once

#include <deal.II/grid/grid_tools.h>
#include <deal.II/grid/tria.h>

#include <cmath>

namespace levelsinter
{
  using namespace dealii;

  /**
   * The edge h of a cell, its diameter / sqrt(dim): the length band widths,
   * filter thicknesses, offsets and step limits are counted in.
   */
  template <typename CellIterator>
  double
  cell_size(const CellIterator &cell)
  {
    return cell->diameter() /
           std::sqrt(double(CellIterator::AccessorType::dimension));
  }

  /**
   * h_min, the edge of the finest active cell of the whole mesh, the same
   * on every rank (collective: GridTools::minimal_cell_diameter takes the
   * minimum over the ranks).
   */
  template <int dim>
  double
  finest_cell_size(const Triangulation<dim> &tria)
  {
    return GridTools::minimal_cell_diameter(tria) / std::sqrt(double(dim));
  }
} // namespace levelsinter
