#include <levelsinter/analysis/grain_measures.h>
#include <levelsinter/analysis/neck.h>
#include <levelsinter/analysis/scene_postprocessors.h>
#include <levelsinter/level_set/interface_measures.h>

#include <boost/archive/text_iarchive.hpp>
#include <boost/archive/text_oarchive.hpp>

#include <cmath>
#include <limits>
#include <sstream>

namespace levelsinter
{
  namespace
  {
    // A postprocessor's checkpoint state as text (boost text archive).
    template <class T>
    std::string
    to_text(const T &object)
    {
      std::ostringstream            out;
      boost::archive::text_oarchive archive(out);
      archive << object;
      return out.str();
    }

    template <class T>
    void
    from_text(const std::string &text, T &object)
    {
      std::istringstream            in(text);
      boost::archive::text_iarchive archive(in);
      archive >> object;
    }
  } // namespace

  template <int dim>
  RunMeasures<dim>::RunMeasures(const bool curvature_driven)
    : curvature_driven(curvature_driven)
  {}

  template <int dim>
  std::vector<std::string>
  RunMeasures<dim>::column_names() const
  {
    std::vector<std::string> columns = {"step",
                                        "time",
                                        "dt",
                                        "cells",
                                        "dofs",
                                        "solid_volume",
                                        "volume_change",
                                        "interface_area",
                                        "max_velocity",
                                        "transport_iterations",
                                        "wall_time"};
    if (curvature_driven)
      columns.emplace_back("under_resolved_curvature_cells");
    return columns;
  }

  template <int dim>
  std::vector<double>
  RunMeasures<dim>::measure(const StepRecord<dim> &record)
  {
    const auto &alpha    = record.level_set;
    const auto  measures = interface_measures::volume_and_area(alpha);
    if (record.step == 0)
      initial_solid_volume = measures.solid_volume;
    std::vector<double> values = {
      double(record.step),
      record.time,
      record.dt,
      double(alpha.dof_handler().get_triangulation().n_global_active_cells()),
      double(alpha.dof_handler().n_dofs()),
      measures.solid_volume,
      (measures.solid_volume - initial_solid_volume) / initial_solid_volume,
      measures.interface_area,
      record.velocity.max_norm(),
      double(record.transport_iterations),
      record.wall_time};
    if (curvature_driven)
      values.push_back(record.under_resolved_curvature_cells);
    return values;
  }

  template <int dim>
  std::string
  RunMeasures<dim>::save() const
  {
    return to_text(initial_solid_volume);
  }

  template <int dim>
  void
  RunMeasures<dim>::load(const std::string &state)
  {
    from_text(state, initial_solid_volume);
  }

  template <int dim>
  PackingMeasures<dim>::PackingMeasures(const SceneParameters &scene,
                                        const MPI_Comm         comm,
                                        TimerOutput           &timer)
    : analysis(scene, comm)
    , timer(timer)
  {}

  template <int dim>
  std::vector<std::string>
  PackingMeasures<dim>::column_names() const
  {
    return analysis.column_names();
  }

  template <int dim>
  std::vector<double>
  PackingMeasures<dim>::measure(const StepRecord<dim> &record)
  {
    TimerOutput::Scope scope(timer, "packing analysis");
    return analysis.measure(record.step, record.time, record.level_set);
  }

  template <int dim>
  std::string
  PackingMeasures<dim>::save() const
  {
    return to_text(analysis);
  }

  template <int dim>
  void
  PackingMeasures<dim>::load(const std::string &state)
  {
    from_text(state, analysis);
  }

  template <int dim>
  NeckMeasures<dim>::NeckMeasures(
    const std::vector<std::vector<double>> &particles,
    PackingMeasures<dim>                   *packing)
    : particles(particles)
    , packing(packing)
    , equal_pair(particles.size() == 2 && particles[0][dim] == particles[1][dim])
  {}

  template <int dim>
  std::vector<std::string>
  NeckMeasures<dim>::column_names() const
  {
    if (has_neck == 0)
      return {};
    if (equal_pair)
      return {"neck_radius", "neck_curvature"};
    return {"neck_radius"};
  }

  template <int dim>
  std::vector<double>
  NeckMeasures<dim>::measure(const StepRecord<dim> &record)
  {
    // In a packing the smallest neck over the pairs that overlap at t = 0:
    // the packing analysis' necks (the same pairs).
    double neck;
    if (packing)
      {
        packing->values(record);
        neck = neck_measures::smallest_neck_radius(packing->necks());
      }
    else
      neck = neck_measures::smallest_neck_radius(record.level_set, particles);
    if (has_neck < 0)
      has_neck = std::isnan(neck) ? 0 : 1;
    if (has_neck == 0)
      return {};
    if (!equal_pair)
      return {neck};
    // An equal pair: the curvature of its neck (from a fit over a few
    // finest cells) and the point one finest cell inside the interface
    // where the mechanisms' fields are read: on the interface the Q1
    // fields mix the particle's nodes with the atmosphere's.
    Point<dim> c1, c2;
    for (unsigned int d = 0; d < dim; ++d)
      {
        c1[d] = particles[0][d];
        c2[d] = particles[1][d];
      }
    const auto shape =
      neck_measures::neck_shape(record.level_set, c1, c2, record.h_min);
    neck_inner_point = shape.inner_point;
    return {neck, shape.curvature};
  }

  template <int dim>
  std::string
  NeckMeasures<dim>::save() const
  {
    return to_text(has_neck);
  }

