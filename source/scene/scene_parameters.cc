#include <deal.II/base/utilities.h>

#include <levelsinter/scene/particles.h>
#include <levelsinter/scene/scene_parameters.h>

#include <cmath>
#include <sstream>
#include <stdexcept>

namespace levelsinter
{
  namespace
  {
    [[noreturn]] void
    fail(const std::string &entry, const std::string &what)
    {
      throw std::runtime_error("entry '" + entry + "': " + what);
    }

    std::vector<double>
    read_coordinates(ParameterHandler  &prm,
                     const std::string &section,
                     const std::string &entry,
                     const unsigned int n)
    {
      const std::string text = prm.get(entry);
      std::vector<double> values;
      try
        {
          values = Utilities::string_to_double(
            Utilities::split_string_list(text, ','));
        }
      catch (...)
        {
          fail(section + "/" + entry,
               "'" + text + "' is not a comma-separated list of numbers");
        }
      if (values.size() != n)
        fail(section + "/" + entry,
             "needs " + std::to_string(n) + " comma-separated numbers (one per "
             "coordinate), got '" + text + "'");
      for (const double v : values)
        if (!std::isfinite(v))
          fail(section + "/" + entry, "contains a non-finite number");
      return values;
    }
  } // namespace

  void
  SceneParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.declare_entry("Dimension",
                      "2",
                      Patterns::Integer(2, 3),
                      "Space dimension of the scene: 2 or 3.");

    prm.enter_subsection("Domain");
    {
      prm.declare_entry("Lower corner",
                        "0, 0",
                        Patterns::Anything(),
                        "Lower corner of the box domain, one coordinate per "
                        "dimension, comma-separated.");
      prm.declare_entry("Upper corner",
                        "1, 1",
                        Patterns::Anything(),
                        "Upper corner of the box domain.");
      prm.declare_entry("Subdivisions",
                        "1, 1",
                        Patterns::List(Patterns::Integer(1), 2, 3, ","),
                        "Number of coarse cells along each axis (level 0 of "
                        "the mesh). Choose them so that coarse cells are "
                        "about cubes.");
    }
    prm.leave_subsection();

    prm.enter_subsection("Geometry");
    {
      prm.declare_entry(
        "Shape",
        "particles",
        Patterns::Selection("particles|slotted disk|perturbed particle"),
        "What the solid is at t = 0: the union of the particles, "
        "Zalesak's slotted disk (2D only; for the transport benchmark), or "
        "the first particle with its radius modulated by one mode "
        "(r = R(1 + delta cos n theta) in 2D, R(1 + delta P_n(cos theta)) "
        "in 3D; the Mullins test of surface diffusion).");
      prm.declare_entry("Perturbation amplitude",
                        "0.05",
                        Patterns::Double(-0.5, 0.5),
                        "delta of the perturbed particle, relative to R "
                        "(either sign).");
      prm.declare_entry("Perturbation mode",
                        "2",
                        Patterns::Integer(0),
                        "n of the perturbed particle.");
      prm.declare_entry(
        "Particles",
        "",
        Patterns::Anything(),
        "Inline particles 'x, y[, z], r' separated by ';', e.g. "
        "'0.3, 0.5, 0.2; 0.7, 0.5, 0.2'. May be combined with a particle "
        "file.");
      prm.declare_entry(
        "Particle file",
        "",
        Patterns::Anything(),
        "CSV file of particles: a header line, then one particle per line "
        "'x,y,r' (2D) or 'x,y,z,r' (3D). Relative paths are relative to the "
        "scene file. Lines starting with '#' are ignored.");
      prm.declare_entry("Slotted disk centre",
                        "0.5, 0.75",
                        Patterns::Anything(),
                        "Centre of Zalesak's disk.");
      prm.declare_entry("Slotted disk radius",
                        "0.15",
                        Patterns::Double(0),
                        "Radius of Zalesak's disk.");
      prm.declare_entry("Slot width",
                        "0.05",
                        Patterns::Double(0),
                        "Width of the slot, centred on the disk's vertical "
                        "axis.");
      prm.declare_entry("Slot depth",
                        "0.25",
                        Patterns::Double(0),
                        "Depth of the slot, measured from the bottom of the "
                        "disk upward.");
    }
    prm.leave_subsection();

