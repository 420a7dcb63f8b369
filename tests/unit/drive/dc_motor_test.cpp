// DC motor laws of seed 001 section 3 (eqs. 3.1.1-3.1.4, series speed law corrected as in
// the extraction). The document gives no numbers for its motors (extraction section 0:
// "no ratings", section 3: "no numbers are given for any of the constants"), so every
// reference value below is derived by hand in its comment.
#include "tehl/drive/dc_motor.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "tehl/error.hpp"

namespace tehl {
namespace {

DcMotorSpec Pm() {  // E = 24 V, R_a = 0.5 Ohm, K_w = K_a = 0.05 V s/rad
  DcMotorSpec s;
  s.type = DcMotorType::kPermanentMagnet;
  s.supply_voltage_v = 24;
  s.armature_resistance_ohm = 0.5;
  s.speed_constant = 0.05;
  return s;
}

// No-load w0 = E/K = 480 rad/s; stall T = K E/R_a = 2.4 N m; half the stall torque
// (1.2 N m, I_a = 24 A) gives half the no-load speed: (24 - 12)/0.05 = 240 rad/s.
TEST(DcMotor, PermanentMagnetLineThroughNoLoadSpeedAndStallTorque) {
  const DcMotor m(Pm());
  EXPECT_DOUBLE_EQ(m.NoLoadSpeed(), 480.0);
  EXPECT_DOUBLE_EQ(m.StallTorque(), 2.4);
  EXPECT_DOUBLE_EQ(m.SpeedAtCurrent(24.0), 240.0);
  const MotorOperatingPoint op = SolveOperatingPoint(m, {1.2, 0.0, 1.0, 1.0});
  ASSERT_TRUE(op.usable());
  EXPECT_NEAR(op.motor_speed_rad_s, 240.0, 1e-9);
  EXPECT_NEAR(op.armature_current_a, 24.0, 1e-9);
  // Power balance: E I_a = T w + I_a^2 R_a: 576 = 288 + 288.
  EXPECT_NEAR(op.input_power_w, 576.0, 1e-7);
  EXPECT_NEAR(op.shaft_power_w, 288.0, 1e-7);
}

// The shunt motor of the tests below: E = 220 V, R_a = 0.4 Ohm, K_w = 0.5 V s/(A rad),
// R_f = 110 Ohm.
DcMotorSpec Shunt220() {
  DcMotorSpec s;
  s.type = DcMotorType::kShunt;
  s.supply_voltage_v = 220;
  s.armature_resistance_ohm = 0.4;
  s.speed_constant = 0.5;
  s.field_resistance_ohm = 110;
  return s;
}

// Shunt (3.1.1), (3.1.2): E = 220 V, R_f = 110 Ohm -> I_f = 2 A; K_w = 0.5 V s/(A rad):
// flux 1 V s/rad; R_a = 0.4 Ohm. At I_a = 50 A: w = (220 - 20)/1 = 200 rad/s, T = 50 N m
// (lossless K_a = K_w I_f = 1 N m/A). Line current 52 A.
TEST(DcMotor, ShuntSpeedAndTorqueLaws) {
  DcMotorSpec s = Shunt220();
  const DcMotor m(s);
  EXPECT_DOUBLE_EQ(m.FieldCurrent(), 2.0);
  EXPECT_DOUBLE_EQ(m.SpeedAtCurrent(50.0), 200.0);
  EXPECT_DOUBLE_EQ(m.TorqueAtCurrent(50.0), 50.0);
  EXPECT_DOUBLE_EQ(m.InputPower(50.0), 220.0 * 52.0);
  // An explicit K_a (seed's T = K_a I_a) is used as given.
  s.torque_constant = 0.9;
  EXPECT_DOUBLE_EQ(DcMotor(s).TorqueAtCurrent(50.0), 45.0);
}

// Series, corrected speed law w = (E - I_a R_a)/(K_w I_a), T = K_a I_a^2 (3.1.4):
// E = 100 V, R_a = 0.5 Ohm, K_w = K_a = 0.01. Load 4 N m: I_a = sqrt(4/0.01) = 20 A,
// w = (100 - 10)/(0.01 * 20) = 450 rad/s.
TEST(DcMotor, SeriesOperatingPointFromTheCorrectedSpeedLaw) {
  DcMotorSpec s;
  s.type = DcMotorType::kSeries;
  s.supply_voltage_v = 100;
  s.armature_resistance_ohm = 0.5;
  s.speed_constant = 0.01;
  const DcMotor m(s);
  EXPECT_DOUBLE_EQ(m.SpeedAtCurrent(20.0), 450.0);
  EXPECT_DOUBLE_EQ(m.TorqueAtCurrent(20.0), 4.0);
  const MotorOperatingPoint op = SolveOperatingPoint(m, {4.0, 0.0, 1.0, 1.0});
  ASSERT_TRUE(op.usable()) << op.message;
  EXPECT_NEAR(op.motor_speed_rad_s, 450.0, 1e-8);
  EXPECT_NEAR(op.armature_current_a, 20.0, 1e-10);
  // Four times the torque: I_a = 40 A, w = (100 - 20)/(0.01 * 40) = 200 rad/s.
  EXPECT_NEAR(SolveOperatingPoint(m, {16.0, 0.0, 1.0, 1.0}).motor_speed_rad_s, 200.0, 1e-8);
  // Without load a series motor runs away.
  EXPECT_EQ(SolveOperatingPoint(m, {0.0, 0.0, 1.0, 1.0}).termination,
            MotorOperatingPoint::Termination::kRunaway);
}

// A load reflected through a train: i = w_L/w_m = 1/10, eta = 0.9, T_L = 9 N m at the
// load -> 9 * 0.1 / 0.9 = 1 N m at the PM motor: I_a = 20 A, w_m = (24 - 10)/0.05 = 280,
// w_L = 28 rad/s, load power 252 W = 0.9 * 280 W shaft power.
TEST(DcMotor, LoadReflectedThroughTrainValueAndEfficiency) {
  const MotorOperatingPoint op = SolveOperatingPoint(DcMotor(Pm()), {9.0, 0.0, 0.1, 0.9});
  EXPECT_NEAR(op.motor_speed_rad_s, 280.0, 1e-9);
  EXPECT_NEAR(op.motor_torque_nm, 1.0, 1e-12);
  EXPECT_NEAR(op.load_speed_rad_s, 28.0, 1e-10);
  EXPECT_NEAR(op.load_power_w, 0.9 * op.shaft_power_w, 1e-8);
}

// Viscous load T = c w_m: K(E - K w)/R_a = c w -> w = K E / (K^2 + c R_a);
// c = 0.005: w = 1.2/(0.0025 + 0.0025) = 240 rad/s.
TEST(DcMotor, ViscousLoadMeetsTheLineAtTheClosedFormSpeed) {
  const MotorOperatingPoint op = SolveOperatingPoint(DcMotor(Pm()), {0.0, 0.005, 1.0, 1.0});
  EXPECT_NEAR(op.motor_speed_rad_s, 240.0, 1e-9);
}

TEST(DcMotor, LoadAboveStallTorqueStalls) {
  const MotorOperatingPoint op = SolveOperatingPoint(DcMotor(Pm()), {3.0, 0.0, 1.0, 1.0});
  EXPECT_EQ(op.termination, MotorOperatingPoint::Termination::kStalled);
  EXPECT_FALSE(op.usable());
}

// Separately excited, rated I_r = 20 A, E = 220 V, R_a = 1 Ohm, K_w I_f = 2 V s/rad:
// base speed w_b = (220 - 20)/2 = 100 rad/s, rated torque 40 N m, P_r = 4000 W.
// Below w_b: T_max = 40; at 200 rad/s: 20 N m (constant power, seed 001 Fig. 3.1.3).
TEST(DcMotor, ConstantTorqueBelowAndConstantPowerAboveTheBaseSpeed) {
  DcMotorSpec s;
  s.type = DcMotorType::kSeparatelyExcited;
  s.supply_voltage_v = 220;
  s.armature_resistance_ohm = 1;
  s.speed_constant = 1;
  s.field_current_a = 2;
  s.rated_current_a = 20;
  const DcMotor m(s);
  EXPECT_DOUBLE_EQ(m.BaseSpeed(), 100.0);
  EXPECT_DOUBLE_EQ(m.RatedTorque(), 40.0);
  EXPECT_DOUBLE_EQ(m.TorqueLimit(50.0), 40.0);
  EXPECT_DOUBLE_EQ(m.TorqueLimit(200.0), 20.0);
  // Speed command 50 rad/s, 30 N m: I_a = 15 A, E_a = 2*50 + 15*1 = 115 V.
  const ControlledPoint low = SolveControlledPoint(m, {30.0, 0.0, 1.0, 1.0}, 50.0);
  EXPECT_EQ(low.region, SpeedRegion::kConstantTorque);
  EXPECT_NEAR(low.armature_voltage_v, 115.0, 1e-12);
  EXPECT_TRUE(low.feasible);
  // 200 rad/s, 20 N m at rated voltage: phi^2 200 - 220 phi + 20 = 0, larger root
  // phi = (220 + sqrt(48400 - 16000))/400 = 1.0 V s/rad -> I_f = 1 A, I_a = 20 A.
  const ControlledPoint high = SolveControlledPoint(m, {20.0, 0.0, 1.0, 1.0}, 200.0);
  EXPECT_EQ(high.region, SpeedRegion::kConstantPower);
  EXPECT_NEAR(high.field_current_a, 1.0, 1e-12);
  EXPECT_NEAR(high.armature_current_a, 20.0, 1e-12);
  EXPECT_TRUE(high.feasible);
  // 25 N m at 200 rad/s needs more than the rated current.
  EXPECT_FALSE(SolveControlledPoint(m, {25.0, 0.0, 1.0, 1.0}, 200.0).feasible);
}

TEST(DcMotor, RejectsMissingFieldAndNonPositiveConstants) {
  DcMotorSpec s = Pm();
  s.type = DcMotorType::kSeparatelyExcited;
  EXPECT_THROW(DcMotor{s}, InputError);
  s = Pm();
  s.armature_resistance_ohm = 0;
  EXPECT_THROW(DcMotor{s}, InputError);
  s = Pm();
  s.rated_current_a = 48;  // I_r R_a = 24 V = E: no base speed
  EXPECT_THROW(DcMotor{s}, InputError);
}

// Energy with (3.1.1), (3.1.2): T w = K_a I_a w and E_b I_a = K_w I_f w I_a, so a torque
// constant above K_w I_f makes more shaft power than the armature takes. Shunt of
// ShuntSpeedAndTorqueLaws: K_w E / R_f = 0.5 * 220 / 110 = 1 N m/A is the largest K_a.
TEST(DcMotor, RejectsATorqueConstantAboveTheLosslessValue) {
  DcMotorSpec s = Shunt220();
  s.torque_constant = 1.0;  // exactly lossless: accepted
  EXPECT_NO_THROW(DcMotor{s});
  s.torque_constant = 1.1;
  try {
    DcMotor{s};
    ADD_FAILURE() << "K_a = 1.1 > K_w I_f = 1 accepted";
  } catch (const InputError& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("torque_constant"), std::string::npos) << m;
    EXPECT_NE(m.find("K_a <= 1 N m/A"), std::string::npos) << m;
  }
  // Series, T = K_a I_a^2 and E_b = K_w I_a w: K_a <= K_w = 0.01 N m/A^2.
  DcMotorSpec series;
  series.type = DcMotorType::kSeries;
  series.supply_voltage_v = 100;
  series.armature_resistance_ohm = 0.5;
  series.speed_constant = 0.01;
  series.torque_constant = 0.011;
  EXPECT_THROW(DcMotor{series}, InputError);
  // Permanent magnet, E_b = K_w w: K_a <= K_w = 0.05 N m/A.
  DcMotorSpec pm = Pm();
  pm.torque_constant = 0.06;
  EXPECT_THROW(DcMotor{pm}, InputError);
}

}  // namespace
}  // namespace tehl
