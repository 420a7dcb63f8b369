// tehl plot RESULT.h5 [-o DIR]: the figures of a mesh-cycle result as PNG files, drawn by
// scripts/plot_cycle.py (matplotlib and h5py, /usr/bin/python3).
#include <cstdio>
#include <filesystem>
#include <memory>
#include <vector>

#include "cli/commands.hpp"
#include "cli/python_script.hpp"
#include "tehl/error.hpp"

namespace tehl::cli {
namespace {
namespace fs = std::filesystem;
}  // namespace

Command AddPlotCommand(CLI::App& app) {
  struct Args {
    std::string result;
    std::string output_dir;
  };
  auto args = std::make_shared<Args>();
  CLI::App* sub =
      app.add_subcommand("plot", "PNG figures of a mesh-cycle result or a study index (.h5)");
  sub->add_option("RESULT", args->result,
                  "Result file written by `tehl run` (NAME.h5) or `tehl sweep` (index.h5)")
      ->required();
  sub->add_option("-o,--output-dir", args->output_dir,
                  "Folder for the PNG files (default: beside the result)");
  return {sub, [args]() {
            if (!fs::is_regular_file(args->result)) {
              ProblemList p;
              p.Add({args->result, 0, "RESULT", args->result, "no such result file",
                     "an .h5 file written by `tehl run`"});
              p.ThrowIfAny();
            }
            // A study's index (tehl sweep, docs/studies.md) goes to the study script.
            const char* name =
                fs::path(args->result).filename() == "index.h5" ? "plot_study.py" : "plot_cycle.py";
            std::string out = args->output_dir;
            if (out.empty()) out = fs::path(args->result).parent_path().string();
            if (out.empty()) out = ".";
            return RunPythonScript("tehl plot", name, {args->result, "-o", out});
          }};
}

}  // namespace tehl::cli