    prm.enter_subsection("Level set");
    {
      prm.declare_entry("Filter",
                        "sine",
                        Patterns::Selection("sine|tanh"),
                        "Filter of the signed distance: 'sine' (paper Eq. 65, "
                        "saturates at 2E/pi) or 'tanh' (Eq. 69, E tanh(d/E)).");
      prm.declare_entry(
        "Filter thickness",
        "0.05",
        Patterns::Double(0),
        "Thickness E of the filter (a length). Must be at least the "
        "refinement band width so that the band can be located from alpha.");
      prm.declare_entry("Theta",
                        "0.5",
                        Patterns::Double(0.5, 1),
                        "Time discretisation of the transport term: 0.5 "
                        "Crank-Nicolson, 1 backward Euler.");
      prm.declare_entry(
        "Reinitialization strength",
        "0.25",
        Patterns::Double(0),
        "lambda dt / h_min in Eq. 68: how far the reinitialisation moves "
        "alpha per step in units of the finest cell. The paper uses 1; 0.25 "
        "conserves volume better and is stable (doc/numerics.md); 0 turns "
        "reinitialisation off (pure transport).");
      prm.declare_entry(
        "Reinitialization diffusion",
        "0.05",
        Patterns::Double(0, 1),
        "c in the consistent diffusion nu div(grad alpha - g(alpha) n), "
        "nu = c (h_min / dt) h, added to the reinitialisation. It vanishes "
        "on an exact filtered distance; without it the scheme grows "
        "grid-scale wiggles where the interface is diagonal to the cells "
        "(doc/numerics.md).");
      prm.declare_entry(
        "Reinitialization tolerance",
        "0.25",
        Patterns::Double(0),
        "delta: the reinitialisation (and its diffusion) acts at full "
        "strength where ||grad alpha| - g(alpha)| >= delta and in proportion "
        "to the deviation below it, so that a level set already at its "
        "target is not rebuilt every step. 0 reinitialises everywhere at "
        "full strength, as in the paper (doc/numerics.md).");
      prm.declare_entry(
        "Solid reinitialization from band cells",
        "auto",
        Patterns::Selection("auto|true|false"),
        "true: inside the solid the reinitialisation speed is strength x "
        "h / dt with h the cell size at 'Mesh refinement/Maximum level' "
        "instead of the finest cell, so that with curvature refinement "
        "levels the level set inside a growing neck stays a distance "
        "(surface-diffusion necks; doc/user_guide.md). false: the finest "
        "cell everywhere. auto: true when surface diffusion is enabled and "
        "viscous flow is not (measured better for surface-diffusion necks, "
        "worse for viscous ones). Changes nothing without curvature "
        "refinement levels.");
      prm.declare_entry("Solver tolerance",
                        "1e-10",
                        Patterns::Double(0, 1),
                        "Relative residual reduction of the GMRES solve of "
                        "each transport step.");
      prm.declare_entry("Maximum solver iterations",
                        "1000",
                        Patterns::Integer(1),
                        "GMRES iterations allowed per transport step.");
    }
    prm.leave_subsection();

