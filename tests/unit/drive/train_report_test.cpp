// The report of `tehl train` (docs/trains.md): what each printed number is, in which unit
// and with which sign, against hand calculations.
#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <string>

#include "unit/cli/run_tehl.hpp"

namespace tehl {
namespace {

std::string Report(const std::string& text, int* code, const std::string& options = "") {
  const std::string path = testing::UniqueTempPath("train.toml");
  std::ofstream(path) << text;
  const auto r = testing::RunTehl("train '" + path + "'" + options);
  std::remove(path.c_str());
  *code = r.exit_code;
  return r.out + r.err;
}

// Input p0 (10 teeth) at `rpm`, then `stages` stages of 10 -> 100 teeth: the output turns at
// rpm (-0.1)^stages.
std::string Chain(int stages, double rpm) {
  std::string t = "[train]\ninput = \"p0\"\noutput = \"g" + std::to_string(stages) +
                  "\"\n[gear.p0]\nteeth = 10\nspeed_rpm = " + std::to_string(rpm) + "\n";
  for (int k = 1; k <= stages; ++k) {
    const std::string n = std::to_string(k);
    t += "[gear.g" + n + "]\nteeth = 100\nshaft = \"s" + n + "\"\n";
    if (k < stages) t += "[gear.p" + n + "]\nteeth = 10\nshaft = \"s" + n + "\"\n";
    t += "[mesh.m" + n + "]\na = \"p" + std::to_string(k - 1) + "\"\nb = \"g" + n + "\"\n";
  }
  return t;
}

TEST(TrainReport, HighRatioTrainsPrintTheirExactSpeedsAndRatio) {
  // 3000 rpm through 8 stages: g8 at 3000e-8 = 3e-05 rpm, speed ratio 1e8 exactly.
  int code = -1;
  std::string out = Report(Chain(8, 3000.0), &code);
  EXPECT_EQ(code, 0) << out;
  EXPECT_NE(out.find("Train value w_g8 / w_p0 = 1e-08 (speed ratio 1e+08 : 1)"), std::string::npos)
      << out;
  EXPECT_NE(out.find("3e-05  counter-clockwise (+)"), std::string::npos) << out;
  // 1 rpm through 12 stages: g12 at 1e-12 rpm = 1.0472e-13 rad/s, slow but turning.
  out = Report(Chain(12, 1.0), &code);
  EXPECT_EQ(code, 0) << out;
  EXPECT_NE(out.find("1.0472e-13          1e-12  counter-clockwise (+)"), std::string::npos) << out;
}

}  // namespace
}  // namespace tehl
