// Contact ratios (seed 003): external, internal and helical pairs, and the design limits.
#include "tehl/gear/contact_ratio.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "tehl/gear/gear_pair.hpp"
#include "unit/gear/reference_pairs.hpp"

namespace tehl {
namespace {

TEST(ContactRatio, Seed004PairMatchesValidation) {
  // VALIDATION.md section 5: eps_alpha = 1.7722, path length g_alpha = 10.464 mm.
  const GearPair p(testing::Seed004Spec());
  EXPECT_NEAR(p.line(Flank::kDrive).contact_ratio, 1.7722, 0.5e-4);
  EXPECT_NEAR(p.line(Flank::kDrive).length_m, 10.464e-3, 0.5e-6);
}

TEST(ContactRatio, FzgCMatchesValidation) {
  // VALIDATION.md section 5: eps_alpha = 1.4625.
  const GearPair p(testing::FzgCSpec());
  EXPECT_NEAR(p.line(Flank::kDrive).contact_ratio, 1.4625, 0.5e-4);
}

TEST(ContactRatio, SimplifiedFormulaOfSeed003AgreesForStandardGears) {
  // Seed 003 section 2.1 (3): eps = [z1 (tan a_a1 - tan a') + z2 (tan a_a2 - tan a')]/(2 pi),
  // an identity with form (1) (r_b tan a_a = sqrt(r_a^2 - r_b^2), a sin a' = (r_b1 + r_b2)
  // tan a', 2 pi r_b / z = p_b). Seed 004 pair.
  const GearPair p(testing::Seed004Spec());
  const double aw = DegToRad(20);
  const double ta1 = std::tan(std::acos(0.035 * std::cos(aw) / 0.037));
  const double ta2 = std::tan(std::acos(0.105 * std::cos(aw) / 0.107));
  const double eps = (35 * (ta1 - std::tan(aw)) + 105 * (ta2 - std::tan(aw))) / (2 * kPi);
  EXPECT_NEAR(p.line(Flank::kDrive).contact_ratio, eps, 1e-12);
}

TEST(ContactRatio, InternalPairMatchesHandCalculation) {
  // Pinion z1 = 20 in a ring z2 = 60, m = 3 mm, 20 deg, x = 0, ring tip radius 88 mm
  // (ring addendum shortened to 2 mm so that its tip stays clear of the pinion's fillet).
  // By hand (seed 003 section 2.3): r_b1 = 30 cos 20 = 28.19078 mm, r_b2 = 84.57234 mm,
  // a = 60 mm, a sin 20 = 20.52121 mm, sqrt(33^2 - r_b1^2) = 17.15459 mm,
  // sqrt(88^2 - r_b2^2) = 24.32118 mm, p_b = 3 pi cos 20 = 8.85639 mm,
  // eps_alpha = (17.15459 - 24.32118 + 20.52121) / 8.85639 = 1.50791;
  // A lies 24.32118 - 20.52121 = 3.79998 mm beyond T1.
  const GearPairSpec s = testing::InternalSpec();
  const GearPair p(s);
  EXPECT_NEAR(p.line(Flank::kDrive).contact_ratio, 1.50791, 0.5e-5);
  EXPECT_NEAR(p.line(Flank::kDrive).a_m, 3.79998e-3, 0.5e-8);
  EXPECT_NEAR(InternalTransverseContactRatio(33e-3, 28.19078e-3, 88e-3, 84.57234e-3, 60e-3,
                                             DegToRad(20), 8.85639e-3),
              1.50791, 1e-5);
}

TEST(ContactRatio, HelicalPairMatchesHandCalculation) {
  // z = 20/40, m_n = 3 mm, alpha_n = 20 deg, beta = 15 deg, b = 30 mm, x = 0, h_a = m_n.
  // By hand (seed 003 section 2.2): m_t = 3 / cos 15 = 3.105829 mm,
  // alpha_t = atan(tan 20 / cos 15) = 20.646896 deg, r = 31.058285 / 62.116571 mm,
  // r_b = 29.063450 / 58.126901 mm, r_a = 34.058285 / 65.116571 mm, a = 93.174856 mm,
  // sqrt(r_a^2 - r_b^2) = 17.756201 / 29.350149 mm, a sin alpha_t = 32.854171 mm,
  // p_bt = pi m_t cos alpha_t = 9.130552 mm -> eps_alpha = 14.252179 / 9.130552 = 1.560933;
  // eps_beta = 30 sin 15 / (3 pi) = 0.823847; eps_gamma = 2.384779.
  GearPairSpec s;
  s.pinion.teeth = 20;
  s.wheel.teeth = 40;
  s.module_m = 3e-3;
  s.face_width_m = 30e-3;
  s.helix_angle_rad = DegToRad(15);
  const GearPair p(s);
  EXPECT_NEAR(p.transverse_module_m(), 3.105829e-3, 0.5e-9);
  EXPECT_NEAR(RadToDeg(p.pinion().drive.pressure_angle_rad), 20.646896, 0.5e-6);
  EXPECT_NEAR(p.line(Flank::kDrive).contact_ratio, 1.560933, 0.5e-6);
  EXPECT_NEAR(p.face_contact_ratio(), 0.823847, 0.5e-6);
  EXPECT_NEAR(p.total_contact_ratio(), 2.384779, 1e-6);
  const TransverseParameters t = HelicalTransverse(3e-3, DegToRad(20), DegToRad(15));
  EXPECT_NEAR(t.module_m, 3.105829e-3, 0.5e-9);
}

TEST(ContactRatio, FaceContactRatioEqualsWidthOverAxialPitch) {
  // Seed 003 section 2.2 (2): eps_beta = b sin(beta)/(pi m_n) = b tan(beta)/p_t,
  // p_t = pi m_n / cos(beta).
  const double b = 0.04, beta = DegToRad(22), mn = 2.5e-3;
  EXPECT_NEAR(FaceContactRatio(b, beta, mn), b * std::tan(beta) / (kPi * mn / std::cos(beta)),
              1e-14);
}

TEST(AssessContactRatio, AppliesTheSeed003DesignLimits) {
  // Seed 003 section 4.1: eps >= 1.2 for industrial gears, avoid integer values; eps > 1 for
  // continuous transmission (section 1.1).
  EXPECT_FALSE(AssessContactRatio(0.95).continuous);
  EXPECT_TRUE(AssessContactRatio(1.1).below_minimum);
  EXPECT_TRUE(AssessContactRatio(1.1).continuous);
  EXPECT_FALSE(AssessContactRatio(1.7722).below_minimum);
  EXPECT_FALSE(AssessContactRatio(1.7722).near_integer);
  EXPECT_TRUE(AssessContactRatio(1.98).near_integer);
  EXPECT_TRUE(AssessContactRatio(2.03).near_integer);
  EXPECT_FALSE(AssessContactRatio(2.2).near_integer);
}

}  // namespace
}  // namespace tehl
