#pragma once

#include <deal.II/distributed/tria.h>

#include <levelsinter/level_set/level_set_field.h>

#include <boost/signals2/connection.hpp>

#include <vector>

namespace levelsinter
{
  /**
   * The work of a cell, for p4est's partition of the mesh among the ranks.
   * Every cell carries the level set (its transport, reinitialisation,
   * curvature and the analysis); a cell with solid also carries the elastic
   * problem of volume diffusion, which lives on the solid only; a cell the
   * interface cuts also its cut-cell quadrature, ghost-penalty faces and
   * xi. Balancing cells alone lets one rank hold more solid than the other,
   * and the other then waits at each of the solid's solves. The classes
   * are read from alpha before each mesh change (classify()); a mesh
   * change without that (a checkpoint's load) balances cells alone.
   */
  template <int dim>
  class LoadBalance
  {
  public:
    /** The work of a cell of each class, in any common unit. */
    struct Weights
    {
      unsigned int void_cell  = 1;
      unsigned int solid_cell = 1;
      unsigned int cut_cell   = 1;
    };

    /**
     * Weights the partitions of @p tria from now on (the connection ends
     * with this object). All weights equal: p4est's partition by cells,
     * untouched.
     */
    LoadBalance(parallel::distributed::Triangulation<dim> &tria,
                const Weights                             &weights);

    /** Classify the locally owned cells from @p alpha for the next mesh
     *  change. */
    void
    classify(const LevelSetField<dim> &alpha);

    /**
     * The largest rank's share against the mean (1 = balanced) of the
     * locally owned cells, cells with solid, cut cells and weighted work,
     * on the mesh @p alpha lives on. Collective.
     */
    struct Imbalance
    {
      double cells = 1, solid_cells = 1, cut_cells = 1, work = 1;
    };
    Imbalance
    imbalance(const LevelSetField<dim> &alpha) const;

  private:
    enum CellClass : unsigned char
    {
      void_cell,
      solid_cell,
      cut_cell
    };

    /** The class of each locally owned active cell of alpha's mesh. */
    static std::vector<CellClass>
    classes(const LevelSetField<dim> &alpha);

    unsigned int
    weight(const typename Triangulation<dim>::cell_iterator &cell,
           const typename Triangulation<dim>::CellStatus     status) const;

    unsigned int
    weight_of(const CellClass cell_class) const;

    const parallel::distributed::Triangulation<dim> &tria;
    const Weights                                    weights;
    // By active cell index; empty when the mesh changed since classify().
    std::vector<CellClass>             cell_classes;
    boost::signals2::scoped_connection weight_connection;
    boost::signals2::scoped_connection change_connection;
  };
} // namespace levelsinter
