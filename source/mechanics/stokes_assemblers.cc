#include <levelsinter/mechanics/stokes_assemblers.h>
#include <levelsinter/mechanics/stokes_cell_data.h>

#include <algorithm>

namespace levelsinter
{
  template <int dim>
  StokesCellData<dim>::StokesCellData(const std::vector<unsigned int> &component)
    : component(component)
    , n_dofs(component.size())
  {}

  template <int dim>
  void
  StokesCellData<dim>::reinit(const FEValues<dim> &values)
  {
    const FEValuesExtractors::Vector velocity(0);
    const FEValuesExtractors::Scalar pressure(dim);
    n_q = values.n_quadrature_points;
    JxW.resize(n_q);
    law.resize(n_q);
    tau.resize(n_q);
    history.resize(n_q);
    balanced_force.resize(n_q);
    eps.resize(n_q, std::vector<SymmetricTensor<2, dim>>(n_dofs));
    grad_w.resize(n_q, std::vector<Tensor<2, dim>>(n_dofs));
    w.resize(n_q, std::vector<Tensor<1, dim>>(n_dofs));
    div.resize(n_q, std::vector<double>(n_dofs));
    q.resize(n_q, std::vector<double>(n_dofs));
    grad_q.resize(n_q, std::vector<Tensor<1, dim>>(n_dofs));
    for (unsigned int k = 0; k < n_q; ++k)
      {
        JxW[k] = values.JxW(k);
        for (unsigned int i = 0; i < n_dofs; ++i)
          {
            eps[k][i]    = values[velocity].symmetric_gradient(i, k);
            grad_w[k][i] = values[velocity].gradient(i, k);
            w[k][i]      = values[velocity].value(i, k);
            div[k][i]    = values[velocity].divergence(i, k);
            q[k][i]      = values[pressure].value(i, k);
            grad_q[k][i] = values[pressure].gradient(i, k);
          }
      }
    std::fill(history.begin(), history.end(), HistoryTerms<dim>());
    std::fill(balanced_force.begin(), balanced_force.end(), Tensor<1, dim>());
    surface.clear();
    free_faces.clear();
  }

  template <int dim>
  void
  BulkAssembler<dim>::assemble(const StokesCellData<dim> &data,
                               CellContribution          &cell) const
  {
    // Each shape function of the FESystem has one component: only
    // velocity-velocity (eps:eps), velocity-pressure (div q) and
    // pressure-pressure pairs are nonzero. The operator is symmetric apart
    // from a2, so the same-type pairs fill the upper triangle.
    for (unsigned int k = 0; k < data.n_q; ++k)
      {
        const PhaseCoefficients &law = data.law[k];
        const double             JxW = data.JxW[k];
        const auto              &eps = data.eps[k];
        const auto              &div = data.div[k];
        const auto              &q   = data.q[k];
        for (unsigned int i = 0; i < data.n_dofs; ++i)
          {
            const bool i_pressure = data.is_pressure(i);
            for (unsigned int j = i; j < data.n_dofs; ++j)
              {
                const bool j_pressure = data.is_pressure(j);
                if (!i_pressure && !j_pressure)
                  cell.matrix(i, j) += law.a1 * eps[i] * eps[j] * JxW;
                else if (i_pressure && j_pressure)
                  {
                    cell.matrix(i, j) -=
                      law.compressibility * q[i] * q[j] * JxW;
                    // Schur approximation M_{1/eta_K} + C (eta_K =
                    // a1_cell / 2).
                    cell.schur(i, j) += (2 / data.a1_cell +
                                         law.compressibility) *
                                        q[i] * q[j] * JxW;
                  }
                else
                  {
                    // a2 weighs p in the momentum equation only (the
                    // elastic law has a2 != 1): both entries here.
                    const unsigned int v = i_pressure ? j : i;
                    const unsigned int p = i_pressure ? i : j;
                    cell.matrix(v, p) -= law.a2 * div[v] * q[p] * JxW;
                    cell.matrix(p, v) -= div[v] * q[p] * JxW;
                  }
              }
          }

        // The law's memory (elastic solid, Eq. 93-94): -sigma_hist : grad
        // w, and div v + c_p p = r in the (negated) continuity rows.
        const HistoryTerms<dim> &history = data.history[k];
        if (history.stress.norm() != 0 || history.dilatation_rate != 0)
          for (unsigned int i = 0; i < data.n_dofs; ++i)
            cell.rhs(i) -=
              (data.is_pressure(i) ? history.dilatation_rate * q[i] :
                                     history.stress * eps[i]) *
              JxW;
      }
  }

