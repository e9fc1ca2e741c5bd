#include <deal.II/base/utilities.h>

#include <levelsinter/io/checkpoint.h>

#include <boost/crc.hpp>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iterator>
#include <sstream>
#include <stdexcept>
#include <utility>
#include <vector>

namespace levelsinter
{
  using namespace dealii;

  namespace checkpoint
  {
    namespace
    {
      namespace fs = std::filesystem;

      // manifest.txt: this header, a line "FILE BYTES CRC32" per file, and
      // "end CRC32" with the CRC-32 of every byte before it, so that a
      // truncated or changed manifest is recognised as well.
      const std::string manifest_name   = "manifest.txt";
      const std::string manifest_header = "levelsinter checkpoint manifest 1";

      std::string
      folder(const std::string &directory, const unsigned int step)
      {
        return directory + "/checkpoints/step_" +
               Utilities::int_to_string(step, 6);
      }

      // The complete checkpoints (no .tmp or .damaged suffix), oldest
      // first: the zero-padded names sort by step.
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

      std::string
      hex(const std::uint32_t value)
      {
        std::ostringstream out;
        out << std::hex << std::setw(8) << std::setfill('0') << value;
        return out.str();
      }

      std::string
      crc32(const std::string &bytes)
      {
        boost::crc_32_type crc;
        crc.process_bytes(bytes.data(), bytes.size());
        return hex(crc.checksum());
      }

      // Read in chunks: a 3D checkpoint can be larger than one wants in
      // memory at once.
      std::string
      crc32(const fs::path &file)
      {
        std::ifstream      in(file, std::ios::binary);
        boost::crc_32_type crc;
        std::vector<char>  buffer(1 << 20);
        while (in)
          {
            in.read(buffer.data(), buffer.size());
            crc.process_bytes(buffer.data(), in.gcount());
          }
        return hex(crc.checksum());
      }

      // Write the manifest of every file in @p checkpoint_folder, into a
      // temporary file renamed at the end; returns an error or "" (rank 0
      // alone runs this: it must not throw past the others).
      std::string
      write_manifest(const fs::path &checkpoint_folder)
      {
        try
          {
            std::vector<fs::path> files;
            for (const auto &entry :
                 fs::directory_iterator(checkpoint_folder))
              if (entry.is_regular_file())
                files.push_back(entry.path());
            std::sort(files.begin(), files.end());
            std::ostringstream body;
            body << manifest_header << '\n';
            for (const auto &file : files)
              body << file.filename().string() << ' ' << fs::file_size(file)
                   << ' ' << crc32(file) << '\n';
            const fs::path manifest  = checkpoint_folder / manifest_name;
            const fs::path temporary = manifest.string() + ".tmp";
            {
              std::ofstream out(temporary, std::ios::binary);
              out << body.str() << "end " << crc32(body.str()) << '\n';
              if (!out)
                return "cannot write '" + temporary.string() + "'";
            }
            fs::rename(temporary, manifest);
            return "";
          }
        catch (const std::exception &e)
          {
            return "cannot write the manifest of '" +
                   checkpoint_folder.string() + "': " + e.what();
          }
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
          error = write_manifest(final_name + ".tmp");
          std::error_code ec;
          if (error.empty())
            {
              fs::remove_all(final_name, ec);
              fs::rename(final_name + ".tmp", final_name, ec);
              if (ec)
                error = "cannot rename the checkpoint folder '" + final_name +
                        ".tmp': " + ec.message();
            }
          if (error.empty())
            {
              const std::string fault = verify(final_name);
              if (!fault.empty())
                error = "the checkpoint just written, '" + final_name +
                        "', does not verify: " + fault +
                        "; the earlier checkpoints are kept";
            }
          if (error.empty())
            {
              const auto all = complete(directory);
              for (std::size_t i = 0; i + 2 < all.size(); ++i)
                fs::remove_all(all[i], ec);
            }
        }
      throw_if_failed(error, comm);
      return final_name;
    }

