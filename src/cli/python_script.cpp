#include "cli/python_script.hpp"

#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>

#include "cli/commands.hpp"
#include "io/script_path.hpp"

namespace tehl::cli {

namespace {
constexpr int kCannotStart = 127;  // the child's exit code when exec fails
}  // namespace

int RunPythonScript(const std::string& command,
                    const std::string& script_name,
                    const std::vector<std::string>& args) {
  const std::string script = internal::FindScript(script_name);
  if (script.empty()) {
    std::fprintf(stderr, "%s: scripts/%s not found (set TEHL_SCRIPT_DIR)\n", command.c_str(),
                 script_name.c_str());
    return kExitInternal;
  }
  const char* env = std::getenv("TEHL_PYTHON");
  const std::string python = env && *env                                   ? env
                             : std::filesystem::exists("/usr/bin/python3") ? "/usr/bin/python3"
                                                                           : "python3";
  std::vector<std::string> argv_text = {python, script};
  argv_text.insert(argv_text.end(), args.begin(), args.end());
  std::vector<char*> argv;
  for (std::string& a : argv_text) argv.push_back(a.data());
  argv.push_back(nullptr);
  std::fflush(stdout);
  std::fflush(stderr);
  const pid_t pid = fork();
  if (pid == 0) {
    execvp(argv[0], argv.data());  // a bare "python3" is looked up on PATH
    _exit(kCannotStart);
  }
  int status = 0;
  if (pid < 0 || waitpid(pid, &status, 0) < 0) return kExitInternal;
  if (WIFEXITED(status) && WEXITSTATUS(status) == 0) return kExitOk;
  if (WIFEXITED(status) && WEXITSTATUS(status) == kCannotStart) {
    std::fprintf(stderr,
                 "%s: cannot start %s (allowed: a python3 with matplotlib and h5py, e.g. "
                 "Debian's python3-matplotlib and python3-h5py, or TEHL_PYTHON naming one)\n",
                 command.c_str(), python.c_str());
    return kExitBadInput;
  }
  // The scripts say why they stop: 2 for input they cannot plot, 4 for a result with nothing
  // converged to plot; anything else (1: an uncaught exception) is a failure of the script.
  if (WIFEXITED(status) && WEXITSTATUS(status) == 2) return kExitBadInput;
  if (WIFEXITED(status) && WEXITSTATUS(status) == 4) return kExitNotConverged;
  std::fprintf(stderr, "%s: the plot script failed\n", command.c_str());
  return kExitInternal;
}

}  // namespace tehl::cli
