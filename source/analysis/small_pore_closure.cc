#include <deal.II/base/mpi.h>
#include <deal.II/base/quadrature_lib.h>

#include <deal.II/fe/fe_values.h>

#include <deal.II/hp/q_collection.h>

#include <deal.II/non_matching/quadrature_generator.h>

#include <levelsinter/analysis/pores.h>
#include <levelsinter/analysis/small_pore_closure.h>
#include <levelsinter/level_set/box_mapping.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <tuple>

namespace levelsinter
{
  template <int dim>
  SmallPoreClosure<dim>::SmallPoreClosure(
    const std::vector<types::boundary_id> &symmetry_boundaries,
    const BoundingBox<dim>                &box,
    const LevelSetFilter                  &filter,
    const double                           closure_radius,
    const double                           speed)
    : symmetry_boundaries(symmetry_boundaries)
    , box(box)
    , filter(filter)
    , closure_radius(closure_radius)
    , speed(speed)
  {}

  template <int dim>
  std::vector<typename SmallPoreClosure<dim>::Seen>
  SmallPoreClosure<dim>::closed_pores(const LevelSetField<dim> &level_set,
                                      std::vector<int> *vertex_pores) const
  {
    const auto pores =
      find_pores(level_set, symmetry_boundaries, box, vertex_pores);
    std::vector<Seen> seen;
    for (const auto &pore : pores)
      {
        // The whole pore: its mirror images across the symmetry planes it
        // touches. Open pores never qualify.
        unsigned int mirrors = 1;
        for (const auto b : symmetry_boundaries)
          if (pore.box_faces & (1u << b))
            mirrors *= 2;
        const double whole  = mirrors * pore.volume;
        const double radius = dim == 3 ? std::cbrt(3 * whole / (4 * M_PI)) :
                                         std::sqrt(whole / M_PI);
        // Its centre: on each symmetry plane it touches (its mirror image
        // across the plane is the rest of it).
        Point<dim> centre = pore.centroid;
        for (const auto b : symmetry_boundaries)
          if (pore.box_faces & (1u << b))
            centre[b / 2] = b % 2 == 0 ? box.get_boundary_points().first[b / 2] :
                                         box.get_boundary_points().second[b / 2];
        seen.push_back({pore.centroid,
                        centre,
                        pore.open ? std::numeric_limits<double>::infinity() :
                                    radius});
      }
    return seen;
  }

  template <int dim>
  void
  SmallPoreClosure<dim>::begin_step(const LevelSetField<dim> &level_set)
  {
    at_start = closed_pores(level_set, nullptr);
  }

