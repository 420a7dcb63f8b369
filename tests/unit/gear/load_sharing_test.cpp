// Load sharing between the tooth pairs in contact: the linear ramp and the stiffness split.
#include "tehl/gear/load_sharing.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "tehl/error.hpp"
#include "tehl/gear/corner_contact.hpp"
#include "tehl/gear/tip_relief.hpp"
#include "unit/gear/reference_pairs.hpp"

namespace tehl {
namespace {

TEST(LoadSharing, NamesRoundTrip) {
  for (LoadSharing l : {LoadSharing::kLinear, LoadSharing::kStiffness, LoadSharing::kLoaded})
    EXPECT_EQ(LoadSharingFromString(ToString(l)), l);
  EXPECT_FALSE(LoadSharingFromString("equal").has_value());
}

TEST(LinearLoadShare, RampValuesAtThePointsOfThePath) {
  // The ramp of load_sharing.hpp: 1/3 at A, 2/3 at B-, 1 on BD, 2/3 at D+, 1/3 at E.
  const GearPair pair(testing::Seed004Spec());
  const PathOfContact path(pair, 100.0);
  const double e = 1e-12;
  EXPECT_NEAR(LinearLoadShare(path, 0), 1.0 / 3, 1e-15);
  EXPECT_NEAR(LinearLoadShare(path, path.s_b_m() - e), 2.0 / 3, 1e-9);
  EXPECT_NEAR(LinearLoadShare(path, path.s_c_m()), 1.0, 0);
  EXPECT_NEAR(LinearLoadShare(path, path.s_d_m() + e), 2.0 / 3, 1e-9);
  EXPECT_NEAR(LinearLoadShare(path, path.length_m()), 1.0 / 3, 1e-12);
}

TEST(LinearLoadShare, PairsInContactAlwaysCarryTheWholeLoad) {
  // D = A + p_b and AB = DE: the shares of the two pairs in contact sum to 1.
  const GearPair pair(testing::FzgCSpec());
  const PathOfContact path(pair, 100.0);
  for (int i = 0; i <= 50; ++i) {
    const double s = path.length_m() * i / 50;
    double sum = 0;
    for (double q : path.SimultaneousContacts(s)) sum += LinearLoadShare(path, q);
    EXPECT_NEAR(sum, 1.0, 1e-12) << "s = " << s;
  }
}

TEST(LinearLoadShare, RejectsContactRatiosOfTwoOrMore) {
  // A high-contact-ratio pair (80/120 teeth, 14.5 deg, addendum 1.2 m): eps_alpha >= 2, where
  // the ramp does not apply.
  GearPairSpec s = testing::Seed004Spec();
  s.pinion.teeth = 80;
  s.wheel.teeth = 120;
  s.drive_pressure_angle_rad = s.coast_pressure_angle_rad = DegToRad(14.5);
  s.addendum_coefficient = 1.2;
  const GearPair pair(s);
  ASSERT_GE(pair.line(Flank::kDrive).contact_ratio, 2.0);
  const PathOfContact path(pair, 100.0);
  try {
    LinearLoadShare(path, 0.0);
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(e.problems()[0].key, "gear.load_sharing");
  }
}

TEST(StiffnessLoadShare, EqualStiffnessSplitsDoubleContactInHalves) {
  const GearPair pair(testing::Seed004Spec());
  const PathOfContact path(pair, 100.0);
  const PairStiffnessFn constant = [](double, double) { return 3e8; };
  EXPECT_NEAR(StiffnessLoadShare(path, 0.2 * path.s_b_m(), constant), 0.5, 1e-15);
  EXPECT_NEAR(StiffnessLoadShare(path, path.s_c_m(), constant), 1.0, 1e-15);
  EXPECT_NEAR(MeshStiffnessAt(path, 0.2 * path.s_b_m(), constant), 6e8, 1e-3);
}

TEST(StiffnessLoadShare, ProportionalToPairStiffnessAndSumsToOne) {
  // A pair stiffness that grows with the pinion contact radius: in double contact the pair
  // nearer the pinion tip (larger r1) carries more, k_i / (k_1 + k_2).
  const GearPair pair(testing::Seed004Spec());
  const PathOfContact path(pair, 100.0);
  const PairStiffnessFn k = [](double r1, double r2) { return 1e8 * (r1 / 0.035) + 0 * r2; };
  const double s = 0.3 * path.s_b_m();
  const ContactPoint a = path.At(s), b = path.At(s + path.base_pitch_m());
  const double ka = k(a.r1_m, a.r2_m), kb = k(b.r1_m, b.r2_m);
  EXPECT_NEAR(StiffnessLoadShare(path, s, k), ka / (ka + kb), 1e-15);
  EXPECT_NEAR(StiffnessLoadShare(path, s, k) + StiffnessLoadShare(path, s + path.base_pitch_m(), k),
              1.0, 1e-15);
}

// The loaded sharing (kLoaded): the stiffness sharing with the corner contact of the pairs
// beyond A and E (tip_relief.hpp RelievedLoadShare with a CornerContact). Constant pair
// stiffness 3e8 N/m on the seed 004 pair; corner contact followed to 0.1 mm.
struct LoadedSeed004 {
  GearPair pair{testing::Seed004Spec()};
  PathOfContact path{pair, 100.0};
  CornerContact corner{pair, Flank::kDrive, 1e-4};
  PairStiffnessFn k = [](double, double) { return 3e8; };
};

TEST(LoadedLoadShare, ContinuousAtBAndDWhereTheStiffnessShareJumps) {
  // The stepped share jumps from 1/2 to 1 at B and back at D; under F = 3000 N (approach
  // 5 um for two pairs) the corners carry load within some 0.5 mm beyond A and E, so the
  // tracked share is continuous: 1/2 on both sides of B and D (the partner pair is at E or
  // A, where its separation is 0). 0.2 mm into the single-contact zone the partner is in
  // corner contact 0.2 mm beyond E (or before A) with separation e: with equal stiffnesses k
  // the approach is (F + k e) / (2 k), so the tracked pair carries 1/2 + k e / (2 F).
  LoadedSeed004 t;
  const double f = 3000.0, nudge = 1e-9 * t.path.length_m();
  for (double sw : {t.path.s_b_m(), t.path.s_d_m()}) {
    const double below = RelievedLoadShare(t.path, sw - nudge, t.k, {}, f, &t.corner).share;
    const double above = RelievedLoadShare(t.path, sw + nudge, t.k, {}, f, &t.corner).share;
    EXPECT_NEAR(below, above, 1e-6) << "at s = " << sw;
    EXPECT_NEAR(below, 0.5, 1e-6) << "at s = " << sw;
    const bool at_b = sw == t.path.s_b_m();
    const double inside = sw + (at_b ? 2e-4 : -2e-4);
    const double partner = inside + (at_b ? 1.0 : -1.0) * t.path.base_pitch_m();
    const double e = t.corner.GapAt(partner);
    ASSERT_GT(e, 0.0);
    ASSERT_LT(e, f / 3e8);  // the partner still touches
    const double ramp = RelievedLoadShare(t.path, inside, t.k, {}, f, &t.corner).share;
    EXPECT_NEAR(ramp, 0.5 + 3e8 * e / (2 * f), 1e-9) << "at s = " << inside;
    const double stepped_below = StiffnessLoadShare(t.path, sw - nudge, t.k);
    const double stepped_above = StiffnessLoadShare(t.path, sw + nudge, t.k);
    EXPECT_NEAR(std::abs(stepped_below - stepped_above), 0.5, 1e-12);
  }
}

TEST(LoadedLoadShare, SharesOfAllPairsSumToOneAndLightLoadsMeshOnThePath) {
  LoadedSeed004 t;
  const double pb = t.path.base_pitch_m(), g = t.path.length_m();
  for (double f : {1e-3, 3000.0, 3e4}) {
    for (double s : {0.1 * g, 0.47 * g, 0.52 * g, 0.9 * g}) {
      // Every pair within the extension, the tracked one among them: their loads k (delta -
      // e) sum to F (CommonApproach).
      const RelievedShare r = RelievedLoadShare(t.path, s, t.k, {}, f, &t.corner);
      double sum = 0;
      for (int j = -3; j <= 3; ++j) {
        const double q = s + j * pb;
        if (q < -t.corner.before_m() || q > g + t.corner.after_m()) continue;
        sum += std::max(0.0, 3e8 * (r.approach_m - t.corner.GapAt(q))) / f;
      }
      EXPECT_NEAR(sum, 1.0, 1e-9) << "F " << f << " s " << s;
      // A vanishing load closes no corner: the stiffness share on the path.
      if (f < 1.0) {
        EXPECT_NEAR(r.share, StiffnessLoadShare(t.path, s, t.k), 1e-9) << s;
      }
    }
  }
}

}  // namespace
}  // namespace tehl
