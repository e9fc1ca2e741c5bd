#include <deal.II/base/utilities.h>

#include <levelsinter/io/checkpoint.h>

#include <algorithm>
#include <filesystem>
#include <stdexcept>
#include <vector>

namespace levelsinter
{
  using namespace dealii;

  namespace checkpoint
  {
    namespace
    {
      namespace fs = std::filesystem;

      std::string
      folder(const std::string &directory, const unsigned int step)
      {
        return directory + "/checkpoints/step_" +
               Utilities::int_to_string(step, 6);
      }

      // The complete checkpoints (no .tmp suffix), oldest first: the
      // zero-padded names sort by step.
      std::vector<fs::path>
      complete(const std::string &directory)
      {
        std::vector<fs::path> found;
        std::error_code       ec;
        for (const auto &entry :
             fs::directory_iterator(directory + "/checkpoints", ec))
          {
            const std::string name = entry.path().filename();
            if (entry.is_directory() && name.rfind("step_", 0) == 0 &&
                entry.path().extension().empty())
              found.push_back(entry.path());
          }
        std::sort(found.begin(), found.end());
        return found;
      }

      // Every rank throws the root's error, so that all stop together.
      void
      throw_if_failed(std::string error, const MPI_Comm comm)
      {
        error = Utilities::MPI::broadcast(comm, error, 0);
        if (!error.empty())
          throw std::runtime_error(error);
      }
    } // namespace

    std::string
    begin(const std::string &directory,
          const unsigned int step,
          const MPI_Comm     comm)
    {
      const std::string temporary = folder(directory, step) + ".tmp";
      std::string       error;
      if (Utilities::MPI::this_mpi_process(comm) == 0)
        {
          std::error_code ec;
          fs::remove_all(temporary, ec);
          fs::create_directories(temporary, ec);
          if (ec)
            error = "cannot create the checkpoint folder '" + temporary +
                    "': " + ec.message();
        }
      throw_if_failed(error, comm);
      return temporary;
    }

    std::string
    commit(const std::string &directory,
           const unsigned int step,
           const MPI_Comm     comm)
    {
      // Every rank has written its part.
      MPI_Barrier(comm);
      const std::string final_name = folder(directory, step);
      std::string       error;
      if (Utilities::MPI::this_mpi_process(comm) == 0)
        {
          std::error_code ec;
          fs::remove_all(final_name, ec);
          fs::rename(final_name + ".tmp", final_name, ec);
          if (ec)
            error = "cannot rename the checkpoint folder '" + final_name +
                    ".tmp': " + ec.message();
          const auto all = complete(directory);
          for (std::size_t i = 0; i + 2 < all.size(); ++i)
            fs::remove_all(all[i], ec);
        }
      throw_if_failed(error, comm);
      return final_name;
    }

    std::string
    newest(const std::string &directory)
    {
      const auto all = complete(directory);
      if (all.empty())
        throw std::runtime_error("'" + directory +
                                 "/checkpoints' holds no complete checkpoint "
                                 "(step_NNNNNN); was Output/Checkpoint "
                                 "interval set?");
      return all.back().string();
    }

    std::uintmax_t
    size(const std::string &checkpoint_folder)
    {
      std::uintmax_t bytes = 0;
      for (const auto &entry : fs::directory_iterator(checkpoint_folder))
        if (entry.is_regular_file())
          bytes += entry.file_size();
      return bytes;
    }
  } // namespace checkpoint
} // namespace levelsinter
