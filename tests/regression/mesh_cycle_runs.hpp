// Reduced-resolution runs of the seed 004 mesh cycle for the regression tests: the case file
// of cases/ with grid points, steps and operating keys replaced, written to a temporary folder.
#pragma once

#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <sstream>
#include <string>

#include "support/scratch_path.hpp"
#include "tehl/scene/mesh_cycle_scene.hpp"

namespace tehl::testing {

inline std::string ReadText(const std::string& path) {
  std::ifstream in(path);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

inline std::string TempDirFor(const std::string& name) {
  // Emptied first: a process of an earlier run with the same pid may have left this path
  // behind, and a test must not see its files (a stale scene result made a resume test fail).
  return ScratchPath("tehl_cycle", name);
}

// cases/<case_name>.toml with each `key = value` line of `replace` (by key name) replaced;
// keys not in the file are added to [numerics] when they are numerics keys. Returns the path
// of the written file.
inline std::string ReducedCase(const std::string& case_name,
                               const std::map<std::string, std::string>& replace) {
  std::string text = ReadText(std::string(TEHL_SOURCE_DIR) + "/cases/" + case_name + ".toml");
  for (const auto& [key, value] : replace) {
    const std::regex line("(^|\n)" + key + " = [^\n]*");
    if (std::regex_search(text, line))
      text = std::regex_replace(text, line, "$1" + key + " = " + value);
    else
      text = std::regex_replace(text, std::regex("\\[numerics\\]\n"),
                                "[numerics]\n" + key + " = " + value + "\n");
  }
  const std::string path = TempDirFor(case_name + ".toml");
  std::ofstream(path) << text;
  return path;
}

// The reduced resolution of these tests: 257 nodes, 40 steps (about 3 s per cycle), and the
// isothermal film unless `more` says otherwise (cases/seed004_sae40.toml is thermal).
inline std::map<std::string, std::string> Reduced(std::map<std::string, std::string> more = {}) {
  more.emplace("grid_points", "257");
  more.emplace("steps", "40");
  more.emplace("thermal", "false");
  return more;
}

inline MeshCycleResult RunReduced(const std::string& case_name,
                                  const std::map<std::string, std::string>& replace = Reduced()) {
  MeshCycleRunOptions o;
  o.quiet = true;
  o.write_files = false;
  return RunMeshCycle(ReducedCase(case_name, replace), o);
}

// Starts `tehl run` as a child and kills it with SIGKILL right after its first checkpoint
// (written every 5 steps): TEHL_STOP_AFTER_CHECKPOINT makes the child stop itself (SIGSTOP)
// once the checkpoint is written, so the kill lands at a known step however fast or slow the
// run is.
inline void RunAndKillAfterCheckpoint(const std::string& case_path, const std::string& dir) {
  const std::string checkpoint =
      dir + "/" + std::filesystem::path(case_path).stem().string() + ".checkpoint";
  const pid_t pid = fork();
  ASSERT_GE(pid, 0);
  if (pid == 0) {
    std::FILE* o = std::freopen("/dev/null", "w", stdout);
    std::FILE* e = std::freopen("/dev/null", "w", stderr);
    (void)o;
    (void)e;
    setenv("TEHL_STOP_AFTER_CHECKPOINT", "1", 1);
    execl(TEHL_BINARY, "tehl", "run", case_path.c_str(), "-o", dir.c_str(), "-q",
          "--checkpoint-every", "5", static_cast<char*>(nullptr));
    _exit(127);
  }
  int status = 0;
  ASSERT_EQ(waitpid(pid, &status, WUNTRACED), pid);
  ASSERT_TRUE(WIFSTOPPED(status)) << "the run ended before its first checkpoint";
  ASSERT_TRUE(std::filesystem::exists(checkpoint)) << "stopped without a checkpoint";
  ASSERT_EQ(kill(pid, SIGKILL), 0);
  ASSERT_EQ(waitpid(pid, &status, 0), pid);
  ASSERT_TRUE(WIFSIGNALED(status));
  EXPECT_EQ(WTERMSIG(status), SIGKILL);
}

}  // namespace tehl::testing
