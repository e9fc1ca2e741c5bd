#pragma once

#include <deal.II/base/mpi.h>
#include <deal.II/base/point.h>

#include <deal.II/dofs/dof_handler.h>

#include <deal.II/fe/mapping_q1.h>

#include <deal.II/grid/grid_tools.h>

#include <stdexcept>
#include <string>

namespace levelsinter
{
  using namespace dealii;

  /**
   * A field's value at @p point on every rank: deal.II lets exactly one rank
   * report a point as inside a locally owned cell (the other ranks see it in
   * a ghost cell or not at all); that rank evaluates
   * @p evaluate(cell, point in the unit cell), and the value is shared.
   * Collective; throws (naming @p what) if no cell holds the point.
   */
  template <typename Value, int dim, typename Evaluate>
  Value
  value_at_point(const DoFHandler<dim> &dofs,
                 const Point<dim>      &point,
                 const std::string     &what,
                 const Evaluate        &evaluate)
  {
    Value        local{};
    unsigned int found          = 0;
    const auto   cell_and_point = GridTools::find_active_cell_around_point(
      StaticMappingQ1<dim>::mapping, dofs, point);
    if (cell_and_point.first != dofs.end() &&
        cell_and_point.first->is_locally_owned())
      {
        local = evaluate(cell_and_point.first,
                         GeometryInfo<dim>::project_to_unit_cell(
                           cell_and_point.second));
        found = 1;
      }
    const MPI_Comm     comm  = dofs.get_communicator();
    const unsigned int total = Utilities::MPI::sum(found, comm);
    if (total == 0)
      throw std::runtime_error(what + " requested outside the mesh");
    return Utilities::MPI::sum(local, comm) / double(total);
  }
} // namespace levelsinter
