// Asymmetric teeth (seed 000 section 3.3, Kapelevich): the symmetric gear is the special
// case phi_d = phi_c, each flank has its own base circle, contact ratio and path.
#include <gtest/gtest.h>

#include <cmath>

#include "tehl/gear/gear_pair.hpp"
#include "tehl/gear/geometry_checks.hpp"
#include "tehl/gear/involute.hpp"
#include "unit/gear/reference_pairs.hpp"

namespace tehl {
namespace {

// Relative agreement to 1e-12 (absolute below 1e-12 of the scale).
void ExpectSame(double got, double want, double scale, const char* what) {
  EXPECT_NEAR(got, want, 1e-12 * std::max(std::abs(want), scale)) << what;
}

TEST(AsymmetricGear, EqualAnglesReproduceTheSymmetricTextbookGear) {
  // A shifted pair with phi_d = phi_c = 20 deg against the symmetric textbook formulas,
  // written here independently: r_b = r cos a (2.7), s(r) = 2r [s/(2r_p) + inv a - inv phi(r)]
  // (2.13), inv a' = inv a + 2 tan a (x1+x2)/(z1+z2), a = a0 cos a / cos a', eps by seed 003.
  GearPairSpec s = testing::Seed004Spec();
  s.pinion.teeth = 19;
  s.wheel.teeth = 47;
  s.pinion.profile_shift = 0.35;
  s.wheel.profile_shift = -0.1;
  const GearPair p(s);
  const double m = 2e-3, a = DegToRad(20);
  const double inv_w = Involute(a) + 2 * std::tan(a) * 0.25 / 66;
  const double aw = InverseInvolute(inv_w);
  const double a0 = 33 * m;
  const double center = a0 * std::cos(a) / std::cos(aw);
  ExpectSame(p.center_distance_m(), center, 0.1, "a");
  ExpectSame(p.line(Flank::kDrive).working_pressure_angle_rad, aw, 1, "alpha_w");
  ExpectSame(p.line(Flank::kCoast).working_pressure_angle_rad, aw, 1, "alpha_w coast");
  const double r1 = 19e-3, rb1 = r1 * std::cos(a), ra1 = r1 + m * 1.35;
  const double r2 = 47e-3, rb2 = r2 * std::cos(a), ra2 = r2 + m * 0.9;
  ExpectSame(p.pinion().drive.base_radius_m, rb1, 0.1, "r_b1 drive");
  ExpectSame(p.pinion().coast.base_radius_m, rb1, 0.1, "r_b1 coast");
  const double s1 = m * (kPi / 2 + 2 * 0.35 * std::tan(a));
  for (double r : {rb1 * 1.01, r1, ra1}) {
    const double t = 2 * r * (s1 / (2 * r1) + Involute(a) - Involute(std::acos(rb1 / r)));
    ExpectSame(p.pinion().ThicknessAtRadius(r), t, 1e-3, "s(r)");
  }
  const double pb = kPi * m * std::cos(a);
  const double eps = (std::sqrt(ra1 * ra1 - rb1 * rb1) + std::sqrt(ra2 * ra2 - rb2 * rb2) -
                      center * std::sin(aw)) /
                     pb;
  ExpectSame(p.line(Flank::kDrive).contact_ratio, eps, 1, "eps_alpha");
  ExpectSame(p.line(Flank::kCoast).contact_ratio, eps, 1, "eps_alpha coast");
  ExpectSame(p.line(Flank::kDrive).a_m, center * std::sin(aw) - std::sqrt(ra2 * ra2 - rb2 * rb2),
             0.1, "A");
}

TEST(AsymmetricGear, BaseRadiusRatioKFor35Over20) {
  // Seed 000 section 6 (derived): K = cos 20 / cos 35 = 1.1472 (eq. 3.23).
  const GearPair p(testing::Seed000Spec(35, 20));
  EXPECT_NEAR(p.pinion().BaseRadiusRatio(), 1.1472, 0.5e-4);
  EXPECT_NEAR(p.pinion().BaseRadiusRatio(), std::cos(DegToRad(20)) / std::cos(DegToRad(35)), 1e-14);
  // Both base circles come from the same pitch circle (eqs. 3.27-3.28).
  EXPECT_NEAR(p.pinion().drive.base_radius_m, 57.15e-3 * std::cos(DegToRad(35)), 1e-15);
  EXPECT_NEAR(p.pinion().coast.base_radius_m, 57.15e-3 * std::cos(DegToRad(20)), 1e-15);
}

TEST(AsymmetricGear, Seed000DriveFlankContactRatioAndTopLand) {
  // Seed 000 extraction section 7.3 (derived from the thesis inputs): 36/36, P = 8,
  // R_o = 2.375 in: symmetric 20 deg m_p = 1.6924; 35 deg drive flank with the same R_o:
  // m_pd ~ 1.289, top land ~ 0.053 in (1.35 mm), "stays positive".
  const GearPair sym(testing::Seed000Spec(20, 20));
  const GearPair asym(testing::Seed000Spec(35, 20));
  EXPECT_NEAR(sym.line(Flank::kDrive).contact_ratio, 1.6924, 0.5e-4);
  EXPECT_NEAR(asym.line(Flank::kDrive).contact_ratio, 1.289, 0.5e-3);
  EXPECT_NEAR(asym.pinion().tip_thickness_m, 0.053 * 25.4e-3, 0.0005 * 25.4e-3);
  // The drive flank at 35 deg has a smaller contact ratio than a 20 deg pair with the same
  // tip radii (seed 003 section 3.1: a larger pressure angle lowers the contact ratio); the
  // 20 deg coast flank keeps the symmetric value.
  EXPECT_LT(asym.line(Flank::kDrive).contact_ratio, sym.line(Flank::kDrive).contact_ratio);
  EXPECT_NEAR(asym.line(Flank::kCoast).contact_ratio, sym.line(Flank::kDrive).contact_ratio, 1e-12);
  // Each flank has its own base pitch (p_b = pi m cos phi) and path.
  EXPECT_NEAR(asym.line(Flank::kDrive).base_pitch_m, kPi * 3.175e-3 * std::cos(DegToRad(35)),
              1e-15);
  EXPECT_LT(asym.line(Flank::kDrive).length_m, sym.line(Flank::kDrive).length_m);
}

TEST(AsymmetricGear, Seed004PairWith35DegreeDriveIsAValidGear) {
  // The seed 004 pair (35/105) with a 35 deg drive flank and 20 deg coast flank, on a basic
  // rack whose tip radius fits (rho_fP <= 0.197 m): not pointed, no interference, and a
  // smaller drive-flank contact ratio than the 20 deg pair (1.7722).
  GearPairSpec s = testing::Seed004Spec();
  s.drive_pressure_angle_rad = DegToRad(35);
  s.root_fillet_coefficient = 0.15;
  const GearPair p(s);
  for (const auto& problem : CheckGeometry(p)) EXPECT_TRUE(problem.warning) << problem.ToString();
  EXPECT_GT(p.pinion().tip_thickness_m, 0.2 * 2e-3);
  EXPECT_LT(p.line(Flank::kDrive).contact_ratio, 1.7722);
  EXPECT_GT(p.line(Flank::kDrive).contact_ratio, 1.0);
}

TEST(AsymmetricGear, PointedRadiusIsWhereTheInvolutesIntersect) {
  // Kapelevich eqs. 3.19 and 3.21: at the pointed tip the profile angles nu_d, nu_c satisfy
  // S_p / r_p = inv nu_d + inv nu_c - inv phi_d - inv phi_c and cos nu_c / cos nu_d = K.
  const GearPair p(testing::Seed000Spec(35, 20));
  const GearGeometry& g = p.pinion();
  const double r = g.pointed_tip_radius_m;
  const double nu_d = std::acos(g.drive.base_radius_m / r);
  const double nu_c = std::acos(g.coast.base_radius_m / r);
  EXPECT_NEAR(std::cos(nu_c) / std::cos(nu_d), g.BaseRadiusRatio(), 1e-13);
  const double lhs = g.reference_thickness_m / g.pitch_radius_m;
  const double rhs =
      Involute(nu_d) + Involute(nu_c) - Involute(DegToRad(35)) - Involute(DegToRad(20));
  EXPECT_NEAR(lhs, rhs, 1e-12);
  EXPECT_GT(r, g.tip_radius_m);
}

TEST(AsymmetricGear, ShiftedAsymmetricPairMeshesWithoutBacklash) {
  // Zero backlash of an asymmetric shifted pair: inv a_wd + inv a_wc = inv a_d + inv a_c
  // + 2 (x1 + x2)(tan a_d + tan a_c)/(z1 + z2), cos a_wc = K cos a_wd (docs/gear.md); the
  // backlash computed back from the tooth thicknesses at the working circle must vanish.
  GearPairSpec s = testing::Seed004Spec();
  s.drive_pressure_angle_rad = DegToRad(30);
  s.root_fillet_coefficient = 0.2;
  s.pinion.profile_shift = 0.3;
  s.wheel.profile_shift = 0.1;
  const GearPair p(s);
  EXPECT_NEAR(p.backlash_m(), 0.0, 1e-15);
  const double awd = p.line(Flank::kDrive).working_pressure_angle_rad;
  const double awc = p.line(Flank::kCoast).working_pressure_angle_rad;
  const double ad = DegToRad(30), ac = DegToRad(20);
  EXPECT_NEAR(Involute(awd) + Involute(awc),
              Involute(ad) + Involute(ac) + 2 * 0.4 * (std::tan(ad) + std::tan(ac)) / 140, 1e-15);
  EXPECT_NEAR(std::cos(awc) / std::cos(awd), std::cos(ac) / std::cos(ad), 1e-14);
  EXPECT_GT(p.center_distance_m(), 0.140);
}

TEST(AsymmetricGear, TipRadiusForATopLandInvertsTheThickness) {
  // Kapelevich step 2 by bisection: the seed 000 35/20 pinion has a top land s_a at
  // R_o = 2.375 in; asking for that land gives R_o back, asking for 0 gives the pointed tip.
  const GearPair p(testing::Seed000Spec(35, 20));
  const GearGeometry& g = p.pinion();
  EXPECT_NEAR(TipRadiusForTopLand(g, g.tip_thickness_m), 2.375 * 25.4e-3, 1e-12);
  EXPECT_NEAR(TipRadiusForTopLand(g, 0.0), g.pointed_tip_radius_m, 1e-12);
  const double r = TipRadiusForTopLand(g, 0.2 * 3.175e-3);
  EXPECT_NEAR(g.ThicknessAtRadius(r), 0.2 * 3.175e-3, 1e-13);
}

}  // namespace
}  // namespace tehl
