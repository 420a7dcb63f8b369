// Train files of cases/trains/ (docs/trains.md) read, solved and checked against the seed
// answers; the `tehl train` command; file:line messages for bad files.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <string>

#include "drive/train_reader.hpp"
#include "tehl/error.hpp"
#include "tehl/units.hpp"
#include "unit/cli/run_tehl.hpp"
#include "unit/drive/train_report_run.hpp"

namespace tehl {
namespace {

std::string Case(const std::string& name) {
  return std::string(TEHL_SOURCE_DIR) + "/cases/trains/" + name + ".toml";
}

struct Solved {
  internal::TrainFile file;
  internal::TrainResult result;
  double Speed(const std::string& member) const {
    return result.solution.speed.at(file.spec.Index(member));
  }
};

Solved Solve(const std::string& name) {
  Solved s{internal::ReadTrainFile(Case(name)), {}};
  s.result = internal::SolveTrainFile(s.file);
  return s;
}

TEST(TrainFile, Seed001Example21) {  // w_F = -240 rpm, w_A / w_F = -20/3
  const Solved s = Solve("seed001_ex2_1_compound");
  EXPECT_NEAR(RadPerSToRpm(s.Speed("F")), -240.0, 1e-9);
  EXPECT_NEAR(1.0 / *s.result.solution.train_value, -20.0 / 3.0, 1e-12);
}

TEST(TrainFile, Seed001Example22) {  // w_E = (N_A / N_E) w_A = 24/40 * 100 rpm
  EXPECT_NEAR(RadPerSToRpm(Solve("seed001_ex2_2_idlers").Speed("E")), 60.0, 1e-9);
}

TEST(TrainFile, Seed001Example23) {  // 0.03125, 7.5 rpm, rack 7.66 m/min
  const Solved s = Solve("seed001_ex2_3_bevel_worm_rack");
  EXPECT_NEAR(std::abs(*s.result.solution.train_value), 0.03125, 1e-12);
  EXPECT_NEAR(std::abs(RadPerSToRpm(s.Speed("9"))), 7.5, 1e-9);
  EXPECT_NEAR(std::abs(s.Speed("10")) * 60.0, 7.66, 0.005);
}

TEST(TrainFile, Seed001Example24) {  // document targets 39.07 and 56.03 rpm
  const Solved s = Solve("seed001_ex2_4_two_rolls");
  // With the rounded teeth, by hand: gear 2 at -1800 (16/25) = -1152 rpm; left-hand worm 6
  // (2 starts) drives 7 at -(2/64)(-1152) = +36; 8 -> 9: -36 (26/24) = -39 rpm. Gear 3 at
  // -1800 (16/20) = -1440; 4 -> 5: +480; right-hand worm 10 (3 starts): +(3/50) 480 = 28.8;
  // 12 -> 13: -28.8 (35/18) = -56 rpm.
  EXPECT_NEAR(RadPerSToRpm(s.Speed("9")), -39.0, 1e-12);
  EXPECT_NEAR(RadPerSToRpm(s.Speed("13")), -56.0, 1e-12);
}

TEST(TrainFile, Seed001Example26Seed002) {  // +30.95 rad/s, tabulation of Example 2.10
  const Solved s = Solve("seed001_ex2_6_seed002_planetary");
  EXPECT_NEAR(s.Speed("2"), 30.95, 0.005);
  ASSERT_EQ(s.result.tables.size(), 1u);
  const TabulationTable& t = s.result.tables[0];
  EXPECT_EQ(t.carrier, "6");
  EXPECT_EQ(t.reference, "5");
  ASSERT_EQ(t.rows.size(), 4u);
  for (size_t k = 0; k < t.columns.size(); ++k) {
    // Row 2: everything +150 with the arm; row 3: gear 5 turned -100 (Example 2.10);
    // row 4 (sum) equals the solved speeds.
    EXPECT_DOUBLE_EQ(*t.rows[1].values[k], 150.0);
    EXPECT_NEAR(*t.rows[3].values[k], s.Speed(t.columns[k]), 1e-9) << t.columns[k];
  }
  const auto col = [&](const std::string& m) {
    return std::find(t.columns.begin(), t.columns.end(), m) - t.columns.begin();
  };
  EXPECT_NEAR(*t.rows[2].values[col("5")], -100.0, 1e-9);
  // Example 2.10 row 3: gear 2 -100 (N5 N3)/(N4 N2), gears 3 and 4 +100 N5/N4.
  EXPECT_NEAR(*t.rows[2].values[col("2")], -100.0 * 25.0 / 21.0, 1e-9);
  EXPECT_NEAR(*t.rows[2].values[col("3")], 100.0 * 20.0 / 28.0, 1e-9);
  EXPECT_NEAR(*t.rows[0].values[col("2")], 25.0 / 21.0, 1e-12);  // Willis value
}

TEST(TrainFile, Seed001Example27) {  // arm +10.86, w5 = +52.14 rad/s
  const Solved s = Solve("seed001_ex2_7_two_subtrains");
  EXPECT_NEAR(s.Speed("6"), 10.86, 0.005);
  EXPECT_NEAR(s.Speed("5"), 52.14, 0.005);
}

TEST(TrainFile, Seed001Example28) {  // -8.33 rad/s from the printed teeth
  EXPECT_NEAR(Solve("seed001_ex2_8_bevel_differential").Speed("7"), -8.33, 0.005);
}

TEST(TrainFile, Seed001Example29) {  // 150 rad/s; tabulation column 2 = 1 + N1/N2 = 3 turns
  const Solved s = Solve("seed001_ex2_9_fixed_sun");
  EXPECT_NEAR(s.Speed("2"), 150.0, 1e-9);
  const TabulationTable& t = s.result.tables.at(0);
  EXPECT_EQ(t.reference, "1");
  // Row 1 with gear 1 +1 turn relative to the arm: gear 2 turns -N1/N2 = -2 (Fig. 2.8a
  // step 3 with the opposite sign: the document turns gear 1 by -1).
  const auto col = std::find(t.columns.begin(), t.columns.end(), "2") - t.columns.begin();
  EXPECT_NEAR(*t.rows[0].values[col], -2.0, 1e-12);
}

TEST(TrainFile, PlanetaryReducerWithSevenPlanetsFitsAndReducesBy28) {
  const Solved s = Solve("seed001_ex2_11_planetary_reducer");
  EXPECT_NEAR(1.0 / *s.result.solution.train_value, 2.8, 1e-12);  // Table 1.1: 1 + 90/50
  ASSERT_EQ(s.file.planetary.size(), 1u);
  EXPECT_EQ(s.file.planetary[0].rules.max_planets, 7);
}

TEST(TrainFile, RevertedReducer) {
  EXPECT_NEAR(*Solve("reverted").result.solution.train_value, (20.0 / 40) * (25.0 / 35), 1e-12);
}

// Hoist: i = (20/40)(25/35)(2/40) = 1/56; T_motor = 300/56/0.6 = 8.929 N m; shunt flux
// K_w E / R_f = 0.5 * 2 = 1 V s/rad: I_a = 8.929 A, w = 220 - 0.5 I_a = 215.54 rad/s.
TEST(TrainFile, MotorHoistOperatingPoint) {
  const Solved s = Solve("motor_hoist");
  ASSERT_TRUE(s.result.motor && s.result.motor->usable());
  const double t = 300.0 / 56.0 / 0.6;
  EXPECT_NEAR(s.result.load_train_value, 1.0 / 56.0, 1e-12);
  EXPECT_NEAR(s.result.motor->motor_torque_nm, t, 1e-9);
  EXPECT_NEAR(s.result.motor->motor_speed_rad_s, 220.0 - 0.5 * t, 1e-9);
  EXPECT_NEAR(s.Speed("drum"), (220.0 - 0.5 * t) / 56.0, 1e-9);
}

TEST(TrainCommand, PrintsSpeedsTrainValueAndTabulation) {
  const auto r = testing::RunTehl("train '" + Case("seed001_ex2_6_seed002_planetary") + "'");
  ASSERT_TRUE(r.exited);
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("30.9524"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("Tabulation, carrier 6"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("whole train locked to 6"), std::string::npos) << r.out;
}

TEST(TrainCommand, EveryShippedTrainFileRuns) {
  for (const char* name :
       {"seed001_ex2_1_compound", "seed001_ex2_2_idlers", "seed001_ex2_3_bevel_worm_rack",
        "seed001_ex2_4_two_rolls", "seed001_ex2_6_seed002_planetary", "seed001_ex2_7_two_subtrains",
        "seed001_ex2_8_bevel_differential", "seed001_ex2_9_fixed_sun",
        "seed001_ex2_11_planetary_reducer", "reverted", "motor_hoist"}) {
    const auto r = testing::RunTehl("train '" + Case(name) + "'");
    ASSERT_TRUE(r.exited) << name;
    EXPECT_EQ(r.exit_code, 0) << name << "\n" << r.err;
  }
}

std::string Problems(const std::string& text) {
  const std::string path = testing::UniqueTempPath("train.toml");
  std::ofstream(path) << text;
  try {
    internal::ReadTrainFile(path);
  } catch (const InputError& e) {
    std::string m = e.what();
    const auto at = m.find(path);
    while (m.find(path) != std::string::npos) m.replace(m.find(path), path.size(), "F");
    return at == std::string::npos ? "no file name: " + m : m;
  }
  return "";
}

TEST(TrainFile, UnderDeterminedTrainIsReportedAtAMemberLine) {
  const std::string m =
      Problems("[gear.A]\nteeth = 20\n[gear.B]\nteeth = 40\n[mesh.AB]\na = \"A\"\nb = \"B\"\n");
  EXPECT_NE(m.find("F:1: [gear.A]: under-determined"), std::string::npos) << m;
}

TEST(TrainFile, OverDeterminedInputIsReportedAtItsKeyLine) {
  const std::string m = Problems(
      "[gear.A]\nteeth = 20\nspeed_rpm = 100.0\n[gear.B]\nteeth = 40\nspeed_rpm = -50.0\n"
      "[mesh.AB]\na = \"A\"\nb = \"B\"\n");
  EXPECT_NE(m.find("F:6: gear.B.speed_rpm = -50.0: over-determined"), std::string::npos) << m;
}

TEST(TrainFile, DeclaredPlanetCountThatCannotBeEquallySpacedIsRejected) {
  const std::string m = Problems(
      "[gear.s]\nteeth = 50\nspeed_rpm = 100.0\n[gear.p]\nteeth = 20\ncarrier = \"c\"\n"
      "[gear.r]\nteeth = 90\nheld = true\n[carrier.c]\nplanets = 3\n"
      "[mesh.sp]\na = \"s\"\nb = \"p\"\n[mesh.pr]\na = \"p\"\nb = \"r\"\nkind = \"internal\"\n");
  EXPECT_NE(m.find("F:11: carrier.c.planets = 3: cannot be equally spaced"), std::string::npos)
      << m;
}

// Seed 001 Example 2.7 (Fig. 2.11) with teeth of gears 2 and 3 and module lines to vary.
std::string Example27(int z2,
                      int z3,
                      const std::string& module_line,
                      const std::string& carrier_lines = "") {
  return "[gear.2]\nteeth = " + std::to_string(z2) + "\nspeed_rad_s = 60.0\n" + module_line +
         "[gear.3]\nteeth = " + std::to_string(z3) + "\nshaft = \"p\"\ncarrier = \"6\"\n" +
         module_line + "[gear.4]\nteeth = 28\nshaft = \"p\"\ncarrier = \"6\"\n" + module_line +
         "[gear.5]\nteeth = 20\n" + module_line + "[gear.7]\nteeth = 76\nheld = true\n" +
         module_line + "[carrier.6]\n" + carrier_lines +
         "[mesh.2-3]\na = \"2\"\nb = \"3\"\n[mesh.4-5]\na = \"4\"\nb = \"5\"\n"
         "[mesh.4-7]\na = \"4\"\nb = \"7\"\nkind = \"internal\"\n";
}

using testing::TrainReport;

TEST(TrainFile, CompoundPlanetStepsMustShareTheirCentreDistance) {
  // Module 2 mm everywhere, gear 3 at 40 teeth: the 2-3 mesh puts the planet shaft at
  // 2 (18 + 40)/2 = 58 mm from the central axis, the 4-5 and 4-7 meshes at 2 (28 + 20)/2 =
  // 2 (76 - 28)/2 = 48 mm: 10 mm = 5 modules apart, more than profile shift bridges.
  const std::string m = Problems(Example27(18, 40, "module_m = 0.002\n"));
  EXPECT_NE(m.find("mesh.2-3.b"), std::string::npos) << m;
  EXPECT_NE(m.find("58 mm"), std::string::npos) << m;
  EXPECT_NE(m.find("48 mm"), std::string::npos) << m;
  // The document's teeth: 2 (18 + 30)/2 = 48 mm as well.
  EXPECT_EQ(Problems(Example27(18, 30, "module_m = 0.002\n")), "");
}

TEST(TrainFile, EveryPlanetGearKeepsTheTipClearanceOfTheDeclaredCount) {
  // Gears 2 and 3 at 12 and 36 teeth (2 (12 + 36)/2 = 48 mm: coaxial with the 4-5 step).
  // Set 5-4-7 alone: N < 180 / asin(30/48) = 4.65 and 96/N integer, so 4 planets pass.
  // Gear 3: d_a = m (36 + 2) = 76 mm on a = 48 mm: N < 180 / asin(38/48) = 3.44 (eq. 2.13
  // before the module cancels): 4 planets touch.
  const std::string m = Problems(Example27(12, 36, "module_m = 0.002\n", "planets = 4\n"));
  EXPECT_NE(m.find("carrier.6.planets = 4: adjacent tips of planet gear 3 would touch: N < 3.439"),
            std::string::npos)
      << m;
  EXPECT_NE(m.find("at most 3 planets"), std::string::npos) << m;
  // Without modules gear 3 still meshes central gear 2: a / m = 24, the same limit.
  EXPECT_NE(Problems(Example27(12, 36, "", "planets = 4\n")).find("N < 3.439"), std::string::npos);
  // 3 planets pass; without modules the steps' centre distances are not compared, and the
  // report says so.
  int code = -1;
  const std::string out = TrainReport(Example27(12, 36, "", "planets = 3\n"), &code);
  EXPECT_EQ(code, 0) << out;
  EXPECT_NE(out.find("are not compared (no module_m on every step)"), std::string::npos) << out;
  EXPECT_NE(out.find("declared 3: fits the rules checked"), std::string::npos) << out;
}

TEST(TrainFile, ModuleInMillimetresIsRejected) {
  const std::string m = Problems(
      "[gear.P]\nteeth = 20\nmodule_m = 2.0\nspeed_rpm = 100.0\n[rack.R]\n"
      "[mesh.PR]\na = \"P\"\nb = \"R\"\nkind = \"rack\"\n");
  EXPECT_NE(m.find("F:3: gear.P.module_m = 2.0: out of range"), std::string::npos) << m;
  EXPECT_NE(m.find("in millimetres?"), std::string::npos) << m;
}

TEST(TrainCommand, BevelPlanetSpinIsPrintedRelativeToItsCarrier) {
  // Seed 001 Example 2.8: w4 = +100, arm 35; bevel 4 (30) - 5 (60):
  // w5 - w_arm = -(30/60)(100 - 35) = -32.5 rad/s.
  const auto r = testing::RunTehl("train '" + Case("seed001_ex2_8_bevel_differential") + "'");
  ASSERT_TRUE(r.exited);
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("spins -32.5 rad/s (-310.352 rpm) about its own axis, relative to "
                       "carrier A"),
            std::string::npos)
      << r.out;
  EXPECT_EQ(r.out.find("looking along the common axis"), std::string::npos) << r.out;
}

TEST(TrainCommand, PlanetaryReducerTorquesPerNewtonMetreOnTheSun) {
  // Sun 50 driven, ring 90 held, arm output: T_arm = -(1 + 90/50) = -2.8 N m, the frame holds
  // the ring with +90/50 = +1.8 N m (train_torques_test.cpp); -2.8 = -1 / (1/2.8).
  const Solved s = Solve("seed001_ex2_11_planetary_reducer");
  ASSERT_TRUE(s.result.torques.solved) << s.result.torques.message;
  EXPECT_NEAR(*s.result.torques.torque[s.file.spec.Index("arm")], -2.8, 1e-12);
  EXPECT_NEAR(*s.result.torques.torque[s.file.spec.Index("ring")], 1.8, 1e-12);
  const std::string csv = testing::UniqueTempPath("speeds.csv");
  const auto r = testing::RunTehl("train '" + Case("seed001_ex2_11_planetary_reducer") +
                                  "' --csv '" + csv + "'");
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("-2.8 N m  output (the load's torque, lossless)"), std::string::npos)
      << r.out;
  std::ifstream in(csv);
  std::string header, sun, planet, ring, arm;
  std::getline(in, header);
  std::getline(in, sun);
  std::getline(in, planet);
  std::getline(in, ring);
  std::getline(in, arm);
  EXPECT_NE(header.find(",worm_hand,"), std::string::npos) << header;
  EXPECT_NE(header.find(",torque_nm,"), std::string::npos) << header;
  EXPECT_EQ(arm.rfind("arm,carrier,,,", 0), 0u) << arm;  // no teeth, no hand
  EXPECT_NE(arm.find(",-2.8,"), std::string::npos) << arm;
  EXPECT_NE(ring.find(",1.8,"), std::string::npos) << ring;
  std::remove(csv.c_str());
}

TEST(TrainCommand, UnwritableCsvFailsBeforeTheReport) {
  const auto r =
      testing::RunTehl("train '" + Case("reverted") + "' --csv /proc/no_such_folder/speeds.csv");
  EXPECT_EQ(r.exit_code, 2) << r.out << r.err;
  EXPECT_EQ(r.out.find("Speeds"), std::string::npos) << r.out;
  EXPECT_NE(r.err.find("--csv"), std::string::npos) << r.err;
}

TEST(TrainFile, LoadOnAHeldMemberIsRejected) {
  const std::string planetary =
      "[train]\ninput = \"sun\"\noutput = \"arm\"\n[gear.sun]\nteeth = 50\n"
      "[gear.planet]\nteeth = 20\ncarrier = \"arm\"\n[gear.ring]\nteeth = 90\nheld = true\n"
      "[carrier.arm]\n[mesh.sp]\na = \"sun\"\nb = \"planet\"\n"
      "[mesh.pr]\na = \"planet\"\nb = \"ring\"\nkind = \"internal\"\n"
      "[motor]\ntype = \"permanent_magnet\"\nsupply_voltage_v = 24.0\n"
      "armature_resistance_ohm = 0.5\nspeed_constant = 0.05\n";
  const std::string m = Problems(planetary + "[load]\nmember = \"ring\"\ntorque_nm = 1.0\n");
  EXPECT_NE(m.find("load.member = \"ring\": the loaded member is held: a held member does no work"),
            std::string::npos)
      << m;
  // The same motor on the arm's load runs: 1 N m on the arm is 1/2.8 N m at the sun.
  EXPECT_EQ(Problems(planetary + "[load]\ntorque_nm = 1.0\n"), "");
}

TEST(TrainCommand, PermanentMagnetMotorHasNoFieldToReport) {
  const std::string text =
      "[train]\ninput = \"A\"\noutput = \"B\"\n[gear.A]\nteeth = 20\n[gear.B]\nteeth = 40\n"
      "[mesh.AB]\na = \"A\"\nb = \"B\"\n[motor]\ntype = \"permanent_magnet\"\n"
      "supply_voltage_v = 24.0\narmature_resistance_ohm = 0.5\nspeed_constant = 0.05\n"
      "rated_current_a = 10.0\nspeed_command_rpm = 1000.0\n[load]\ntorque_nm = 0.5\n";
  int code = -1;
  const std::string out = TrainReport(text, &code);
  EXPECT_EQ(code, 0) << out;
  EXPECT_EQ(out.find("field current"), std::string::npos) << out;
  EXPECT_EQ(out.find("constant power"), std::string::npos) << out;
  EXPECT_NE(out.find("no field to weaken"), std::string::npos) << out;
}

TEST(TrainCommand, RackTrainValueCarriesItsUnit) {
  // Pinion 20 teeth, module 2 mm: v = w m z / 2 = 0.02 w, w_R / w_P = 0.02 m/rad.
  int code = -1;
  const std::string out = TrainReport(
      "[train]\ninput = \"P\"\noutput = \"R\"\n[gear.P]\nteeth = 20\nmodule_m = 0.002\n"
      "speed_rad_s = 10.0\n[rack.R]\n[mesh.PR]\na = \"P\"\nb = \"R\"\nkind = \"rack\"\n",
      &code);
  EXPECT_EQ(code, 0) << out;
  EXPECT_NE(out.find("Train value w_R / w_P = 0.02 m/rad"), std::string::npos) << out;
}

}  // namespace
}  // namespace tehl

