#pragma once

#include <deal.II/base/bounding_box.h>

#include <levelsinter/analysis/neck.h>
#include <levelsinter/analysis/pores.h>
#include <levelsinter/geometry/power_cells.h>
#include <levelsinter/io/metrics_log.h>
#include <levelsinter/level_set/level_set_field.h>
#include <levelsinter/scene/scene_parameters.h>

#include <array>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace levelsinter
{
  /**
   * The state of a packing, measured every metrics interval: relative
   * density and porosity in a control volume, the closed pores, the neck of
   * every contact (neck_measures::PairNeck), the near misses, the
   * coordination number and the shrinkage
   * (doc/user_guide.md, "Packing metrics", names the columns). Writes
   * necks.csv, pores.csv and pore_events.csv in the output directory (none
   * if the directory is empty), opened at the first measure().
   */
  template <int dim>
  class PackingAnalysis
  {
  public:
    PackingAnalysis(const SceneParameters &scene, const MPI_Comm comm);

    /** The metrics.csv columns of measure(), in its order. */
    std::vector<std::string>
    column_names() const;

    std::vector<double>
    measure(const unsigned int        step,
            const double              t,
            const LevelSetField<dim> &level_set);

    /** The pores and the pair necks of the last measure(). */
    const std::vector<Pore<dim>> &
    pores() const
    {
      return last_pores;
    }

    const std::vector<neck_measures::PairNeck> &
    necks() const
    {
      return pairs;
    }

    /**
     * The state a restart needs (boost archives; the checkpoint's
     * counters): the pore tracking, the shrinkage reference (the spread at
     * the first measure()) and the rows written to the CSV files, which a
     * loaded analysis cuts back to these and continues.
     */
    template <class Archive>
    void
    serialize(Archive &archive, const unsigned int)
    {
      std::array<unsigned int, 3> rows = {
        {necks_log ? necks_log->n_rows() : 0,
         pores_log ? pores_log->n_rows() : 0,
         events_log ? events_log->n_rows() : 0}};
      archive &tracker &initial_spread &rows[0] &rows[1] &rows[2];
      if (Archive::is_loading::value)
        kept_rows = rows;
    }

  private:
    // Solid volume in the window's cells and the solid's centroid in each
    // particle's power cell (the points nearer to it than to any other in
    // |x - c|^2 - r^2).
    struct SolidMeasures
    {
      double                       window_volume = 0;
      double                       window_solid  = 0;
      std::vector<Point<dim>>      centroids;
    };
    SolidMeasures
    measure_solid(const LevelSetField<dim> &level_set) const;

    // necks.csv, pores.csv and pore_events.csv, new or continued after
    // kept_rows.
    void
    open_logs();

    std::vector<std::vector<double>>    particles;
    PowerCells<dim>                     power_cells;
    std::vector<Point<dim>>             centres;
    std::vector<types::boundary_id>     symmetry_boundaries;
    BoundingBox<dim>                    window;
    std::vector<bool>                   interior; // centre inside the window
    std::vector<unsigned int>           shrinkage_axes;
    std::vector<double>                 initial_spread;
    bool                                has_interior = false;
    MPI_Comm                            comm;
    PoreTracker<dim>                    tracker;
    std::string                         directory;
    std::unique_ptr<MetricsLog>         necks_log;
    std::unique_ptr<MetricsLog>         pores_log;
    std::unique_ptr<MetricsLog>         events_log;
    std::optional<std::array<unsigned int, 3>> kept_rows;
    std::vector<Pore<dim>>              last_pores;
    // The contacts and near misses, measured by the last measure().
    std::vector<neck_measures::PairNeck> pairs;
  };
} // namespace levelsinter