    std::string
    verify(const std::string &checkpoint_folder)
    {
      const fs::path folder_path(checkpoint_folder);
      std::ifstream  in(folder_path / manifest_name, std::ios::binary);
      if (!in)
        return "it has no " + manifest_name +
               " (it was written by a levelsinter older than checkpoint "
               "manifests, or the manifest was lost), so it cannot be "
               "verified";
      const std::string text((std::istreambuf_iterator<char>(in)),
                             std::istreambuf_iterator<char>());
      const auto        end_line = text.rfind("\nend ");
      if (end_line == std::string::npos || text.back() != '\n')
        return manifest_name + " is incomplete (it has no final 'end' line)";
      const std::string body = text.substr(0, end_line + 1);
      if (text.substr(end_line + 1) != "end " + crc32(body) + "\n")
        return manifest_name +
               " is damaged (its content does not match its own CRC-32)";

      std::istringstream lines(body);
      std::string        line;
      std::getline(lines, line);
      if (line != manifest_header)
        return manifest_name + " does not start with '" + manifest_header +
               "'";
      while (std::getline(lines, line))
        {
          std::istringstream fields(line);
          std::string        name, checksum;
          std::uintmax_t     bytes = 0;
          if (!(fields >> name >> bytes >> checksum))
            return manifest_name + " has a malformed line '" + line + "'";
          const fs::path  file = folder_path / name;
          std::error_code ec;
          if (!fs::is_regular_file(file, ec))
            return "'" + name + "' is missing";
          const std::uintmax_t actual = fs::file_size(file, ec);
          if (actual != bytes)
            return "'" + name + "' has " + std::to_string(actual) +
                   " bytes, the manifest lists " + std::to_string(bytes);
          const std::string actual_checksum = crc32(file);
          if (actual_checksum != checksum)
            return "'" + name + "' is damaged: its CRC-32 is " +
                   actual_checksum + ", the manifest lists " + checksum;
        }
      return "";
    }

    std::string
    newest_verified(const std::string &directory,
                    const MPI_Comm     comm,
                    std::ostream      &progress)
    {
      std::string chosen, error;
      if (Utilities::MPI::this_mpi_process(comm) == 0)
        {
          const auto all = complete(directory);
          // The newer checkpoints that do not verify, with their faults.
          std::vector<std::pair<fs::path, std::string>> damaged;
          for (auto c = all.rbegin(); c != all.rend() && chosen.empty(); ++c)
            {
              const std::string fault = verify(*c);
              if (fault.empty())
                chosen = c->string();
              else
                damaged.emplace_back(*c, fault);
            }
          if (all.empty())
            error = "'" + directory +
                    "/checkpoints' holds no complete checkpoint "
                    "(step_NNNNNN); was Output/Checkpoint interval set?";
          else if (chosen.empty())
            {
              error = "no checkpoint in '" + directory +
                      "/checkpoints' can be used:";
              for (const auto &[path, fault] : damaged)
                error += " " + path.filename().string() + ": " + fault + ";";
              error += " start the run again without --resume";
            }
          // Set aside rather than deleted: the resumed run would otherwise
          // prune good checkpoints before them, and they can be looked at.
          for (const auto &[path, fault] : damaged)
            if (error.empty())
              {
                const fs::path  aside = path.string() + ".damaged";
                std::error_code ec;
                fs::remove_all(aside, ec);
                fs::rename(path, aside, ec);
                if (ec)
                  error = "cannot rename '" + path.string() + "' to '" +
                          aside.string() + "': " + ec.message();
                else
                  progress << "warning: checkpoint '" << path.string()
                           << "' cannot be used: " << fault
                           << "; set aside as '" << aside.filename().string()
                           << "'" << std::endl;
              }
          if (error.empty() && !damaged.empty())
            progress << "resuming from the previous checkpoint '" << chosen
                     << "' instead" << std::endl;
        }
      throw_if_failed(error, comm);
      return Utilities::MPI::broadcast(comm, chosen, 0);
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
