// Reduced-resolution runs of the seed 004 mesh cycle for the regression tests: the case file
// of cases/ with grid points, steps and operating keys replaced, written to a temporary folder.
#pragma once

#include <gtest/gtest.h>
#include <unistd.h>

#include <fstream>
#include <filesystem>
#include <map>
#include <regex>
#include <sstream>
#include <string>

#include "tehl/scene/mesh_cycle_scene.hpp"
#include "support/scratch_path.hpp"

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

}  // namespace tehl::testing
