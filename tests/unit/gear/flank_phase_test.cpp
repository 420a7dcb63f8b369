// The coast side of a pair (src/gear/flank_phase.cpp): the mirrored pair's drive line is the
// coast line, and the coast contacts the pinion's rotation places (CoastPhaseOffset) are
// checked against those the wheel's rotation places, computed here from the wheel's own
// teeth: at zero backlash both flanks of the mesh touch at once, so the two must agree; with
// backlash j on the working pitch circle they differ by the coast gap j cos(alpha_wc), that
// is j / p_w pitches (docs/dynamics.md "Back flanks").
#include "tehl/gear/flank_phase.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "tehl/gear/involute.hpp"
#include "unit/gear/reference_pairs.hpp"

namespace tehl {
namespace {

double Wrap(double q) { return q - std::round(q); }  // to [-1/2, 1/2]

// The wheel's side of the derivation in flank_phase.hpp: its crossings u2 are measured from
// T2 towards T1, u2 = T1T2 - T1A - s, and the same identity holds for its teeth.
double WheelCoastPhaseOffset(const GearPair& pair) {
  const GearGeometry& w = pair.wheel();
  const LineOfAction& d = pair.line(Flank::kDrive);
  const LineOfAction& c = pair.line(Flank::kCoast);
  const double theta_b = w.reference_thickness_m / w.pitch_radius_m +
                         Involute(w.drive.pressure_angle_rad) +
                         Involute(w.coast.pressure_angle_rad);
  return (d.tangent_length_m - d.a_m) / d.base_pitch_m +
         (c.tangent_length_m - c.a_m) / c.base_pitch_m -
         w.teeth * (theta_b + d.working_pressure_angle_rad + c.working_pressure_angle_rad) /
             (2.0 * kPi);
}

double WorkingPitch(const GearPair& pair) {
  const double z1 = pair.pinion().teeth, z2 = pair.wheel().teeth;
  return 2.0 * kPi * pair.center_distance_m() / (z1 + z2);  // 2 pi r_w1 / z1
}

GearPairSpec Shifted(GearPairSpec s, double x1, double x2) {
  s.pinion.profile_shift = x1;
  s.wheel.profile_shift = x2;
  return s;
}

TEST(CoastSide, MirroredPairsDriveLineIsTheCoastLine) {
  for (const GearPairSpec& s : {testing::Seed000Spec(35, 20), testing::Seed000Spec(20, 35),
                                Shifted(testing::Seed000Spec(30, 20), 0.2, -0.1)}) {
    const GearPair pair(s), mirrored(CoastSideSpec(s));
    const LineOfAction& c = pair.line(Flank::kCoast);
    const LineOfAction& m = mirrored.line(Flank::kDrive);
    EXPECT_DOUBLE_EQ(m.pinion_base_radius_m, c.pinion_base_radius_m);
    EXPECT_DOUBLE_EQ(m.wheel_base_radius_m, c.wheel_base_radius_m);
    EXPECT_NEAR(m.a_m, c.a_m, 1e-12);
    EXPECT_NEAR(m.length_m, c.length_m, 1e-12);
    EXPECT_NEAR(m.c_m, c.c_m, 1e-12);
    EXPECT_NEAR(mirrored.center_distance_m(), pair.center_distance_m(), 1e-12);
    EXPECT_NEAR(mirrored.backlash_m(), pair.backlash_m(), 1e-12);
  }
}

TEST(CoastPhaseOffset, PinionAndWheelPlaceTheCoastContactsAlikeAtZeroBacklash) {
  for (const GearPairSpec& s :
       {testing::Seed004Spec(), testing::Seed000Spec(35, 20), testing::Seed000Spec(20, 35),
        Shifted(testing::Seed000Spec(30, 20), 0.3, -0.2),
        Shifted(testing::Seed004Spec(), 0.4, 0.1)}) {
    const GearPair pair(s);
    ASSERT_NEAR(pair.backlash_m(), 0.0, 1e-12);
    const double delta = CoastPhaseOffset(pair);
    EXPECT_GE(delta, 0.0);
    EXPECT_LT(delta, 1.0);
    EXPECT_NEAR(Wrap(delta - WheelCoastPhaseOffset(pair)), 0.0, 1e-9);
  }
}

TEST(CoastPhaseOffset, WithBacklashTheWheelLagsByTheCoastGap) {
  for (double extra_m : {20e-6, 100e-6, 400e-6}) {
    GearPairSpec s = testing::Seed000Spec(35, 20);
    s.center_distance_m = GearPair(s).center_distance_m() + extra_m;
    const GearPair pair(s);
    ASSERT_GT(pair.backlash_m(), 0.0);
    const double gap = pair.backlash_m() / WorkingPitch(pair);
    EXPECT_NEAR(std::abs(Wrap(CoastPhaseOffset(pair) - WheelCoastPhaseOffset(pair))), gap, 1e-9)
        << "centre distance +" << extra_m;
  }
}

// Symmetric teeth: by mirror symmetry about the line of centres a tooth whose axis lies on
// it has its drive and coast crossings at the same s, s_C + r_b1 s_w1 / (2 r_w1); so
// s_c + s_d = 2 s_C + s_w1 p_b / p_w for every tooth.
TEST(CoastPhaseOffset, SymmetricTeethFollowMirrorSymmetry) {
  for (const GearPairSpec& s :
       {testing::Seed004Spec(), Shifted(testing::Seed004Spec(), 0.4, 0.1), testing::FzgCSpec()}) {
    const GearPair pair(s);
    const LineOfAction& d = pair.line(Flank::kDrive);
    const double rw1 =
        pair.center_distance_m() * pair.pinion().teeth / (pair.pinion().teeth + pair.wheel().teeth);
    const double s_w1 = pair.pinion().ThicknessAtRadius(rw1);
    const double s_c = d.c_m - d.a_m;  // the pitch point on the path (C is from T1)
    const double expected = 2.0 * s_c / d.base_pitch_m + s_w1 / WorkingPitch(pair);
    EXPECT_NEAR(Wrap(CoastPhaseOffset(pair) - expected), 0.0, 1e-9);
  }
}

}  // namespace
}  // namespace tehl