    prm.enter_subsection("Mesh refinement");
    {
      prm.declare_entry("Minimum level",
                        "0",
                        Patterns::Integer(0, 20),
                        "Refinement level far from the interface (0 = the "
                        "coarse subdivision).");
      prm.declare_entry("Maximum level",
                        "4",
                        Patterns::Integer(0, 20),
                        "Refinement level inside the interface band.");
      prm.declare_entry(
        "Band width",
        "0.05",
        Patterns::Double(0),
        "Cells closer than this distance to the interface are refined to the "
        "maximum level. It must cover the interface motion between two "
        "adaptations: band width >= (adapt interval * CFL + 2) * h_min.");
      prm.declare_entry("Adapt interval",
                        "5",
                        Patterns::Integer(1),
                        "Re-adapt the mesh every this many steps.");
      prm.declare_entry(
        "Curvature refinement levels",
        "0",
        Patterns::Integer(0, 10),
        "Extra levels above the maximum level where the interface is "
        "sharply curved (necks): a band cell is refined further while its "
        "size h and the curvature k = sqrt(k1^2 + k2^2) of the level set "
        "there (|kappa| in 2D) give (Cells per curvature radius) * k * h > 1. "
        "Extra level j is confined to the band width / 2^j. 0 = off.");
      prm.declare_entry(
        "Cells per curvature radius",
        "4",
        Patterns::Double(0.1),
        "With Curvature refinement levels > 0: how many cells a curvature "
        "radius 1/k must span before the refinement stops. A cell is "
        "coarsened again once its parent would span twice as many.");
    }
    prm.leave_subsection();

    prm.enter_subsection("Time");
    {
      prm.declare_entry("End time",
                        "1",
                        Patterns::Double(0),
                        "Simulated time at which the run stops.");
      prm.declare_entry("Time step",
                        "0",
                        Patterns::Double(0),
                        "Fixed time step; 0 lets the CFL number choose it. "
                        "When both are given the smaller step is used.");
      prm.declare_entry("CFL number",
                        "0.5",
                        Patterns::Double(0),
                        "Courant number max|v| dt / h_min; 0 disables the "
                        "CFL limit (then 'Time step' must be set).");
      prm.declare_entry(
        "Relative time step",
        "0",
        Patterns::Double(0),
        "0 = off. When positive (r), the step is max('Time step', r t): "
        "once r t exceeds 'Time step', which is then the first and smallest "
        "step, the steps grow in proportion to the time reached (about "
        "2.3 / r steps per decade of t). For flows whose own time scale is t, "
        "such as an early sintering neck x ~ t^(1/n), which then grows by "
        "the same fraction every step. The CFL number and the mechanisms' "
        "limits still cap the step: set CFL number = 0 where the largest "
        "speed is not the neck's.");
      prm.declare_entry("Maximum steps",
                        "0",
                        Patterns::Integer(0),
                        "Stop after this many steps (0 = no limit).");
    }
    prm.leave_subsection();

    prm.enter_subsection("Velocity");
    {
      prm.declare_entry("Type",
                        "none",
                        Patterns::Selection(
                          "none|constant|rotation|expression"),
                        "Prescribed velocity that transports the level set.");
      prm.declare_entry("Constant",
                        "0, 0",
                        Patterns::Anything(),
                        "Velocity vector for Type = constant.");
      prm.declare_entry("Rotation centre",
                        "0.5, 0.5",
                        Patterns::Anything(),
                        "A point on the rotation axis (Type = rotation).");
      prm.declare_entry("Rotation axis",
                        "0, 0, 1",
                        Patterns::Anything(),
                        "Rotation axis in 3D (normalised internally); "
                        "ignored in 2D.");
      prm.declare_entry("Angular velocity",
                        "6.283185307179586",
                        Patterns::Double(),
                        "Angular velocity in radians per unit time, "
                        "counter-clockwise about the axis.");
      prm.declare_entry("Expression",
                        "0; 0",
                        Patterns::Anything(),
                        "Velocity components separated by ';' as functions "
                        "of x, y[, z] and t (deal.II FunctionParser syntax).");
      prm.declare_entry("Expression constants",
                        "",
                        Patterns::Anything(),
                        "Constants for the expression, e.g. 'U=1, T=2'.");
    }
    prm.leave_subsection();

