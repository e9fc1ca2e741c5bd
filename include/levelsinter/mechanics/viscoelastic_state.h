#pragma once

#include <deal.II/base/point.h>
#include <deal.II/base/symmetric_tensor.h>

#include <deal.II/fe/fe_values.h>

#include <deal.II/lac/trilinos_vector.h>

#include <deal.II/numerics/data_out.h>

#include <levelsinter/level_set/level_set_field.h>
#include <levelsinter/level_set/level_set_filter.h>
#include <levelsinter/level_set/state_transfer.h>
#include <levelsinter/level_set/velocity_field.h>
#include <levelsinter/mechanics/conformation_field.h>
#include <levelsinter/mechanics/conformation_model.h>
#include <levelsinter/scene/phase_law_parameters.h>

#include <array>
#include <memory>
#include <string>
#include <vector>

namespace levelsinter
{
  /** The conformation model of a viscoelastic 'Phase law'. */
  ConformationModel::Parameters
  conformation_parameters(const PhaseLawParameters &law);

  /**
   * The polymer state of a viscoelastic melt (the viscoelastic seed,
   * Eq. 4-7): its conformation field on the level set's DoFs, kept across
   * steps (advance() from the committed state, accept() commits) and mesh
   * adaptation (add_state()); the polymer stress ViscoelasticPhases reads
   * (stress_values()); and what it shows of c, under names that start with
   * `viscoelastic_`: tr c and the principal stretches as fields, the
   * conformation solves' iterations and the largest tr c as metrics, tr c
   * at a pair's neck.
   */
  template <int dim>
  class ViscoelasticState
  {
  public:
    /**
     * @p interface_half_width: E of the Stokes phases in band cells
     * (`Viscous flow/Interface half-width`), @p band_level: the refinement
     * level of the interface band; together they say where the flow
     * stretches c (advance()).
     */
    ViscoelasticState(const PhaseLawParameters &law,
                      const LevelSetFilter     &filter,
                      const double              interface_half_width,
                      const unsigned int        band_level);

    /** The mesh changed (or t = 0): size the field for the level set's
     * DoFs; its values come back through add_state(). */
    void
    setup(const LevelSetField<dim> &alpha);

    /** Advance c over the step with the scene's velocity so far; held
     * until accept(). */
    void
    advance(const LevelSetField<dim> &alpha,
            const VelocityField<dim> &velocity,
            const double              dt);

    /** The last advance() becomes the state (no-op if none is pending);
     * c relaxes to I beyond the filtered band in the atmosphere, which
     * carries no polymer; tr c and the stretches are measured on it. */
    void
    accept(const LevelSetField<dim> &alpha);

    /** The last advance() is dropped: c stays the committed state. */
    void
    reject()
    {
      pending = false;
    }

    /** The committed c travels across mesh adaptation. */
    void
    add_state(StateTransfer<dim> &transfer);

    /** tau = G (c - I) at the points of @p level_set_values (the level
     * set's FEValues, reinit on the cell), see
     * ConformationField::stress_values(). */
    void
    stress_values(const FEValues<dim>                  &level_set_values,
                  std::vector<SymmetricTensor<2, dim>> &stress,
                  std::vector<double>                  &hoop_stress) const;

    std::vector<std::string>
    metric_names() const;

    std::vector<double>
    metric_values() const;

    std::vector<std::string>
    point_metric_names() const;

    /** tr c at @p point (3, c = I, before the first accepted step). */
    std::vector<double>
    point_metric_values(const LevelSetField<dim> &alpha,
                        const Point<dim>         &point) const;

    void
    add_output_fields(const LevelSetField<dim> &alpha,
                      DataOut<dim>             &data_out) const;

  private:
    /** Where the flow stretches c (ConformationField::advance()): 1 in
     * the melt, fading to 0 over the atmosphere's side of the transition
     * zone. */
    TrilinosWrappers::MPI::Vector
    stretch_weight(const LevelSetField<dim> &alpha) const;

    const ConformationModel                 model;
    const LevelSetFilter                    filter;
    const double                            interface_half_width;
    const unsigned int                      band_level;
    std::unique_ptr<ConformationField<dim>> field;
    // Cell size at the band level.
    double       h_band     = 0;
    bool         pending    = false;
    unsigned int iterations = 0;
    // tr c at the nodes for the output and its maximum; the principal
    // stretches sqrt(eigenvalues of c), largest first.
    TrilinosWrappers::MPI::Vector                trace_c;
    std::array<TrilinosWrappers::MPI::Vector, 3> stretches;
    double                                       max_trace_c = 3;
  };
} // namespace levelsinter
