#include <levelsinter/scene/parameter_entries.h>
#include <levelsinter/scene/renamed_entries.h>
#include <levelsinter/scene/particles.h>
#include <levelsinter/scene/scene_parameters.h>

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>

namespace levelsinter
{
  namespace
  {
    // Every entry that moved, old path -> new path.
    const std::vector<RenamedEntry> renamed_entries = {
      {"Viscous flow/Symmetry planes", "Domain/Symmetry planes"},
      {"Viscous flow/Solver", "Viscous flow/Linear solver"},
      {"Level set/Reinitialization strength",
       "Level set/Reinitialisation strength"},
      {"Level set/Reinitialization diffusion",
       "Level set/Reinitialisation diffusion"},
      {"Level set/Reinitialization tolerance",
       "Level set/Reinitialisation tolerance"},
      {"Level set/Solid reinitialization from band cells",
       "Level set/Solid reinitialisation from band cells"},
      // Volume diffusion needs them with viscous flow off.
      {"Viscous flow/Surface tension", "Materials/Surface tension"},
      {"Viscous flow/Fluid viscosity", "Materials/Fluid viscosity"},
      {"Viscous flow/Fluid compressibility",
       "Materials/Fluid compressibility"}};

    // Memory per cell, measured with viscous flow (the largest footprint
    // of the mechanisms) as the growth of the peak resident memory between
    // two Maximum levels over the growth of the cells: two_cylinders_2d,
    // levels 8 -> 10: 6.8 kB; two_spheres_3d, levels 5 -> 6: 20.7 kB.
    double
    bytes_per_cell(const unsigned int dim)
    {
      return dim == 2 ? 6.8e3 : 2.07e4;
    }

    double
    physical_memory()
    {
      return double(sysconf(_SC_PHYS_PAGES)) * double(sysconf(_SC_PAGE_SIZE));
    }

    // Measure of a sphere's surface (a circle's perimeter in 2D).
    double
    sphere_measure(const double r, const unsigned int dim)
    {
      return dim == 2 ? 2 * M_PI * r : 4 * M_PI * r * r;
    }
  } // namespace

