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

// Pinion p, 20 teeth, module 2 mm: pitch radius r = m z / 2 = 0.02 m, v_rack = w_p r.
std::string RackPair(const std::string& input,
                     const std::string& output,
                     const std::string& p,
                     const std::string& r) {
  return "[train]\ninput = \"" + input + "\"\noutput = \"" + output +
         "\"\n[gear.p]\nteeth = 20\nmodule_m = 0.002\n" + p + "[rack.r]\n" + r +
         "[mesh.pr]\na = \"p\"\nb = \"r\"\nkind = \"rack\"\n";
}

TEST(TrainReport, RackTrainValuesAndSpeedRatiosCarryInverseUnits) {
  // Rack driven at 0.5 m/s: w_p = 0.5 / 0.02 = 25 rad/s; w_p / v_r = 50 rad/m, so the speed
  // ratio v_r / w_p is 0.02 m/rad. The driven rack is the input: 1 N on it balances
  // -F r = -0.02 N m on the pinion.
  int code = -1;
  std::string out = Report(RackPair("r", "p", "", "speed_m_s = 0.5\n"), &code);
  EXPECT_EQ(code, 0) << out;
  EXPECT_NE(out.find("Train value w_p / w_r = 50 rad/m (speed ratio 0.02 m/rad : 1)"),
            std::string::npos)
      << out;
  EXPECT_NE(out.find("0.5 m/s = 30 m/min  [input]"), std::string::npos) << out;
  EXPECT_NE(out.find("per 1 N on r;"), std::string::npos) << out;
  EXPECT_NE(out.find("-0.02 N m"), std::string::npos) << out;
  // Pinion driven at 100 rpm = 10.472 rad/s: v_r = 0.20944 m/s; v_r / w_p = 0.02 m/rad and
  // the speed ratio w_p / v_r = 50 rad/m.
  out = Report(RackPair("p", "r", "speed_rpm = 100.0\n", ""), &code);
  EXPECT_EQ(code, 0) << out;
  EXPECT_NE(out.find("Train value w_r / w_p = 0.02 m/rad (speed ratio 50 rad/m : 1)"),
            std::string::npos)
      << out;
  EXPECT_NE(out.find("per 1 N m on p;"), std::string::npos) << out;
}

TEST(TrainReport, TheMemberTheMotorDrivesIsMarkedAsTheInput) {
  const auto r = testing::RunTehl("train '" + std::string(TEHL_SOURCE_DIR) +
                                  "/cases/trains/motor_hoist.toml'");
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("counter-clockwise (+)  [input, motor]"), std::string::npos) << r.out;
}

}  // namespace
}  // namespace tehl
