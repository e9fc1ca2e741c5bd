// The mechanisms' hooks for state transfer and output fields (issue 14):
//
//   mechanism_hooks transfer MIN_LEVEL [MIN_LEVEL ...] --min-order-q1 P
//                            --min-order-q2 P
//     A smooth field on two DoFHandlers (the level set's Q1 and a vector Q2
//     of its own) is kept by StateTransfer through eight adaptations that
//     move a refined ring across a square with base level MIN_LEVEL; the
//     largest nodal error against the field's interpolant on the final
//     mesh must fall with the orders of interpolation (2 and 3) between
//     the levels. After each change of alpha its mesh classifier is one
//     object for all callers, a new one, and classifies as a fresh one.
//   mechanism_hooks lagged SCENE.prm STEPS --max-lag-change C [--set ...]
//     A surface-diffusion run: after every step that followed an
//     adaptation, v_s^{n-1} must be there, on the new DoFs, and within
//     |v_s^{n-1} - v_s^n| <= C |v_s^n| of the v_s of the step.
//   mechanism_hooks bubble SCENE.prm --max-jump-error E [--set ...]
//     The static bubble: the pressure written by the field output (the same
//     DataOut fields, read back from its patches) jumps by gamma / R.
//
// Exit code 0 only if every check passes.

#include <deal.II/base/function.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/utilities.h>

#include <deal.II/distributed/tria.h>

#include <deal.II/dofs/dof_handler.h>
#include <deal.II/dofs/dof_tools.h>

#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>

#include <deal.II/grid/grid_generator.h>

#include <deal.II/numerics/data_out.h>
#include <deal.II/numerics/vector_tools.h>

#include <deal.II/non_matching/mesh_classifier.h>

#include <levelsinter/level_set/level_set_field.h>
#include <levelsinter/level_set/state_transfer.h>
#include <levelsinter/mechanisms/surface_diffusion.h>
#include <levelsinter/scene/command_line.h>
#include <levelsinter/time/simulation.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

using namespace levelsinter;

namespace
{
  bool root = true;

  bool
  check(const std::string &what, const bool ok)
  {
    if (root)
      std::cout << (ok ? "PASS " : "FAIL ") << what << std::endl;
    return ok;
  }

  // Smooth, not a polynomial of the elements' degree in any direction.
  class Smooth : public Function<2>
  {
  public:
    Smooth()
      : Function<2>(2)
    {}
    double
    value(const Point<2> &p, const unsigned int c) const override
    {
      return c == 0 ? std::sin(3 * p[0]) * std::cos(2 * p[1]) :
                      std::exp(p[0] - p[1]);
    }
  };

  // Largest |v - I f| over the locally owned DoFs, over all ranks.
  double
  nodal_error(const DoFHandler<2>                 &dofs,
              const TrilinosWrappers::MPI::Vector &v,
              const Function<2>                   &f)
  {
    TrilinosWrappers::MPI::Vector exact(dofs.locally_owned_dofs(),
                                        dofs.get_communicator());
    VectorTools::interpolate(dofs, f, exact);
    double error = 0;
    for (const auto i : dofs.locally_owned_dofs())
      error = std::max(error, std::abs(v(i) - exact(i)));
    return Utilities::MPI::max(error, dofs.get_communicator());
  }

  // The level set's shared classifier after alpha changed (@p changed_from:
  // the one before): one object for all callers, a new one after each
  // change, and the same locations as a classification made afresh.
  bool
  classifier_follows(
    const LevelSetField<2>                                &level_set,
    const std::shared_ptr<const NonMatching::MeshClassifier<2>> &changed_from)
  {
    const auto shared = level_set.classifier();
    bool       ok =
      shared == level_set.classifier() && shared != changed_from;
    NonMatching::MeshClassifier<2> fresh(level_set.dof_handler(),
                                         level_set.alpha());
    fresh.reclassify();
    for (const auto &cell : level_set.dof_handler().active_cell_iterators())
      if (cell->is_locally_owned())
        ok &= shared->location_to_level_set(cell) ==
              fresh.location_to_level_set(cell);
    return Utilities::MPI::min(ok ? 1 : 0, MPI_COMM_WORLD) == 1;
  }

  bool classifier_shared = true;

