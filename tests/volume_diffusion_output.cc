// The volume-diffusion velocity among the written fields
// (doc/validation.md, "Volume diffusion: stiff and extreme cases"):
//
//   volume_diffusion_output SCENE.prm [--set "Section/Entry=value"]...
//
// runs SCENE (two grains by volume diffusion alone), then checks that
//   - the last fields_NNNNN.pvtu lists volume_diffusion_velocity, and
//     volume_diffusion_displacement as one vector (no pressure block);
//   - its values, read back from the patches of the same DataOut fields,
//     equal the velocity the level set was carried with (volume diffusion
//     is the only mechanism; the volume correction is a field of its own),
//     to rounding (relative 1e-6 of the largest speed: patches hold
//     floats);
//   - at the top of the neck (the midpoint plus the neck radius along y)
//     it points out of the solid (+y): the neck grows.
// Exit code 0 only if every check passes.

#include <deal.II/base/mpi.h>

#include <deal.II/numerics/data_out.h>

#include <levelsinter/analysis/neck.h>
#include <levelsinter/scene/command_line.h>
#include <levelsinter/time/simulation.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <limits>
#include <sstream>

using namespace levelsinter;

namespace
{
  bool
  check(const bool root, const std::string &what, const bool ok)
  {
    if (root)
      std::cout << (ok ? "PASS " : "FAIL ") << what << std::endl;
    return ok;
  }

  // DataOut's per-component names, as the writers label the patches.
  struct NamedDataOut : DataOut<2>
  {
    using DataOut<2>::get_dataset_names;
  };

  unsigned int
  first_index(const std::vector<std::string> &names, const std::string &name)
  {
    for (unsigned int i = 0; i < names.size(); ++i)
      if (names[i] == name)
        return i;
    throw std::runtime_error("no field named " + name);
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const bool root = Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0;
  try
    {
      const std::vector<std::string> args(argv + 1, argv + argc);
      if (args.empty())
        throw std::runtime_error(
          "usage: volume_diffusion_output SCENE.prm [--set ENTRY=VALUE]...");
      std::vector<std::pair<std::string, std::string>> overrides;
      for (unsigned int i = 1; i + 1 < args.size(); i += 2)
        {
          const auto eq = args[i + 1].find('=');
          if (args[i] != "--set" || eq == std::string::npos)
            throw std::runtime_error("expected --set ENTRY=VALUE, got " +
                                     args[i] + " " + args[i + 1]);
          overrides.emplace_back(args[i + 1].substr(0, eq),
                                 args[i + 1].substr(eq + 1));
        }
      const SceneParameters parameters = read_scene(args[0], overrides);
      if (root)
        std::filesystem::create_directories(parameters.output.directory);
      MPI_Barrier(MPI_COMM_WORLD);
      Simulation<2> simulation(parameters, MPI_COMM_WORLD, std::cout);
      simulation.run();

      bool ok = true;
      if (root)
        {
          // The last field file: the run writes at its final step.
          std::string last;
          for (const auto &entry : std::filesystem::directory_iterator(
                 parameters.output.directory))
            if (entry.path().extension() == ".pvtu" &&
                entry.path().filename().string() > last)
              last = entry.path().filename().string();
          std::ifstream     pvtu(parameters.output.directory + "/" + last);
          std::stringstream text;
          text << pvtu.rdbuf();
          ok &= check(root,
                      last + " lists volume_diffusion_velocity",
                      text.str().find("\"volume_diffusion_velocity\"") !=
                        std::string::npos);
          // The displacement u^{n-1} as one vector field, without the
          // unused pressure block of its velocity-pressure vector.
          ok &= check(
            root,
            last + " lists volume_diffusion_displacement as a vector only",
            text.str().find("Name=\"volume_diffusion_displacement\" "
                            "NumberOfComponents=\"3\"") !=
                std::string::npos &&
              text.str().find("displacement_unused") == std::string::npos);
        }

      NamedDataOut data_out;
      data_out.attach_triangulation(simulation.triangulation());
      const auto &velocity = simulation.interface_velocity();
      data_out.add_data_vector(
        velocity.dof_handler(),
        velocity.values(),
        std::vector<std::string>(2, "velocity"),
        std::vector<DataComponentInterpretation::DataComponentInterpretation>(
          2, DataComponentInterpretation::component_is_part_of_vector));
      simulation.add_output_fields(data_out);
      data_out.build_patches();
      const auto         names = data_out.get_dataset_names();
      const unsigned int v     = first_index(names, "velocity");
      const unsigned int w =
        first_index(names, "volume_diffusion_velocity");

      const auto &particles = parameters.geometry.particles;
      const Point<2> c1(particles[0][0], particles[0][1]);
      const Point<2> c2(particles[1][0], particles[1][1]);
      const double   x =
        neck_measures::neck_radius(simulation.level_set(), c1, c2);
      const Point<2> neck_top = 0.5 * (c1 + c2) + Point<2>(0, x);

      double difference = 0, speed = 0, nearest = 1e300, neck_vy = 0;
      for (const auto &patch : data_out.get_patches())
        for (unsigned int k = 0; k < GeometryInfo<2>::vertices_per_cell; ++k)
          {
            for (unsigned int d = 0; d < 2; ++d)
              {
                const double carried = patch.data(v + d, k);
                difference = std::max(difference,
                                      std::abs(carried - patch.data(w + d, k)));
                speed = std::max(speed, std::abs(carried));
              }
            if (const double r = patch.vertices[k].distance(neck_top);
                r < nearest)
              {
                nearest = r;
                neck_vy = patch.data(w + 1, k);
              }
          }
      difference = Utilities::MPI::max(difference, MPI_COMM_WORLD);
      speed      = Utilities::MPI::max(speed, MPI_COMM_WORLD);
      // The rank whose patches hold the vertex nearest to the neck's top.
      const auto closest = Utilities::MPI::min_max_avg(nearest, MPI_COMM_WORLD);
      const double neck_speed = Utilities::MPI::max(
        nearest == closest.min ? neck_vy : -1e300, MPI_COMM_WORLD);
      if (root)
        std::cout << "largest |v - v_vd| " << difference << " of |v| "
                  << speed << "; neck x = " << x << ", v_y at the node "
                  << closest.min << " from its top: " << neck_speed
                  << std::endl;
      ok &= check(root,
                  "the written field is the carried velocity",
                  speed > 0 && difference <= 1e-6 * speed);
      ok &= check(root,
                  "it points out of the solid at the neck",
                  neck_speed > 0);
      return ok ? 0 : 1;
    }
  catch (const std::exception &e)
    {
      std::cerr << "FAIL: " << e.what() << std::endl;
      return 1;
    }
}
