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

    /** The neck between particles i and j (indices into the particle list). */
    struct PairNeck
    {
      unsigned int i      = 0;
      unsigned int j      = 0;
      double       radius = 0;
    };

    /**
     * The necks of all pairs of particles (x, y[, z], r) that overlap, or of
     * the pair if there are exactly two: neck_radius() for equal radii,
     * narrowest_neck() otherwise, in the order of the pairs (i, j). A pair
     * whose neck has pinched off (the point between the centres lies in
     * the pore) has radius 0. All pairs share one RayCaster, and the
     * searches advance together: about 20 reductions over the ranks in
     * all, whatever the number of pairs.
     */
    template <int dim>
    std::vector<PairNeck>
    pair_necks(const LevelSetField<dim>               &level_set,
               const std::vector<std::vector<double>> &particles);

    /**
     * The smallest of the pair_necks(); NaN without a pair.
     */
    template <int dim>
    double
    smallest_neck_radius(const LevelSetField<dim>               &level_set,
                         const std::vector<std::vector<double>> &particles);

    /** The smallest of @p necks (pair_necks() measured already); NaN if empty. */
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