  template <int dim>
  void
  StabilisationAssembler<dim>::assemble(const StokesCellData<dim> &data,
                                        CellContribution          &cell) const
  {
    for (unsigned int k = 0; k < data.n_q; ++k)
      {
        const double weight = data.tau[k] * data.JxW[k];
        const auto  &grad_q = data.grad_q[k];
        for (unsigned int i = 0; i < data.n_dofs; ++i)
          if (data.is_pressure(i))
            for (unsigned int j = i; j < data.n_dofs; ++j)
              if (data.is_pressure(j))
                {
                  const double entry = weight * (grad_q[i] * grad_q[j]);
                  cell.matrix(i, j) -= entry;
                  cell.schur(i, j) += entry;
                }
      }
  }

  template <int dim>
  void
  TensorialSurfaceTensionAssembler<dim>::assemble(
    const StokesCellData<dim> &data,
    CellContribution          &cell) const
  {
    for (const auto &point : data.surface)
      {
        const Tensor<2, dim> projector = point.projector();
        for (unsigned int i = 0; i < data.n_dofs; ++i)
          if (!data.is_pressure(i))
            cell.rhs(i) -=
              gamma * scalar_product(projector, point.grad_w[i]) * point.dS;
      }
  }

  template <int dim>
  void
  BalancedForceAssembler<dim>::assemble(const StokesCellData<dim> &data,
                                        CellContribution          &cell) const
  {
    // f = gamma kappa grad H_h points into the solid (grad H_s = -n delta),
    // so p = gamma kappa H_h balances it. The pressure rows carry f in
    // tau (grad p - f) . grad q.
    for (unsigned int k = 0; k < data.n_q; ++k)
      {
        const Tensor<1, dim> &f = data.balanced_force[k];
        for (unsigned int i = 0; i < data.n_dofs; ++i)
          cell.rhs(i) += (data.is_pressure(i) ?
                            -data.tau[k] * (f * data.grad_q[k][i]) :
                            f * data.w[k][i]) *
                         data.JxW[k];
      }
  }

  template <int dim>
  void
  LaplaceBeltramiAssembler<dim>::assemble(const StokesCellData<dim> &data,
                                          CellContribution          &cell) const
  {
    for (const auto &point : data.surface)
      {
        const Tensor<2, dim> projector = point.projector();
        // grad_Gamma w = (grad w) P; the upper triangle suffices.
        for (unsigned int i = 0; i < data.n_dofs; ++i)
          if (!data.is_pressure(i))
            {
              const Tensor<2, dim> surface_i = point.grad_w[i] * projector;
              for (unsigned int j = i; j < data.n_dofs; ++j)
                if (!data.is_pressure(j))
                  cell.matrix(i, j) +=
                    weight *
                    scalar_product(surface_i, point.grad_w[j] * projector) *
                    point.dS;
            }
      }
  }

  template <int dim>
  void
  TractionAssembler<dim>::assemble(const StokesCellData<dim> &data,
                                   CellContribution          &cell) const
  {
    for (const auto &point : data.free_faces)
      for (unsigned int i = 0; i < data.n_dofs; ++i)
        cell.rhs(i) -= p_ext * (point.w[i] * point.normal) * point.JxW;
  }

  template <int dim>
  void
  symmetrise(const StokesCellData<dim> &data, CellContribution &cell)
  {
    for (unsigned int i = 0; i < data.n_dofs; ++i)
      for (unsigned int j = 0; j < i; ++j)
        if (data.is_pressure(i) == data.is_pressure(j))
          {
            cell.matrix(i, j) = cell.matrix(j, i);
            cell.schur(i, j)  = cell.schur(j, i);
          }
  }

#define INSTANTIATE(dim)                                            \
  template struct StokesCellData<dim>;                              \
  template class BulkAssembler<dim>;                                \
  template class StabilisationAssembler<dim>;                       \
  template class TensorialSurfaceTensionAssembler<dim>;             \
  template class BalancedForceAssembler<dim>;                       \
  template class LaplaceBeltramiAssembler<dim>;                     \
  template class TractionAssembler<dim>;                            \
  template void symmetrise(const StokesCellData<dim> &, CellContribution &);
  INSTANTIATE(2)
  INSTANTIATE(3)
#undef INSTANTIATE
} // namespace levelsinter