  template <int dim>
  void
  SmallPoreClosure<dim>::end_step(LevelSetField<dim> &level_set,
                                  const double        dt,
                                  const double        h_min)
  {
    const double closure_radius = this->closure_radius * h_min;
    std::vector<int> vertex;
    const auto       now = closed_pores(level_set, &vertex);

    // The fraction of its volume each small pore may keep after the step:
    // that of the law's radius from the radius it had at the start (the
    // same pore: the nearest closed pore of the start within the larger of
    // the two radii; a pore that appeared during the step waits a step).
    std::vector<double> target(now.size(), -1);
    bool                any = false;
    for (unsigned int i = 0; i < now.size(); ++i)
      if (now[i].radius < closure_radius)
        {
          double start_radius = -1, nearest = std::numeric_limits<double>::max();
          for (const auto &old : at_start)
            if (const double d = old.centroid.distance(now[i].centroid);
                d < std::max(old.radius, now[i].radius) && d < nearest)
              {
                nearest      = d;
                start_radius = old.radius;
              }
          if (start_radius < 0)
            continue;
          const double radius = std::max(start_radius - speed * dt, 0.);
          if (now[i].radius <= radius)
            continue; // the flow closes it as fast
          target[i] = std::pow(radius / now[i].radius, dim);
          any       = true;
        }
    if (!any)
      return;

    // Move each such pore's surface in by s_i as the level set of a round
    // pore of radius R_i about its centre c_i would move:
    // alpha - F(R_i - |x - c_i|) + F(R_i - s_i - |x - c_i|), F the
    // filter. This keeps alpha's profile (lowering the pore's vertices by a
    // constant, the next step's reinitialisation pushed the surface out
    // again and the surface measure grew). s_i by bisection on the pore's
    // volume (monotone in s_i), from 0 to R_i + 3 E; past the filter's reach
    // alpha is unchanged. A removed pore (s_i = R_i + 3 E) keeps no
    // positive vertex.
    const IndexSet &relevant = level_set.locally_relevant();
    const MPI_Comm  comm     = level_set.dof_handler().get_communicator();
    const double    reach    = 3 * filter.thickness();
    TrilinosWrappers::MPI::Vector original(level_set.locally_owned(), comm);
    original = level_set.alpha();
    std::vector<double> low(now.size(), 0), high(now.size(), 0);
    for (unsigned int i = 0; i < now.size(); ++i)
      if (target[i] >= 0)
        high[i] = now[i].radius + reach;
    // The owned DoFs in reach of a pore: (DoF, pore, distance).
    std::vector<std::tuple<types::global_dof_index, unsigned int, double>>
      near;
    std::vector<types::global_dof_index> indices(
      level_set.fe().n_dofs_per_cell());
    std::vector<bool> seen(vertex.size(), false);
    for (const auto &cell : level_set.dof_handler().active_cell_iterators())
      if (cell->is_locally_owned())
        {
          cell->get_dof_indices(indices);
          for (const unsigned int v : cell->vertex_indices())
            {
              const unsigned int k = relevant.index_within_set(indices[v]);
              if (seen[k] || !level_set.locally_owned().is_element(indices[v]))
                continue;
              seen[k] = true;
              for (unsigned int i = 0; i < now.size(); ++i)
                if (const double d = cell->vertex(v).distance(now[i].centre);
                    target[i] >= 0 && d < now[i].radius + reach)
                  {
                    near.emplace_back(indices[v], i, d);
                    break;
                  }
            }
        }
    const auto apply = [&](const std::vector<double> &shift) {
      TrilinosWrappers::MPI::Vector shifted(original);
      for (const auto &[dof, i, d] : near)
        {
          double value = original(dof) - filter.filter(now[i].radius - d) +
                         filter.filter(now[i].radius - shift[i] - d);
          if (target[i] == 0 &&
              vertex[relevant.index_within_set(dof)] == int(i))
            value = std::min(value, filter.filter(-closure_radius));
          shifted(dof) = value;
        }
      level_set.set_from_owned(shifted);
    };
    // The volume left of each pore, measured on the owned cells that hold
    // it at the end of the step (a vertex in it): alpha only falls in the
    // bisection, so the pore (or its parts, if it splits) stays in them.
    // Searching the whole mesh for pores at each bisection step doubled the
    // CPU time of a step. Its volume at s = 0 is measured the same way, so
    // that the target and the bisection agree where it shares a cell with
    // another component.
    std::vector<std::pair<typename DoFHandler<dim>::active_cell_iterator,
                          unsigned int>>
      pore_cells;
    for (const auto &cell : level_set.dof_handler().active_cell_iterators())
      if (cell->is_locally_owned())
        {
          cell->get_dof_indices(indices);
          for (const unsigned int v : cell->vertex_indices())
            if (const int i = vertex[relevant.index_within_set(indices[v])];
                i >= 0 && target[i] >= 0)
              {
                pore_cells.emplace_back(cell, i);
                break;
              }
        }
    const hp::QCollection<1> gauss(QGauss<1>(3)); // as integrate_regions()
    const auto               remaining = [&]() {
      NonMatching::DiscreteQuadratureGenerator<dim> generator(
        gauss, level_set.dof_handler(), level_set.alpha());
      std::vector<double> left(now.size(), 0);
      for (const auto &[cell, i] : pore_cells)
        {
          generator.generate(cell);
          const Quadrature<dim> &outside = generator.get_outside_quadrature();
          if (outside.size() == 0)
            continue;
          FEValues<dim> values(box_mapping<dim>(),
                               level_set.fe(),
                               outside,
                               update_JxW_values | update_quadrature_points);
          values.reinit(cell);
          for (const unsigned int q : values.quadrature_point_indices())
            left[i] += level_set.measure().JxW(values, q);
        }
      Utilities::MPI::sum(left, comm, left);
      return left;
    };
    const std::vector<double> before = remaining();
    for (unsigned int i = 0; i < now.size(); ++i)
      if (target[i] > 0)
        target[i] *= before[i]; // the volume it may keep
    std::vector<double> shift(now.size(), 0);
    for (unsigned int iteration = 0; iteration < 30; ++iteration)
      {
        for (unsigned int i = 0; i < now.size(); ++i)
          shift[i] = (low[i] + high[i]) / 2;
        apply(shift);
        const auto left = remaining();
        for (unsigned int i = 0; i < now.size(); ++i)
          (left[i] > target[i] ? low[i] : high[i]) = shift[i];
      }
    apply(high);
    const auto left = remaining();
    for (unsigned int i = 0; i < now.size(); ++i)
      if (target[i] >= 0)
        {
          added_volume += before[i] - left[i];
          removed += target[i] == 0;
        }
  }

  template <int dim>
  std::string
  SmallPoreClosure<dim>::save() const
  {
    std::ostringstream out;
    out.precision(17);
    out << added_volume << ' ' << removed;
    return out.str();
  }

  template <int dim>
  void
  SmallPoreClosure<dim>::load(const std::string &state)
  {
    std::istringstream in(state);
    in >> added_volume >> removed;
  }

  template class SmallPoreClosure<2>;
  template class SmallPoreClosure<3>;
} // namespace levelsinter
