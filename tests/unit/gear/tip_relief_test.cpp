// Tip relief in the quasi-static load sharing (tip_relief.hpp): the limits that can be worked
// out by hand for equal pair stiffnesses, the load balance, and the step at B it softens.
#include "tehl/gear/tip_relief.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "unit/gear/reference_pairs.hpp"

namespace tehl {
namespace {

constexpr double kForce = 2903.5;  // F_bt of seed 004 at 10 kW, 1000 rpm [N] (VALIDATION §5)
constexpr double kPair = 2e8;      // equal pair stiffness [N/m]: F / k = 14.5 um

PathOfContact SeedPath() { return PathOfContact(GearPair(testing::Seed004Spec()), 100.0); }

TEST(TipRelief, NamesRoundTrip) {
  for (ReliefShape r : {ReliefShape::kLinear, ReliefShape::kParabolic})
    EXPECT_EQ(ReliefShapeFromString(ToString(r)), r);
  EXPECT_FALSE(ReliefShapeFromString("circular").has_value());
}

TEST(TipRelief, GapFollowsTheShapeFromEachTip) {
  TipRelief r;
  r.wheel_amount_m = 10e-6;
  r.wheel_length_m = 2e-3;
  r.pinion_amount_m = 8e-6;
  r.pinion_length_m = 1e-3;
  const double g = 10e-3;
  EXPECT_DOUBLE_EQ(r.GapAt(0, g), 10e-6);        // wheel tip at A: the whole amount
  EXPECT_DOUBLE_EQ(r.GapAt(0.5e-3, g), 7.5e-6);  // a quarter into the relief
  EXPECT_EQ(r.GapAt(2e-3, g), 0.0);              // relief ends at L
  EXPECT_EQ(r.GapAt(5e-3, g), 0.0);
  EXPECT_NEAR(r.GapAt(9.5e-3, g), 4e-6, 1e-17);  // halfway into the pinion's relief
  EXPECT_DOUBLE_EQ(r.GapAt(g, g), 8e-6);
  r.pinion_shape = r.wheel_shape = ReliefShape::kParabolic;
  EXPECT_DOUBLE_EQ(r.GapAt(0.5e-3, g), 10e-6 * 0.75 * 0.75);
  EXPECT_NEAR(r.GapAt(9.5e-3, g), 8e-6 * 0.25, 1e-17);  // (s - (g - L)) / L rounds
  // Each gear its own shape: a linear wheel relief with a parabolic pinion relief.
  r.wheel_shape = ReliefShape::kLinear;
  EXPECT_DOUBLE_EQ(r.GapAt(0.5e-3, g), 7.5e-6);
  EXPECT_NEAR(r.GapAt(9.5e-3, g), 8e-6 * 0.25, 1e-17);
}

TEST(RelievedLoadShare, WithoutReliefItIsTheStiffnessShare) {
  const PathOfContact path = SeedPath();
  const PairStiffnessFn k = [](double r1, double r2) {
    return 1e8 * (r1 / 0.035) + 5e7 * r2 / 0.1;
  };
  const TipRelief none;
  for (int i = 0; i <= 40; ++i) {
    const double s = path.length_m() * i / 40;
    EXPECT_NEAR(RelievedLoadShare(path, s, k, none, kForce).share, StiffnessLoadShare(path, s, k),
                1e-14)
        << "s = " << s;
  }
}

TEST(RelievedLoadShare, TwoEqualPairsByHand) {
  // Pair at s in the wheel's relief (gap e), partner at s + p_b without relief, both of
  // stiffness k: k (d - e) + k d = F, so d = (F/k + e) / 2 and the share is 1/2 - k e / (2 F)
  // while e < F/k.
  const PathOfContact path = SeedPath();
  const PairStiffnessFn k = [](double, double) { return kPair; };
  TipRelief r;
  r.wheel_amount_m = 10e-6;
  r.wheel_length_m = 0.5 * path.s_b_m();
  const double s = 0.1 * path.s_b_m();
  const double e = r.GapAt(s, path.length_m());
  ASSERT_NEAR(e, 10e-6 * 0.8, 1e-18);
  const RelievedShare got = RelievedLoadShare(path, s, k, r, kForce);
  EXPECT_NEAR(got.share, 0.5 - kPair * e / (2 * kForce), 1e-14);
  EXPECT_NEAR(got.approach_m, (kForce / kPair + e) / 2, 1e-18);
  // The partner's share is the rest.
  EXPECT_NEAR(RelievedLoadShare(path, s + path.base_pitch_m(), k, r, kForce).share, 1 - got.share,
              1e-14);
}

TEST(RelievedLoadShare, PairsInContactCarryTheWholeLoad) {
  const GearPair pair(testing::FzgCSpec());
  const PathOfContact path(pair, 100.0);
  const PairStiffnessFn k = [](double r1, double) { return 1.5e8 * (r1 / 0.04); };
  for (ReliefShape shape : {ReliefShape::kLinear, ReliefShape::kParabolic}) {
    TipRelief r;
    r.pinion_shape = r.wheel_shape = shape;
    r.pinion_amount_m = 12e-6;
    r.pinion_length_m = 0.6 * (path.length_m() - path.s_d_m());
    r.wheel_amount_m = 30e-6;  // lifts the pair near A off: its share is 0 there, not negative
    r.wheel_length_m = 0.8 * path.s_b_m();
    for (int i = 0; i <= 60; ++i) {
      const double s = path.length_m() * i / 60;
      double sum = 0;
      for (double q : path.SimultaneousContacts(s)) {
        const double share = RelievedLoadShare(path, q, k, r, kForce).share;
        EXPECT_GE(share, 0.0);
        sum += share;
      }
      EXPECT_NEAR(sum, 1.0, 1e-12) << "s = " << s;
    }
  }
}

TEST(RelievedLoadShare, ApproachWithoutThePairIsWhereItLiftsOff) {
  // At A with equal stiffnesses and no relief at D, the partner alone closes F/k: a wheel
  // relief just below that keeps the pair at A loaded, just above lifts it off.
  const PathOfContact path = SeedPath();
  const PairStiffnessFn k = [](double, double) { return kPair; };
  TipRelief r;
  r.wheel_length_m = 0.5 * path.s_b_m();
  EXPECT_NEAR(ApproachWithoutPair(path, 0.0, k, r, kForce), kForce / kPair, 1e-18);
  r.wheel_amount_m = 0.99 * kForce / kPair;
  EXPECT_GT(RelievedLoadShare(path, 0.0, k, r, kForce).share, 0.0);
  r.wheel_amount_m = 1.01 * kForce / kPair;
  EXPECT_EQ(RelievedLoadShare(path, 0.0, k, r, kForce).share, 0.0);
  // In single contact there is no other pair.
  EXPECT_TRUE(std::isinf(ApproachWithoutPair(path, path.s_c_m(), k, r, kForce)));
}

TEST(RelievedLoadShare, PinionReliefShrinksTheStepAtB) {
  // At B the partner leaves at E, so the tracked pair's step at B is the partner's share at
  // E: (F/k - C_a)/ (2 F/k) with equal stiffnesses, 1/2 without relief, 0 once C_a >= F/k.
  const PathOfContact path = SeedPath();
  const PairStiffnessFn k = [](double, double) { return kPair; };
  const double sb = path.s_b_m(), nudge = 1e-9 * path.length_m();
  TipRelief r;
  r.pinion_length_m = 0.5 * (path.length_m() - path.s_d_m());
  for (double c : {0.0, 5e-6, 10e-6, 14e-6, 20e-6}) {
    r.pinion_amount_m = c;
    const double before = RelievedLoadShare(path, sb - nudge, k, r, kForce).share;
    const double after = RelievedLoadShare(path, sb + nudge, k, r, kForce).share;
    EXPECT_NEAR(after, 1.0, 1e-14);
    const double expected = std::max(0.0, (kForce / kPair - c) / (2 * kForce / kPair));
    EXPECT_NEAR(after - before, expected, 1e-6) << "C_a = " << c;
  }
}

TEST(LoadedPathOf, StartsWhereTheShareReachesTheMinimum) {
  // Two equal pairs, the one at s in the wheel's linear relief: share 1/2 - k e / (2 F) >= m
  // while e = C (L - s) / L <= (1 - 2 m) F / k, so the loaded path starts at
  // s' = L (1 - (1 - 2 m) F / (k C)); no pinion relief, so it ends at E.
  const PathOfContact path = SeedPath();
  const PairStiffnessFn k = [](double, double) { return kPair; };
  TipRelief r;
  r.wheel_amount_m = 30e-6;
  r.wheel_length_m = 0.5 * path.s_b_m();
  const double m = 0.01;
  const LoadedPath loaded = LoadedPathOf(path, k, r, kForce, m);
  const double expected =
      r.wheel_length_m * (1 - (1 - 2 * m) * kForce / (kPair * r.wheel_amount_m));
  EXPECT_NEAR(loaded.begin_m, expected, 2e-9 * path.length_m());
  EXPECT_EQ(loaded.end_m, path.length_m());
  EXPECT_FALSE(loaded.empty());
  // Without relief: the whole path. A pinion relief over the whole path leaves the pair
  // loaded from A (the partner at s + p_b has the larger gap) to D, where single contact
  // ends and the entering partner, free of relief, takes the load.
  const LoadedPath whole = LoadedPathOf(path, k, TipRelief{}, kForce, m);
  EXPECT_EQ(whole.begin_m, 0.0);
  EXPECT_EQ(whole.end_m, path.length_m());
  TipRelief huge;
  huge.pinion_amount_m = 1e-3;
  huge.pinion_length_m = path.length_m();
  const LoadedPath single = LoadedPathOf(path, k, huge, kForce, m);
  EXPECT_EQ(single.begin_m, 0.0);
  EXPECT_NEAR(single.end_m, path.s_d_m(), 2e-9 * path.length_m());
}

}  // namespace
}  // namespace tehl
