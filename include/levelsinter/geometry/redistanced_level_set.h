#pragma once

#include <deal.II/lac/trilinos_vector.h>

#include <levelsinter/level_set/level_set_field.h>
#include <levelsinter/level_set/level_set_filter.h>

namespace levelsinter
{
  using namespace dealii;

  /**
   * The level set with its values replaced where they are not the
   * (filtered) distance to the discrete interface alpha_h = 0; a ghosted
   * vector on the level set's DoFs. The balanced surface-tension force
   * (csf-curvature) reads every level set of its transition zone, H_h and
   * the curvature's normals, not only the zero one, and so needs this.
   *
   * Why: where a neck fills, the transport carries the small |alpha| of
   * the neck's surface into the merged body along the neck plane, a ridge
   * of alpha ~ -h where the depth is many cells (doc/numerics.md,
   * "The level set the form reads"). On a symmetry plane or a grid line the
   * ridge's slopes in the cells on either side are those of a distance,
   * so the convective reinitialisation does not see it; the sharp form
   * does not either (it reads alpha_h = 0 only), but the smoothed
   * Heaviside does: H_h < 1 deep inside the body, with the curvature of
   * the ridge's level sets (-100 to -240 where the body's is 6).
   *
   * Nodes are counted in cell layers from the cut cells (a sign change of
   * alpha among the cell's vertices; layer 0 their vertices, layer k the
   * vertices of the cells touching layer k - 1). The interface lies in the
   * cut cells and each layer adds a cell of edge at least h_min, so a node
   * of layer k is at least k h_min from the interface (hanging nodes
   * aside, whose values are constrained).
   * - Up to @p layers layers, the node's distance is measured: the
   *   distance to the tangent line (plane) of the nearest of the
   *   interface's quadrature points (4 Gauss points per direction on the
   *   Q1 zero level set of each cut cell, gathered from all ranks), signed
   *   as alpha. Where it differs from filter^-1(alpha) by more than
   *   h_min / 4, alpha is replaced by its filter.
   * - Beyond, a node closer than k h_min (less h_min / 4) by its alpha is
   *   moved out to filter(k h_min).
   * A level set that is a distance to within a quarter cell is returned
   * unchanged (the plane static bubble over time: C and the area error
   * the same to all printed digits). Hanging nodes take the constrained
   * values. Cost: one gather of the interface points and one R-tree query
   * per node within the layers.
   */
  template <int dim>
  TrilinosWrappers::MPI::Vector
  redistanced_level_set(const LevelSetField<dim> &level_set,
                        const LevelSetFilter     &filter,
                        const unsigned int        layers);
} // namespace levelsinter
