#pragma once

#include <deal.II/lac/vector.h>

#include <deal.II/numerics/data_out.h>

#include <levelsinter/geometry/power_cells.h>
#include <levelsinter/level_set/level_set_field.h>

#include <vector>

namespace levelsinter
{
  /**
   * The output field particle_id: per cell, the index (from 0, in the order
   * of the scene's list, as in necks.csv) of the particle whose power cell
   * of the initial centres holds the cell's centre, the same assignment as
   * the packing analysis' centroids; -1 on cells with no solid (alpha > 0
   * at every vertex). A cell field, so that ParaView shows each grain in
   * one colour rather than ids blended between vertices.
   */
  template <int dim>
  class ParticleIdField
  {
  public:
    /** Rows (x, y[, z], r) as the scene parameters hold them. */
    explicit ParticleIdField(const std::vector<std::vector<double>> &particles);

    /**
     * Computes the ids on the current mesh and adds them to @p data_out
     * (the level set's DoFHandler attached); the values live in this object
     * until the next call.
     */
    void
    add_to(const LevelSetField<dim> &level_set, DataOut<dim> &data_out);

  private:
    PowerCells<dim>       power_cells;
    dealii::Vector<float> ids;
  };
} // namespace levelsinter
