#pragma once

#include <levelsinter/mechanics/stokes_assemblers.h>
#include <levelsinter/mechanics/stokes_cell_data.h>
#include <levelsinter/mechanics/two_phase_stokes.h>

#include <memory>
#include <vector>

namespace levelsinter
{
  /**
   * The terms of one assembly of the velocity-pressure operator, chosen
   * once from its settings (TwoPhaseStokes and ExtendedPressureStokes
   * share them): the bulk terms (Eq. 93-94 and ASGS; per phase with the
   * extended pressure), the surface terms (the surface-tension load of the
   * settings' form and, for a positive surface time step, the
   * Laplace-Beltrami term) and the terms on the free box faces (external
   * pressure).
   */
  template <int dim>
  class StokesTerms
  {
  public:
    using Settings = typename TwoPhaseStokes<dim>::Settings;

    /** For @p settings and the surface time step @p surface_time_step of
     * assemble() (0: explicit surface tension). */
    StokesTerms(const Settings &settings, const double surface_time_step);

    /** Set what the cell data gathers for these terms: the surface
     * measure, the free faces and the settings' constants (the rest of
     * @p inputs is the operator's). */
    void
    set_inputs(typename StokesCellData<dim>::Inputs &inputs) const;

    /** Add the bulk terms on the cell (or phase part) @p data holds. */
    void
    assemble_bulk(const StokesCellData<dim> &data,
                  CellContribution          &cell) const;

    /** Add the surface terms and those of the cell's free box faces. */
    void
    assemble_surface(const StokesCellData<dim> &data,
                     CellContribution          &cell) const;

    /** Whether the load is the balanced force gamma kappa_h grad H_h. */
    bool
    balanced_force() const
    {
      return load == Load::balanced_force;
    }

    /** Whether the load reads the nodal curvature (balanced force or the
     * sharp curvature load). */
    bool
    needs_curvature() const
    {
      return load == Load::balanced_force || load == Load::curvature;
    }

  private:
    enum class Load
    {
      none,
      tensorial,
      balanced_force,
      curvature
    };

    const Settings settings;
    const double   implicit_dt;
    const Load     load;
    std::vector<std::unique_ptr<StokesAssembler<dim>>>     bulk;
    std::vector<std::unique_ptr<StokesAssembler<dim>>>     surface;
    std::vector<std::unique_ptr<StokesFaceAssembler<dim>>> faces;
  };
} // namespace levelsinter
