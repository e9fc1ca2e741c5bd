// levelsinter: parse a scene, check it, run it.

#include <deal.II/base/mpi.h>

#include <levelsinter/scene/command_line.h>
#include <levelsinter/time/simulation.h>

#include <filesystem>
#include <fstream>
#include <iostream>

namespace
{
  using namespace levelsinter;

  // Create the output directory and prove it is writable before any
  // computing, so that a bad path fails at once and leaves nothing behind.
  void
  prepare_output_directory(const std::string &directory, const MPI_Comm comm)
  {
    std::string error;
    if (Utilities::MPI::this_mpi_process(comm) == 0)
      {
        std::error_code ec;
        std::filesystem::create_directories(directory, ec);
        const std::string probe = directory + "/.levelsinter_write_test";
        std::ofstream     out(probe);
        if (ec || !out)
          error = "output directory '" + directory +
                  "' cannot be created or written (check Output/Directory "
                  "and its permissions)";
        out.close();
        std::filesystem::remove(probe, ec);
      }
    error = Utilities::MPI::broadcast(comm, error, 0);
    if (!error.empty())
      throw std::runtime_error(error);
  }

  template <int dim>
  void
  run(const SceneParameters &scene, const MPI_Comm comm)
  {
    // A failure inside the run is reported after the simulation has been
    // destroyed normally (its timers communicate in their destructors),
    // with the time per phase up to the failure.
    std::string failure;
    {
      Simulation<dim> simulation(scene, comm, std::cout);
      prepare_output_directory(scene.output.directory, comm);
      try
        {
          const auto summary = simulation.run();
          if (Utilities::MPI::this_mpi_process(comm) == 0)
            std::cout << "done: " << summary.steps << " steps to t = "
                      << summary.time << " in " << summary.wall_time
                      << " s; at most " << summary.max_cells << " cells, "
                      << summary.max_dofs << " DoFs; mean GMRES iterations "
                      << summary.mean_iterations << "\n";
        }
      catch (const std::exception &e)
        {
          failure = e.what();
        }
      simulation.timer().print_wall_time_statistics(comm);
    }
    if (!failure.empty())
      throw std::runtime_error(failure);
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const MPI_Comm comm = MPI_COMM_WORLD;
  const bool     root = dealii::Utilities::MPI::this_mpi_process(comm) == 0;
  try
    {
      const CommandLine command_line = CommandLine::parse(argc, argv);
      if (command_line.action == CommandLine::Action::help)
        {
          if (root)
            std::cout << CommandLine::usage();
          return 0;
        }
      if (command_line.action == CommandLine::Action::print_parameters)
        {
          dealii::ParameterHandler prm;
          SceneParameters::declare_parameters(prm);
          if (root)
            prm.print_parameters(std::cout, dealii::ParameterHandler::PRM);
          return 0;
        }

      const SceneParameters scene =
        read_scene(command_line.scene_file, command_line.overrides);
      if (scene.dimension == 2)
        run<2>(scene, comm);
      else
        run<3>(scene, comm);
    }
  catch (const std::exception &e)
    {
      if (root)
        std::cerr << "levelsinter: error: " << e.what() << std::endl;
      return 1;
    }
  return 0;
}
