#include <deal.II/base/mpi.h>

#include <levelsinter/analysis/pores.h>
#include <levelsinter/analysis/small_pore_closure.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

namespace levelsinter
{
  template <int dim>
  SmallPoreClosure<dim>::SmallPoreClosure(
    const std::vector<types::boundary_id> &symmetry_boundaries,
    const BoundingBox<dim>                &box,
    const double                           closure_radius,
    const double                           speed)
    : symmetry_boundaries(symmetry_boundaries)
    , box(box)
    , closure_radius(closure_radius)
    , speed(speed)
  {}

  template <int dim>
  std::vector<typename SmallPoreClosure<dim>::Seen>
  SmallPoreClosure<dim>::closed_pores(const LevelSetField<dim> &level_set,
                                      std::vector<int>         *vertex_pores,
                                      std::vector<double> *part_volumes) const
  {
    const auto pores =
      find_pores(level_set, symmetry_boundaries, box, vertex_pores);
    std::vector<Seen> seen;
    part_volumes->clear();
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
        seen.push_back({pore.centroid,
                        pore.open ? std::numeric_limits<double>::infinity() :
                                    radius});
        part_volumes->push_back(pore.volume);
      }
    return seen;
  }

  template <int dim>
  void
  SmallPoreClosure<dim>::begin_step(const LevelSetField<dim> &level_set)
  {
    std::vector<double> volumes;
    at_start = closed_pores(level_set, nullptr, &volumes);
  }

  template <int dim>
  void
  SmallPoreClosure<dim>::end_step(LevelSetField<dim> &level_set,
                                  const double        dt,
                                  const double        h_min)
  {
    const double closure_radius = this->closure_radius * h_min;
    std::vector<int>    vertex;
    std::vector<double> volume;
    const auto          now = closed_pores(level_set, &vertex, &volume);

    // The part volume each small pore must not exceed after the step: that
    // of the law's radius from the radius it had at the start (the same
    // pore: the nearest closed pore of the start within the larger of the
    // two radii; a pore that appeared during the step waits a step).
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
          target[i] = volume[i] * std::pow(radius / now[i].radius, dim);
          any       = true;
        }
    if (!any)
      return;

    // Lower alpha by one constant s_i at each such pore's vertices and the
    // other vertices of their cells, which moves the pore's interface in by
    // about s_i and keeps alpha's profile there (lowering the pore's
    // vertices alone, the reinitialisation of the next step would push
    // the interface out again). s_i by bisection on the pore's volume
    // (monotone in s_i), from 0 to the pore's largest alpha. A removed
    // pore's vertices take the mean alpha of the solid vertices of their
    // cells.
    const IndexSet &relevant = level_set.locally_relevant();
    const MPI_Comm  comm     = level_set.dof_handler().get_communicator();
    TrilinosWrappers::MPI::Vector original(level_set.locally_owned(), comm);
    original = level_set.alpha();
    std::vector<int>    shifted_by(vertex.size(), -1);
    std::vector<double> low(now.size(), 0), high(now.size(), 0),
      ring_sum(now.size(), 0), ring_count(now.size(), 0);
    std::vector<types::global_dof_index> indices(
      level_set.fe().n_dofs_per_cell());
    for (const auto &cell : level_set.dof_handler().active_cell_iterators())
      if (!cell->is_artificial())
        {
          cell->get_dof_indices(indices);
          int pore = -1;
          for (const auto dof : indices)
            if (const int i = vertex[relevant.index_within_set(dof)];
                i >= 0 && target[i] >= 0)
              pore = i;
          if (pore < 0)
            continue;
          for (const auto dof : indices)
            {
              const unsigned int k     = relevant.index_within_set(dof);
              const double       value = level_set.alpha()(dof);
              if (shifted_by[k] < 0)
                shifted_by[k] = vertex[k] >= 0 ? vertex[k] : pore;
              high[pore] = std::max(high[pore], value);
              if (value <= 0 && cell->is_locally_owned())
                {
                  ring_sum[pore] += value;
                  ring_count[pore] += 1;
                }
            }
        }
    Utilities::MPI::max(high, comm, high);
    Utilities::MPI::sum(ring_sum, comm, ring_sum);
    Utilities::MPI::sum(ring_count, comm, ring_count);
    const auto apply = [&](const std::vector<double> &shift) {
      TrilinosWrappers::MPI::Vector shifted(original);
      for (unsigned int k = 0; k < vertex.size(); ++k)
        if (const int i = shifted_by[k]; i >= 0)
          if (const auto dof = relevant.nth_index_in_set(k);
              level_set.locally_owned().is_element(dof))
            shifted(dof) =
              target[i] > 0 ? original(dof) - shift[i] :
              vertex[k] < 0 ? original(dof) :
              ring_count[i] > 0 ? ring_sum[i] / ring_count[i] :
                                  -closure_radius;
      level_set.set_from_owned(shifted);
    };
    // The volume left of pore i: the closed pores whose centroid lies
    // within the pore's radius of its centroid (lowering alpha may split
    // it).
    const auto remaining = [&]() {
      std::vector<double> left_volume;
      const auto          after = closed_pores(level_set, nullptr, &left_volume);
      std::vector<double> left(now.size(), 0);
      for (unsigned int i = 0; i < now.size(); ++i)
        for (unsigned int j = 0; j < after.size(); ++j)
          if (after[j].centroid.distance(now[i].centroid) <= now[i].radius)
            left[i] += left_volume[j];
      return left;
    };
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
          added_volume += volume[i] - left[i];
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
