#pragma once

#include <deal.II/base/bounding_box.h>
#include <deal.II/base/point.h>
#include <deal.II/base/types.h>

#include <levelsinter/analysis/postprocessor.h>
#include <levelsinter/level_set/level_set_field.h>
#include <levelsinter/level_set/level_set_filter.h>

#include <string>
#include <vector>

namespace levelsinter
{
  /**
   * The rule for a closed pore below a few cells (issue 27;
   * doc/numerics.md, "A pore below a few cells"). The Q1 velocity cannot
   * carry the radial sink that closes a pore smaller than about a cell, so
   * the discrete pore stalls there. Below the radius @p closure_radius
   * (of the whole pore, i.e. its mirror images across symmetry planes
   * included) the rule shrinks a closed pore at least as fast as the
   * closing law of a small pore in a viscous body with no load,
   * dr/dt = -gamma / (2 eta_s) (a cylindrical pore in 2D, a spherical one
   * in 3D alike), by moving its surface in as that of a round pore would
   * move (end_step()) until its volume is that of the law, and removes it
   * when the law's radius reaches zero. The solid volume this adds (the pore's volume the
   * flow did not remove) is a metrics.csv column, `pore_closure_volume`
   * (cumulative, the part in the box), next to `pores_closed_by_rule`.
   *
   * Call begin_step() with alpha at the start of a step and end_step()
   * after its transport and corrections.
   */
  template <int dim>
  class SmallPoreClosure : public Postprocessor<dim>
  {
  public:
    /** @p closure_radius: in finest cells; @p speed: gamma / (2 eta_s). */
    SmallPoreClosure(const std::vector<types::boundary_id> &symmetry_boundaries,
                     const BoundingBox<dim>                &box,
                     const LevelSetFilter                  &filter,
                     const double                           closure_radius,
                     const double                           speed);

    void
    begin_step(const LevelSetField<dim> &level_set);

    /** Applies the rule over the step of length @p dt; collective. */
    void
    end_step(LevelSetField<dim> &level_set,
             const double        dt,
             const double        h_min);

    std::string
    name() const override
    {
      return "small_pore_closure";
    }

    std::vector<std::string>
    column_names() const override
    {
      return {"pore_closure_volume", "pores_closed_by_rule"};
    }

    std::string
    save() const override;

    void
    load(const std::string &state) override;

  protected:
    std::vector<double>
    measure(const StepRecord<dim> &) override
    {
      return {added_volume, double(removed)};
    }

  private:
    // A closed pore as the rule sees it: the centroid of its part in the
    // box, the whole pore's centre and radius.
    struct Seen
    {
      Point<dim> centroid;
      Point<dim> centre;
      double     radius;
    };

    std::vector<Seen>
    closed_pores(const LevelSetField<dim> &level_set,
                 std::vector<int>         *vertex_pores) const;

    const std::vector<types::boundary_id> symmetry_boundaries;
    const BoundingBox<dim>                box;
    const LevelSetFilter                  filter;
    const double                          closure_radius;
    const double                          speed;
    std::vector<Seen>                     at_start;
    double                                added_volume = 0;
    unsigned int                          removed      = 0;
  };
} // namespace levelsinter
