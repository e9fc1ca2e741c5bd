#include <deal.II/base/quadrature_lib.h>

#include <deal.II/fe/fe_values.h>

#include <deal.II/lac/vector.h>

#include <levelsinter/geometry/nodal_normals.h>
#include <levelsinter/level_set/box_mapping.h>
#include <levelsinter/level_set/ghosted_vector.h>

#include <cmath>

#include <algorithm>

namespace levelsinter
{
  template <int dim>
  std::array<TrilinosWrappers::MPI::Vector, dim>
  nodal_normals(const LevelSetField<dim>             &level_set,
                const LevelSetFilter                 &filter,
                const bool                            from_distance,
                const std::vector<types::boundary_id> &symmetry_boundaries)
  {
    return nodal_normals(level_set,
                         level_set.alpha(),
                         filter,
                         from_distance,
                         symmetry_boundaries);
  }

  template <int dim>
  std::array<TrilinosWrappers::MPI::Vector, dim>
  nodal_normals(const LevelSetField<dim>             &level_set,
                const TrilinosWrappers::MPI::Vector  &alpha,
                const LevelSetFilter                 &filter,
                const bool                            from_distance,
                const std::vector<types::boundary_id> &symmetry_boundaries)
  {
    using Vector        = TrilinosWrappers::MPI::Vector;
    const auto    &dofs = level_set.dof_handler();
    const MPI_Comm comm = dofs.get_communicator();
    std::array<Vector, dim> sums;
    for (auto &sum : sums)
      sum.reinit(level_set.locally_owned(),
                 level_set.locally_relevant(),
                 comm,
                 true);
    const QMidpoint<dim> centre;
    FEValues<dim> fe_values(box_mapping<dim>(),
                            level_set.fe(),
                            centre,
                            update_gradients);
    std::vector<Tensor<1, dim>> gradient(1);
    dealii::Vector<double>      local_alpha(level_set.fe().dofs_per_cell);
    for (const auto &cell : dofs.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          fe_values.reinit(cell);
          if (from_distance)
            {
              cell->get_dof_values(alpha, local_alpha);
              gradient[0] = 0;
              for (unsigned int i = 0; i < local_alpha.size(); ++i)
                gradient[0] += filter.distance(local_alpha[i]) *
                               fe_values.shape_grad(i, 0);
            }
          else
            fe_values.get_function_gradients(alpha, gradient);
          const double norm = gradient[0].norm();
          if (norm == 0)
            continue;
          for (const unsigned int v : cell->vertex_indices())
            for (unsigned int c = 0; c < dim; ++c)
              sums[c](cell->vertex_dof_index(v, 0)) += gradient[0][c] / norm;
        }
    for (auto &sum : sums)
      sum.compress(VectorOperation::add);
    // Nodes on a symmetry face: the mirror cells' sum cancels the component
    // across the face (ghost cells too, so that every owned node is seen).
    // The axis of an axisymmetric scene (face x-, id 0) is one: n_r = 0
    // there.
    std::vector<types::boundary_id> mirrors = symmetry_boundaries;
    if (level_set.measure().is_axisymmetric())
      mirrors.push_back(0);
    for (const auto &cell : dofs.active_cell_iterators())
      if (!cell->is_artificial())
        for (const unsigned int f : cell->face_indices())
          if (cell->face(f)->at_boundary() &&
              std::find(mirrors.begin(),
                        mirrors.end(),
                        cell->face(f)->boundary_id()) != mirrors.end())
            {
              const unsigned int axis = cell->face(f)->boundary_id() / 2;
              for (const unsigned int v : cell->face(f)->vertex_indices())
                {
                  const auto i = cell->face(f)->vertex_dof_index(v, 0);
                  if (level_set.locally_owned().is_element(i))
                    sums[axis](i) = 0;
                }
            }

    std::array<Vector, dim> owned_normals;
    for (unsigned int c = 0; c < dim; ++c)
      owned_normals[c].reinit(level_set.locally_owned(), comm);
    for (const auto i : level_set.locally_owned())
      {
        double norm2 = 0;
        for (unsigned int c = 0; c < dim; ++c)
          norm2 += sums[c](i) * sums[c](i);
        if (norm2 > 0)
          for (unsigned int c = 0; c < dim; ++c)
            owned_normals[c](i) = sums[c](i) / std::sqrt(norm2);
      }
    std::array<Vector, dim> normals;
    for (unsigned int c = 0; c < dim; ++c)
      normals[c] = ghosted_from_owned(owned_normals[c],
                                      level_set.constraints(),
                                      level_set.locally_relevant());
    return normals;
  }

  template std::array<TrilinosWrappers::MPI::Vector, 2>
  nodal_normals<2>(const LevelSetField<2> &,
                   const LevelSetFilter &,
                   bool,
                   const std::vector<types::boundary_id> &);
  template std::array<TrilinosWrappers::MPI::Vector, 3>
  nodal_normals<3>(const LevelSetField<3> &,
                   const LevelSetFilter &,
                   bool,
                   const std::vector<types::boundary_id> &);
  template std::array<TrilinosWrappers::MPI::Vector, 2>
  nodal_normals<2>(const LevelSetField<2> &,
                   const TrilinosWrappers::MPI::Vector &,
                   const LevelSetFilter &,
                   bool,
                   const std::vector<types::boundary_id> &);
  template std::array<TrilinosWrappers::MPI::Vector, 3>
  nodal_normals<3>(const LevelSetField<3> &,
                   const TrilinosWrappers::MPI::Vector &,
                   const LevelSetFilter &,
                   bool,
                   const std::vector<types::boundary_id> &);
} // namespace levelsinter
