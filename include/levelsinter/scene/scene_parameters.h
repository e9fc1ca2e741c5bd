#pragma once

#include <deal.II/base/parameter_handler.h>

#include <levelsinter/scene/analysis_parameters.h>
#include <levelsinter/scene/domain_parameters.h>
#include <levelsinter/scene/geometry_parameters.h>
#include <levelsinter/scene/grain_boundary_parameters.h>
#include <levelsinter/scene/level_set_parameters.h>
#include <levelsinter/scene/materials_parameters.h>
#include <levelsinter/scene/output_parameters.h>
#include <levelsinter/scene/phase_law_parameters.h>
#include <levelsinter/scene/prescribed_velocity_parameters.h>
#include <levelsinter/scene/refinement_parameters.h>
#include <levelsinter/scene/surface_diffusion_parameters.h>
#include <levelsinter/scene/time_parameters.h>
#include <levelsinter/scene/viscous_flow_parameters.h>
#include <levelsinter/scene/volume_correction_parameters.h>
#include <levelsinter/scene/volume_diffusion_parameters.h>

#include <string>
#include <vector>

namespace levelsinter
{
  using namespace dealii;

  /**
   * Everything a scene file says, parsed and checked: one parameter group
   * per section (each declares and parses its own entries), then the
   * values that depend on several sections are resolved, then the rules
   * that span sections are checked. The entries are declared once
   * (declare_parameters()) so that `--print-parameters` and the parser
   * always agree.
   */
  struct SceneParameters
  {
    // The section types under the names the consumers use.
    using Domain           = DomainParameters;
    using Refinement       = RefinementParameters;
    using Velocity         = PrescribedVelocityParameters;
    using SurfaceDiffusion = SurfaceDiffusionParameters;

    static void
    declare_parameters(ParameterHandler &prm);

    /**
     * Read the values out of a parsed handler and check the ones the
     * patterns cannot (vector lengths, orderings, files, rules across
     * sections). Throws std::runtime_error with a message naming the entry.
     * @p scene_directory resolves relative file names. Renamed entries given
     * under their old name are moved to the new one with a warning.
     */
    void
    parse_parameters(ParameterHandler &prm, const std::string &scene_directory);

    /**
     * Edge length of the cells at `Mesh refinement/Maximum level`, the
     * level of the band around the interface (the largest over the axes
     * if the coarse cells are not square). Curvature refinement makes
     * cells finer than this near sharp features.
     */
    double
    band_cell_size() const;

    /**
     * Cells of the mesh at t = 0, estimated from the interface measure:
     * the band of width 2 x Band width at Maximum level, and for each
     * particle the levels curvature refinement adds (Cells per curvature
     * radius over its radius), plus the coarse mesh at Minimum level.
     */
    double
    estimated_initial_cells() const;

    /**
     * Seconds per unit of the scene's time (End time, Time step): 1, or
     * the reduced time scale of the one diffusion mechanism whose section
     * says `Time unit = reduced` (R^4 / C_s, R^3 / (C_v gamma)). A
     * mechanism's coefficient in the scene's time is its coefficient per
     * second times this, so that surface and volume diffusion run in one
     * time when both are on.
     */
    double
    seconds_per_time_unit() const;

    unsigned int dimension = 2;

    DomainParameters             domain;
    GeometryParameters           geometry;
    LevelSetParameters           level_set;
    RefinementParameters         refinement;
    TimeParameters               time;
    MaterialsParameters          materials;
    PrescribedVelocityParameters velocity;
    ViscousFlowParameters        viscous_flow;
    SurfaceDiffusionParameters   surface_diffusion;
    VolumeDiffusionParameters    volume_diffusion;
    VolumeCorrectionParameters   volume_correction;
    OutputParameters             output;
    AnalysisParameters           analysis;
    PhaseLawParameters           phase_law;
    GrainBoundaryParameters      grain_boundaries;

    /** Warnings for the user (deprecated entries, legitimate but unusual
     * choices); the driver prints them before the run. */
    std::vector<std::string> warnings;

  private:
    /** The values that depend on other sections ('automatic' choices, the
     * axis of an axisymmetric scene as a symmetry plane), after every
     * section is parsed. */
    void
    resolve_automatic_values();

    /** The rules that span sections, on the resolved values; unusual but
     * legitimate combinations add a warning. */
    void
    check_across_sections();

    /** The grains' rules (Grain boundaries/Enabled): surface diffusion on,
     * two or more particles, no grain cut by the domain's boundary but by
     * a symmetry plane through its centre. */
    void
    check_grains() const;
  };
} // namespace levelsinter
