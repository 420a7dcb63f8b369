// Torques of frictionless trains by virtual work (train_torques.hpp), against hand
// calculations: a simple planetary (seed 001 Table 1.1 / Example 2.11 teeth), a compound
// reducer (seed 001 Example 2.1) and a rack.
#include "tehl/drive/train_torques.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "unit/drive/train_spec_builders.hpp"

namespace tehl {
namespace {
using testing::Arm;
using testing::Gear;
using testing::Mesh;

double Torque(const GearTrainSpec& s, const TrainTorques& t, const std::string& name) {
  return t.torque.at(s.Index(name)).value();
}

// Sun 50 driven with 1 N m, ring 90 held, carrier output. By hand: the planet is in
// equilibrium, so the tangential forces at its two meshes are equal, F = T_sun / r_sun; the
// planet pushes the ring with -F r_ring, which the frame holds with +F r_ring:
// T_ring = +T_sun z_ring / z_sun = +1.8 N m (the ring pushes the frame with -1.8 N m).
// The three torques sum to zero: T_arm = -(1 + z_ring / z_sun) = -2.8 N m, and
// T_sun w_sun + T_arm w_arm = w - 2.8 w / 2.8 = 0 (Table 1.1: w_sun / w_arm = 2.8).
TEST(TrainTorques, SimplePlanetaryByHand) {
  GearTrainSpec s;
  TrainMember arm;
  arm.name = "arm";
  arm.kind = MemberKind::kCarrier;
  s.members = {Gear("sun", 50), Gear("planet", 20, "", "arm"), Gear("ring", 90), arm};
  s.meshes = {Mesh("sun", "planet"), Mesh("planet", "ring", MeshKind::kInternal)};
  s.members[0].speed = 157.0;
  s.members[2].speed = 0.0;
  s.input = "sun";
  s.output = "arm";
  const TrainSolution r = SolveGearTrain(s);
  const TrainTorques t = SolveTrainTorques(s, r);
  ASSERT_TRUE(t.solved) << t.message;
  EXPECT_DOUBLE_EQ(Torque(s, t, "sun"), 1.0);
  EXPECT_NEAR(Torque(s, t, "ring"), 90.0 / 50.0, 1e-12);
  EXPECT_NEAR(Torque(s, t, "arm"), -2.8, 1e-12);
  EXPECT_FALSE(t.torque[1].has_value());  // no external torque on the planet
  EXPECT_NEAR(Torque(s, t, "sun") + Torque(s, t, "ring") + Torque(s, t, "arm"), 0.0, 1e-12);
  EXPECT_LT(t.power_residual, 1e-12);
  // Scaled by the input torque.
  EXPECT_NEAR(Torque(s, SolveTrainTorques(s, r, 10.0), "arm"), -28.0, 1e-11);
}

// Seed 001 Example 2.1: A 20 - B 40, C 30 - D 40, E 20 - F 50 (B-C, D-E compound);
// w_F / w_A = -3/20 (w_A / w_F = -20/3). Power: T_A w_A + T_F w_F = 0, so
// T_F = -T_A / (w_F / w_A) = -1 / (-0.15) = +6.667 N m per N m on A.
TEST(TrainTorques, CompoundReducerOutputTorqueIsInputOverTrainValue) {
  GearTrainSpec s;
  s.members = {Gear("A", 20),       Gear("B", 40, "BC"), Gear("C", 30, "BC"),
               Gear("D", 40, "DE"), Gear("E", 20, "DE"), Gear("F", 50)};
  s.meshes = {Mesh("A", "B"), Mesh("C", "D"), Mesh("E", "F")};
  s.members[0].speed = 10.0;
  s.input = "A";
  s.output = "F";
  const TrainSolution r = SolveGearTrain(s);
  ASSERT_NEAR(*r.train_value, -3.0 / 20.0, 1e-12);
  const TrainTorques t = SolveTrainTorques(s, r);
  ASSERT_TRUE(t.solved) << t.message;
  EXPECT_NEAR(Torque(s, t, "F"), -1.0 / *r.train_value, 1e-12);
  EXPECT_NEAR(Torque(s, t, "F"), 20.0 / 3.0, 1e-12);
}

// Rack on a pinion of 20 teeth, module 2 mm: r = 0.02 m, v = w r. 1 N m on the pinion
// balances a force F with F v + T w = 0: F = -T / r = -50 N.
TEST(TrainTorques, RackCarriesAForce) {
  GearTrainSpec s;
  TrainMember rack;
  rack.name = "R";
  rack.kind = MemberKind::kRack;
  s.members = {Gear("P", 20), rack};
  s.members[0].module_m = 0.002;
  s.members[0].speed = 3.0;
  s.meshes = {Mesh("P", "R", MeshKind::kRack)};
  s.input = "P";
  s.output = "R";
  const TrainTorques t = SolveTrainTorques(s, SolveGearTrain(s));
  ASSERT_TRUE(t.solved) << t.message;
  EXPECT_NEAR(Torque(s, t, "R"), -50.0, 1e-10);
}

TEST(TrainTorques, SayWhyWhenNotDetermined) {
  GearTrainSpec s;
  s.members = {Gear("A", 20), Gear("B", 40)};
  s.meshes = {Mesh("A", "B")};
  s.members[0].speed = 1.0;
  const TrainSolution r = SolveGearTrain(s);
  EXPECT_NE(SolveTrainTorques(s, r).message.find("no [train] output"), std::string::npos);
  s.output = "A";
  EXPECT_NE(SolveTrainTorques(s, r).message.find("the output is the driven member"),
            std::string::npos);
}

}  // namespace
}  // namespace tehl