  template <int dim>
  void
  NeckMeasures<dim>::load(const std::string &state)
  {
    from_text(state, has_neck);
  }

  template <int dim>
  MechanismMeasures<dim>::MechanismMeasures(
    const std::vector<std::unique_ptr<Mechanism<dim>>> &mechanisms,
    NeckMeasures<dim>                                   *neck)
    : mechanisms(mechanisms)
    , neck(neck)
  {}

  template <int dim>
  std::vector<std::string>
  MechanismMeasures<dim>::column_names() const
  {
    std::vector<std::string> columns;
    for (const auto &mechanism : mechanisms)
      for (const auto &name : mechanism->metric_names())
        columns.push_back(name);
    if (neck && neck->has_shape())
      for (const auto &mechanism : mechanisms)
        for (const auto &name : mechanism->point_metric_names())
          columns.push_back("neck_" + name);
    return columns;
  }

  template <int dim>
  std::vector<double>
  MechanismMeasures<dim>::measure(const StepRecord<dim> &record)
  {
    std::vector<double> values;
    for (const auto &mechanism : mechanisms)
      for (const double value : mechanism->metric_values())
        values.push_back(value);
    if (neck && neck->has_shape())
      {
        // The viscoelastic seed's Figs. 8, 11, 13: fields at the neck.
        neck->values(record);
        for (const auto &mechanism : mechanisms)
          for (const double value :
               mechanism->point_metric_values(record.level_set,
                                              *neck->inner_point()))
            values.push_back(value);
      }
    return values;
  }

  template <int dim>
  CentreMeasures<dim>::CentreMeasures(const SceneParameters &scene,
                                      PackingMeasures<dim>  &packing,
                                      const MPI_Comm         comm,
                                      TimerOutput           &timer)
    : centres(scene.geometry.particles, scene.domain, comm)
    , packing(packing)
    , timer(timer)
  {}

  template <int dim>
  std::vector<std::string>
  CentreMeasures<dim>::column_names() const
  {
    return centres.column_names();
  }

  template <int dim>
  std::vector<double>
  CentreMeasures<dim>::measure(const StepRecord<dim> &record)
  {
    packing.values(record);
    TimerOutput::Scope scope(timer, "packing analysis");
    return centres.measure(record.level_set, packing.necks());
  }

  template <int dim>
  std::string
  CentreMeasures<dim>::save() const
  {
    return to_text(centres);
  }

  template <int dim>
  void
  CentreMeasures<dim>::load(const std::string &state)
  {
    from_text(state, centres);
  }

  template <int dim>
  std::vector<std::unique_ptr<Postprocessor<dim>>>
  make_scene_postprocessors(
    const SceneParameters                              &scene,
    const std::vector<std::unique_ptr<Mechanism<dim>>> &mechanisms,
    const bool                                          curvature_driven,
    const MPI_Comm                                      comm,
    TimerOutput                                        &timer)
  {
    const auto &particles = scene.geometry.particles;
    const bool  bodies =
      scene.geometry.particles_are_bodies() && particles.size() >= 2;
    std::unique_ptr<PackingMeasures<dim>> packing;
    if (scene.analysis.enabled(scene.geometry.shape, particles.size()))
      packing = std::make_unique<PackingMeasures<dim>>(scene, comm, timer);
    std::unique_ptr<NeckMeasures<dim>> neck;
    if (bodies)
      neck = std::make_unique<NeckMeasures<dim>>(particles, packing.get());
    std::unique_ptr<CentreMeasures<dim>> centres;
    if (packing && bodies)
      centres =
        std::make_unique<CentreMeasures<dim>>(scene, *packing, comm, timer);
    auto on_mechanisms =
      std::make_unique<MechanismMeasures<dim>>(mechanisms, neck.get());

    std::vector<std::unique_ptr<Postprocessor<dim>>> list;
    list.push_back(std::make_unique<RunMeasures<dim>>(curvature_driven));
    if (neck)
      list.push_back(std::move(neck));
    list.push_back(std::move(on_mechanisms));
    if (packing)
      list.push_back(std::move(packing));
    if (centres)
      list.push_back(std::move(centres));
    // The grains of a scene with grain boundaries, measured at the
    // mechanism's centres.
    for (const auto &mechanism : mechanisms)
      if (const auto *grains =
            dynamic_cast<const GrainBoundaryDiffusion<dim> *>(mechanism.get()))
        list.push_back(std::make_unique<GrainMeasures<dim>>(
          *grains, scene.output.directory, comm, timer));
    return list;
  }

  template class RunMeasures<2>;
  template class RunMeasures<3>;
  template class PackingMeasures<2>;
  template class PackingMeasures<3>;
  template class NeckMeasures<2>;
  template class NeckMeasures<3>;
  template class MechanismMeasures<2>;
  template class MechanismMeasures<3>;
  template class CentreMeasures<2>;
  template class CentreMeasures<3>;
  template std::vector<std::unique_ptr<Postprocessor<2>>>
  make_scene_postprocessors(const SceneParameters &,
                            const std::vector<std::unique_ptr<Mechanism<2>>> &,
                            const bool,
                            const MPI_Comm,
                            TimerOutput &);
  template std::vector<std::unique_ptr<Postprocessor<3>>>
  make_scene_postprocessors(const SceneParameters &,
                            const std::vector<std::unique_ptr<Mechanism<3>>> &,
                            const bool,
                            const MPI_Comm,
                            TimerOutput &);
} // namespace levelsinter
