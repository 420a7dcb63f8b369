// Path of contact: points A-E, radii of curvature, surface speeds, time, and the kinematic
// identities (VALIDATION.md section 5).
#include "tehl/gear/path_of_contact.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "tehl/units.hpp"
#include "unit/gear/reference_pairs.hpp"

namespace tehl {
namespace {

const double kW1 = RpmToRadPerS(1000);  // seed 004: 1000 rpm of the pinion

TEST(PathOfContact, Seed004PointsFromT1) {
  // VALIDATION.md section 5: A = 6.486, B = 11.046, C = 11.971, D = 12.390, E = 16.950 mm.
  const GearPair pair(testing::Seed004Spec());
  const LineOfAction& l = pair.line(Flank::kDrive);
  EXPECT_NEAR(l.a_m, 6.486e-3, 0.5e-6);
  EXPECT_NEAR(l.b_m, 11.046e-3, 0.5e-6);
  EXPECT_NEAR(l.c_m, 11.971e-3, 0.5e-6);
  EXPECT_NEAR(l.d_m, 12.390e-3, 0.5e-6);
  EXPECT_NEAR(l.e_m, 16.950e-3, 0.5e-6);
  const PathOfContact path(pair, kW1);
  EXPECT_NEAR(path.length_m(), 10.464e-3, 0.5e-6);
  EXPECT_NEAR(path.s_c_m(), (11.971 - 6.486) * 1e-3, 1e-6);
}

TEST(PathOfContact, Seed004PitchPointRadiusAndSpeed) {
  // VALIDATION.md section 5: R = 8.978 mm, um = 1.254 m/s at the pitch point.
  const GearPair pair(testing::Seed004Spec());
  const PathOfContact path(pair, kW1);
  const ContactPoint c = path.At(path.s_c_m());
  EXPECT_NEAR(c.reduced_radius_m, 8.978e-3, 0.5e-6);
  EXPECT_NEAR(c.um_m_s, 1.254, 0.5e-3);
  EXPECT_NEAR(c.sliding_m_s, 0.0, 1e-14);
  EXPECT_NEAR(c.srr, 0.0, 1e-14);
  // At the pitch point the contact radii are the pitch radii.
  EXPECT_NEAR(c.r1_m, 0.035, 1e-15);
  EXPECT_NEAR(c.r2_m, 0.105, 1e-15);
  EXPECT_EQ(c.pairs_in_contact, 1);  // C lies in the single-contact zone BD
}

TEST(PathOfContact, FzgCDistancesFromA) {
  // VALIDATION.md section 5: AB = 6.14, AC = 9.68, AD = 13.28, AE = 19.43 mm.
  const GearPair pair(testing::FzgCSpec());
  const PathOfContact path(pair, RpmToRadPerS(1450));
  EXPECT_NEAR(path.s_b_m(), 6.14e-3, 0.5e-5);
  EXPECT_NEAR(path.s_c_m(), 9.68e-3, 0.5e-5);
  EXPECT_NEAR(path.s_d_m(), 13.28e-3, 0.5e-5);
  EXPECT_NEAR(path.length_m(), 19.43e-3, 0.5e-5);
}

TEST(PathOfContact, KinematicIdentitiesHoldAlongThePath) {
  // rho1 + rho2 = T1T2; u1 - u2 = (w1 + w2)(P - C); u1 + u2 = w1 rho1 + w2 rho2;
  // r_i^2 = r_bi^2 + rho_i^2; t = s / (r_b1 w1); w2 = w1 z1/z2.
  const GearPair pair(testing::FzgCSpec());
  const double w1 = RpmToRadPerS(1450);
  const PathOfContact path(pair, w1);
  const double w2 = w1 * 16.0 / 24.0;
  EXPECT_NEAR(path.wheel_speed_rad_s(), w2, 1e-13);
  const LineOfAction& l = path.line();
  for (int i = 0; i <= 20; ++i) {
    const double s = path.length_m() * i / 20;
    const ContactPoint c = path.At(s);
    EXPECT_NEAR(c.rho1_m + c.rho2_m, l.tangent_length_m, 1e-15);
    EXPECT_NEAR(c.sliding_m_s, (w1 + w2) * (c.position_m - l.c_m), 1e-13);
    EXPECT_NEAR(c.r1_m * c.r1_m,
                l.pinion_base_radius_m * l.pinion_base_radius_m + c.rho1_m * c.rho1_m, 1e-16);
    EXPECT_NEAR(c.time_s, s / (l.pinion_base_radius_m * w1), 1e-15);
    EXPECT_NEAR(1 / c.reduced_radius_m, 1 / c.rho1_m + 1 / c.rho2_m, 1e-9);
    EXPECT_NEAR(c.srr, 2 * (c.u1_m_s - c.u2_m_s) / (c.u1_m_s + c.u2_m_s), 1e-14);
  }
  // Negative sliding (pinion slower) in the approach, positive in the recess.
  EXPECT_LT(path.At(0).srr, 0);
  EXPECT_GT(path.At(path.length_m()).srr, 0);
  // Mesh period: one base pitch at r_b1 w1; equals 2 pi / (z1 w1) (one tooth passage).
  EXPECT_NEAR(path.mesh_period_s(), 2 * kPi / (16 * w1), 1e-15);
}

TEST(PathOfContact, InternalIdentities) {
  // Ring: rho2 = T1T2 + rho1 (T2 behind T1), 1/R = 1/rho1 - 1/rho2, and
  // u1 - u2 = (w1 - w2)(P - C) since both turn the same way.
  const GearPairSpec s = testing::InternalSpec();
  const GearPair pair(s);
  const double w1 = 100.0;
  const PathOfContact path(pair, w1);
  const double w2 = w1 / 3;
  const LineOfAction& l = path.line();
  for (int i = 0; i <= 10; ++i) {
    const ContactPoint c = path.At(path.length_m() * i / 10);
    EXPECT_NEAR(c.rho2_m - c.rho1_m, l.tangent_length_m, 1e-15);
    EXPECT_NEAR(1 / c.reduced_radius_m, 1 / c.rho1_m - 1 / c.rho2_m, 1e-9);
    EXPECT_NEAR(c.sliding_m_s, (w1 - w2) * (c.position_m - l.c_m), 1e-13);
  }
  // The pitch point: contact radii are the pitch radii 30 and 90 mm.
  const ContactPoint c = path.At(path.s_c_m());
  EXPECT_NEAR(c.r1_m, 0.030, 1e-15);
  EXPECT_NEAR(c.r2_m, 0.090, 1e-15);
}

TEST(PathOfContact, SingleAndDoubleContactZones) {
  // 1 < eps < 2: double contact on AB and DE, single on BD; the partner pair is one base
  // pitch away.
  const GearPair pair(testing::Seed004Spec());
  const PathOfContact path(pair, kW1);
  const double pb = path.base_pitch_m();
  EXPECT_EQ(path.At(0.5 * path.s_b_m()).pairs_in_contact, 2);
  EXPECT_EQ(path.At(0.5 * (path.s_b_m() + path.s_d_m())).pairs_in_contact, 1);
  EXPECT_EQ(path.At(0.5 * (path.s_d_m() + path.length_m())).pairs_in_contact, 2);
  const auto q = path.SimultaneousContacts(0.001);
  ASSERT_EQ(q.size(), 2u);
  EXPECT_DOUBLE_EQ(q[0], 0.001);
  EXPECT_NEAR(q[1], 0.001 + pb, 1e-15);
  // A pair exactly at A or E counts.
  EXPECT_EQ(path.At(0).pairs_in_contact, 2);
  EXPECT_EQ(path.At(path.length_m()).pairs_in_contact, 2);
}

}  // namespace
}  // namespace tehl
