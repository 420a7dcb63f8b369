// tehl run CASE: runs a case (a [contact] line contact in this version).
#include <cstdio>
#include <memory>

#include "cli/commands.hpp"
#include "tehl/scene/contact_scene.hpp"

namespace tehl::cli {

Command AddRunCommand(CLI::App& app) {
  struct Args {
    std::string case_path;
    std::string output_dir;
    bool quiet = false;
  };
  auto args = std::make_shared<Args>();
  CLI::App* sub = app.add_subcommand("run", "Run a case: film pressure and thickness");
  sub->add_option("CASE", args->case_path, "Case file (.toml)")->required();
  sub->add_option("-o,--output-dir", args->output_dir, "Folder for the results ([output])");
  sub->add_flag("-q,--quiet", args->quiet, "No progress line on stderr");
  return {sub, [args]() {
            ContactRunOptions o;
            o.quiet = args->quiet;
            o.output_dir = args->output_dir;
            const ContactRunResult r = RunContactCase(args->case_path, o);
            const auto& last = r.steps.back();
            std::printf("h_min = %.6g m, h_c = %.6g m, p_max = %.6g Pa\n", last.h_min_m,
                        last.h_c_m, last.p_max_pa);
            std::printf("wrote %s and %s\n", r.profile_csv.c_str(), r.history_csv.c_str());
            if (!r.converged()) {
              std::fprintf(stderr, "tehl run: the solver did not converge: %s\n",
                           last.summary.message.c_str());
              return kExitNotConverged;
            }
            return kExitOk;
          }};
}

}  // namespace tehl::cli
