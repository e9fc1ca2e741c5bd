#include <deal.II/grid/grid_tools.h>

#include <levelsinter/mechanics/rigid_body_modes.h>

namespace levelsinter
{
  template <int dim>
  std::vector<std::vector<double>>
  rigid_body_modes(const DoFHandler<dim> &dofs, const IndexSet &owned_velocity)
  {
    constexpr unsigned int n_rotations = dim * (dim - 1) / 2;
    std::vector<std::vector<double>> modes(
      dim + n_rotations, std::vector<double>(owned_velocity.n_elements(), 0.));
    // Rotations about the box centre keep the modes O(1) and nearly
    // orthogonal to the translations.
    const auto box    = GridTools::compute_bounding_box(dofs.get_triangulation());
    const auto centre = box.center();
    for (const auto &cell : dofs.active_cell_iterators())
      // Cells without DoFs (FE_Nothing of the solid-only problem) skipped.
      if (cell->is_locally_owned() && cell->get_fe().n_dofs_per_cell() > 0)
        for (const unsigned int v : cell->vertex_indices())
          {
            const Tensor<1, dim> x = cell->vertex(v) - centre;
            for (unsigned int c = 0; c < dim; ++c)
              {
                const auto index = cell->vertex_dof_index(v, c);
                if (!owned_velocity.is_element(index))
                  continue;
                const auto row = owned_velocity.index_within_set(index);
                modes[c][row]  = 1;
                // Rotation r: omega x x with omega = e_z (2D and 3D), e_y,
                // e_x (3D): (-y, x, 0), (z, 0, -x), (0, -z, y).
                if (c == 0)
                  modes[dim][row] = -x[1];
                if (c == 1)
                  modes[dim][row] = x[0];
                if constexpr (dim == 3)
                  {
                    if (c == 0)
                      modes[dim + 1][row] = x[2];
                    if (c == 2)
                      modes[dim + 1][row] = -x[0];
                    if (c == 1)
                      modes[dim + 2][row] = -x[2];
                    if (c == 2)
                      modes[dim + 2][row] = x[1];
                  }
              }
          }
    return modes;
  }

  template std::vector<std::vector<double>>
  rigid_body_modes(const DoFHandler<2> &, const IndexSet &);
  template std::vector<std::vector<double>>
  rigid_body_modes(const DoFHandler<3> &, const IndexSet &);
} // namespace levelsinter
