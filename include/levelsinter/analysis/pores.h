#pragma once

#include <deal.II/base/bounding_box.h>
#include <deal.II/base/point.h>
#include <deal.II/base/types.h>

#include <levelsinter/level_set/level_set_field.h>

#include <boost/serialization/vector.hpp>

#include <string>
#include <vector>

namespace levelsinter
{
  /** One connected component of the atmosphere {alpha_h > 0}. */
  template <int dim>
  struct Pore
  {
    double     volume = 0; // area in 2D
    double     area   = 0; // against the solid (length in 2D); no box faces
    double     volume_in_window = 0; // the part in the window's cells
    Point<dim> centroid;
    // Touches a box face that is not a symmetry plane.
    bool open = false;
    // The box faces it touches, symmetry planes included (bit b: the face
    // of colorized boundary id b): volume and area are those of the part
    // in the box. Not serialised: the tracker does not use it.
    unsigned int box_faces = 0;

    /**
     * 36 pi V^2 / S^3 in 3D, 4 pi A / P^2 in 2D: 1 for a ball. A closed
     * pore cut by k symmetry planes is measured as the whole pore their
     * mirrors make (2^k times its volume and area in the box, so the
     * ratio divided by 2^k). NaN for an open pore, and for one that
     * touches both planes of one axis (its mirrors never close): the box
     * faces are not part of a surface, so the ratio would describe no
     * shape.
     */
    double
    sphericity() const;

    /** Radius of the ball of the same volume. */
    double
    equivalent_radius() const;

    template <class Archive>
    void
    serialize(Archive &archive, const unsigned int)
    {
      archive &volume &area &volume_in_window &centroid &open;
    }
  };

  /**
   * The connected components of the atmosphere of the Q1 level set, on all
   * ranks (the same list on each, sorted by centroid: the order does not
   * depend on the partition).
   *
   * Connectivity follows the Q1 zero level set: two mesh vertices with
   * alpha > 0 are connected if they share a cell edge (alpha_h is linear
   * along it, so the whole edge is atmosphere), or are diagonal on a cell
   * face whose other two vertices are solid and whose bilinear saddle value
   * is positive (the asymptotic decider, alpha_0 alpha_3 > alpha_1
   * alpha_2): exactly the connectivity of {alpha_h > 0} on the cell faces.
   * Hanging faces are consistent since their values are interpolated. Not
   * resolved: a tunnel through the interior of a trilinear cell whose faces
   * do not connect (3D only, a sub-cell feature). Every component of
   * {alpha_h > 0} in a cell holds a vertex (a multilinear function has no
   * interior maximum), so no pore is missed.
   *
   * Volume and centroid come from cut-cell quadrature of the atmosphere,
   * the area from the interface quadrature; a quadrature point in a cell
   * with several components belongs to the positive vertex with the
   * largest alpha_v N_v(x). The labels are merged across ranks by
   * exchanging the smallest global vertex index of each component through
   * the ghost vertices until no label changes (as many rounds as ranks a
   * component crosses).
   *
   * @p window: volume_in_window counts the cells whose centre lies in it.
   * @p vertex_pores, if given, receives for each locally relevant DoF of
   * the level set (in the order of locally_relevant()) the index in the
   * returned list of the pore it belongs to, -1 where alpha <= 0.
   */
  template <int dim>
  std::vector<Pore<dim>>
  find_pores(const LevelSetField<dim>              &level_set,
             const std::vector<types::boundary_id> &symmetry_boundaries,
             const BoundingBox<dim>                &window,
             std::vector<int> *vertex_pores = nullptr);

  /**
   * Follows the closed pores from one call to the next: a closed pore keeps
   * its id if its centroid lies within the larger equivalent radius of a
   * closed pore of the previous call (nearest pairs first).
   */
  template <int dim>
  class PoreTracker
  {
  public:
    struct Event
    {
      std::string  name; // "closed" (new closed pore) or "vanished"
      unsigned int pore   = 0;
      double       volume = 0; // at the event (the last one seen if vanished)
    };

    /** Ids of @p pores (0 for open ones); appends the events to @p events. */
    std::vector<unsigned int>
    update(const std::vector<Pore<dim>> &pores, std::vector<Event> &events);

    /** The closed pores of the last update() and the next id (restart). */
    template <class Archive>
    void
    serialize(Archive &archive, const unsigned int)
    {
      archive &previous &next_id;
    }

  private:
    struct Tracked
    {
      unsigned int id;
      Pore<dim>    pore;

      template <class Archive>
      void
      serialize(Archive &archive, const unsigned int)
      {
        archive &id &pore;
      }
    };
    std::vector<Tracked> previous;
    unsigned int         next_id = 1;
  };
} // namespace levelsinter
