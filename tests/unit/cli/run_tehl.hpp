// Runs the real `tehl` program (TEHL_BINARY) and captures its exit status and output.
#pragma once

#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>
#include "support/scratch_path.hpp"

namespace tehl::testing {

struct RunResult {
  bool exited = false;   // false: killed by a signal (a crash)
  int exit_code = -1;    // valid when exited
  int signal = 0;        // valid when !exited
  std::string out, err;  // stdout and stderr
};

inline std::string ReadAll(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

// A path in the test temporary folder that no other process uses (ctest -j, other builds).
inline std::string UniqueTempPath(const std::string& name) {
  return testing::ScratchPath("tehl", name);
}

// `args` is appended to the program path as shell words; paths must not contain quotes.
inline RunResult RunTehl(const std::string& args) {
  const ScratchDir dir("tehl");
  const std::string out = dir.Path("stdout.txt"), err = dir.Path("stderr.txt");
  const std::string cmd =
      std::string("'") + TEHL_BINARY + "' " + args + " >'" + out + "' 2>'" + err + "'";
  const int status = std::system(cmd.c_str());
  RunResult r;
  if (status != -1 && WIFEXITED(status)) {
    r.exited = true;
    r.exit_code = WEXITSTATUS(status);
  } else if (status != -1 && WIFSIGNALED(status)) {
    r.signal = WTERMSIG(status);
  }
  r.out = ReadAll(out);
  r.err = ReadAll(err);
  return r;
}

}  // namespace tehl::testing
