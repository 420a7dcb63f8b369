// Load sharing between the tooth pairs in contact: the linear ramp and the stiffness split.
#include "tehl/gear/load_sharing.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "tehl/error.hpp"
#include "unit/gear/reference_pairs.hpp"

namespace tehl {
namespace {

TEST(LoadSharing, NamesRoundTrip) {
  for (LoadSharing l : {LoadSharing::kLinear, LoadSharing::kStiffness})
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

}  // namespace
}  // namespace tehl