namespace tehl {
namespace {

// A gear case whose pinion a DC motor drives ([motor] of the case schema): shunt motor with
// flux K_w E / R_f = 0.5 * 220/110 = 1 V s/rad, R_a = 0.1 Ohm, a 2:1 reduction to the pinion
// (train_value 0.5). Pinion torque 100 N m -> motor torque 50 N m, I_a = 50 A,
// w_m = (220 - 5)/1 = 215 rad/s, pinion 107.5 rad/s.
const char* kMotorCase =
    "[gear]\nmodule_m = 0.002\nface_width_m = 0.025\n"
    "[gear.pinion]\nteeth = 35\n[gear.wheel]\nteeth = 105\n"
    "[operating]\npinion_torque_nm = 100.0\n"
    "[lubricant]\nname = \"sae40\"\n"
    "[motor]\ntype = \"shunt\"\nsupply_voltage_v = 220.0\narmature_resistance_ohm = 0.1\n"
    "speed_constant = 0.5\nfield_resistance_ohm = 110.0\ntrain_value = 0.5\n";

TEST(CaseMotor, PinionSpeedComesFromTheMotorOperatingPoint) {
  const std::string path = testing::UniqueTempPath("motor_case.toml");
  std::ofstream(path) << kMotorCase;
  const auto r = testing::RunTehl("gear '" + path + "'");
  std::remove(path.c_str());
  ASSERT_TRUE(r.exited);
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("(107.500 rad/s)"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("the pinion speed is the [motor]'s operating point"), std::string::npos)
      << r.out;
}

TEST(CaseMotor, SpeedInOperatingAndMotorIsGivenTwice) {
  const std::string path = testing::UniqueTempPath("motor_case_twice.toml");
  std::string text = kMotorCase;
  text.insert(text.find("pinion_torque_nm"), "pinion_speed_rpm = 1000.0\n");
  std::ofstream(path) << text;
  const auto r = testing::RunTehl("case --check '" + path + "'");
  std::remove(path.c_str());
  ASSERT_TRUE(r.exited);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find(":9: operating.pinion_speed_rpm = 1000.0: [motor] gives the pinion speed"),
            std::string::npos)
      << r.err;
}

}  // namespace
}  // namespace tehl
