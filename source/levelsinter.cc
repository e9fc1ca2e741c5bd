// levelsinter: parse a scene, check it, run it.

#include <deal.II/base/mpi.h>

#include <levelsinter/io/checkpoint.h>
#include <levelsinter/io/run_directory.h>
#include <levelsinter/scene/command_line.h>
#include <levelsinter/time/simulation.h>
#include <levelsinter/version.h>

#include <chrono>
#include <csignal>
#include <ctime>
#include <iomanip>
#include <iostream>
#include <optional>
#include <sstream>
#include <thread>

namespace
{
  using namespace levelsinter;

  const std::string version = std::string("levelsinter ") +
                              LEVELSINTER_VERSION + " (commit " +
                              LEVELSINTER_COMMIT + ")";

  // An argument as a shell would need it, so that the recorded command
  // line can be pasted again.
  std::string
  quoted(const std::string &argument)
  {
    if (!argument.empty() &&
        argument.find_first_not_of("abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMN"
                                   "OPQRSTUVWXYZ0123456789-_./=:,+@%") ==
          std::string::npos)
      return argument;
    std::string result = "'";
    for (const char c : argument)
      result += (c == '\'' ? std::string("'\\''") : std::string(1, c));
    return result + "'";
  }

  // The comment at the top of parameters.prm: what ran, when and how.
  std::string
  run_record(const int argc, char **argv, const MPI_Comm comm)
  {
    const std::time_t  now = std::time(nullptr);
    std::ostringstream out;
    out << "The effective value of every entry of this run (scene file, "
           "then --set).\n"
        << "version: " << version << "\n"
        << "date: " << std::put_time(std::gmtime(&now), "%Y-%m-%d %H:%M:%S UTC")
        << "\n"
        << "MPI ranks: " << Utilities::MPI::n_mpi_processes(comm) << "\n"
        << "command line:";
    for (int i = 0; i < argc; ++i)
      out << ' ' << quoted(argv[i]);
    out << "\n";
    return out.str();
  }

  // Whether every rank has reached a failure within @p seconds. An error
  // found collectively (a solver, a check on global values) reaches all
  // ranks at about the same point; one found by a single rank (a file only
  // the first rank writes, an error inside a rank's own assembly) leaves
  // the others waiting in a collective call that never completes, and the
  // run would hang. The barrier runs on a communicator of its own, so that
  // it cannot meet the calls they wait in.
  bool
  every_rank_failed(const MPI_Comm failure_comm, const double seconds)
  {
    MPI_Request request;
    MPI_Ibarrier(failure_comm, &request);
    const auto start = std::chrono::steady_clock::now();
    for (;;)
      {
        int done = 0;
        MPI_Test(&request, &done, MPI_STATUS_IGNORE);
        if (done)
          return true;
        if (std::chrono::duration<double>(std::chrono::steady_clock::now() -
                                          start)
              .count() > seconds)
          return false;
        std::this_thread::sleep_for(std::chrono::milliseconds(10));
      }
  }