    ViscousFlowParameters::declare_parameters(prm);
    PhaseLawParameters::declare_parameters(prm);
    prm.enter_subsection("Surface diffusion");
    {
      prm.declare_entry("Enabled",
                        "false",
                        Patterns::Bool(),
                        "Move the interface by surface diffusion, "
                        "v_n = C_s Delta_s kappa (paper Eq. 75), with the "
                        "mixed curvature / surface-Laplacian system (Eq. 82).");
      prm.declare_entry("Coefficient",
                        "0",
                        Patterns::Double(0),
                        "C_s [m^4/s]. 0: computed as D_s delta_s gamma Omega "
                        "/ kT from the five entries below.");
      // The material entries of C_s = D_s delta_s gamma Omega / kT.
      for (const auto &[name, unit] :
           std::vector<std::pair<std::string, std::string>>{
             {"Surface diffusivity", "D_s [m^2/s]."},
             {"Surface layer thickness", "delta_s [m]."},
             {"Surface energy", "gamma_sf [J/m^2]."},
             {"Atomic volume", "Omega [m^3]."},
             {"Thermal energy", "kT [J]."}})
        prm.declare_entry(name, "0", Patterns::Double(0), unit);
      prm.declare_entry("Time unit",
                        "seconds",
                        Patterns::Selection("seconds|reduced"),
                        "Unit of Time/End time and Time/Time step: seconds, "
                        "or the reduced time t* = C_s t / R^4 with R the "
                        "reference radius.");
      prm.declare_entry("Reference radius",
                        "0",
                        Patterns::Double(0),
                        "R of the reduced time t* (needed when Time unit = "
                        "reduced).");
      prm.declare_entry("Coupled",
                        "true",
                        Patterns::Bool(),
                        "true: the mixed kappa / v_s system with the dt "
                        "coupling term (Eq. 80-82), stable for large steps; "
                        "false: kappa then v_s (decoupled, explicit in the "
                        "fourth-order operator, only for comparisons).");
      prm.declare_entry("Solver tolerance",
                        "1e-8",
                        Patterns::Double(0),
                        "Relative residual of the kappa / v_s solve (gmres).");
      prm.declare_entry("Linear solver",
                        "gmres",
                        Patterns::Selection("direct|gmres"),
                        "gmres: FGMRES with a block-triangular preconditioner "
                        "(Schur complement (M + b L) M^-1 (M + b K), CG with "
                        "AMG inside), 20-30 iterations whatever h and dt, "
                        "runs in parallel; direct: KLU (Trilinos Amesos) on "
                        "the coupled system, serial factorisation, for small "
                        "2D checks (doc/numerics.md).");
    }
    prm.leave_subsection();

    prm.enter_subsection("Volume correction");
    {
      prm.declare_entry("Enabled",
                        "false",
                        Patterns::Bool(),
                        "Add to the velocity of the other mechanisms the "
                        "uniform normal speed v^c of Eq. 113-116 that gives "
                        "back, over each step, the solid volume gained or "
                        "lost since t = 0 (by the scheme, the transport and "
                        "the remeshing alike).");
    }
    prm.leave_subsection();

