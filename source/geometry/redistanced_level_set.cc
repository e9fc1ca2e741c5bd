#include <deal.II/base/mpi.h>
#include <deal.II/base/quadrature_lib.h>

#include <deal.II/hp/fe_collection.h>
#include <deal.II/hp/mapping_collection.h>
#include <deal.II/hp/q_collection.h>

#include <deal.II/non_matching/fe_values.h>
#include <deal.II/non_matching/mesh_classifier.h>

#include <deal.II/numerics/rtree.h>

#include <levelsinter/geometry/redistanced_level_set.h>
#include <levelsinter/level_set/box_mapping.h>
#include <levelsinter/level_set/cell_size.h>
#include <levelsinter/level_set/ghosted_vector.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace levelsinter
{
  namespace
  {
    using Vector = TrilinosWrappers::MPI::Vector;

    /** Cell layers from the cut cells (see the header), up to
     * @p max_layers; max_layers + 1 further out. Ghosted. */
    template <int dim>
    Vector
    interface_layers(const LevelSetField<dim> &level_set,
                     const unsigned int        max_layers)
    {
      const auto    &dofs  = level_set.dof_handler();
      const auto    &owned = level_set.locally_owned();
      const MPI_Comm comm  = dofs.get_communicator();
      const auto    &alpha = level_set.alpha();

      Vector layers(owned, comm);
      layers = max_layers + 1;
      Vector ghosted(owned, level_set.locally_relevant(), comm);
      ghosted = layers;
      std::vector<types::global_dof_index> indices(
        level_set.fe().dofs_per_cell);
      for (unsigned int layer = 0; layer <= max_layers; ++layer)
        {
          // The vertices of this layer's cells, marked from the cells each
          // rank owns and summed at the owners.
          Vector reached;
          reached.reinit(owned, level_set.locally_relevant(), comm, true);
          for (const auto &cell : dofs.active_cell_iterators())
            if (cell->is_locally_owned())
              {
                cell->get_dof_indices(indices);
                bool in_layer = false;
                if (layer == 0)
                  {
                    // A cut cell: alpha changes sign among its vertices.
                    const auto [lowest, highest] =
                      std::minmax_element(indices.begin(),
                                          indices.end(),
                                          [&](const auto i, const auto j) {
                                            return alpha(i) < alpha(j);
                                          });
                    in_layer = alpha(*lowest) <= 0 && alpha(*highest) >= 0;
                  }
                else
                  in_layer = std::any_of(indices.begin(),
                                         indices.end(),
                                         [&](const auto i) {
                                           return ghosted(i) < layer;
                                         });
                if (in_layer)
                  for (const auto i : indices)
                    reached(i) += 1;
              }
          reached.compress(VectorOperation::add);
          for (const auto i : owned)
            if (reached(i) > 0 && layers(i) > layer)
              layers(i) = layer;
          layers.compress(VectorOperation::insert);
          ghosted = layers;
        }
      return ghosted;
    }

    /** Points of the interface alpha_h = 0 with its unit normals (out of
     * the solid), from every rank: 4 Gauss points per direction in each
     * cut cell, so that the nearest lies within about h / 8 of the foot
     * of a node's normal, and the tangent there gives the distance. */
    template <int dim>
    std::pair<std::vector<Point<dim>>, std::vector<Tensor<1, dim>>>
    interface_points(const LevelSetField<dim> &level_set)
    {
      const auto &dofs = level_set.dof_handler();
      const auto classifier = level_set.classifier();
      NonMatching::RegionUpdateFlags flags;
      flags.surface = update_normal_vectors | update_quadrature_points;
      const hp::FECollection<dim>     fe_collection(level_set.fe());
      const hp::MappingCollection<dim> mapping(box_mapping<dim>());
      // NonMatching::FEValues keeps references to the rules.
      const hp::QCollection<dim> cells{QGauss<dim>(4)};
      const hp::QCollection<1>   lines{QGauss<1>(4)};
      NonMatching::FEValues<dim> cut_values(mapping,
                                            fe_collection,
                                            cells,
                                            lines,
                                            flags,
                                            *classifier,
                                            dofs,
                                            level_set.alpha());
      std::vector<double> local;
      for (const auto &cell : dofs.active_cell_iterators())
        if (cell->is_locally_owned())
          {
            cut_values.reinit(cell);
            if (const auto &surface = cut_values.get_surface_fe_values())
              for (const unsigned int q : surface->quadrature_point_indices())
                for (unsigned int c = 0; c < 2 * dim; ++c)
                  local.push_back(c < dim ?
                                    surface->quadrature_point(q)[c] :
                                    surface->normal_vector(q)[c - dim]);
          }
      std::pair<std::vector<Point<dim>>, std::vector<Tensor<1, dim>>> result;
      for (const auto &part :
           Utilities::MPI::all_gather(dofs.get_communicator(), local))
        for (std::size_t k = 0; k + 2 * dim <= part.size(); k += 2 * dim)
          {
            Point<dim>     point;
            Tensor<1, dim> normal;
            for (unsigned int c = 0; c < dim; ++c)
              {
                point[c]  = part[k + c];
                normal[c] = part[k + dim + c];
              }
            result.first.push_back(point);
            result.second.push_back(normal);
          }
      return result;
    }
  } // namespace

  template <int dim>
  TrilinosWrappers::MPI::Vector
  redistanced_level_set(const LevelSetField<dim> &level_set,
                        const LevelSetFilter     &filter,
                        const unsigned int        layers)
  {
    const auto    &dofs  = level_set.dof_handler();
    const auto    &owned = level_set.locally_owned();
    const MPI_Comm comm  = dofs.get_communicator();
    const auto    &alpha = level_set.alpha();
    const double   h_min = finest_cell_size(dofs.get_triangulation());
    // A level set within a quarter cell of the distance is left alone.
    const double tolerance = 0.25 * h_min;

    const Vector layer = interface_layers(level_set, layers);
    const auto [points, normals] = interface_points(level_set);
    const auto tree              = pack_rtree_of_indices(points);

    Vector            result(owned, comm);
    std::vector<bool> visited(owned.n_elements(), false);
    for (const auto &cell : dofs.active_cell_iterators())
      if (cell->is_locally_owned())
        for (const unsigned int v : cell->vertex_indices())
          {
            const auto i = cell->vertex_dof_index(v, 0);
            if (!owned.is_element(i) || visited[owned.index_within_set(i)])
              continue;
            visited[owned.index_within_set(i)] = true;
            const double sign     = alpha(i) < 0 ? -1. : 1.;
            const double distance = filter.distance(alpha(i));
            double       measured = distance;
            if (layer(i) <= layers && !points.empty())
              {
                std::vector<unsigned int> nearest;
                tree.query(boost::geometry::index::nearest(cell->vertex(v), 1),
                           std::back_inserter(nearest));
                const auto k = nearest.front();
                measured =
                  sign * std::abs((cell->vertex(v) - points[k]) * normals[k]);
              }
            else if (layer(i) > layers)
              measured =
                sign * std::max(std::abs(distance), layer(i) * h_min);
            result(i) = std::abs(measured - distance) > tolerance ?
                          filter.filter(measured) :
                          alpha(i);
          }
    return ghosted_from_owned(result,
                              level_set.constraints(),
                              level_set.locally_relevant());
  }

  template TrilinosWrappers::MPI::Vector
  redistanced_level_set(const LevelSetField<2> &,
                        const LevelSetFilter &,
                        const unsigned int);
  template TrilinosWrappers::MPI::Vector
  redistanced_level_set(const LevelSetField<3> &,
                        const LevelSetFilter &,
                        const unsigned int);
} // namespace levelsinter
