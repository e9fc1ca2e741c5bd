#include <levelsinter/mechanics/stokes_assemblers.h>

namespace levelsinter
{
  template <int dim>
  void
  BulkAssembler<dim>::assemble(const StokesCellData<dim> &data,
                               CellContribution          &cell) const
  {
    // Only velocity-velocity (eps:eps), velocity-pressure (div q) and
    // pressure-pressure pairs are nonzero. The operator is symmetric apart
    // from a2, so the same-type pairs fill the upper triangle (the lists of
    // shape functions are ascending).
    const auto &velocity_dofs = data.velocity_dofs;
    const auto &pressure_dofs = data.pressure_dofs;
    for (unsigned int k = 0; k < data.n_q; ++k)
      {
        const PhaseCoefficients &law  = data.law[k];
        const double             JxW  = data.JxW[k];
        const auto              &g    = data.gradient[k];
        const auto              &q    = data.value[k];
        const double             a1_2 = 0.5 * law.a1 * JxW;
        for (unsigned int a = 0; a < velocity_dofs.size(); ++a)
          {
            const unsigned int i      = velocity_dofs[a];
            const unsigned int ci     = data.component[i];
            const double       hoop_i = data.hoop(k, i);
            // eps(w_i) : eps(w_j) = (delta_{c_i c_j} g_i . g_j
            //                        + g_i[c_j] g_j[c_i]) / 2
            //                       + e_thth(w_i) e_thth(w_j).
            for (unsigned int b = a; b < velocity_dofs.size(); ++b)
              {
                const unsigned int j  = velocity_dofs[b];
                const unsigned int cj = data.component[j];
                double eps_eps =
                  g[i][cj] * g[j][ci] + 2 * hoop_i * data.hoop(k, j);
                if (ci == cj)
                  eps_eps += g[i] * g[j];
                cell.matrix(i, j) += a1_2 * eps_eps;
              }
            // a2 weighs p in the momentum equation only (the elastic law
            // has a2 != 1): both entries here. div w = d_c w_c + w_r / r.
            const double div_i = (g[i][ci] + hoop_i) * JxW;
            for (const unsigned int p : pressure_dofs)
              {
                cell.matrix(i, p) -= law.a2 * div_i * q[p];
                cell.matrix(p, i) -= div_i * q[p];
              }
          }
        // Schur approximation M_{1/eta_K} + C (eta_K = a1_cell / 2).
        const double schur_weight =
          (2 / data.a1_cell + law.compressibility) * JxW;
        for (unsigned int a = 0; a < pressure_dofs.size(); ++a)
          for (unsigned int b = a; b < pressure_dofs.size(); ++b)
            {
              const unsigned int i = pressure_dofs[a], j = pressure_dofs[b];
              cell.matrix(i, j) -= law.compressibility * q[i] * q[j] * JxW;
              cell.schur(i, j) += schur_weight * q[i] * q[j];
            }

        // The law's memory (elastic solid, Eq. 93-94): -sigma_hist : grad
        // w (with sigma_thth w_r / r on an axisymmetric scene), and
        // div v + c_p p = r in the (negated) continuity rows.
        const HistoryTerms<dim> &history = data.history[k];
        if (history.stress.norm() != 0 || history.hoop_stress != 0 ||
            history.dilatation_rate != 0)
          {
            for (const unsigned int i : velocity_dofs)
              {
                Tensor<1, dim> stress_row;
                for (unsigned int d = 0; d < dim; ++d)
                  stress_row[d] = history.stress[data.component[i]][d];
                cell.rhs(i) -=
                  (stress_row * g[i] + history.hoop_stress * data.hoop(k, i)) *
                  JxW;
              }
            for (const unsigned int p : pressure_dofs)
              cell.rhs(p) -= history.dilatation_rate * q[p] * JxW;
          }
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
        const auto  &grad_q = data.gradient[k];
        const auto  &pressure_dofs = data.pressure_dofs;
        for (unsigned int a = 0; a < pressure_dofs.size(); ++a)
          for (unsigned int b = a; b < pressure_dofs.size(); ++b)
            {
              const unsigned int i = pressure_dofs[a], j = pressure_dofs[b];
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
        // The surface divergence of w: P : grad w, plus w_r / r on a body
        // of revolution (P_thth = 1).
        const Tensor<2, dim> projector = point.projector();
        for (unsigned int i = 0; i < data.n_dofs; ++i)
          if (!data.is_pressure(i))
            cell.rhs(i) -= gamma *
                           (scalar_product(projector, point.grad_w[i]) +
                            point.hoop[i]) *
                           point.dS;
      }
  }

  template <int dim>
  void
  CurvatureSurfaceTensionAssembler<dim>::assemble(
    const StokesCellData<dim> &data,
    CellContribution          &cell) const
  {
    for (const auto &point : data.surface)
      for (unsigned int i = 0; i < data.n_dofs; ++i)
        if (!data.is_pressure(i))
          cell.rhs(i) -= gamma * point.curvature * point.normal_w[i] * point.dS;
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
                            -data.tau[k] * (f * data.gradient[k][i]) :
                            f[data.component[i]] * data.value[k][i]) *
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
        // grad_Gamma w = (grad w) P, plus the hoop entry w_r / r on a
        // body of revolution; the upper triangle suffices.
        for (unsigned int i = 0; i < data.n_dofs; ++i)
          if (!data.is_pressure(i))
            {
              const Tensor<2, dim> surface_i = point.grad_w[i] * projector;
              for (unsigned int j = i; j < data.n_dofs; ++j)
                if (!data.is_pressure(j))
                  cell.matrix(i, j) +=
                    weight *
                    (scalar_product(surface_i, point.grad_w[j] * projector) +
                     point.hoop[i] * point.hoop[j]) *
                    point.dS;
            }
      }
  }

  template <int dim>
  void
  DragAssembler<dim>::assemble(const StokesCellData<dim> &data,
                               CellContribution          &cell) const
  {
    // w_i . w_j = delta_{c_i c_j} phi_i phi_j; the upper triangle suffices.
    const auto &velocity_dofs = data.velocity_dofs;
    for (unsigned int k = 0; k < data.n_q; ++k)
      {
        const double c_d = relative * data.law[k].a1 * data.JxW[k];
        const auto  &phi = data.value[k];
        for (unsigned int a = 0; a < velocity_dofs.size(); ++a)
          for (unsigned int b = a; b < velocity_dofs.size(); ++b)
            {
              const unsigned int i = velocity_dofs[a], j = velocity_dofs[b];
              if (data.component[i] == data.component[j])
                cell.matrix(i, j) += c_d * phi[i] * phi[j];
            }
      }
  }

  template <int dim>
  void
  TractionAssembler<dim>::assemble(
    const StokesCellData<dim>                  &data,
    const typename StokesCellData<dim>::Face &face,
    CellContribution                           &cell) const
  {
    for (const auto &point : face.points)
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

  template <int dim>
  void
  GhostPenaltyAssembler<dim>::assemble(const FEInterfaceValues<dim> &values,
                                       const SceneMeasure           &measure,
                                       const unsigned int            component,
                                       const double                  weight,
                                       FullMatrix<double>           &matrix,
                                       FullMatrix<double>           &schur) const
  {
    const FEValuesExtractors::Scalar pressure(component);
    const unsigned int               n = values.n_current_interface_dofs();
    std::vector<double>              jump(n);
    for (const unsigned int q : values.quadrature_point_indices())
      {
        const Tensor<1, dim> normal = values.normal(q);
        const double factor =
          constant * weight * measure.JxW(values.get_fe_face_values(0), q);
        for (unsigned int i = 0; i < n; ++i)
          jump[i] = values[pressure].jump_in_gradients(i, q) * normal;
        for (unsigned int i = 0; i < n; ++i)
          if (jump[i] != 0)
            for (unsigned int j = 0; j < n; ++j)
              {
                const double entry = factor * jump[i] * jump[j];
                matrix(i, j) -= entry;
                schur(i, j) += entry;
              }
      }
  }

#define INSTANTIATE(dim)                                            \
  template class BulkAssembler<dim>;                                \
  template class StabilisationAssembler<dim>;                       \
  template class TensorialSurfaceTensionAssembler<dim>;             \
  template class CurvatureSurfaceTensionAssembler<dim>;             \
  template class BalancedForceAssembler<dim>;                       \
  template class LaplaceBeltramiAssembler<dim>;                     \
  template class DragAssembler<dim>;                                \
  template class TractionAssembler<dim>;                            \
  template class GhostPenaltyAssembler<dim>;                        \
  template void symmetrise(const StokesCellData<dim> &, CellContribution &);
  INSTANTIATE(2)
  INSTANTIATE(3)
#undef INSTANTIATE
} // namespace levelsinter