  // Returns the exit code: 0, or 128 + the signal that stopped the run
  // (doc/user_guide.md, "Exit codes").
  template <int dim>
  int
  run(const SceneParameters &scene,
      const CommandLine     &command_line,
      const bool             overwrite,
      const std::string     &record,
      const std::string     &parameters,
      const MPI_Comm         comm)
  {
    const bool root = Utilities::MPI::this_mpi_process(comm) == 0;
    // A failure is reported after the simulation has been destroyed
    // normally (its timers communicate in their destructors), with the time
    // per phase up to the failure if the run had started.
    std::string failure;
    bool        started     = false;
    int         stop_signal = 0;
    const Utilities::MPI::DuplicatedCommunicator failure_comm(comm);
    {
      // Everything is checked (the scene, the mechanisms it builds, the
      // output directory) before the earlier run is removed and anything
      // is written.
      std::optional<Simulation<dim>> simulation;
      try
        {
          simulation.emplace(scene, comm, std::cout);
        }
      catch (const std::runtime_error &e)
        {
          // The scene's values were checked when it was read: an input
          // error here would unwind through the timers, whose destructors
          // print deal.II's "uncaught exception" block first. What is left
          // (e.g. a file that vanished since) still names its source.
          throw std::runtime_error(with_source(e.what(),
                                               command_line.scene_file,
                                               command_line.overrides));
        }
      try
        {
          // A resumed run continues the directory's files.
          if (command_line.resume_directory.empty())
            {
              run_directory::prepare(scene.output.directory, overwrite, comm);
              run_directory::write_parameters(scene.output.directory,
                                              record,
                                              parameters,
                                              comm);
            }
          else
            simulation->resume(checkpoint::newest_verified(
              scene.output.directory, comm, std::cout));
          started            = true;
          const auto summary = simulation->run();
          stop_signal        = summary.stop_signal;
          if (root && stop_signal != 0)
            std::cout << "stopped by "
                      << (stop_signal == SIGINT  ? "SIGINT" :
                          stop_signal == SIGTERM ? "SIGTERM" :
                                                   "SIGUSR1")
                      << " at step " << summary.steps
                      << ", t = " << summary.time << "; metrics.csv is "
                      << "complete up to that step\n";
          else if (root)
            {
              std::cout << "done: " << summary.steps << " steps to t = "
                        << summary.time << " in " << summary.wall_time
                        << " s; at most " << summary.max_cells << " cells, "
                        << summary.max_dofs << " DoFs; mean GMRES iterations "
                        << summary.mean_iterations;
              if (summary.shortened_steps > 0)
                std::cout << "; " << summary.shortened_steps
                          << " step(s) computed again with a smaller dt "
                             "after the velocity came out faster than the "
                             "CFL step allowed";
              std::cout << "\n";
            }
        }
      catch (const std::exception &e)
        {
          failure = e.what();
          if (Utilities::MPI::n_mpi_processes(comm) > 1 &&
              !every_rank_failed(*failure_comm, 60))
            {
              std::cerr << "levelsinter: error on rank "
                        << Utilities::MPI::this_mpi_process(comm)
                        << " alone: " << failure
                        << "; the other ranks cannot go on without it, so "
                           "the run is aborted (the last checkpoint stays)"
                        << std::endl;
              MPI_Abort(comm, 1);
            }
        }
      if (started)
        simulation->timer().print_wall_time_statistics(comm);
    }
    if (!failure.empty())
      throw std::runtime_error(failure);
    return stop_signal == 0 ? 0 : 128 + stop_signal;
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
      if (command_line.action == CommandLine::Action::help ||
          command_line.action == CommandLine::Action::version)
        {
          if (root)
            std::cout << (command_line.action == CommandLine::Action::help ?
                            CommandLine::usage() :
                            version + "\n");
          return 0;
        }

      dealii::ParameterHandler prm;
      if (command_line.action == CommandLine::Action::print_parameters)
        {
          // Without a scene: the defaults, which need not form a scene.
          if (command_line.scene_file.empty())
            read_scene_entries(prm, "", command_line.overrides);
          else
            read_scene(prm, command_line.scene_file, command_line.overrides);
          if (root)
            prm.print_parameters(std::cout, dealii::ParameterHandler::PRM);
          return 0;
        }

      const SceneParameters scene =
        read_scene(prm, command_line.scene_file, command_line.overrides);
      prm.enter_subsection("Output");
      const bool overwrite =
        command_line.overwrite || prm.get_bool("Overwrite");
      prm.leave_subsection();
      std::ostringstream parameters;
      prm.print_parameters(parameters, dealii::ParameterHandler::PRM);
      const std::string record = run_record(argc, argv, comm);

      stop_on_signals();
      return scene.dimension == 2 ?
               run<2>(scene,
                      command_line,
                      overwrite,
                      record,
                      parameters.str(),
                      comm) :
               run<3>(scene,
                      command_line,
                      overwrite,
                      record,
                      parameters.str(),
                      comm);
    }
  catch (const std::exception &e)
    {
      if (root)
        std::cerr << "levelsinter: error: " << e.what() << std::endl;
      return 1;
    }
}
