#pragma once

#include <deal.II/base/timer.h>

#include <levelsinter/analysis/packing_analysis.h>
#include <levelsinter/analysis/particle_centres.h>
#include <levelsinter/analysis/postprocessor.h>
#include <levelsinter/mechanisms/mechanism.h>
#include <levelsinter/scene/scene_parameters.h>

#include <memory>
#include <optional>
#include <vector>

namespace levelsinter
{
  /**
   * The columns every run writes: step, time, dt, mesh size, the solid's
   * volume (and its change since t = 0) and interface area from the sharp
   * cut-cell measures, the largest interface velocity, the transport's
   * iterations, the wall time, and with curvature-driven mechanisms the
   * count of under-resolved interface cells.
   */
  template <int dim>
  class RunMeasures : public Postprocessor<dim>
  {
  public:
    explicit RunMeasures(const bool curvature_driven);

    std::string
    name() const override
    {
      return "run";
    }

    std::vector<std::string>
    column_names() const override;

    std::string
    save() const override;

    void
    load(const std::string &state) override;

  protected:
    std::vector<double>
    measure(const StepRecord<dim> &record) override;

  private:
    const bool curvature_driven;
    // The solid volume at step 0, the reference of volume_change.
    double initial_solid_volume = 0;
  };

  /**
   * The packing analysis (PackingAnalysis): density, pores, the necks of
   * all pairs, coordination, shrinkage.
   */
  template <int dim>
  class PackingMeasures : public Postprocessor<dim>
  {
  public:
    PackingMeasures(const SceneParameters &scene,
                    const MPI_Comm         comm,
                    TimerOutput           &timer);

    std::string
    name() const override
    {
      return "packing analysis";
    }

    std::vector<std::string>
    column_names() const override;

    std::string
    save() const override;

    void
    load(const std::string &state) override;

    /** The pair necks of the last values(). */
    const std::vector<neck_measures::PairNeck> &
    necks() const
    {
      return analysis.necks();
    }

  protected:
    std::vector<double>
    measure(const StepRecord<dim> &record) override;

  private:
    PackingAnalysis<dim> analysis;
    TimerOutput         &timer;
  };

  /**
   * The neck of a run of particle bodies: neck_radius, the smallest neck
   * over the pairs (the packing analysis' pairs where it runs); for an
   * equal pair also neck_curvature and the point one finest cell inside
   * the neck where the mechanisms' fields are read (MechanismMeasures).
   */
  template <int dim>
  class NeckMeasures : public Postprocessor<dim>
  {
  public:
    NeckMeasures(const std::vector<std::vector<double>> &particles,
                 PackingMeasures<dim>                   *packing);

    std::string
    name() const override
    {
      return "neck";
    }

    std::vector<std::string>
    column_names() const override;

    /** Where an equal pair's neck is read, after values(); else empty. */
    const std::optional<Point<dim>> &
    inner_point() const
    {
      return neck_inner_point;
    }

    /** True for an equal pair: its neck shape is measured. */
    bool
    has_shape() const
    {
      return equal_pair;
    }

    std::string
    save() const override;

    void
    load(const std::string &state) override;

  protected:
    std::vector<double>
    measure(const StepRecord<dim> &record) override;

  private:
    const std::vector<std::vector<double>> particles;
    PackingMeasures<dim>                  *packing;
    const bool                             equal_pair;
    // Set by the first measure() (-1 before): a packing without overlapping
    // pairs at t = 0 has no neck column.
    int                       has_neck = -1;
    std::optional<Point<dim>> neck_inner_point;
  };

  /**
   * Each mechanism's metrics (Mechanism::metric_names()), then its fields
   * read at an equal pair's neck (columns neck_ + name).
   */
  template <int dim>
  class MechanismMeasures : public Postprocessor<dim>
  {
  public:
    MechanismMeasures(
      const std::vector<std::unique_ptr<Mechanism<dim>>> &mechanisms,
      NeckMeasures<dim>                                   *neck);

    std::string
    name() const override
    {
      return "mechanisms";
    }

    std::vector<std::string>
    column_names() const override;

  protected:
    std::vector<double>
    measure(const StepRecord<dim> &record) override;

  private:
    const std::vector<std::unique_ptr<Mechanism<dim>>> &mechanisms;
    NeckMeasures<dim>                                   *neck;
  };

  /** Densification: the approach of the particle centres (ParticleCentres). */
  template <int dim>
  class CentreMeasures : public Postprocessor<dim>
  {
  public:
    CentreMeasures(const SceneParameters &scene,
                   PackingMeasures<dim>  &packing,
                   const MPI_Comm         comm,
                   TimerOutput           &timer);

    std::string
    name() const override
    {
      return "particle centres";
    }

    std::vector<std::string>
    column_names() const override;

    std::string
    save() const override;

    void
    load(const std::string &state) override;

  protected:
    std::vector<double>
    measure(const StepRecord<dim> &record) override;

  private:
    ParticleCentres<dim>  centres;
    PackingMeasures<dim> &packing;
    TimerOutput          &timer;
  };

  /**
   * The postprocessors of a scene in the order of their metrics.csv
   * columns: run, neck (bodies of two or more particles), mechanisms,
   * packing analysis and particle centres (where the analysis is on,
   * doc/user_guide.md "Packing metrics").
   */
  template <int dim>
  std::vector<std::unique_ptr<Postprocessor<dim>>>
  make_scene_postprocessors(
    const SceneParameters                              &scene,
    const std::vector<std::unique_ptr<Mechanism<dim>>> &mechanisms,
    const bool                                          curvature_driven,
    const MPI_Comm                                      comm,
    TimerOutput                                        &timer);
} // namespace levelsinter
