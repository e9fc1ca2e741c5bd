// CutCellRules (mechanics/cut_cell_rules.h) against NonMatching::FEValues,
// which builds FEValues objects on the generated rules of each cut cell:
//
//   cut_cell_rules DIM
//
// On an anisotropic box mesh (cells 1/8 x 1/10 (x 1/12)) and the Q1
// interpolant of an ellipse (ellipsoid) that is no distance function, for
// every cut cell and the Q1 element: the inside and outside parts' mass
// and stiffness matrices (int phi_i phi_j, int d_d phi_i d_e phi_j) from
// the moment-fitted weights on the cell's 3 x 3 (x 3) Gauss points, and
// the surface's int dS, int phi_i n dS and int d_d phi_i n_e dS from the
// rules' points. These integrands are polynomials of degree 2 per
// direction, so both must agree to round-off: the largest difference,
// relative to the entries' scale on that cell, must stay below 1e-11.
// Prints the cut cells and the largest differences.

#include <deal.II/base/function.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/quadrature_lib.h>

#include <deal.II/dofs/dof_handler.h>

#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_values.h>

#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/tria.h>

#include <deal.II/hp/fe_collection.h>

#include <deal.II/lac/trilinos_vector.h>

#include <deal.II/non_matching/fe_values.h>
#include <deal.II/non_matching/mesh_classifier.h>

#include <deal.II/numerics/vector_tools.h>

#include <levelsinter/mechanics/cut_cell_rules.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <string>

using namespace dealii;

namespace
{
  // (x - c)^2 / a^2 + ... - 1: an ellipse, not a distance.
  template <int dim>
  class Ellipse : public Function<dim>
  {
  public:
    double
    value(const Point<dim> &p, const unsigned int = 0) const override
    {
      const double axes[3] = {0.31, 0.23, 0.37};
      double       v       = -1;
      for (unsigned int d = 0; d < dim; ++d)
        v += (p[d] - 0.47) * (p[d] - 0.47) / (axes[d] * axes[d]);
      return v;
    }
  };

