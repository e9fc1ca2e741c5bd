#pragma once

#include <deal.II/base/symmetric_tensor.h>

#include <deal.II/dofs/dof_handler.h>

#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_values.h>

#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/trilinos_precondition.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <levelsinter/level_set/scene_measure.h>
#include <levelsinter/level_set/state_transfer.h>
#include <levelsinter/level_set/velocity_field.h>
#include <levelsinter/mechanics/conformation_model.h>

#include <functional>
#include <utility>
#include <vector>

namespace levelsinter
{
  /**
   * The conformation tensor of a viscoelastic melt on the mesh, carried in
   * log form (s = log c, so c stays positive definite) as one Q1 field per
   * independent component of the 3 x 3 tensor (2D: xx, yy, zz, xy; 3D: all
   * six). advance() solves the conformation equation (viscoelastic seed,
   * Eq. 6-7) in the Eulerian frame,
   *   ds/dt + v . grad s = r(s, grad v)   (ConformationModel::log_rate),
   * by Strang splitting: the relaxation at the nodes (stable for any step,
   * ConformationModel::relax_log()) around the transport, Crank-Nicolson
   * with SUPG (one matrix for all components) with the deformation terms
   * explicit in a two-stage Heun step; second order. At inflow boundaries
   * c = I is imposed weakly. On an axisymmetric scene the third axis is the
   * hoop direction: the velocity gradient has L_thth = v_r / r, and the
   * transport of the components is that of scalars (no swirl, so the
   * cylindrical basis adds no terms).
   */
  template <int dim>
  class ConformationField
  {
  public:
    using Vector = TrilinosWrappers::MPI::Vector;

    /** @p dofs: a scalar Q1 DoFHandler (the level set's in a scene), on
     * which the field lives; @p measure says whether the scene is
     * axisymmetric. */
    ConformationField(const DoFHandler<dim>   &dofs,
                      const ConformationModel &model,
                      const SceneMeasure      &measure = SceneMeasure(false));

    /** Sizes the vectors for the current DoFs of the DoFHandler (c = I);
     * their values come from set() or a StateTransfer. */
    void
    setup();

    /** s = log c at the nodes. */
    void
    set(const std::function<SymmetricTensor<2, 3>(const Point<dim> &)> &c);

    /** One step of length @p dt in the velocity field @p velocity from the
     * committed state; the result is held until commit(), so a step that is
     * taken again starts from the same state. @p stretch_weight (nodal, on
     * this field's DoFs with ghosts; none: 1 everywhere) scales the
     * deformation terms: where it is 0, c is only carried and relaxes.
     * Returns the largest GMRES iteration count of the solves. */
    unsigned int
    advance(const VelocityField<dim> &velocity,
            const double              dt,
            const Vector             *stretch_weight = nullptr);

    /** The last advance() becomes the state. */
    void
    commit();

    /** s -> w s at every node, w from @p weight(global DoF index): c
     * relaxes to I where w = 0. */
    void
    fade(const std::function<double(types::global_dof_index)> &weight);

    /** The committed log-conformation at the nodes: component k is the
     * entry components()[k] of s. */
    const std::vector<Vector> &
    log_conformation() const
    {
      return state;
    }

    /** The polymer stress tau = G (c - I) at the quadrature points of
     * @p values, FEValues of this field's element with update_values, reinit
     * on the cell: its dim x dim block in @p stress, tau_thth (the third
     * axis) in @p hoop_stress. */
    void
    stress_values(const FEValues<dim>                  &values,
                  std::vector<SymmetricTensor<2, dim>> &stress,
                  std::vector<double>                  &hoop_stress) const;

    const FE_Q<dim> &
    finite_element() const
    {
      return fe;
    }

    static std::vector<std::pair<unsigned int, unsigned int>>
    components();

    /** c at a node from the component values s_k there. */
    static SymmetricTensor<2, 3>
    conformation(const std::vector<double> &s);

    const DoFHandler<dim> &
    dof_handler() const
    {
      return dofs;
    }

    /** The committed s travels across mesh adaptation through
     * @p transfer. */
    void
    add_state(StateTransfer<dim> &transfer);

  private:
    void
    assemble_matrix(const VelocityField<dim> &velocity, const double dt);

    /** Right-hand sides of the transport from @p old, the deformation
     * source evaluated at @p stage (averaged with the source at @p old when
     * @p average) and scaled by @p stretch_weight if given. */
    std::vector<Vector>
    assemble_rhs(const VelocityField<dim>  &velocity,
                 const double               dt,
                 const std::vector<Vector> &old,
                 const std::vector<Vector> &stage,
                 const bool                 average,
                 const Vector              *stretch_weight) const;

    /** @p s after relaxing alone for @p dt at every node
     * (ConformationModel::relax_log()). */
    std::vector<Vector>
    relaxed(const std::vector<Vector> &s, const double dt) const;

    unsigned int
    solve(std::vector<Vector> &rhs, std::vector<Vector> &result);

    const ConformationModel           model;
    const DoFHandler<dim>            &dofs;
    const SceneMeasure                measure;
    FE_Q<dim>                         fe;
    MPI_Comm                          comm;
    IndexSet                          owned, relevant;
    AffineConstraints<double>         constraints;
    TrilinosWrappers::SparseMatrix    matrix;
    TrilinosWrappers::PreconditionILU preconditioner;
    std::vector<Vector>               state, advanced;
  };
} // namespace levelsinter
