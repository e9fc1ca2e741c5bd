#include <levelsinter/scene/output_parameters.h>
#include <levelsinter/scene/parameter_entries.h>

namespace levelsinter
{
  void
  OutputParameters::declare(ParameterHandler &prm)
  {
    prm.enter_subsection("Output");
    {
      prm.declare_entry("Directory",
                        "output",
                        Patterns::Anything(),
                        "Directory for fields and metrics.csv; created if "
                        "missing. Relative paths are relative to the "
                        "working directory: what a run writes goes where it "
                        "is started, what a scene reads (Geometry/Particle "
                        "file) is found beside the scene file.");
      prm.declare_entry("Overwrite",
                        "false",
                        Patterns::Bool(),
                        "Replace an earlier run in Directory (its fields, "
                        "metrics.csv and parameters.prm are removed first); "
                        "false refuses such a directory. Read by the "
                        "levelsinter program, like its --overwrite.");
      prm.declare_entry("Field interval",
                        "10",
                        Patterns::Integer(0),
                        "Write fields every this many steps (0 = first and "
                        "last step only).");
      prm.declare_entry("Field formats",
                        "vtu, xdmf",
                        Patterns::MultipleSelection("vtu|xdmf|none"),
                        "vtu: PVD/PVTU/VTU series; xdmf: XDMF + HDF5; none.");
      prm.declare_entry("Metrics interval",
                        "1",
                        Patterns::Integer(1),
                        "Append a row to metrics.csv every this many steps "
                        "(the first and last step are always written).");
      prm.declare_entry("Progress interval",
                        "10",
                        Patterns::Integer(0),
                        "Print a progress line every this many steps (0 = "
                        "never).");
      prm.declare_entry("Checkpoint interval",
                        "0",
                        Patterns::Integer(0),
                        "Write a checkpoint to Directory/checkpoints every "
                        "this many steps (0 = never; SIGINT and SIGTERM "
                        "write one anyway). With checkpoints on, a run that "
                        "'Time/Maximum steps' stops before its end time "
                        "writes one of its last step. The last two are "
                        "kept; 'levelsinter --resume Directory' continues "
                        "from the newest.");
      prm.declare_entry("Checkpoint minutes",
                        "0",
                        Patterns::Double(0),
                        "Also write a checkpoint when this many wall-clock "
                        "minutes have passed since the last one (0 = "
                        "never).");
    }
    prm.leave_subsection();
  }

  void
  OutputParameters::parse(ParameterHandler &prm)
  {
    prm.enter_subsection("Output");
    directory         = prm.get("Directory");
    field_interval    = prm.get_integer("Field interval");
    const std::string formats = prm.get("Field formats");
    write_vtu  = formats.find("vtu") != std::string::npos;
    write_xdmf = formats.find("xdmf") != std::string::npos;
    if (formats.find("none") != std::string::npos &&
        (write_vtu || write_xdmf))
      fail_entry("Output/Field formats",
                 "'none' cannot be combined with a format");
    metrics_interval  = prm.get_integer("Metrics interval");
    progress_interval = prm.get_integer("Progress interval");
    checkpoint_interval = prm.get_integer("Checkpoint interval");
    checkpoint_minutes  = prm.get_double("Checkpoint minutes");
    if (directory.empty())
      fail_entry("Output/Directory", "must not be empty");
    prm.leave_subsection();
  }
} // namespace levelsinter
