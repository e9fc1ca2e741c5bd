#pragma once

#include <deal.II/base/bounding_box.h>

#include <levelsinter/analysis/neck.h>
#include <levelsinter/analysis/pores.h>
#include <levelsinter/io/metrics_log.h>
#include <levelsinter/level_set/level_set_field.h>
#include <levelsinter/scene/scene_parameters.h>

#include <fstream>
#include <memory>
#include <string>
#include <vector>

namespace levelsinter
{
  /**
   * The state of a packing, measured every metrics interval: relative
   * density and porosity in a control volume, the closed pores, the neck of
   * every overlapping pair, the coordination number and the shrinkage
   * (doc/user_guide.md, "Packing metrics", names the columns). Writes
   * necks.csv, pores.csv and pore_events.csv in the output directory (none
   * if the directory is empty).
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

    const BoundingBox<dim> &
    control_volume() const
    {
      return window;
    }

    /** The pores and the pair necks of the last measure(). */
    const std::vector<Pore<dim>> &
    pores() const
    {
      return last_pores;
    }

    const std::vector<neck_measures::PairNeck> &
    necks() const
    {
      return last_necks;
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

    std::vector<std::vector<double>>    particles;
    std::vector<Point<dim>>             centres;
    std::vector<types::boundary_id>     symmetry_boundaries;
    BoundingBox<dim>                    window;
    std::vector<bool>                   interior; // centre inside the window
    std::vector<unsigned int>           shrinkage_axes;
    std::vector<double>                 initial_spread;
    bool                                has_interior = false;
    MPI_Comm                            comm;
    PoreTracker<dim>                    tracker;
    std::unique_ptr<MetricsLog>         necks_log;
    std::unique_ptr<MetricsLog>         pores_log;
    std::ofstream                       events_log;
    std::vector<Pore<dim>>              last_pores;
    std::vector<neck_measures::PairNeck> last_necks;
  };
} // namespace levelsinter
