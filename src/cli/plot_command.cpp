// tehl plot RESULT.h5 [-o DIR]: the figures of a mesh-cycle result as PNG files, drawn by
// scripts/plot_cycle.py (matplotlib and h5py, /usr/bin/python3).
#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <memory>
#include <vector>

#include "cli/commands.hpp"
#include "io/script_path.hpp"
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
            const char* name = fs::path(args->result).filename() == "index.h5" ? "plot_study.py"
                                                                                : "plot_cycle.py";
            const std::string script = internal::FindScript(name);
            if (script.empty()) {
              std::fprintf(stderr, "tehl plot: scripts/%s not found (set TEHL_SCRIPT_DIR)\n",
                           name);
              return kExitInternal;
            }
            std::string out = args->output_dir;
            if (out.empty()) out = fs::path(args->result).parent_path().string();
            if (out.empty()) out = ".";
            std::fflush(stdout);
            const pid_t pid = fork();
            if (pid == 0) {
              execl("/usr/bin/python3", "python3", script.c_str(), args->result.c_str(), "-o",
                    out.c_str(), static_cast<char*>(nullptr));
              std::perror("tehl plot: cannot start /usr/bin/python3");
              _exit(127);
            }
            int status = 0;
            if (pid < 0 || waitpid(pid, &status, 0) < 0) return kExitInternal;
            if (WIFEXITED(status) && WEXITSTATUS(status) == 0) return kExitOk;
            std::fprintf(stderr, "tehl plot: the plot script failed\n");
            return WIFEXITED(status) && WEXITSTATUS(status) == 2 ? kExitBadInput : kExitInternal;
          }};
}

}  // namespace tehl::cli
