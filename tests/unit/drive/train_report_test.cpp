// The report of `tehl train` (docs/trains.md): what each printed number is, in which unit
// and with which sign, against hand calculations.
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
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
  // 1 rpm through 12 stages: g12 at 1e-12 rpm = 1.0472e-13 rad/s, slow but turning; in the
  // CSV too.
  const std::string csv = testing::UniqueTempPath("chain.csv");
  out = Report(Chain(12, 1.0), &code, " --csv '" + csv + "'");
  EXPECT_EQ(code, 0) << out;
  EXPECT_NE(out.find("1.0472e-13          1e-12  counter-clockwise (+)"), std::string::npos) << out;
  EXPECT_NE(testing::ReadAll(csv).find("g12,gear,100,,1.047197551e-13,1e-12,"), std::string::npos)
      << testing::ReadAll(csv);
  std::remove(csv.c_str());
  // 14 stages: a train value of 1e-14 is no round-off either.
  out = Report(Chain(14, 1.0), &code);
  EXPECT_NE(out.find("Train value w_g14 / w_p0 = 1e-14 (speed ratio 1e+14 : 1)"), std::string::npos)
      << out;
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

std::string Shipped(const std::string& name, const std::string& options = "") {
  const auto r = testing::RunTehl("train '" + std::string(TEHL_SOURCE_DIR) + "/cases/trains/" +
                                  name + ".toml'" + options);
  EXPECT_EQ(r.exit_code, 0) << r.err;
  return r.out;
}

TEST(TrainReport, MotorRunSplitsTheLosslessOutputTorqueIntoLoadAndLosses) {
  // Hoist: i = (20/40)(25/35)(2/40) = 1/56, T_m = 300 / 56 / 0.6 = 8.92857 N m. Lossless,
  // the drum would take -T_m / i = -500 N m; the load takes 300 of them, the losses
  // (efficiency 0.6) the other 200: 0.6 x 500 = 300.
  const std::string out = Shipped("motor_hoist");
  EXPECT_NE(out.find("at the motor's torque 8.92857 N m on A"), std::string::npos) << out;
  EXPECT_NE(out.find("+8.92857 N m  input (the motor)"), std::string::npos) << out;
  EXPECT_NE(out.find("-500 N m  output at the motor's torque, lossless"), std::string::npos) << out;
  EXPECT_EQ(out.find("(the load)"), std::string::npos) << out;
  EXPECT_NE(out.find("load on drum: -300 N m (the load's torque T_L = 300 N m, against the "
                     "motion); the train's losses: -200 N m (efficiency 0.6)"),
            std::string::npos)
      << out;
}

TEST(TrainReport, MotorCsvGivesTheLosslessAndTheLoadTorque) {
  // Separately excited motor, pinion 20 - gear 80 (i = -1/4), 100 N m on the gear,
  // efficiency 0.95: T_m = 100 / 4 / 0.95 = 26.3158 N m. The gear turns negatively: the
  // lossless output torque is +26.3158 x 4 = +105.263 N m, the load's +100 N m.
  const std::string text =
      "[train]\ninput = \"p\"\noutput = \"g\"\n[gear.p]\nteeth = 20\n[gear.g]\nteeth = 80\n"
      "[mesh.pg]\na = \"p\"\nb = \"g\"\n[motor]\ntype = \"separately_excited\"\n"
      "supply_voltage_v = 240.0\narmature_resistance_ohm = 0.2\nspeed_constant = 1.2\n"
      "field_current_a = 1.5\n[load]\ntorque_nm = 100.0\nefficiency = 0.95\n";
  const std::string csv = testing::UniqueTempPath("motor.csv");
  int code = -1;
  const std::string out = Report(text, &code, " --csv '" + csv + "'");
  EXPECT_EQ(code, 0) << out;
  std::ifstream in(csv);
  std::string header, p, g;
  std::getline(in, header);
  std::getline(in, p);
  std::getline(in, g);
  std::remove(csv.c_str());
  EXPECT_NE(header.find(",torque_nm,force_n,load_torque_nm"), std::string::npos) << header;
  EXPECT_NE(p.find(",26.31578947,,"), std::string::npos) << p;
  EXPECT_NE(g.find(",105.2631579,,100"), std::string::npos) << g;
  // Input power: E I_a = 240 x 14.6199 = 3508.77 W (K_w I_f = 1.8: I_a = 26.3158 / 1.8);
  // the field has its own supply.
  EXPECT_NE(out.find("input 3508.77 W (armature E I_a = 240 V x 14.6199 A; the separately "
                     "excited field, I_f = 1.5 A, has its own supply, not included)"),
            std::string::npos)
      << out;
}

TEST(TrainReport, ShuntMotorInputPowerIsArmatureAndField) {
  // Hoist: E = 220 V, I_a = 8.92857 A, I_f = E / R_f = 220 / 110 = 2 A: the supply gives
  // 220 x 8.92857 = 1964.29 W to the armature and 220 x 2 = 440 W to the field.
  const std::string out = Shipped("motor_hoist");
  EXPECT_NE(out.find("input 2404.29 W (armature E I_a = 1964.29 W + shunt field E I_f = 440 W, "
                     "I_f = 2 A)"),
            std::string::npos)
      << out;
}

TEST(TrainReport, SumOfTheTorquesIsTheHousingReaction) {
  // Reverted reducer, 1 N m on A: T_D = -1 / ((20/40)(25/35)) = -2.8 N m; the bearings of
  // the counter shaft take the rest: the frame applies -(1 - 2.8) = +1.8 N m to the gears.
  std::string out = Shipped("reverted");
  EXPECT_NE(out.find("housing (frame) reaction through the bearings: +1.8 N m"), std::string::npos)
      << out;
  // A planetary is coaxial: the held ring's +1.8 N m is the frame's whole share.
  out = Shipped("seed001_ex2_11_planetary_reducer");
  EXPECT_NE(out.find("housing (frame) reaction through the bearings: 0 N m"), std::string::npos)
      << out;
}

TEST(TrainReport, CsvIntoMissingFoldersCreatesThem) {
  // As `tehl gear --csv`: the folders of the path are made, the file written atomically.
  namespace fs = std::filesystem;
  const fs::path top = testing::UniqueTempPath("csv_folders");
  const fs::path csv = top / "a" / "b" / "speeds.csv";
  ASSERT_FALSE(fs::exists(top));
  Shipped("reverted", " --csv '" + csv.string() + "'");
  EXPECT_TRUE(fs::is_regular_file(csv));
  EXPECT_FALSE(fs::exists(csv.string() + ".part"));
  fs::remove_all(top);
}

}  // namespace
}  // namespace tehl
