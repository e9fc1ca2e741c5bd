#pragma once

#include <deal.II/base/timer.h>

#include <levelsinter/analysis/postprocessor.h>
#include <levelsinter/io/metrics_log.h>
#include <levelsinter/mechanisms/grain_boundary_diffusion.h>

#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace levelsinter
{
  /**
   * The grains of a scene with grain boundaries (GrainBoundaryDiffusion):
   * their number, volumes (mass per grain) and the grain boundaries
   * measured at the accepted centres, the densification (shrinkage of the
   * centres' extent along each axis, the dilatometric relative density of
   * the box the centres span) and, per pair, grain_boundaries.csv in the output
   * directory (doc/user_guide.md, "Grain boundaries" names the columns).
   */
  template <int dim>
  class GrainMeasures : public Postprocessor<dim>
  {
  public:
    GrainMeasures(const GrainBoundaryDiffusion<dim> &grains,
                  const std::string                 &directory,
                  const MPI_Comm                     comm,
                  TimerOutput                       &timer);

    std::string
    name() const override
    {
      return "grains";
    }

    std::vector<std::string>
    column_names() const override;

    /** The grains' volumes at t = 0 and the rows of grain_boundaries.csv. */
    std::string
    save() const override;

    void
    load(const std::string &state) override;

  protected:
    std::vector<double>
    measure(const StepRecord<dim> &record) override;

  private:
    const GrainBoundaryDiffusion<dim> &grains;
    const std::string                  directory;
    const MPI_Comm                     comm;
    TimerOutput                       &timer;
    const std::vector<Point<dim>>      initial_centre;
    // The axes along which the centres spread at t = 0, their extents.
    std::vector<unsigned int>          axes;
    std::vector<double>                initial_extent;
    // The centres span a box with volume (a packing, not a row).
    bool                               box_has_volume = false;
    std::vector<double>                initial_volume;
    // The solid fraction of the box of the centres at t = 0.
    double                             initial_density = 0;
    std::unique_ptr<MetricsLog>        log;
    std::optional<unsigned int>        kept_rows;
  };
} // namespace levelsinter
