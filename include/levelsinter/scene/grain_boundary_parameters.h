#pragma once

#include <deal.II/base/parameter_handler.h>

#include <vector>

namespace levelsinter
{
  using namespace dealii;

  /**
   * The `Grain boundaries` subsection: each particle is a grain, and
   * grain-boundary diffusion between rigid grains densifies (mechanism
   * GrainBoundaryDiffusion, doc/numerics.md "Grain boundaries and
   * densification").
   */
  struct GrainBoundaryParameters
  {
    static void
    declare(ParameterHandler &prm);

    /** Read and check; throws std::runtime_error naming the entry. */
    void
    parse(ParameterHandler &prm);

    /**
     * sin(psi/2) of the dihedral angle psi, cos(psi/2) = gamma_gb /
     * (2 gamma_s): the share of the surface tension at the triple line
     * that pulls the grains together.
     */
    double
    sin_half_dihedral_angle() const;

    /**
     * pi - psi: the angle the surface's tangent turns through across a
     * triple line at equilibrium (doc/numerics.md, "The dihedral angle at
     * the triple line").
     */
    double
    triple_line_turning() const;

    /**
     * The factor of C_s on grain @p i's surface (Surface diffusion
     * factors; 1 without them).
     */
    double
    surface_factor(const unsigned int i) const;

    /**
     * The factor of C_gb on the grain boundary of grains @p i and @p j:
     * the mean of the grains' Coefficient factors (1 without them). The
     * boundary's layer of width delta_gb lies half in each grain, and the
     * two halves carry the flux along it side by side (doc/numerics.md,
     * "Per-grain materials").
     */
    double
    boundary_factor(const unsigned int i, const unsigned int j) const;

    bool   enabled            = false;
    double energy_ratio       = 0; // gamma_gb / gamma_s, in [0, 2)
    double coefficient        = 0; // C_gb = delta_gb D_gb gamma_s Omega / kT
    double sliding_resistance = 1; // beta
    double deposition_width   = 2; // l in finest cells
    bool   triple_line        = false; // the dihedral angle in surface diffusion
    double kink_width         = 0; // its kink across the plane, finest cells
    bool   conserve_volumes   = false; // planes moved to keep each grain's volume
    bool   implicit_contact   = false; // the contact law implicit in the approach
    bool   sharp_contact      = false; // the law's a at the sharp triple line
    // Per grain (empty: one material): factors of C_s and of C_gb.
    std::vector<double> surface_factors;
    std::vector<double> coefficient_factors;
  };
} // namespace levelsinter