    prm.enter_subsection("Output");
    {
      prm.declare_entry("Directory",
                        "output",
                        Patterns::Anything(),
                        "Directory for fields and metrics.csv; created if "
                        "missing. Relative paths are relative to the current "
                        "working directory.");
      prm.declare_entry("Field interval",
                        "10",
                        Patterns::Integer(0),
                        "Write fields every this many steps (0 = first and "
                        "last step only).");
      prm.declare_entry("Field formats",
                        "vtu, xdmf",
                        Patterns::MultipleSelection("vtu|xdmf|none"),
                        "vtu: PVD/PVTU/VTU series; xdmf: XDMF + HDF5; none.");
      prm.declare_entry("Metrics interval",
                        "1",
                        Patterns::Integer(1),
                        "Append a row to metrics.csv every this many steps "
                        "(the first and last step are always written).");
      prm.declare_entry("Progress interval",
                        "10",
                        Patterns::Integer(0),
                        "Print a progress line every this many steps (0 = "
                        "never).");
    }
    prm.leave_subsection();
  }

  double
  SceneParameters::band_cell_size() const
  {
    double h_coarse = 0;
    for (unsigned int i = 0; i < dimension; ++i)
      h_coarse = std::max(h_coarse,
                          (domain.upper_corner[i] - domain.lower_corner[i]) /
                            domain.subdivisions[i]);
    return h_coarse / std::pow(2.0, refinement.max_level);
  }

  void
  SceneParameters::parse_parameters(ParameterHandler  &prm,
                                    const std::string &scene_directory)
  {
    dimension          = prm.get_integer("Dimension");
    const unsigned int d = dimension;

    prm.enter_subsection("Domain");
    domain.lower_corner = read_coordinates(prm, "Domain", "Lower corner", d);
    domain.upper_corner = read_coordinates(prm, "Domain", "Upper corner", d);
    {
      const auto values = Utilities::string_to_int(
        Utilities::split_string_list(prm.get("Subdivisions"), ','));
      if (values.size() != d)
        fail("Domain/Subdivisions",
             "needs " + std::to_string(d) + " integers, got '" +
               prm.get("Subdivisions") + "'");
      domain.subdivisions.assign(values.begin(), values.end());
    }
    for (unsigned int i = 0; i < d; ++i)
      if (!(domain.lower_corner[i] < domain.upper_corner[i]))
        fail("Domain/Upper corner",
             "each coordinate must be larger than the lower corner's");
    prm.leave_subsection();

    prm.enter_subsection("Geometry");
    geometry.shape = prm.get("Shape");
    geometry.particles =
      parse_inline_particles(prm.get("Particles"), d, "Geometry/Particles");
    geometry.particle_file = prm.get("Particle file");
    if (!geometry.particle_file.empty())
      {
        if (geometry.particle_file.front() != '/' && !scene_directory.empty())
          geometry.particle_file =
            scene_directory + "/" + geometry.particle_file;
        const auto from_file = read_particle_file(geometry.particle_file, d);
        geometry.particles.insert(geometry.particles.end(),
                                  from_file.begin(),
                                  from_file.end());
      }
    if (geometry.shape == "slotted disk")
      geometry.slotted_disk_centre =
        read_coordinates(prm, "Geometry", "Slotted disk centre", 2);
    geometry.slotted_disk_radius = prm.get_double("Slotted disk radius");
    geometry.slot_width          = prm.get_double("Slot width");
    geometry.slot_depth          = prm.get_double("Slot depth");
    geometry.perturbation_amplitude = prm.get_double("Perturbation amplitude");
    geometry.perturbation_mode      = prm.get_integer("Perturbation mode");
    if (geometry.shape == "perturbed particle" && geometry.particles.size() != 1)
      fail("Geometry/Particles",
           "Shape = perturbed particle needs exactly one particle");
    if (geometry.shape == "particles" ||
        geometry.shape == "perturbed particle")
      {
        if (geometry.particles.empty())
          fail("Geometry/Particles",
               "the scene has no particle: give 'Particles' or 'Particle "
               "file'");
        check_particles_in_domain(geometry.particles,
                                  domain.lower_corner,
                                  domain.upper_corner);
      }
    else
      {
        if (d != 2)
          fail("Geometry/Shape", "'slotted disk' exists in 2D only");
        if (geometry.slot_width >= 2 * geometry.slotted_disk_radius ||
            geometry.slot_depth >= 2 * geometry.slotted_disk_radius)
          fail("Geometry/Slot width",
               "slot width and depth must be smaller than the disk diameter");
        check_particles_in_domain({{geometry.slotted_disk_centre[0],
                                    geometry.slotted_disk_centre[1],
                                    geometry.slotted_disk_radius}},
                                  domain.lower_corner,
                                  domain.upper_corner);
      }
    prm.leave_subsection();

    prm.enter_subsection("Level set");
    level_set.filter           = prm.get("Filter");
    level_set.filter_thickness = prm.get_double("Filter thickness");
    level_set.theta            = prm.get_double("Theta");
    level_set.solver_tolerance = prm.get_double("Solver tolerance");
    level_set.max_iterations   = prm.get_integer("Maximum solver iterations");
    level_set.reinitialization_strength =
      prm.get_double("Reinitialization strength");
    level_set.reinitialization_diffusion =
      prm.get_double("Reinitialization diffusion");
    level_set.reinitialization_tolerance =
      prm.get_double("Reinitialization tolerance");
    const std::string solid_reinitialization =
      prm.get("Solid reinitialization from band cells");
    if (level_set.filter_thickness <= 0)
      fail("Level set/Filter thickness", "must be positive");
    prm.leave_subsection();

    prm.enter_subsection("Mesh refinement");
    refinement.min_level      = prm.get_integer("Minimum level");
    refinement.max_level      = prm.get_integer("Maximum level");
    refinement.band_width     = prm.get_double("Band width");
    refinement.adapt_interval = prm.get_integer("Adapt interval");
    refinement.curvature_levels = prm.get_integer("Curvature refinement levels");
    refinement.cells_per_curvature_radius =
      prm.get_double("Cells per curvature radius");
    if (refinement.max_level + refinement.curvature_levels > 20)
      fail("Mesh refinement/Curvature refinement levels",
           "Maximum level + Curvature refinement levels must not exceed 20");
    if (refinement.max_level < refinement.min_level)
      fail("Mesh refinement/Maximum level",
           "must be at least the minimum level (" +
             std::to_string(refinement.min_level) + ")");
    prm.leave_subsection();

    prm.enter_subsection("Time");
    time.end_time  = prm.get_double("End time");
    time.time_step = prm.get_double("Time step");
    time.cfl       = prm.get_double("CFL number");
    time.max_steps = prm.get_integer("Maximum steps");
    time.relative_time_step = prm.get_double("Relative time step");
    if (time.time_step == 0 && time.cfl == 0)
      fail("Time/CFL number",
           "a CFL number or a fixed 'Time step' must be given (both are 0)");
    if (time.relative_time_step > 0 && time.time_step == 0)
      fail("Time/Time step",
           "must be positive with a Relative time step: it is the first "
           "step, taken at t = 0 where r t is 0");
    prm.leave_subsection();

    viscous_flow.parse_parameters(prm, d);
    phase_law.parse_parameters(prm);
    prm.enter_subsection("Surface diffusion");
    surface_diffusion.enabled          = prm.get_bool("Enabled");
    surface_diffusion.coefficient      = prm.get_double("Coefficient");
    surface_diffusion.diffusivity      = prm.get_double("Surface diffusivity");
    surface_diffusion.layer_thickness  = prm.get_double("Surface layer thickness");
    surface_diffusion.surface_energy   = prm.get_double("Surface energy");
    surface_diffusion.atomic_volume    = prm.get_double("Atomic volume");
    surface_diffusion.thermal_energy   = prm.get_double("Thermal energy");
    surface_diffusion.time_unit        = prm.get("Time unit");
    surface_diffusion.reference_radius = prm.get_double("Reference radius");
    surface_diffusion.coupled          = prm.get_bool("Coupled");
    surface_diffusion.solver_tolerance = prm.get_double("Solver tolerance");
    surface_diffusion.linear_solver    = prm.get("Linear solver");
    if (surface_diffusion.enabled)
      {
        if (surface_diffusion.coefficient == 0 &&
            surface_diffusion.thermal_energy == 0)
          fail("Surface diffusion/Coefficient",
               "give C_s or the material entries (Thermal energy is 0)");
        if (!(surface_diffusion.surface_mobility() > 0))
          fail("Surface diffusion/Coefficient",
               "C_s = D_s delta_s gamma Omega / kT must be positive");
        if (surface_diffusion.time_unit == "reduced" &&
            surface_diffusion.reference_radius == 0)
          fail("Surface diffusion/Reference radius",
               "must be positive when Time unit = reduced");
      }
    prm.leave_subsection();
    level_set.solid_reinitialization_from_band =
      solid_reinitialization == "auto" ?
        surface_diffusion.enabled && !viscous_flow.enabled :
        solid_reinitialization == "true";

    prm.enter_subsection("Velocity");
    velocity.type = prm.get("Type");
    // Vectors are read only where the chosen type uses them, so that the
    // 2D defaults do not get in the way of a 3D scene.
    if (velocity.type == "constant")
      velocity.constant = read_coordinates(prm, "Velocity", "Constant", d);
    if (velocity.type == "rotation")
      {
        velocity.rotation_centre =
          read_coordinates(prm, "Velocity", "Rotation centre", d);
        velocity.rotation_axis =
          read_coordinates(prm, "Velocity", "Rotation axis", 3);
      }
    velocity.angular_velocity     = prm.get_double("Angular velocity");
    velocity.expression           = prm.get("Expression");
    velocity.expression_constants = prm.get("Expression constants");
    if (velocity.type == "expression" &&
        Utilities::split_string_list(velocity.expression, ';').size() != d)
      fail("Velocity/Expression",
           "needs " + std::to_string(d) + " components separated by ';'");
    if (velocity.type == "rotation" && d == 3 &&
        std::hypot(velocity.rotation_axis[0],
                   velocity.rotation_axis[1],
                   velocity.rotation_axis[2]) == 0)
      fail("Velocity/Rotation axis", "must not be the zero vector");
    // A mechanism that computes a velocity (viscous flow, surface
    // diffusion) lets the CFL number or its own limit choose the step.
    if (velocity.type == "none" && time.time_step == 0 &&
        !viscous_flow.enabled && !surface_diffusion.enabled)
      {
        prm.leave_subsection();
        fail("Time/Time step",
             "with Velocity/Type = none and no mechanism giving a velocity "
             "the CFL number cannot choose a step: "
             "set a positive 'Time step'");
      }
    prm.leave_subsection();

    // Checks across sections. The band is located by reading distances back
    // through the filter, which saturates at E; and between two adaptations
    // the interface moves up to adapt_interval * CFL finest cells, which the
    // band must still hold (plus one cell for the cut cell itself).
    // Curvature refinement keeps this sufficient: extra level j lives in a
    // band of width band_width / 2^j, which holds (adapt_interval * CFL + 1)
    // of its own cells whenever this check passes, and the CFL step then
    // uses the smaller h_min.
    // At E itself every saturated node reads as "in the band", which
    // refines the whole box: on an adaptive mesh the band must stay below E.
    if (refinement.band_width > level_set.filter_thickness ||
        (refinement.band_width == level_set.filter_thickness &&
         refinement.min_level < refinement.max_level))
      fail("Mesh refinement/Band width",
           "must be smaller than Level set/Filter thickness (" +
             std::to_string(level_set.filter_thickness) +
             "): from E on the filtered level set carries no distance");
    {
      const double needed =
        (refinement.adapt_interval * time.cfl + 1) * band_cell_size();
      if (time.cfl > 0 && refinement.band_width < needed)
        fail("Mesh refinement/Band width",
             "is " + std::to_string(refinement.band_width) +
               " but must be at least (adapt interval * CFL + 1) * h_min = " +
               std::to_string(needed) +
               " so that the interface cannot leave the refined band "
               "between two adaptations");
    }

    prm.enter_subsection("Volume correction");
    volume_correction = prm.get_bool("Enabled");
    prm.leave_subsection();

    prm.enter_subsection("Output");
    output.directory         = prm.get("Directory");
    output.field_interval    = prm.get_integer("Field interval");
    const std::string formats = prm.get("Field formats");
    output.write_vtu  = formats.find("vtu") != std::string::npos;
    output.write_xdmf = formats.find("xdmf") != std::string::npos;
    if (formats.find("none") != std::string::npos &&
        (output.write_vtu || output.write_xdmf))
      fail("Output/Field formats", "'none' cannot be combined with a format");
    output.metrics_interval  = prm.get_integer("Metrics interval");
    output.progress_interval = prm.get_integer("Progress interval");
    if (output.directory.empty())
      fail("Output/Directory", "must not be empty");
    prm.leave_subsection();
  }

  double
  SceneParameters::SurfaceDiffusion::surface_mobility() const
  {
    if (coefficient > 0)
      return coefficient;
    return diffusivity * layer_thickness * surface_energy * atomic_volume /
           thermal_energy;
  }
} // namespace levelsinter
