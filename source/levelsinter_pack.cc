// levelsinter-pack: writes a random packing as a particle CSV for the
// scenes (scene/packing_generator.h for the algorithm).
#include <levelsinter/scene/packing_generator.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <sstream>
#include <stdexcept>

namespace
{
  using namespace levelsinter;

  std::string
  corners(const std::vector<double> &lo, const std::vector<double> &hi)
  {
    std::ostringstream out;
    for (unsigned int d = 0; d < lo.size(); ++d)
      out << (d ? "," : "") << lo[d];
    out << ":";
    for (unsigned int d = 0; d < hi.size(); ++d)
      out << (d ? "," : "") << hi[d];
    return out.str();
  }

  // The statistics, one per line, for the terminal and the CSV comments.
  std::vector<std::string>
  summary(const packing::Settings &s, const packing::Result &r)
  {
    std::vector<std::string> lines;
    std::ostringstream       out;
    const auto               line = [&]() {
      lines.push_back(out.str());
      out.str("");
    };
    out << std::setprecision(5);
    out << "particles: " << s.n_particles << " (+ " << r.n_images
        << " mirror images across symmetry planes)";
    line();
    out << "container: " << corners(r.container_lower, r.container_upper)
        << (s.periodic ? " (periodic)" : "");
    line();
    out << "force-biased iterations: " << r.iterations
        << (r.converged ? "" : " (not converged: looser than jammed)");
    line();
    out << "solid fraction, sum of particle volumes / container (before "
           "necks): "
        << r.nominal_fraction;
    line();
    out << "solid fraction of the union, container: " << r.fraction
        << "; interior " << corners(r.interior_lower, r.interior_upper)
        << ": ";
    if (std::isnan(r.interior_fraction))
      out << "n/a (container smaller than the margins)";
    else
      out << r.interior_fraction;
    out << " (sampled, spacing " << r.sample_spacing << ")";
    line();
    out << "mean coordination number: " << r.coordination << ", interior: "
        << r.interior_coordination << " (" << r.n_contacts
        << " contacts: centre distance < (r_i + r_j)(1 + " << s.contact_gap
        << "), mirror images count, walls do not)";
    line();
    out << "neck x0/R of the contacting pairs (R = 2 r_i r_j/(r_i + r_j)): "
           "min "
        << r.neck_min << ", mean " << r.neck_mean << ", max " << r.neck_max
        << "; other overlapping pairs: " << r.n_other_overlaps
        << ", largest x0/R " << r.other_overlap_neck_max
        << " (distance error left / r_min: " << r.neck_residual << ")";
    line();
    return lines;
  }
} // namespace

int
main(int argc, char **argv)
{
  try
    {
      const std::vector<std::string> arguments(argv + 1, argv + argc);
      for (const auto &a : arguments)
        if (a == "--help" || a == "-h")
          {
            std::cout << packing::usage();
            return 0;
          }
      std::string    output_file;
      bool           overwrite = false;
      const auto     settings =
        packing::parse_arguments(arguments, output_file, overwrite);
      // As levelsinter refuses an output directory holding a run: checked
      // before the (possibly long) generation.
      if (std::filesystem::is_directory(output_file))
        throw std::runtime_error("--output: '" + output_file +
                                 "' is a directory; give a file name");
      if (std::filesystem::exists(output_file) && !overwrite)
        throw std::runtime_error("--output: '" + output_file +
                                 "' exists; choose another file, or replace "
                                 "it with --overwrite");
      const auto     result   = packing::generate(settings);
      const auto     lines    = summary(settings, result);
      std::string    command  = "levelsinter-pack";
      for (const auto &a : arguments)
        command += " " + (a.find_first_of(" ;") == std::string::npos ?
                            a :
                            "\"" + a + "\"");
      // Written next to it and renamed: a failed write leaves an existing
      // file as it was.
      const std::string temporary = output_file + ".tmp";
      std::ofstream     out(temporary);
      if (!out)
        throw std::runtime_error("--output: '" + output_file +
                                 "' cannot be opened for writing");
      out << "# " << command << "\n";
      for (const auto &l : lines)
        {
          out << "# " << l << "\n";
          std::cout << l << "\n";
        }
      out << (settings.dim == 2 ? "x,y,r\n" : "x,y,z,r\n");
      out << std::setprecision(10);
      for (const auto &p : result.particles)
        for (unsigned int k = 0; k < p.size(); ++k)
          out << p[k] << (k + 1 < p.size() ? "," : "\n");
      out.close();
      if (!out)
        {
          std::filesystem::remove(temporary);
          throw std::runtime_error("--output: writing '" + output_file +
                                   "' failed");
        }
      std::filesystem::rename(temporary, output_file);
      std::cout << "wrote " << output_file << "\n";
    }
  catch (const std::exception &e)
    {
      std::cerr << "levelsinter-pack: error: " << e.what() << "\n";
      return 1;
    }
  return 0;
}