  void
  SceneParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.declare_entry("Dimension",
                      "2",
                      Patterns::Integer(2, 3),
                      "Space dimension of the scene: 2 or 3.");
    DomainParameters::declare(prm);
    GeometryParameters::declare(prm);
    LevelSetParameters::declare(prm);
    RefinementParameters::declare(prm);
    TimeParameters::declare(prm);
    MaterialsParameters::declare(prm);
    PrescribedVelocityParameters::declare(prm);
    ViscousFlowParameters::declare(prm);
    SurfaceDiffusionParameters::declare(prm);
    VolumeDiffusionParameters::declare(prm);
    VolumeCorrectionParameters::declare(prm);
    OutputParameters::declare(prm);
    AnalysisParameters::declare(prm);
    PhaseLawParameters::declare(prm);
    GrainBoundaryParameters::declare(prm);
    declare_renamed_entries(prm, renamed_entries);
  }

  double
  SceneParameters::band_cell_size() const
  {
    return domain.coarse_cell_size() / std::pow(2.0, refinement.max_level);
  }

  double
  SceneParameters::estimated_initial_cells() const
  {
    const unsigned int d = dimension;
    double coarse = std::pow(2.0, d * refinement.min_level);
    for (const unsigned int n : domain.subdivisions)
      coarse *= n;
    // A band of half-width w around a surface of measure S holds about
    // S x 2w / h^d cells of size h (at least the one layer the interface
    // cuts on each side).
    const auto band_cells = [&](const double measure, const double w,
                                const double h) {
      return measure * std::max(2 * w, 2 * h) / std::pow(h, d);
    };
    const double h_band = band_cell_size();
    if (geometry.shape == GeometryParameters::Shape::slotted_disk)
      return coarse +
             band_cells(sphere_measure(geometry.slotted_disk_radius, d) +
                          2 * geometry.slot_depth,
                        refinement.band_width,
                        h_band);
    double cells = coarse;
    for (const auto &p : geometry.particles)
      {
        const double r = p[d];
        // The share of the particle inside the box (mirrored particles lie
        // partly or wholly outside), from its extent along each axis.
        double inside = 1;
        for (unsigned int k = 0; k < d; ++k)
          inside *= std::clamp((std::min(p[k] + r, domain.upper_corner[k]) -
                                std::max(p[k] - r, domain.lower_corner[k])) /
                                 (2 * r),
                               0.,
                               1.);
        // Level j (j <= Curvature refinement levels) holds cells of size
        // h_band / 2^j in the band / 2^j while C h / r > 1.
        for (unsigned int j = 0; j <= refinement.curvature_levels; ++j)
          {
            const double h = h_band / std::pow(2.0, j);
            cells += band_cells(inside * sphere_measure(r, d),
                                refinement.band_width / std::pow(2.0, j),
                                h);
            if (refinement.cells_per_curvature_radius * h / r <= 1)
              break;
          }
      }
    return cells;
  }

  double
  SceneParameters::seconds_per_time_unit() const
  {
    const auto &sd = surface_diffusion;
    const auto &vd = volume_diffusion;
    if (sd.enabled && sd.time_unit == SurfaceDiffusion::TimeUnit::reduced)
      return sd.reduced_time_scale(sd.reference_radius);
    if (vd.enabled &&
        vd.time_unit == VolumeDiffusionParameters::TimeUnit::reduced)
      return vd.reduced_time_scale(vd.reference_radius,
                                   materials.surface_tension);
    return 1;
  }

  void
  SceneParameters::parse_parameters(ParameterHandler  &prm,
                                    const std::string &scene_directory)
  {
    const auto used = move_renamed_entries(prm, renamed_entries);
    for (const auto &r : used)
      warnings.push_back(deprecation_warning(r));
    try
      {
        dimension = prm.get_integer("Dimension");
        domain.parse(prm, dimension);
        geometry.parse(prm, dimension, scene_directory, domain);
        level_set.parse(prm);
        refinement.parse(prm);
        time.parse(prm);
        materials.parse(prm);
        velocity.parse(prm, dimension);
        viscous_flow.parse(prm);
        surface_diffusion.parse(prm);
        volume_diffusion.parse(prm);
        volume_correction.parse(prm);
        output.parse(prm);
        analysis.parse(prm, dimension);
        phase_law.parse(prm);
        grain_boundaries.parse(prm);
        resolve_automatic_values();
        check_across_sections();
      }
    catch (const std::runtime_error &e)
      {
        // An error about an entry given under its old name names that too.
        std::string message = e.what();
        for (const auto &r : used)
          if (message.find("'" + r.new_path + "'") != std::string::npos)
            message += " (given as '" + r.old_path + "', deprecated)";
        throw std::runtime_error(message);
      }
  }

  void
  SceneParameters::resolve_automatic_values()
  {
    level_set.solid_reinitialization_from_band =
      level_set.solid_reinitialization ==
          LevelSetParameters::SolidReinitialization::automatic ?
        surface_diffusion.enabled && !viscous_flow.enabled :
        level_set.solid_reinitialization ==
          LevelSetParameters::SolidReinitialization::band_cells;

    // The tensorial surface-tension forms drain the solid through the
    // interface (the ASGS stabilisation acts on the Laplace jump); by
    // default the volume correction gives the area back.
    using Form = ViscousFlowParameters::SurfaceTensionForm;
    volume_correction.enabled =
      volume_correction.choice ==
          VolumeCorrectionParameters::Choice::automatic ?
        viscous_flow.enabled && materials.surface_tension != 0 &&
          viscous_flow.surface_tension_form != Form::csf_curvature :
        volume_correction.choice == VolumeCorrectionParameters::Choice::on;

    // The axis of an axisymmetric scene is a mirror of the half plane:
    // v_r = 0 there, and the refinement and the rigid modes treat it as a
    // symmetry plane.
    auto &planes = domain.symmetry_planes;
    if (geometry.axisymmetric &&
        std::find(planes.begin(), planes.end(), 0) == planes.end())
      planes.insert(planes.begin(), 0);
  }

  void
  SceneParameters::check_across_sections()
  {
    const unsigned int d = dimension;

    // A mechanism that computes a velocity (viscous flow, surface
    // diffusion) lets the CFL number or its own limit choose the step.
    const bool moving = velocity.type !=
                          PrescribedVelocityParameters::Type::none ||
                        viscous_flow.enabled || surface_diffusion.enabled ||
                        volume_diffusion.enabled;
    if (!moving && time.time_step == 0)
      fail_entry("Time/Time step",
                 "with Velocity/Type = none and no mechanism giving a "
                 "velocity the CFL number cannot choose a step: set a "
                 "positive 'Time step'");
    // A step longer than the run is cut to the run; said, because the
    // run's result depends on it.
    const double duration = time.end_time - time.start_time;
    if (duration > 0 && time.time_step > duration)
      {
        std::ostringstream what;
        what << "'Time/Time step' = " << time.time_step
             << " is longer than the run (End time - Start time = "
             << duration << "): the steps are at most " << duration;
        warnings.push_back(what.str());
      }

    // Volume diffusion moves the interface with -C_v (grad p . n) n of the
    // elastic solid's pressure (Algorithm 3): the particles do not flow.
    if (volume_diffusion.enabled)
      {
        if (viscous_flow.enabled)
          fail_entry("Volume diffusion/Enabled",
                     "cannot be combined with 'Viscous flow/Enabled = "
                     "true': volume diffusion solves the elastic-solid "
                     "problem itself and moves the interface by diffusion "
                     "only");
        if (phase_law.law != PhaseLawParameters::Law::elastic_solid)
          fail_entry("Phase law/Law",
                     "must be 'elastic-solid' with volume diffusion: the "
                     "pressure that drives it is that of the elastic "
                     "particles (paper Eq. 92-94)");
        if (!(materials.surface_tension > 0))
          fail_entry("Materials/Surface tension",
                     "must be positive with volume diffusion: it is the "
                     "surface energy gamma that loads the elastic solid");
        if (!(materials.fluid_viscosity > 0))
          fail_entry("Materials/Fluid viscosity",
                     "must be positive with volume diffusion: the "
                     "atmosphere around the elastic solid is a fluid");
        // The explicit step limit was measured with xi read 6 cells deep;
        // nearer the interface the continuous pressure still oscillates,
        // and the limit and the rate are far off. A sharp pressure (solid
        // or extended space) read by the recovered gradient keeps the rate
        // at 3 cells, but not the step (both measured on the perturbed
        // cylinder, doc/validation.md).
        if (volume_diffusion.interior_offset < 6 &&
            !volume_diffusion.boundary_flux)
          {
            using Space = ViscousFlowParameters::PressureSpace;
            const bool sharp_recovered =
              viscous_flow.pressure_space != Space::continuous &&
              volume_diffusion.recovered_gradient;
            std::ostringstream what;
            what << "'Volume diffusion/Interior offset' = "
                 << volume_diffusion.interior_offset
                 << " cells is below 6, where the step limit of volume "
                    "diffusion was measured: ";
            if (sharp_recovered)
              what << "with this pressure space and the recovered gradient "
                      "a perturbed cylinder's mode decays within 2.1 % of "
                      "the exact rate at 3 cells (R/h = 16-64), but the "
                      "stable step is 15-45 times shorter than at 6 cells; "
                      "the step is held by the CFL number, not by the "
                      "volume-diffusion limit (doc/validation.md, \"Volume "
                      "diffusion: xi as the boundary flux\" and \"Sharp "
                      "interfaces: a recovered gradient for xi\")";
            else
              what << "on a perturbed cylinder the stable step is 10-180 "
                      "times shorter at 3-5 cells, and at 3 cells the mode "
                      "decays 18-62 % too fast; expect one-step speed "
                      "spikes, which the CFL number answers with shorter "
                      "steps (doc/validation.md, \"Volume diffusion: "
                      "explicit stability limit\")";
            warnings.push_back(what.str());
          }
        // Surface and volume diffusion together (Eq. 118, Algorithm 4) run
        // in one time: seconds, or the one reduced time a section names.
        if (surface_diffusion.enabled &&
            surface_diffusion.time_unit ==
              SurfaceDiffusion::TimeUnit::reduced &&
            volume_diffusion.time_unit ==
              VolumeDiffusionParameters::TimeUnit::reduced)
          fail_entry("Volume diffusion/Time unit",
                     "cannot be 'reduced' when 'Surface diffusion/Time "
                     "unit' is too: a scene has one time, t* = C_s t / "
                     "R^4 or C_v gamma t / R^3; set one of the two to "
                     "seconds (its coefficient is then converted to the "
                     "other's t*)");
      }

    if (viscous_flow.enabled)
      {
        // The particles move with the Stokes velocity: a phase law with
        // history (the elastic solid of volume diffusion) has none.
        if (phase_law.law == PhaseLawParameters::Law::elastic_solid)
          fail_entry("Phase law/Law",
                     "'elastic-solid' cannot be used with viscous flow, "
                     "which moves the particles with their Newtonian (or "
                     "viscoelastic) velocity: use 'newtonian', or volume "
                     "diffusion for elastic particles");
        if (!(materials.fluid_viscosity > 0))
          fail_entry("Materials/Fluid viscosity",
                     "must be positive when viscous flow is enabled");
        // Without surface tension and external pressure nothing drives the
        // flow: the right-hand side is zero, the solver returns at once and
        // the run would only repeat t = 0.
        if (materials.surface_tension == 0 &&
            viscous_flow.external_pressure == 0)
          fail_entry("Materials/Surface tension",
                     "must be positive when viscous flow is enabled and "
                     "'Viscous flow/External pressure' is 0: nothing else "
                     "drives the flow");
        // The flow's time is the seconds of its viscosities and surface
        // tension.
        if (surface_diffusion.enabled &&
            surface_diffusion.time_unit == SurfaceDiffusion::TimeUnit::reduced)
          fail_entry("Surface diffusion/Time unit",
                     "cannot be 'reduced' with viscous flow: the flow runs "
                     "in the seconds of its viscosity and surface tension; "
                     "set 'seconds'");
        if (surface_diffusion.enabled)
          warnings.push_back(
            "viscous flow and surface diffusion are both enabled: the "
            "interface moves with the sum of the Stokes velocity and the "
            "surface-diffusion velocity C_s (Laplace-Beltrami of kappa) n, "
            "each computed as if alone (doc/user_guide.md, \"Combining "
            "mechanisms\")");
      }

    // An axisymmetric scene has the hoop terms in the viscous-flow forms
    // and the 2 pi r measure everywhere; the mechanisms without them are
    // refused rather than run as planar.
    if (geometry.axisymmetric)
      {
        if (volume_diffusion.enabled)
          fail_entry("Volume diffusion/Enabled",
                     "is not available with 'Geometry/Axisymmetric = true' "
                     "yet; run the scene in 3D");
        if (phase_law.law == PhaseLawParameters::Law::elastic_solid)
          fail_entry("Phase law/Law",
                     "'elastic-solid' is not available with "
                     "'Geometry/Axisymmetric = true' yet (it serves volume "
                     "diffusion, which is not axisymmetric); run the scene "
                     "in 3D");
      }

    // A viscoelastic melt flows: its polymer stress is part of the viscous
    // flow problem.
    if (phase_law.is_viscoelastic() && !viscous_flow.enabled)
      fail_entry("Phase law/Law",
                 "a viscoelastic law (giesekus, xpp) needs 'Viscous "
                 "flow/Enabled = true': the melt's polymer stress enters "
                 "the viscous flow problem");

    // The extended pressure integrates each phase on its side of the
    // interface; a melt's polymer stress lives on the level set's element,
    // which its cut-cell quadrature does not evaluate yet.
    if (phase_law.is_viscoelastic() &&
        viscous_flow.pressure_space ==
          ViscousFlowParameters::PressureSpace::extended)
      fail_entry("Viscous flow/Pressure space",
                 "'extended' is not available with a viscoelastic law "
                 "(giesekus, xpp) yet; use 'continuous'");

    // The band is located by reading distances back through the filter,
    // which saturates at E; at E itself every saturated node reads as "in
    // the band", which refines the whole box, so on an adaptive mesh the
    // band must stay below E. Between two adaptations the interface moves
    // up to adapt_interval * CFL band cells, which the band must still hold
    // (plus one cell for the cut cell itself). Curvature refinement keeps
    // this sufficient: extra level j lives in a band of width
    // band_width / 2^j, which holds (adapt_interval * CFL + 1) of its own
    // cells whenever this check passes, and the CFL step then uses the
    // smaller h_min.
    const double needed =
      (refinement.adapt_interval * time.cfl + 1) * band_cell_size();
    if (refinement.band_width > level_set.filter_thickness ||
        (refinement.band_width == level_set.filter_thickness &&
         refinement.min_level < refinement.max_level) ||
        (time.cfl > 0 && refinement.band_width < needed))
      {
        std::ostringstream message;
        message << "is " << refinement.band_width << ", but "
                << RefinementParameters::band_width_rule
                << ": here it must be smaller than "
                << level_set.filter_thickness;
        if (time.cfl > 0)
          message << " and at least " << needed;
        fail_entry("Mesh refinement/Band width", message.str());
      }

    // A particle needs a few cells across its radius: the Q1 interpolant
    // of the level set loses the shape below that (doc/user_guide.md,
    // "Particle size"). Curvature refinement resolves small particles
    // itself (it refines while C h / r > 1), up to its finest level.
    const double h_band   = band_cell_size();
    const double h_finest = h_band / std::pow(2.0, refinement.curvature_levels);
    constexpr double min_cells_per_radius = 2;
    if (geometry.shape != GeometryParameters::Shape::slotted_disk)
      for (unsigned int i = 0; i < geometry.particles.size(); ++i)
        {
          const double r = geometry.particles[i][d];
          if (r >= min_cells_per_radius * h_band)
            continue;
          const unsigned int resolving_level = std::ceil(
            std::log2(min_cells_per_radius * domain.coarse_cell_size() / r));
          std::ostringstream what;
          what << "particle " << i + 1 << " (radius " << r << ") spans "
               << r / h_band << " cells of the band (cell size " << h_band
               << " at Maximum level " << refinement.max_level
               << "); a radius needs at least " << min_cells_per_radius
               << " cells: Maximum level " << resolving_level
               << " would resolve it";
          if (r < min_cells_per_radius * h_finest)
            fail_entry("Mesh refinement/Maximum level", what.str());
          warnings.push_back(what.str() +
                             "; the curvature refinement levels resolve it "
                             "near its interface only");
        }

    // Particles inside others or closer than a band cell (particles.h).
    check_particle_pairs(geometry.particles,
                         geometry.particle_origins,
                         h_band);

    if (grain_boundaries.enabled)
      check_grains();
    // Surface diffusion's band rule (doc/numerics.md, "Filter thickness
    // against the step"): with the refined band narrower than the mixed
    // system's band (|d| < 0.8 E) the surface loses solid, the volume
    // correction returns it as a uniform speed, and the neck-root
    // curvature the contact law reads is biased: the rigid grains drift
    // apart (doc/validation.md, "Settling the pair: the refined band").
    if (grain_boundaries.enabled &&
        refinement.band_width < 0.8 * level_set.filter_thickness)
      {
        std::ostringstream what;
        what << "Mesh refinement/Band width is " << refinement.band_width
             << ", less than 0.8 x Level set/Filter thickness = "
             << 0.8 * level_set.filter_thickness
             << ": surface diffusion then loses solid, and the grains' "
             << "contact law reads a biased neck curvature; measured on "
             << "the ring of twelve grains at R/h = 16 (doc/validation.md): "
             << "the rigid grains' spacing grows from 6 % to 12.5 % above "
             << "the equilibrium's over t in [0.005, 0.02], and stays at "
             << "4.8-5.6 % with the band at 0.8 E. Widen the band";
        warnings.push_back(what.str());
      }

    // Refuse a mesh that cannot fit in memory before anything is written.
    const double cells  = estimated_initial_cells();
    const double bytes  = cells * bytes_per_cell(d);
    const double memory = physical_memory();
    if (memory > 0 && bytes > memory)
      {
        std::ostringstream what;
        what.precision(3);
        what << "Maximum level " << refinement.max_level << " with "
             << refinement.curvature_levels
             << " curvature refinement levels would give a mesh of about "
             << cells << " cells at t = 0, about " << bytes / 1e9
             << " GB at the measured " << bytes_per_cell(d)
             << " bytes per cell, more than the " << memory / 1e9
             << " GB of memory of this machine; lower the level or the "
             << "band width";
        fail_entry("Mesh refinement/Maximum level", what.str());
      }
  }

  void
  SceneParameters::check_grains() const
  {
    const std::string entry = "Grain boundaries/Enabled";
    if (!surface_diffusion.enabled)
      fail_entry(entry,
                 "needs 'Surface diffusion/Enabled = true': surface "
                 "diffusion spreads the matter the grain boundaries "
                 "deposit at the necks and gives the neck curvature");
    if (viscous_flow.enabled)
      fail_entry(entry,
                 "cannot be combined with 'Viscous flow/Enabled = true' "
                 "(grains are crystalline solids, viscous flow is for "
                 "amorphous particles)");
    if (!geometry.particles_are_bodies() || geometry.particles.size() < 2)
      fail_entry(entry,
                 "needs two or more particles in Geometry/Particles (each "
                 "particle is a grain)");
    // Per-grain materials: a factor for every grain, or none.
    for (const auto &[name, factors] :
         {std::make_pair("Surface diffusion factors",
                         &grain_boundaries.surface_factors),
          std::make_pair("Coefficient factors",
                         &grain_boundaries.coefficient_factors)})
      if (!factors->empty() && factors->size() != geometry.particles.size())
        fail_entry(std::string("Grain boundaries/") + name,
                   "gives " + std::to_string(factors->size()) +
                     " factors for " +
                     std::to_string(geometry.particles.size()) +
                     " grains: give one per particle, or none (one "
                     "material)");
    // A grain boundary on the domain's boundary is not measured: a grain
    // lies on a symmetry plane through its centre or off the planes.
    for (unsigned int i = 0; i < geometry.particles.size(); ++i)
      {
        const auto  &p = geometry.particles[i];
        const double r = p[dimension];
        for (unsigned int k = 0; k < dimension; ++k)
          {
            const double tolerance =
              1e-9 * (domain.upper_corner[k] - domain.lower_corner[k]);
            const bool on_lower =
              std::abs(p[k] - domain.lower_corner[k]) <= tolerance;
            const bool on_upper =
              std::abs(p[k] - domain.upper_corner[k]) <= tolerance;
            const auto is_plane = [&](const types::boundary_id id) {
              return std::find(domain.symmetry_planes.begin(),
                               domain.symmetry_planes.end(),
                               id) != domain.symmetry_planes.end();
            };
            const bool inside = p[k] - r >= domain.lower_corner[k] - tolerance &&
                                p[k] + r <= domain.upper_corner[k] + tolerance;
            if (!inside && !(on_lower && is_plane(2 * k)) &&
                !(on_upper && is_plane(2 * k + 1)))
              {
                std::ostringstream what;
                what << "particle " << i + 1 << " crosses the domain's "
                     << "boundary along axis " << "xyz"[k]
                     << ": with grain boundaries every grain lies inside "
                     << "the domain or is cut in half by a symmetry plane "
                     << "through its centre (mirrored grains off their "
                     << "centre are not supported yet)";
                fail_entry(entry, what.str());
              }
          }
      }
  }
} // namespace levelsinter
