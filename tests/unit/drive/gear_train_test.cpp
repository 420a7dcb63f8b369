// Gear trains against the worked examples of seed 001 section 2 (numbers from
// /work/shared/seeds/001_extract_en.md, VALIDATION.md section 6) and seed 002.
// Speeds are in the document's units where the ratio is unit-free (rpm in and out).
#include "tehl/drive/gear_train.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "tehl/error.hpp"
#include "tehl/units.hpp"
#include "unit/drive/train_spec_builders.hpp"

namespace tehl {
namespace {
using testing::Arm;
using testing::Gear;
using testing::Mesh;

double Speed(const GearTrainSpec& s, const TrainSolution& r, const std::string& name) {
  return r.speed.at(s.Index(name));
}

// Example 2.1 (Fig. 2.2): A-B, C-D, E-F external, B-C and D-E compound; w_A = 1600 rpm.
// Document: w_A / w_F = -20/3, w_F = -240 rpm (opposite to A).
TEST(GearTrain, Seed001Example21CompoundTrainGivesMinus240Rpm) {
  GearTrainSpec s;
  s.members = {Gear("A", 30),       Gear("B", 50, "BC"), Gear("C", 20, "BC"),
               Gear("D", 40, "DE"), Gear("E", 18, "DE"), Gear("F", 36)};
  s.members[0].speed = 1600.0;
  s.meshes = {Mesh("A", "B"), Mesh("C", "D"), Mesh("E", "F")};
  s.input = "A";
  s.output = "F";
  const TrainSolution r = SolveGearTrain(s);
  EXPECT_NEAR(Speed(s, r, "F"), -240.0, 1e-9);
  EXPECT_NEAR(1.0 / *r.train_value, -20.0 / 3.0, 1e-12);
  EXPECT_EQ(r.rank, 6);
}

// Example 2.2 (Fig. 2.3): idlers B, C, D cancel; w_E = (N_A / N_E) w_A, same direction.
// Four external meshes: (-1)^4 = +1. Teeth are symbolic in the document: any values work.
TEST(GearTrain, Seed001Example22IdlersOnlySetTheDirection) {
  GearTrainSpec s;
  s.members = {Gear("A", 24), Gear("B", 51), Gear("C", 17), Gear("D", 90), Gear("E", 40)};
  s.members[0].speed = 100.0;
  s.meshes = {Mesh("A", "B"), Mesh("B", "C"), Mesh("C", "D"), Mesh("D", "E")};
  const TrainSolution r = SolveGearTrain(s);
  EXPECT_NEAR(Speed(s, r, "E"), 100.0 * 24.0 / 40.0, 1e-9);
}

// Example 2.3 (Fig. 2.5): bevel 1-2, spur 3-4, bevel 5-6, worm 7 (2 starts) - wheel 8,
// pinion 9 (65 teeth, m = 5 mm) on the wheel's shaft drives rack 10. n1 = 240 rpm.
// Document: w9/w1 = 0.03125, n9 = 7.5 rpm, w9 = 47.12 rad/min, V = 7.66 m/min.
// The signs of bevel and worm stages are conventions: the magnitudes are the test.
TEST(GearTrain, Seed001Example23BevelSpurWormRackGivesRackAt766MetresPerMinute) {
  GearTrainSpec s;
  s.members = {Gear("1", 60),        Gear("2", 48, "s2"), Gear("3", 80, "s2"),
               Gear("4", 120, "s4"), Gear("5", 60, "s4"), Gear("6", 40, "s6"),
               Gear("7", 2, "s6"),   Gear("8", 80, "s8"), Gear("9", 65, "s8")};
  s.members[6].worm_hand = WormHand::kRight;
  s.members[8].module_m = 0.005;
  TrainMember rack;
  rack.name = "10";
  rack.kind = MemberKind::kRack;
  s.members.push_back(rack);
  s.members[0].speed = RpmToRadPerS(240.0);
  s.meshes = {Mesh("1", "2", MeshKind::kBevel), Mesh("3", "4"), Mesh("5", "6", MeshKind::kBevel),
              Mesh("7", "8", MeshKind::kWorm), Mesh("9", "10", MeshKind::kRack)};
  s.input = "1";
  s.output = "9";
  const TrainSolution r = SolveGearTrain(s);
  EXPECT_NEAR(std::abs(*r.train_value), 0.03125, 1e-12);
  EXPECT_NEAR(std::abs(RadPerSToRpm(Speed(s, r, "9"))), 7.5, 1e-9);
  EXPECT_NEAR(std::abs(Speed(s, r, "9")) * 60.0, 47.12, 0.005);  // rad/min
  EXPECT_NEAR(std::abs(Speed(s, r, "10")) * 60.0, 7.66, 0.005);  // m/min
  // A left-hand worm turns the wheel, hence the rack, the other way.
  GearTrainSpec left = s;
  left.members[6].worm_hand = WormHand::kLeft;
  const TrainSolution rl = SolveGearTrain(left);
  EXPECT_NEAR(Speed(left, rl, "10"), -Speed(s, r, "10"), 1e-12);
}

// Example 2.4 (synthesis): branch A = 16 -> N2 | worm 6 (2 starts) -> 64 | 26 -> 24, so
// w1 / w9 = 1.846 N2 (document "1.85 N2"); branch B = 16 -> N3 | 14 -> 42 | worm 10 (3
// starts) -> 50 | 35 -> 18, w1 / w13 = 1.607 N3 ("1.61 N3"). With n1 = 1800 rpm and the
// document's roll speeds 39.07 and 56.03 rpm: N2 = 24.90 -> 25, N3 = 19.95 -> 20.
TEST(GearTrain, Seed001Example24PartialTrainValuesGiveTheSynthesisedTeeth) {
  GearTrainSpec s;
  s.members = {Gear("1", 16),       Gear("2", 1, "a1"),  Gear("6", 2, "a1"),   Gear("7", 64, "a2"),
               Gear("8", 26, "a2"), Gear("9", 24),       Gear("3", 1, "b1"),   Gear("4", 14, "b1"),
               Gear("5", 42, "b2"), Gear("10", 3, "b2"), Gear("11", 50, "b3"), Gear("12", 35, "b3"),
               Gear("13", 18)};
  s.members[2].worm_hand = WormHand::kLeft;
  s.members[9].worm_hand = WormHand::kRight;
  s.members[0].speed = 1.0;
  s.meshes = {Mesh("1", "2"), Mesh("6", "7", MeshKind::kWorm),   Mesh("8", "9"),  Mesh("1", "3"),
              Mesh("4", "5"), Mesh("10", "11", MeshKind::kWorm), Mesh("12", "13")};
  const TrainSolution r = SolveGearTrain(s);  // N2 = N3 = 1: w1/w9 is the factor itself
  const double factor_a = 1.0 / std::abs(Speed(s, r, "9"));
  const double factor_b = 1.0 / std::abs(Speed(s, r, "13"));
  // The document rounds the factors to two decimals before dividing: 1536/832 = 1.846 ->
  // 1.85 and 37800/23520 = 1.607 -> 1.61.
  EXPECT_NEAR(factor_a, 1536.0 / 832.0, 1e-12);
  EXPECT_NEAR(factor_b, 37800.0 / 23520.0, 1e-12);
  EXPECT_DOUBLE_EQ(std::round(factor_a * 100) / 100, 1.85);
  EXPECT_DOUBLE_EQ(std::round(factor_b * 100) / 100, 1.61);
  EXPECT_NEAR(1800.0 / 39.07 / (std::round(factor_a * 100) / 100), 24.90, 0.005);
  EXPECT_NEAR(1800.0 / 56.03 / (std::round(factor_b * 100) / 100), 19.95, 0.005);
  // Rounded to whole teeth, with or without the document's rounding: 25 and 20.
  EXPECT_EQ(std::lround(1800.0 / 39.07 / factor_a), 25);
  EXPECT_EQ(std::lround(1800.0 / 56.03 / factor_b), 20);
  // With the rounded teeth 25 and 20 the rolls turn at 1800/(1.846*25) and 1800/(1.607*20).
  s.members[1].teeth = 25;
  s.members[6].teeth = 20;
  const TrainSolution r2 = SolveGearTrain(s);
  EXPECT_NEAR(std::abs(Speed(s, r2, "9")) * 1800.0, 1800.0 / (factor_a * 25), 1e-9);
  EXPECT_NEAR(std::abs(Speed(s, r2, "13")) * 1800.0, 1800.0 / (factor_b * 20), 1e-9);
}

// Example 2.5 / eq. (2.3), Fig. 2.8a: fixed sun 1, planet 2 on arm 3: w2 = w3 (1 + N1/N2).
// Eq. (2.4), Fig. 2.8b: fixed ring 1 (internal): w2 = w3 (1 - N1/N2).
TEST(GearTrain, Seed001Example25PlanetAroundFixedSunAndInsideFixedRing) {
  for (MeshKind k : {MeshKind::kExternal, MeshKind::kInternal}) {
    GearTrainSpec s;
    s.members = {Gear("1", 60), Gear("2", 20, "", "3"), Arm("3")};
    s.members[0].speed = 0.0;
    s.members[2].speed = 10.0;
    s.meshes = {Mesh("2", "1", k)};  // internal: 1 is the ring (b), 2 inside it (a)
    const TrainSolution r = SolveGearTrain(s);
    const double expected = k == MeshKind::kExternal ? 10.0 * (1 + 60.0 / 20) : 10.0 * (1 - 3.0);
    EXPECT_NEAR(Speed(s, r, "2"), expected, 1e-9) << ToString(k);
  }
}

// Examples 2.6 and 2.10, seed 002: arm 6 at 150 rad/s and gear 5 at 50 rad/s, both the same
// sense; 5-4 external, 4-3 compound on the arm, 3-2 external. w2 = +30.95 rad/s.
GearTrainSpec Example26() {
  GearTrainSpec s;
  s.members = {Gear("2", 18), Gear("3", 30, "p", "6"), Gear("4", 28, "p", "6"), Gear("5", 20),
               Arm("6")};
  s.members[3].speed = 50.0;
  s.members[4].speed = 150.0;
  s.meshes = {Mesh("5", "4"), Mesh("3", "2")};
  return s;
}

TEST(GearTrain, Seed001Example26AndSeed002GivePlus3095RadPerS) {
  const GearTrainSpec s = Example26();
  const TrainSolution r = SolveGearTrain(s);
  // 150 - 100 * 25/21 = 30.952...
  EXPECT_NEAR(Speed(s, r, "2"), 150.0 - 100.0 * 25.0 / 21.0, 1e-9);
  EXPECT_NEAR(Speed(s, r, "2"), 30.95, 0.005);
}

// Example 2.7 (Fig. 2.11): same teeth plus ring 7 (76, fixed) meshing planet 4 internally;
// w2 = 60 rad/s. Document: w_arm = +10.86, w5 = +52.14 rad/s (VALIDATION section 6).
TEST(GearTrain, Seed001Example27TwoSubTrainsOnOneArmGivePlus5214RadPerS) {
  GearTrainSpec s = Example26();
  s.members[3].speed.reset();
  s.members[4].speed.reset();
  s.members[0].speed = 60.0;
  s.members.push_back(Gear("7", 76));
  s.members.back().speed = 0.0;
  s.meshes.push_back(Mesh("4", "7", MeshKind::kInternal));
  const TrainSolution r = SolveGearTrain(s);
  EXPECT_NEAR(Speed(s, r, "6"), 21.0 * 60.0 / 116.0, 1e-9);  // 10.862
  EXPECT_NEAR(Speed(s, r, "6"), 10.86, 0.005);
  EXPECT_NEAR(Speed(s, r, "5"), 52.14, 0.005);
}

// Example 2.8 (Fig. 2.12): shaft B (gear 2, 20) drives gear 3 (40), compound with gear 4
// (30) coaxial with the arm on shaft A (35 rad/s); bevel planets 5 (60) and 6 (24) on the
// arm; gear 7 (18) on shaft C faces gear 4. Train value from the printed teeth:
// -(30*24)/(60*18) = -2/3 (the document prints -5/8 and -5.63 rad/s; VALIDATION section 6:
// test the teeth): w7 = 35 - (2/3)(100 - 35) = -8.33 rad/s.
TEST(GearTrain, Seed001Example28PrintedTeethGiveMinus833RadPerS) {
  GearTrainSpec s;
  s.members = {Gear("2", 20),
               Gear("3", 40, "s4"),
               Gear("4", 30, "s4"),
               Gear("5", 60, "p", "A"),
               Gear("6", 24, "p", "A"),
               Gear("7", 18),
               Arm("A")};
  s.members[0].speed = -200.0;  // shaft B turns against A: w4 = +100 (same sense as A)
  s.members[6].speed = 35.0;
  s.meshes = {Mesh("2", "3"), Mesh("4", "5", MeshKind::kBevel), Mesh("6", "7", MeshKind::kBevel)};
  s.meshes[2].bevel_same_sense = true;  // 7 faces 4: seen from the common side, one is a front
  const TrainSolution r = SolveGearTrain(s);
  EXPECT_NEAR(Speed(s, r, "4"), 100.0, 1e-9);
  EXPECT_NEAR((Speed(s, r, "7") - 35.0) / (Speed(s, r, "4") - 35.0), -2.0 / 3.0, 1e-12);
  EXPECT_NEAR(Speed(s, r, "7"), -8.33, 0.005);
}

// Example 2.9 (Fig. 2.13): fixed sun 1 (80), planet 2 (40), arm 4 at 50 rad/s:
// w2 = 50 (1 + 80/40) = 150 rad/s, same sense as the arm.
TEST(GearTrain, Seed001Example29Gives150RadPerS) {
  GearTrainSpec s;
  s.members = {Gear("1", 80), Gear("2", 40, "", "4"), Arm("4")};
  s.members[0].speed = 0.0;
  s.members[2].speed = 50.0;
  s.meshes = {Mesh("1", "2")};
  EXPECT_NEAR(SolveGearTrain(s).speed[1], 150.0, 1e-9);
}

// Table 1.1 of seed 001 (decoded in the extraction, section 1.5): sun S, ring R, carrier C,
// (n_S - n_C)/(n_R - n_C) = -z_R/z_S. z_S = 30, z_R = 90 (coaxial planet 30).
TEST(GearTrain, Seed001Table11SixRatiosOfASimplePlanetary) {
  struct Case {
    const char* driver;
    const char* held;
    const char* driven;
    double driver_over_driven;
  };
  const double zs = 30, zr = 90;
  const Case cases[] = {{"S", "R", "C", 1 + zr / zs},       {"S", "C", "R", -zr / zs},
                        {"C", "R", "S", 1 / (1 + zr / zs)}, {"C", "S", "R", 1 / (1 + zs / zr)},
                        {"R", "S", "C", 1 + zs / zr},       {"R", "C", "S", -zs / zr}};
  for (const Case& c : cases) {
    GearTrainSpec s;
    s.members = {Gear("S", 30), Gear("P", 30, "", "C"), Gear("R", 90), Arm("C")};
    s.meshes = {Mesh("S", "P"), Mesh("P", "R", MeshKind::kInternal)};
    s.members[s.Index(c.driver)].speed = 1.0;
    s.members[s.Index(c.held)].speed = 0.0;
    s.input = c.driver;
    s.output = c.driven;
    EXPECT_NEAR(1.0 / *SolveGearTrain(s).train_value, c.driver_over_driven, 1e-12)
        << c.driver << " drives, " << c.held << " held";
  }
  // Two members locked together (driven at the same speed): the whole set turns 1:1.
  GearTrainSpec s;
  s.members = {Gear("S", 30), Gear("P", 30, "", "C"), Gear("R", 90), Arm("C")};
  s.meshes = {Mesh("S", "P"), Mesh("P", "R", MeshKind::kInternal)};
  s.members[0].speed = 7.0;
  s.members[3].speed = 7.0;
  for (double w : SolveGearTrain(s).speed) EXPECT_NEAR(w, 7.0, 1e-12);
}

// A reverted train (first and last shafts coaxial) is solved like any compound train.
TEST(GearTrain, RevertedTrainValueIsTheProductOfStageRatios) {
  GearTrainSpec s;
  s.members = {Gear("A", 20), Gear("B", 40, "c"), Gear("C", 25, "c"), Gear("D", 35)};
  s.members[0].speed = 70.0;
  s.meshes = {Mesh("A", "B"), Mesh("C", "D")};
  s.input = "A";
  s.output = "D";
  EXPECT_NEAR(*SolveGearTrain(s).train_value, (20.0 / 40.0) * (25.0 / 35.0), 1e-12);
}

using testing::Message;

TEST(GearTrain, UnderDeterminedTrainNamesTheFreeMembers) {
  GearTrainSpec s = Example26();
  s.members[4].speed.reset();  // the arm is free: one condition missing
  const std::string m = Message(s);
  EXPECT_NE(m.find("under-determined"), std::string::npos) << m;
  EXPECT_NE(m.find("1 more condition"), std::string::npos) << m;
  EXPECT_NE(m.find("6"), std::string::npos) << m;
}

TEST(GearTrain, OverDeterminedInputIsRejectedAtThatMember) {
  GearTrainSpec s;
  s.members = {Gear("A", 20), Gear("B", 40)};
  s.members[0].speed = 10.0;
  s.members[1].speed = -5.0;  // consistent, but given twice
  s.meshes = {Mesh("A", "B")};
  std::string m = Message(s);
  EXPECT_NE(m.find("gear.B.speed: over-determined"), std::string::npos) << m;
  s.members[1].speed = 3.0;  // contradictory
  m = Message(s);
  EXPECT_NE(m.find("gear.B.speed: contradictory"), std::string::npos) << m;
}

TEST(GearTrain, LockedTriangleOfExternalGearsRejectsItsInput) {
  // Three external gears in a ring force each other's sense: only w = 0 fits.
  GearTrainSpec s;
  s.members = {Gear("A", 20), Gear("B", 20), Gear("C", 20)};
  s.members[0].speed = 1.0;
  s.meshes = {Mesh("A", "B"), Mesh("B", "C"), Mesh("C", "A")};
  const std::string m = Message(s);
  EXPECT_NE(m.find("locked"), std::string::npos) << m;
}

TEST(GearTrain, RejectsMeshesThatCannotExist) {
  GearTrainSpec s;
  s.members = {Gear("A", 20), Gear("B", 20),          Arm("X"),
               Arm("Y"),      Gear("P", 10, "", "X"), Gear("Q", 10, "", "Y")};
  s.members[0].speed = 1.0;
  s.meshes = {Mesh("A", "Z"), Mesh("A", "B", MeshKind::kInternal), Mesh("P", "Q"),
              Mesh("A", "B", MeshKind::kWorm), Mesh("A", "B", MeshKind::kRack)};
  const std::string m = Message(s);
  EXPECT_NE(m.find("mesh.AZ.b: no member named 'Z'"), std::string::npos) << m;
  EXPECT_NE(m.find("z_ring > z_pinion"), std::string::npos) << m;
  EXPECT_NE(m.find("rides on X"), std::string::npos) << m;
  EXPECT_NE(m.find("A is not a worm"), std::string::npos) << m;
  EXPECT_NE(m.find("B is not a rack"), std::string::npos) << m;
}

TEST(GearTrain, RackPinionNeedsAModule) {
  GearTrainSpec s;
  s.members = {Gear("P", 20)};
  TrainMember rack;
  rack.name = "R";
  rack.kind = MemberKind::kRack;
  rack.where = "rack.R";
  s.members.push_back(rack);
  s.members[0].speed = 1.0;
  s.meshes = {Mesh("P", "R", MeshKind::kRack)};
  EXPECT_NE(Message(s).find("gear.P.module_m"), std::string::npos);
  s.members[1].module_m = 0.002;  // the rack's module serves: v = w m z / 2
  EXPECT_NEAR(SolveGearTrain(s).speed[1], 0.5 * 0.002 * 20, 1e-15);
}

// The simple planetary of seed 001 Example 2.11's teeth: sun 50, planet 20, ring 90.
GearTrainSpec Planetary(const char* held) {
  GearTrainSpec s;
  s.members = {Gear("sun", 50), Gear("planet", 20, "", "arm"), Gear("ring", 90), Arm("arm")};
  s.meshes = {Mesh("sun", "planet"), Mesh("planet", "ring", MeshKind::kInternal)};
  s.members[0].speed = 157.0;
  s.members[s.Index(held)].speed = 0.0;
  return s;
}

TEST(GearTrain, HeldInputHasNoTrainValue) {
  // w_arm / w_ring with the ring held is x / 0: the ring cannot be the input.
  GearTrainSpec s = Planetary("ring");
  s.input = "ring";
  s.output = "arm";
  const std::string m = Message(s);
  EXPECT_NE(m.find("train.input: the input member is held: w_output / w_input is undefined"),
            std::string::npos)
      << m;
}

TEST(GearTrain, RoundOffOfAMemberAtRestIsExactlyZero) {
  // Ring held, sun driven: the ring's solved speed is exactly 0, not 1e-15 of the sun's;
  // the arm turns at 157 / (1 + 90/50) (Table 1.1).
  const GearTrainSpec s = Planetary("ring");
  const TrainSolution r = SolveGearTrain(s);
  EXPECT_EQ(Speed(s, r, "ring"), 0.0);
  EXPECT_NEAR(Speed(s, r, "arm"), 157.0 / 2.8, 1e-12);
}

TEST(GearTrain, GearsOfDifferentModulesDoNotMesh) {
  GearTrainSpec s;
  s.members = {Gear("A", 20), Gear("B", 40)};
  s.members[0].speed = 1.0;
  s.members[0].module_m = 0.002;
  s.members[1].module_m = 0.003;
  s.meshes = {Mesh("A", "B")};
  EXPECT_NE(Message(s).find("mesh.AB.b: B has module 0.003 m and A 0.002 m"), std::string::npos)
      << Message(s);
  s.members[1].module_m = 0.002;
  EXPECT_NEAR(SolveGearTrain(s).speed[1], -0.5, 1e-15);  // eq. 2.1: -z_A/z_B
}

TEST(GearTrain, ASecondMeshOfTheSamePairIsReportedThere) {
  GearTrainSpec s;
  s.members = {Gear("A", 20), Gear("B", 40)};
  s.members[0].speed = 1.0;
  // (B as the ring of 20 teeth around A's 40 would be wrong too: the repeat is the slip.)
  s.meshes = {Mesh("A", "B"), Mesh("B", "A", MeshKind::kInternal)};
  s.meshes[1].where = "mesh.again";
  const std::string m = Message(s);
  EXPECT_NE(m.find("mesh.again.b: B and A already mesh in [mesh.AB]"), std::string::npos) << m;
  EXPECT_EQ(m.find("the ring"), std::string::npos) << m;
  EXPECT_EQ(m.find("speed"), std::string::npos) << m;
}

TEST(GearTrain, LockedTriangleWithoutInputIsRejectedToo) {
  // The same triangle as above, nothing driven: w = 0 is its only motion, not an answer.
  GearTrainSpec s;
  s.members = {Gear("A", 20), Gear("B", 20), Gear("C", 20)};
  s.meshes = {Mesh("A", "B"), Mesh("B", "C"), Mesh("C", "A")};
  const std::string m = Message(s);
  EXPECT_NE(m.find("gear.A.speed: locked: the meshes and shafts alone hold A, B, C at rest"),
            std::string::npos)
      << m;
}

}  // namespace
}  // namespace tehl
