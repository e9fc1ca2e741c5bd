#include <deal.II/base/mpi.h>
#include <deal.II/base/utilities.h>

#include <levelsinter/io/run_directory.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <vector>

namespace levelsinter
{
  namespace run_directory
  {
    namespace
    {
      namespace fs = std::filesystem;

      // The files a run writes (FieldOutput, MetricsLog, write_parameters):
      // fields_NNNNN.pvtu, fields_NNNNN.R.vtu and fields_NNNNN.h5 besides
      // the named ones.
      bool
      is_field_file(const std::string &name)
      {
        const std::string extension = fs::path(name).extension();
        return name.rfind("fields_", 0) == 0 &&
               (extension == ".vtu" || extension == ".pvtu" ||
                extension == ".h5");
      }

      const std::vector<std::string> named_files = {"metrics.csv",
                                                    "parameters.prm",
                                                    "fields.pvd",
                                                    "fields.xdmf"};

      // The error message, empty if the directory is ready.
      std::string
      prepare_on_root(const std::string &directory, const bool overwrite)
      {
        std::error_code ec;
        fs::create_directories(directory, ec);
        {
          const std::string probe = directory + "/.levelsinter_write_test";
          std::ofstream     out(probe);
          const bool        writable = !ec && out;
          out.close();
          fs::remove(probe, ec);
          if (!writable)
            return "output directory '" + directory +
                   "' cannot be created or written (check Output/Directory "
                   "and its permissions)";
        }

        std::vector<fs::path> earlier;
        std::vector<std::string> named;
        unsigned int             n_field_files = 0;
        for (const auto &entry : fs::directory_iterator(directory, ec))
          {
            const std::string name = entry.path().filename();
            if (entry.is_directory() && name == "checkpoints")
              named.push_back(name);
            else if (!entry.is_regular_file())
              continue;
            else if (is_field_file(name))
              ++n_field_files;
            else if (std::find(named_files.begin(),
                               named_files.end(),
                               name) != named_files.end())
              named.push_back(name);
            else
              continue;
            earlier.push_back(entry.path());
          }
        if (earlier.empty())
          return "";
        if (!overwrite)
          {
            std::sort(named.begin(), named.end());
            if (n_field_files > 0)
              named.push_back(std::to_string(n_field_files) + " field files");
            std::string list;
            for (const auto &item : named)
              list += (list.empty() ? "" : ", ") + item;
            return "output directory '" + directory +
                   "' holds an earlier run (" + list +
                   "); choose another Output/Directory, or replace that "
                   "run with --overwrite or 'set Overwrite = true' in "
                   "subsection Output";
          }
        for (const auto &path : earlier)
          {
            // checkpoints/ is a folder.
            fs::remove_all(path, ec);
            if (ec)
              return "cannot remove '" + path.string() +
                     "' of the earlier run: " + ec.message();
          }
        return "";
      }

      // Every rank throws the root's error, so that all stop together.
      void
      throw_if_failed(std::string error, const MPI_Comm comm)
      {
        error = dealii::Utilities::MPI::broadcast(comm, error, 0);
        if (!error.empty())
          throw std::runtime_error(error);
      }
    } // namespace

    void
    prepare(const std::string &directory,
            const bool         overwrite,
            const MPI_Comm     comm)
    {
      std::string error;
      if (dealii::Utilities::MPI::this_mpi_process(comm) == 0)
        error = prepare_on_root(directory, overwrite);
      throw_if_failed(error, comm);
    }

    void
    write_parameters(const std::string &directory,
                     const std::string &header,
                     const std::string &parameters,
                     const MPI_Comm     comm)
    {
      std::string error;
      if (dealii::Utilities::MPI::this_mpi_process(comm) == 0)
        {
          const std::string file_name = directory + "/parameters.prm";
          std::ofstream     out(file_name);
          std::istringstream lines(header);
          for (std::string line; std::getline(lines, line);)
            out << "# " << line << '\n';
          out << parameters;
          if (!out)
            error = "cannot write '" + file_name + "'";
        }
      throw_if_failed(error, comm);
    }
  } // namespace run_directory
} // namespace levelsinter
