#pragma once

#include <deal.II/base/point.h>

#include <levelsinter/level_set/level_set_field.h>

#include <vector>

namespace levelsinter
{
  /** Necks between particles, measured on the discrete zero level set. */
  namespace neck_measures
  {
    /**
     * Neck radius between two particles centred at c1 and c2: the distance
     * from the midpoint to the interface across the plane through the
     * midpoint normal to c2 - c1, averaged over rays in that plane (2 rays in
     * 2D, i.e. the half-width; 8 in 3D). Rays that leave the domain before
     * meeting the interface (symmetry planes) are skipped. Zero when the
     * midpoint lies outside the solid. For equal particles the mid-plane is
     * the plane of the neck by symmetry.
     */
    template <int dim>
    double
    neck_radius(const LevelSetField<dim> &level_set,
                const Point<dim>         &c1,
                const Point<dim>         &c2);

    /** Where the neck of an equal pair meets the interface, and its shape. */
    template <int dim>
    struct NeckShape
    {
      // On the mid-plane, on the first of neck_radius()'s rays that meets
      // the interface (the mid-point if none does, or if it lies in the
      // pore), and on that ray one @p spacing inside the solid (at most
      // half-way to the mid-point).
      Point<dim> point;
      Point<dim> inner_point;
      // The viscoelastic seed's neck curvature kappa = 1/R1 + 1/R2 (Eq.
      // 45-47), in its sign: -div n, positive where the neck is concave;
      // the hoop term 1/R2 about the line of centres in 3D only.
      double curvature = 0;
    };

    /**
     * The neck of two equal particles centred at c1 and c2 (on the
     * mid-plane): its point on the interface and its curvature, from a
     * parabola fitted to the cross-section radii at 7 planes @p spacing
     * apart along the line of centres (a few finest cells: closer planes
     * see the Q1 interface's kinks).
     */
    template <int dim>
    NeckShape<dim>
    neck_shape(const LevelSetField<dim> &level_set,
               const Point<dim>         &c1,
               const Point<dim>         &c2,
               const double              spacing);

    /**
     * A pair of particles i < j (indices into the particle list) whose neck
     * is measured. A contact is a pair whose balls overlap or touch at
     * t = 0 (a gap of at most 1e-3 (r_i + r_j), the contact gap of
     * levelsinter-pack, whose jammed packings leave their contacts that
     * close), or the pair of a two-particle scene whatever its gap. A near
     * miss is a pair with a larger gap at t = 0, but below a given
     * distance (a cell): the mesh may join it or not, so it is reported
     * apart from the contacts.
     */
    struct PairNeck
    {
      unsigned int i       = 0;
      unsigned int j       = 0;
      bool         contact = true;
      double       radius  = 0;
      // Near misses: the gap along the line of the initial centres, between
      // the points where the rays from each centre towards the other leave
      // the solid; 0 once the level set joins the pair. NaN for contacts.
      double gap = 0;
    };

    /**
     * The contacts and the near misses (gap below @p near_miss_gap at
     * t = 0) among @p particles (x, y[, z], r), in the order of the pairs
     * (i, j), not yet measured.
     */
    std::vector<PairNeck>
    neighbour_pairs(const std::vector<std::vector<double>> &particles,
                    const double                            near_miss_gap);

    /**
     * Measures @p pairs of @p particles: neck_radius() for equal radii,
     * narrowest_neck() otherwise, and the gap of the near misses. A pair
     * whose neck has pinched off or never formed (the point between the
     * centres lies in the pore) has radius 0. All pairs share one
     * RayCaster, and the searches advance together: about 20 reductions
     * over the ranks in all, whatever the number of pairs.
     */
    template <int dim>
    void
    measure_necks(const LevelSetField<dim>               &level_set,
                  const std::vector<std::vector<double>> &particles,
                  std::vector<PairNeck>                  &pairs);

    /**
     * The smallest neck radius of the contacts of @p particles (the
     * metrics' neck_radius); NaN without a contact.
     */
    template <int dim>
    double
    smallest_neck_radius(const LevelSetField<dim>               &level_set,
                         const std::vector<std::vector<double>> &particles);

    /** The smallest radius of the contacts among @p necks; NaN if none. */
    double
    smallest_neck_radius(const std::vector<PairNeck> &necks);

    /**
     * The neck of unequal particles is not on the mid-plane: it is the
     * narrowest cross-section between the centres.
     */
    struct Neck
    {
      double radius   = 0;   // measured as in neck_radius()
      double position = 0.5; // s on c1 + s (c2 - c1)
    };

    template <int dim>
    Neck
    narrowest_neck(const LevelSetField<dim> &level_set,
                   const Point<dim>         &c1,
                   const Point<dim>         &c2);

  } // namespace neck_measures
} // namespace levelsinter
