// `tehl train` on a train file written from text, for the train tests: its report (stdout
// and stderr) and exit code.
#pragma once

#include <cstdio>
#include <fstream>
#include <string>

#include "unit/cli/run_tehl.hpp"

namespace tehl::testing {

inline std::string TrainReport(const std::string& text, int* code) {
  const std::string path = UniqueTempPath("train.toml");
  std::ofstream(path) << text;
  const RunResult r = RunTehl("train '" + path + "'");
  std::remove(path.c_str());
  *code = r.exit_code;
  return r.out + r.err;
}

}  // namespace tehl::testing