  // Errors (Q1 scalar, Q2 vector) after eight adaptations from level L.
  std::pair<double, double>
  transfer_errors(const unsigned int min_level)
  {
    const MPI_Comm                          comm = MPI_COMM_WORLD;
    parallel::distributed::Triangulation<2> tria(
      comm, Triangulation<2>::limit_level_difference_at_vertices);
    GridGenerator::hyper_cube(tria);
    tria.refine_global(min_level);

    LevelSetField<2> q1(tria);
    FESystem<2>      q2_element(FE_Q<2>(2), 2);
    DoFHandler<2>    q2(tria);
    const auto       setup_q2 = [&](TrilinosWrappers::MPI::Vector &v) {
      q2.distribute_dofs(q2_element);
      v.reinit(q2.locally_owned_dofs(),
               DoFTools::extract_locally_relevant_dofs(q2),
               comm);
    };
    const Smooth                        smooth;
    const ScalarFunctionFromFunctionObject<2> scalar(
      [&](const Point<2> &p) { return smooth.value(p, 0); });
    TrilinosWrappers::MPI::Vector       vector_field;
    q1.setup_dofs();
    q1.interpolate(scalar);
    classifier_shared &= classifier_follows(q1, nullptr);
    setup_q2(vector_field);
    {
      TrilinosWrappers::MPI::Vector owned(q2.locally_owned_dofs(), comm);
      VectorTools::interpolate(q2, smooth, owned);
      vector_field = owned;
    }

    // A ring of radius 0.25, two levels finer, whose centre moves along
    // the diagonal: cells are refined and coarsened again behind it.
    for (unsigned int cycle = 0; cycle < 4; ++cycle)
      {
        const Point<2> centre(0.3 + 0.12 * cycle, 0.3 + 0.12 * cycle);
        for (unsigned int pass = 0; pass < 2; ++pass)
          {
            for (const auto &cell : tria.active_cell_iterators())
              if (cell->is_locally_owned())
                {
                  const double ring = std::abs(
                    cell->center().distance(centre) - 0.25);
                  const bool near = ring < 0.1;
                  if (near && cell->level() < int(min_level + 2))
                    cell->set_refine_flag();
                  else if (!near && cell->level() > int(min_level))
                    cell->set_coarsen_flag();
                }
            const auto       before = q1.classifier();
            StateTransfer<2> state;
            q1.add_to(state);
            state.add(q2, {&vector_field});
            state.prepare_for_coarsening_and_refinement();
            tria.execute_coarsening_and_refinement();
            q1.setup_dofs();
            setup_q2(vector_field);
            state.interpolate();
            classifier_shared &= classifier_follows(q1, before);
          }
      }
    return {nodal_error(q1.dof_handler(), q1.alpha(), scalar),
            nodal_error(q2, vector_field, smooth)};
  }

  double
  option(const std::vector<std::string> &args, const std::string &name)
  {
    for (unsigned int i = 0; i + 1 < args.size(); ++i)
      if (args[i] == name)
        return std::stod(args[i + 1]);
    throw std::runtime_error("missing option " + name);
  }

  SceneParameters
  scene(const std::string &file, const std::vector<std::string> &args)
  {
    std::vector<std::pair<std::string, std::string>> overrides;
    for (unsigned int i = 0; i + 1 < args.size(); ++i)
      if (args[i] == "--set")
        {
          const auto eq = args[i + 1].find('=');
          overrides.emplace_back(args[i + 1].substr(0, eq),
                                 args[i + 1].substr(eq + 1));
        }
    auto parameters = read_scene(file, overrides);
    // The metrics and fields go there; levelsinter's main makes it too.
    if (root)
      std::filesystem::create_directories(parameters.output.directory);
    MPI_Barrier(MPI_COMM_WORLD);
    return parameters;
  }

  bool
  run_transfer(const std::vector<std::string> &args)
  {
    std::vector<unsigned int> levels;
    for (const auto &a : args)
      if (a.rfind("--", 0) == 0)
        break;
      else
        levels.push_back(std::stoi(a));
    std::vector<std::pair<double, double>> errors;
    for (const unsigned int level : levels)
      {
        errors.push_back(transfer_errors(level));
        if (root)
          std::cout << "base level " << level << ": largest nodal error Q1 "
                    << errors.back().first << ", Q2 " << errors.back().second
                    << std::endl;
      }
    bool ok = true;
    for (unsigned int i = 1; i < errors.size(); ++i)
      {
        const double q1 = std::log2(errors[i - 1].first / errors[i].first);
        const double q2 = std::log2(errors[i - 1].second / errors[i].second);
        if (root)
          std::cout << "order Q1 " << q1 << ", Q2 " << q2 << std::endl;
        ok &= check("Q1 transfer order >= " +
                      std::to_string(option(args, "--min-order-q1")),
                    q1 >= option(args, "--min-order-q1"));
        ok &= check("Q2 transfer order >= " +
                      std::to_string(option(args, "--min-order-q2")),
                    q2 >= option(args, "--min-order-q2"));
      }
    ok &= check("one shared mesh classifier per alpha, renewed with alpha, "
                "classifying as a fresh one",
                classifier_shared);
    return ok;
  }