  template <int dim>
  double
  run()
  {
    Triangulation<dim>        tria;
    std::vector<unsigned int> subdivisions{8, 10, 12};
    subdivisions.resize(dim);
    GridGenerator::subdivided_hyper_rectangle(tria,
                                              subdivisions,
                                              Point<dim>(),
                                              dim == 2 ? Point<dim>(1, 1) :
                                                         Point<dim>(1, 1, 1));
    const FE_Q<dim> fe(1);
    DoFHandler<dim> dofs(tria);
    dofs.distribute_dofs(fe);
    TrilinosWrappers::MPI::Vector level_set(dofs.locally_owned_dofs(),
                                            MPI_COMM_WORLD);
    VectorTools::interpolate(dofs, Ellipse<dim>(), level_set);

    NonMatching::MeshClassifier<dim> classifier(dofs, level_set);
    classifier.reclassify();
    NonMatching::RegionUpdateFlags flags;
    flags.inside = flags.outside =
      update_values | update_gradients | update_JxW_values;
    flags.surface = update_values | update_gradients | update_JxW_values |
                    update_normal_vectors;
    const hp::FECollection<dim> fe_collection(fe);
    NonMatching::FEValues<dim>  reference(
      fe_collection, QGauss<1>(3), flags, classifier, dofs, level_set);
    levelsinter::CutCellRules<dim> rules(dofs, level_set, 3);
    FEValues<dim> fitted(fe,
                         rules.cell_quadrature(),
                         update_values | update_gradients | update_JxW_values);

    const unsigned int n = fe.dofs_per_cell;
    double             worst = 0;
    unsigned int       n_cut = 0;
    // The integrals compared on one cell, in one list per rule.
    const auto volume_integrals = [&](const FEValues<dim>        &values,
                                      const std::vector<double> *weights) {
      std::vector<double> out;
      for (unsigned int i = 0; i < n; ++i)
        for (unsigned int j = 0; j < n; ++j)
          {
            double m = 0;
            Tensor<2, dim> k;
            for (unsigned int q = 0; q < values.n_quadrature_points; ++q)
              {
                const double w =
                  weights ? values.JxW(q) * (*weights)[q] /
                              rules.cell_quadrature().weight(q) :
                            values.JxW(q);
                m += values.shape_value(i, q) * values.shape_value(j, q) * w;
                k += outer_product(values.shape_grad(i, q),
                                   values.shape_grad(j, q)) *
                     w;
              }
            out.push_back(m);
            for (unsigned int d = 0; d < dim; ++d)
              for (unsigned int e = 0; e < dim; ++e)
                out.push_back(k[d][e]);
          }
      return out;
    };
    const auto compare = [&](const std::vector<double> &a,
                             const std::vector<double> &b) {
      AssertThrow(a.size() == b.size(), ExcInternalError());
      double scale = 0, difference = 0;
      for (unsigned int i = 0; i < a.size(); ++i)
        {
          scale      = std::max(scale, std::abs(a[i]));
          difference = std::max(difference, std::abs(a[i] - b[i]));
        }
      worst = std::max(worst, scale > 0 ? difference / scale : difference);
    };

    for (const auto &cell : dofs.active_cell_iterators())
      if (classifier.location_to_level_set(cell) ==
          NonMatching::LocationToLevelSet::intersected)
        {
          ++n_cut;
          reference.reinit(cell);
          rules.generate(cell);
          fitted.reinit(cell);
          for (const bool inside : {true, false})
            {
              const auto &part = inside ? reference.get_inside_fe_values() :
                                          reference.get_outside_fe_values();
              AssertThrow(bool(part) == rules.has_part(inside),
                          ExcMessage("the parts differ"));
              if (part)
                compare(volume_integrals(*part, nullptr),
                        volume_integrals(fitted, &rules.weights(inside)));
            }

          const auto &surface = reference.get_surface_fe_values();
          AssertThrow(surface.has_value() == !rules.surface().empty(),
                      ExcMessage("the surfaces differ"));
          if (!surface)
            continue;
          std::vector<double> a(1 + n * dim * (1 + dim)), b(a.size());
          for (const unsigned int q : surface->quadrature_point_indices())
            {
              const Tensor<1, dim> normal = surface->normal_vector(q);
              a[0] += surface->JxW(q);
              for (unsigned int i = 0; i < n; ++i)
                for (unsigned int d = 0; d < dim; ++d)
                  {
                    const unsigned int at = 1 + (i * dim + d) * (1 + dim);
                    a[at] += surface->shape_value(i, q) * normal[d] *
                             surface->JxW(q);
                    for (unsigned int e = 0; e < dim; ++e)
                      a[at + 1 + e] += surface->shape_grad(i, q)[d] *
                                       normal[e] * surface->JxW(q);
                  }
            }
          for (const auto &p : rules.surface())
            {
              b[0] += p.dS;
              for (unsigned int i = 0; i < n; ++i)
                for (unsigned int d = 0; d < dim; ++d)
                  {
                    const unsigned int at = 1 + (i * dim + d) * (1 + dim);
                    b[at] += p.value[i] * p.normal[d] * p.dS;
                    for (unsigned int e = 0; e < dim; ++e)
                      b[at + 1 + e] += p.gradient[i][d] * p.normal[e] * p.dS;
                  }
            }
          compare(a, b);
        }
    std::cout << dim << "D: " << n_cut << " cut cells, largest relative "
              << "difference " << worst << std::endl;
    AssertThrow(n_cut > 0, ExcMessage("no cut cell"));
    return worst;
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const std::string                dim = argc > 1 ? argv[1] : "";
  if (dim != "2" && dim != "3")
    {
      std::cerr << "usage: cut_cell_rules DIM (2 or 3)" << std::endl;
      return 2;
    }
  const double worst = dim == "2" ? run<2>() : run<3>();
  if (worst > 1e-11)
    {
      std::cerr << "the cut-cell rules differ from NonMatching::FEValues by "
                << worst << " (limit 1e-11)" << std::endl;
      return 1;
    }
  return 0;
}
