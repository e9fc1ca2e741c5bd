#pragma once

#include <deal.II/base/parameter_handler.h>

namespace levelsinter
{
  using namespace dealii;

  /** The `Viscous flow` subsection of a scene: Newtonian particles flowing
   * under their own surface tension (ViscousFlow mechanism); the surface
   * tension and the atmosphere are MaterialsParameters. */
  struct ViscousFlowParameters
  {
    enum class SurfaceTensionForm
    {
      csf,
      sharp,
      csf_curvature,
      sharp_curvature
    };

    enum class LinearSolver
    {
      iterative,
      direct
    };

    /** How the pressure sees the interface (doc/numerics.md, "Sharp
     * interfaces"). */
    enum class PressureSpace
    {
      continuous, // one Q1 pressure across the smeared interface
      extended,   // one Q1 pressure per phase, cut at {alpha_h = 0}
      solid       // (v, p) on the cells with solid only, the atmosphere a
                  // void (the elastic problem of volume diffusion)
    };

    static void
    declare(ParameterHandler &prm);

    /** Read and check what needs only this section; throws
     * std::runtime_error naming the entry. */
    void
    parse(ParameterHandler &prm);

    bool        enabled               = false;
    double      solid_viscosity       = 1;
    SurfaceTensionForm surface_tension_form = SurfaceTensionForm::sharp;
    bool        semi_implicit_surface_tension = false;
    double      interface_half_width  = 1.5; // in cell sizes h_K
    double      stabilisation_constant = 0.1;
    double      external_pressure      = 0;
    LinearSolver linear_solver              = LinearSolver::iterative;
    double       solver_tolerance           = 1e-10;
    unsigned int max_iterations             = 500;
    bool         smoothed_aggregation       = true;
    double       capillary_time_step_factor = 1;
    PressureSpace pressure_space            = PressureSpace::continuous;
    double        ghost_penalty             = 0.1;
    double        pore_closure_radius       = 0; // in h_min; 0: no rule
  };
} // namespace levelsinter