  bool
  run_lagged(const std::vector<std::string> &args)
  {
    auto parameters           = scene(args.at(0), args);
    parameters.time.max_steps = std::stoi(args.at(1));
    std::ostringstream quiet;
    Simulation<2>      simulation(parameters, MPI_COMM_WORLD, quiet);
    const SurfaceDiffusion<2> *diffusion = nullptr;
    for (const auto &m : simulation.scene_mechanisms())
      if (const auto *d = dynamic_cast<const SurfaceDiffusion<2> *>(m.get()))
        diffusion = d;
    if (!diffusion)
      throw std::runtime_error("the scene has no surface diffusion");

    bool         ok            = true;
    unsigned int adapted_steps = 0;
    bool         adapted       = false;
    // Adaptations of the time loop, not the initial refinement.
    simulation.initialise();
    simulation.triangulation().signals.post_distributed_refinement.connect(
      [&]() { adapted = true; });
    simulation.set_step_observer(
      [&](const unsigned int step, double, const LevelSetField<2> &alpha) {
        if (!adapted)
          return;
        // This step solved with the transferred v_s^{n-1}.
        adapted = false;
        ++adapted_steps;
        const auto &lagged = diffusion->lagged_velocity();
        const auto &v_s    = diffusion->geometry().normal_velocity();
        const auto  n_dofs = alpha.dof_handler().n_dofs();
        double      change = -1;
        if (lagged.size() == n_dofs)
          {
            TrilinosWrappers::MPI::Vector difference(
              alpha.locally_owned(), alpha.dof_handler().get_communicator());
            difference = lagged;
            TrilinosWrappers::MPI::Vector current(difference);
            current = v_s;
            difference -= current;
            change = difference.l2_norm() / current.l2_norm();
          }
        if (root)
          std::cout << "step " << step << ": " << n_dofs
                    << " DoFs after adaptation, |v_s^{n-1} - v_s^n| / "
                       "|v_s^n| = "
                    << change << std::endl;
        ok &= check("v_s^{n-1} kept at step " + std::to_string(step),
                    change >= 0 && change < option(args, "--max-lag-change"));
      });
    simulation.run();
    ok &= check("at least one adaptation changed the mesh", adapted_steps > 0);
    return ok;
  }

  bool
  run_bubble(const std::vector<std::string> &args)
  {
    const auto    parameters = scene(args.at(0), args);
    Simulation<2> simulation(parameters, MPI_COMM_WORLD, std::cout);
    simulation.run();

    // The pressure is among the written fields...
    bool ok = true;
    if (root)
      {
        std::ifstream     pvtu(parameters.output.directory +
                           "/fields_00000.pvtu");
        std::stringstream text;
        text << pvtu.rdbuf();
        ok &= check("fields_00000.pvtu lists viscous_flow_pressure",
                    text.str().find("\"viscous_flow_pressure\"") !=
                      std::string::npos);
      }
    // ... and these are its values: the same DataOut fields, read back from
    // the patches.
    // get_dataset_names() is what the writers use to label the patches.
    struct NamedDataOut : DataOut<2>
    {
      using DataOut<2>::get_dataset_names;
    } data_out;
    data_out.attach_triangulation(simulation.triangulation());
    simulation.add_output_fields(data_out);
    data_out.build_patches();
    const auto   names = data_out.get_dataset_names();
    unsigned int p     = names.size();
    for (unsigned int i = 0; i < names.size(); ++i)
      if (names[i] == "viscous_flow_pressure")
        p = i;
    if (p == names.size())
      return check("a viscous_flow_pressure field", false);

    const auto    &particle = parameters.geometry.particles.at(0);
    const Point<2> centre(particle.at(0), particle.at(1));
    const double   R     = particle.at(2);
    const double  gamma    = parameters.materials.surface_tension;
    // Means over r < R/2 and r > 3R/2, off the zone where the ASGS term
    // smears the jump (as viscous_static_bubble_2d).
    double sums[4] = {0, 0, 0, 0};
    for (const auto &patch : data_out.get_patches())
      for (unsigned int v = 0; v < GeometryInfo<2>::vertices_per_cell; ++v)
        {
          const double r = patch.vertices[v].distance(centre);
          const double value = patch.data(p, v);
          if (r < R / 2)
            sums[0] += value, sums[1] += 1;
          else if (r > 1.5 * R)
            sums[2] += value, sums[3] += 1;
        }
    Utilities::MPI::sum(sums, MPI_COMM_WORLD, sums);
    const double jump  = sums[0] / sums[1] - sums[2] / sums[3];
    const double error = std::abs(jump - gamma / R) / (gamma / R);
    if (root)
      std::cout << "p_in - p_out = " << jump << " against gamma / R = "
                << gamma / R << ": relative error " << error << std::endl;
    ok &= check("pressure jump error <= " +
                  std::to_string(option(args, "--max-jump-error")),
                error <= option(args, "--max-jump-error"));
    return ok;
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const std::map<std::string, bool (*)(const std::vector<std::string> &)>
             modes = {{"transfer", run_transfer},
                      {"lagged", run_lagged},
                      {"bubble", run_bubble}};
  const auto mode = argc > 1 ? modes.find(argv[1]) : modes.end();
  root            = Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0;
  try
    {
      if (mode == modes.end())
        throw std::runtime_error(
          "usage: mechanism_hooks transfer|lagged|bubble ARGS (see the head "
          "of mechanism_hooks.cc)");
      return mode->second({argv + 2, argv + argc}) ? 0 : 1;
    }
  catch (const std::exception &e)
    {
      std::cerr << "error: " << e.what() << std::endl;
      return 2;
    }
}
