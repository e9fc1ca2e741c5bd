#pragma once

#include <string>
#include <vector>

namespace levelsinter
{
  /**
   * Random packings of spheres (3D) or discs (2D) for the particle files the
   * scenes read (rows x, y[, z], r as in read_particle_file).
   *
   * Densification: the force-biased algorithm (Moscinski, Bargiel, Rycerz &
   * Jacobs, Mol. Simul. 3 (1989) 201; Bezrukov, Bargiel & Stoyan, Part.
   * Part. Syst. Charact. 19 (2002) 111). Every particle has an outer radius
   * s_out r_i and an inner radius s_in r_i, r_i its sampled radius;
   * s_in is the largest scale at which no two particles overlap (and none
   * crosses a wall), so the inner packing is always valid. Pairs that
   * overlap at the outer scale push each other apart, and s_out shrinks
   * towards s_in at a rate that slows as the two densities approach each
   * other; the packing is done when they meet. The result is scaled so that
   * the particles have their sampled radii: the container is the region
   * given, scaled about its centre (or about its symmetry planes).
   */
  namespace packing
  {
    enum class RadiusDistribution
    {
      constant,
      uniform,
      normal,
      log_normal
    };

    struct Settings
    {
      unsigned int       dim         = 3;
      unsigned int       n_particles = 0;
      RadiusDistribution distribution = RadiusDistribution::constant;
      // Bounds of the radii; equal for a constant radius. Normal and
      // log-normal radii are drawn with this mean and standard deviation
      // (of the radius itself) and redrawn until they fall within the bounds.
      double r_min = 0, r_max = 0, r_mean = 0, r_std = 0;
      // Shape and place of the container before scaling.
      std::vector<double> region_lower, region_upper;
      // The scene's box, if given: the container and the particles (with
      // their images) must fit in it as check_particles_in_domain() wants.
      std::vector<double> domain_lower, domain_upper;
      bool                periodic = false;
      // Faces of the region that are symmetry planes: a particle there meets
      // the mirror images of the others instead of a wall. At most one per
      // axis, and none in a periodic box. symmetry_upper[d] says which face.
      std::vector<bool> symmetry, symmetry_upper;
      // Solid fraction to stop at (an error if the packing jams below it);
      // 0 = as dense as the algorithm gets.
      double target_fraction = 0;
      // Neck x0/R on the contacting pairs; 0 leaves them nearly tangent.
      double neck_ratio = 0;
      // Pairs closer than (r_i + r_j)(1 + contact_gap) are in contact.
      double contact_gap = 1e-3;
      // Interior control volume: the container minus this many largest
      // diameters at each wall.
      double interior_margin = 1;
      // tau of the contraction rule (larger: slower, denser).
      double       contraction     = 1000;
      unsigned int max_iterations  = 200000;
      unsigned long seed           = 1;

      /** Throw std::runtime_error naming the option if something is wrong. */
      void
      check() const;
    };

    struct Result
    {
      // x, y[, z], r: the particles, then the mirror images of those that
      // cross a symmetry plane (all combinations of the planes crossed).
      std::vector<std::vector<double>> particles;
      unsigned int                     n_images = 0;
      std::vector<double>              container_lower, container_upper;
      std::vector<double>              interior_lower, interior_upper;
      unsigned int                     iterations = 0;
      bool                             converged  = false;
      // Sum of the particle volumes over the container volume, before
      // the necks are made (exact).
      double nominal_fraction = 0;
      // Volume of the union of the particles (with necks) over the
      // container and over the interior control volume, sampled on a grid
      // of spacing sample_spacing.
      double fraction = 0, interior_fraction = 0, sample_spacing = 0;
      // Mean number of contacts per particle (images across symmetry planes
      // count, walls do not), over all particles and over those whose
      // centre is in the interior control volume.
      double       coordination = 0, interior_coordination = 0;
      unsigned int n_contacts   = 0;
      // x0/R over the contacting pairs (R = 2 r_i r_j / (r_i + r_j)) after
      // the necks are made, and the largest x0/R of the other pairs that
      // overlap (0 if none).
      double neck_min = 0, neck_mean = 0, neck_max = 0,
             other_overlap_neck_max = 0;
      unsigned int n_other_overlaps = 0;
      // Largest error of a pair distance or wall constraint left by the
      // neck projection, over the smallest radius.
      double neck_residual = 0;
    };

    Result
    generate(const Settings &settings);

    /**
     * x0/R of two spheres (discs) of radii @p r1, @p r2 at centre distance
     * @p distance: the radius of their intersection circle over the
     * equivalent radius 2 r1 r2 / (r1 + r2) (paper Sect. 5.4); 0 if apart.
     */
    double
    neck_ratio(const double distance, const double r1, const double r2);

    /**
     * Settings from "--name value" arguments; see usage(). @p overwrite:
     * whether --overwrite allows replacing an existing output file.
     */
    Settings
    parse_arguments(const std::vector<std::string> &arguments,
                    std::string                     &output_file,
                    bool                            &overwrite);

    std::string
    usage();
  } // namespace packing
} // namespace levelsinter
