#pragma once

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/types.h>

#include <string>
#include <vector>

namespace levelsinter
{
  using namespace dealii;

  /** The `Viscous flow` subsection of a scene: Newtonian particles flowing
   * under their own surface tension (ViscousFlow mechanism). */
  struct ViscousFlowParameters
  {
    static void
    declare_parameters(ParameterHandler &prm);

    /** Read and check; throws std::runtime_error naming the entry. */
    void
    parse_parameters(ParameterHandler &prm, const unsigned int dimension);

    bool        enabled               = false;
    double      surface_tension       = 1;
    double      solid_viscosity       = 1;
    double      fluid_viscosity       = 1e-3;
    double      fluid_compressibility = 1;
    std::string surface_tension_form; // csf, sharp or csf-curvature
    bool        semi_implicit_surface_tension = false;
    double      interface_half_width  = 1.5; // in cell sizes h_K
    double      stabilisation_constant = 0.1;
    double      external_pressure      = 0;
    std::vector<types::boundary_id> symmetry_boundaries;
    bool                            direct_solver     = false;
    double                          solver_tolerance  = 1e-10;
    unsigned int                    max_iterations    = 500;
    double                          capillary_time_step_factor = 1;
  };
} // namespace levelsinter
