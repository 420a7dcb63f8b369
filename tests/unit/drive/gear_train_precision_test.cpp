// Trains of many stages and very large ratios: the speeds are products of tooth ratios along
// the meshes, so every member's speed is exact to round-off (here 1e-12 relative) whatever
// the ratio, and a legal train is never mistaken for a locked one. References by hand: a
// stage of z_a driving z_b multiplies the speed by -z_a / z_b (external, seed 001 eq. 2.1),
// +starts / z_wheel (right-hand worm).
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "tehl/drive/gear_train.hpp"
#include "tehl/drive/train_torques.hpp"
#include "tehl/error.hpp"
#include "unit/drive/train_spec_builders.hpp"

namespace tehl {
namespace {

// prefix + k (appended: GCC 12 warns falsely of overlapping copies for "literal" + string).
std::string Name(const char* prefix, int k) {
  std::string s = prefix;
  s += std::to_string(k);
  return s;
}
using testing::Arm;
using testing::Gear;
using testing::Mesh;

constexpr double kRelative = 1e-12;

// Input p0 (z_in) drives g1 (z_out); p1 on g1's shaft drives g2; ... g<stages> is the output.
GearTrainSpec Chain(int stages, int z_in, int z_out, double w_in) {
  GearTrainSpec s;
  s.members.push_back(Gear("p0", z_in));
  s.members.back().speed = w_in;
  for (int k = 1; k <= stages; ++k) {
    const std::string shaft = Name("s", k);
    s.members.push_back(Gear(Name("g", k), z_out, shaft));
    if (k < stages) s.members.push_back(Gear(Name("p", k), z_in, shaft));
    s.meshes.push_back(Mesh(Name("p", k - 1), Name("g", k)));
  }
  s.input = "p0";
  s.output = Name("g", stages);
  return s;
}

void ExpectRelative(double got, double want, const std::string& what) {
  EXPECT_LE(std::abs(got - want), kRelative * std::abs(want))
      << what << ": got " << got << ", want " << want << ", relative error "
      << std::abs(got / want - 1);
}

TEST(GearTrainPrecision, NineStagesOfTenToOneAreSolvedNotLocked) {
  // 3000 rpm through nine 10 -> 100 stages: w_g9 = 314.159... * (-0.1)^9, ratio 1e9.
  for (int stages : {6, 8, 9, 12}) {
    const GearTrainSpec s = Chain(stages, 10, 100, 314.0);
    const TrainSolution r = SolveGearTrain(s);
    const double value = std::pow(-0.1, stages);
    ExpectRelative(*r.train_value, value, std::to_string(stages) + " stages, train value");
    for (int k = 1; k <= stages; ++k)
      ExpectRelative(r.speed[s.Index(Name("g", k))], 314.0 * std::pow(-0.1, k), Name("g", k));
  }
}

TEST(GearTrainPrecision, TwentyStagesOfFourToOneGiveTwoToTheMinusForty) {
  // (-10/40)^20 = 4^-20 = 2^-40 = 9.09e-13 (ratio 1.0995e12), exact in binary.
  const GearTrainSpec s = Chain(20, 10, 40, 1.0);
  const TrainSolution r = SolveGearTrain(s);
  ExpectRelative(*r.train_value, std::ldexp(1.0, -40), "train value");
  ExpectRelative(r.speed[s.Index("g20")], std::ldexp(1.0, -40), "g20");
  EXPECT_EQ(r.rank, r.unknowns);
}

TEST(GearTrainPrecision, FiveWormStagesGiveTenToTheTen) {
  // Five right-hand single-start worms into 100-tooth wheels: (+1/100)^5 = 1e-10.
  GearTrainSpec s;
  s.members.push_back(Gear("w0", 1));
  s.members.back().worm_hand = WormHand::kRight;
  s.members.back().speed = 314.0;
  for (int k = 1; k <= 5; ++k) {
    const std::string shaft = Name("s", k);
    s.members.push_back(Gear(Name("wh", k), 100, shaft));
    if (k < 5) {
      s.members.push_back(Gear(Name("w", k), 1, shaft));
      s.members.back().worm_hand = WormHand::kRight;
    }
    s.meshes.push_back(Mesh(Name("w", k - 1), Name("wh", k), MeshKind::kWorm));
  }
  s.input = "w0";
  s.output = "wh5";
  const TrainSolution r = SolveGearTrain(s);
  ExpectRelative(*r.train_value, 1e-10, "train value");
  ExpectRelative(r.speed[s.Index("wh5")], 314.0e-10, "wh5");
}

TEST(GearTrainPrecision, PlanetaryFollowedByTenStagesIsExact) {
  // Sun 50 driven at 280 rad/s, ring 90 held: arm at 280 / (1 + 90/50) = 100 rad/s (seed
  // 001 Table 1.1); the arm's shaft carries p0 into ten 10 -> 100 stages: g10 = 100e-10.
  GearTrainSpec s = Chain(10, 10, 100, 0.0);
  s.members[0].speed.reset();
  s.members[0].shaft = "arm_shaft";
  s.members.push_back(Gear("sun", 50));
  s.members.back().speed = 280.0;
  s.members.push_back(Gear("planet", 20, "", "arm"));
  s.members.push_back(Gear("ring", 90));
  s.members.back().speed = 0.0;
  s.members.push_back(Arm("arm", "arm_shaft"));
  s.meshes.push_back(Mesh("sun", "planet"));
  s.meshes.push_back(Mesh("planet", "ring", MeshKind::kInternal));
  s.input = "sun";
  s.output = "g10";
  const TrainSolution r = SolveGearTrain(s);
  ExpectRelative(r.speed[s.Index("arm")], 100.0, "arm");
  ExpectRelative(r.speed[s.Index("g10")], 100.0e-10, "g10");
  ExpectRelative(*r.train_value, 1e-10 / 2.8, "train value");
  EXPECT_EQ(r.speed[s.Index("ring")], 0.0);
  // Torques per N m on the sun: the output takes -1 / train value = -2.8e10 N m, the frame
  // holds the ring with +z_ring / z_sun = +1.8 N m as without the chain (seed 001 Example
  // 2.11's teeth, train_torques_test.cpp).
  const TrainTorques t = SolveTrainTorques(s, r);
  ASSERT_TRUE(t.solved) << t.message;
  ExpectRelative(*t.torque[s.Index("g10")], -2.8e10, "T_g10");
  ExpectRelative(*t.torque[s.Index("ring")], 1.8, "T_ring");
  EXPECT_LT(t.power_residual, 1e-12);
}

TEST(GearTrainPrecision, TwelveStagesIntoAPlanetaryAreExact) {
  // p0 at 1 rad/s through twelve 10 -> 100 stages: g12 at 1e-12 rad/s drives the sun (50) on
  // its shaft; ring 90 held: arm at 1e-12 / 2.8 (seed 001 Table 1.1). Beside it, a pair
  // A (20) - B (40) driven at 1e4 rad/s, on its own: B at -5e3 rad/s.
  GearTrainSpec s = Chain(12, 10, 100, 1.0);
  s.members[s.Index("g12")].shaft = "sun_shaft";
  s.members.push_back(Gear("sun", 50, "sun_shaft"));
  s.members.push_back(Gear("planet", 20, "", "arm"));
  s.members.push_back(Gear("ring", 90));
  s.members.back().speed = 0.0;
  s.members.push_back(Arm("arm"));
  s.members.push_back(Gear("A", 20));
  s.members.back().speed = 1e4;
  s.members.push_back(Gear("B", 40));
  s.meshes.push_back(Mesh("sun", "planet"));
  s.meshes.push_back(Mesh("planet", "ring", MeshKind::kInternal));
  s.meshes.push_back(Mesh("A", "B"));
  s.output = "arm";
  const TrainSolution r = SolveGearTrain(s);
  ExpectRelative(r.speed[s.Index("arm")], 1e-12 / 2.8, "arm");
  ExpectRelative(*r.train_value, 1e-12 / 2.8, "train value");
  ExpectRelative(r.speed[s.Index("B")], -5e3, "B");
  EXPECT_EQ(r.speed[s.Index("ring")], 0.0);
}

TEST(GearTrainPrecision, TorquesOfATwelveStageTrainBalanceExactly) {
  // T_out = -T_in / train value = -1 / (-0.1)^12 = -1e12 N m per N m on p0; T w sums to 0.
  const GearTrainSpec s = Chain(12, 10, 100, 1.0);
  const TrainSolution r = SolveGearTrain(s);
  const TrainTorques t = SolveTrainTorques(s, r);
  ASSERT_TRUE(t.solved) << t.message;
  ExpectRelative(*t.torque[s.Index("g12")], -1e12, "T_g12");
  EXPECT_LT(t.power_residual, 1e-12);
}

TEST(GearTrainPrecision, RedundantTwinCountershaftsAreAcceptedAndExact) {
  // A (20) drives B1 and B2 (60); C1 and C2 (15) on their shafts both drive D (45):
  // w_D = w_A (20/60)(15/45) = w_A / 9 by either path, so the second path is redundant.
  GearTrainSpec s;
  s.members = {Gear("A", 20),        Gear("B1", 60, "s1"), Gear("C1", 15, "s1"),
               Gear("B2", 60, "s2"), Gear("C2", 15, "s2"), Gear("D", 45)};
  s.members[0].speed = 9.0;
  s.meshes = {Mesh("A", "B1"), Mesh("C1", "D"), Mesh("A", "B2"), Mesh("C2", "D")};
  const TrainSolution r = SolveGearTrain(s);
  ExpectRelative(r.speed[s.Index("D")], 1.0, "D");
  // One tooth less on D2's path: the paths disagree and hold everything at rest.
  s.members[4].teeth = 16;
  const std::string m = testing::Message(s);
  EXPECT_NE(m.find("locked"), std::string::npos) << m;
}

TEST(GearTrainPrecision, TriangleAtTheEndOfAHighRatioChainIsStillLocked) {
  // Nine 10 -> 100 stages, then g9 meshes X and Y, which mesh each other: three external
  // gears in a loop force g9, X, Y (and so the whole chain) to rest.
  GearTrainSpec s = Chain(9, 10, 100, 1.0);
  s.members.push_back(Gear("X", 30));
  s.members.push_back(Gear("Y", 30));
  s.meshes.push_back(Mesh("g9", "X"));
  s.meshes.push_back(Mesh("X", "Y"));
  s.meshes.push_back(Mesh("Y", "g9"));
  const std::string m = testing::Message(s);
  EXPECT_NE(m.find("locked"), std::string::npos) << m;
}

}  // namespace
}  // namespace tehl
