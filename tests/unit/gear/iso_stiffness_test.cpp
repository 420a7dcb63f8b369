// ISO 6336-1 method B single and mesh stiffness (src/gear/iso_stiffness.cpp).
#include <gtest/gtest.h>

#include <cmath>

#include "tehl/error.hpp"
#include "tehl/gear/mesh_stiffness.hpp"
#include "tehl/units.hpp"

namespace tehl {
namespace {

ToothBlank Blank(int z, double m, double x, double tip_radius_m) {
  ToothBlank b;
  b.teeth = z;
  b.module_m = m;
  b.drive_pressure_angle_rad = b.coast_pressure_angle_rad = DegToRad(20.0);
  b.profile_shift = x;
  b.tip_radius_m = tip_radius_m;
  b.face_width_m = 0.02;
  b.youngs_modulus_pa = 206e9;
  b.poisson_ratio = 0.3;
  return b;
}

// Standard involute contact ratio (seed 003; DESIGN.md section 2):
// eps = [sqrt(ra1^2 - rb1^2) + sqrt(ra2^2 - rb2^2) - a sin(alpha_w)] / (pi m cos(alpha)).
double ContactRatio(const ToothBlank& p, const ToothBlank& w, double a) {
  const double alpha = p.drive_pressure_angle_rad, m = p.module_m;
  const double rb1 = 0.5 * p.teeth * m * std::cos(alpha);
  const double rb2 = 0.5 * w.teeth * m * std::cos(alpha);
  const double alpha_w = std::acos((rb1 + rb2) / a);
  return (std::sqrt(p.tip_radius_m * p.tip_radius_m - rb1 * rb1) +
          std::sqrt(w.tip_radius_m * w.tip_radius_m - rb2 * rb2) - a * std::sin(alpha_w)) /
         (kPi * m * std::cos(alpha));
}

TEST(IsoMethodB, SixtyTwoToSixtyTwoStandardPair) {
  // 62/62 teeth, m = 2 mm, x = 0, r_a = 64 mm, a = 124 mm. Contact ratio by the standard
  // formula: rb = 62 cos 20 deg = 58.2609 mm, sqrt(64^2 - 58.2609^2) = 26.4889 mm,
  // a sin 20 deg = 42.4105 mm, pi m cos 20 deg = 5.9043 mm -> eps_alpha = 1.7898.
  const ToothBlank g = Blank(62, 0.002, 0.0, 0.064);
  const double eps = ContactRatio(g, g, 0.124);
  EXPECT_NEAR(eps, 1.7898, 5e-4);
  const IsoStiffness iso = IsoMethodB(g, g, eps);
  // VALIDATION.md section 5 (computed): c' = 14.47, c_gamma_alpha = 23.04 N/(mm um).
  EXPECT_NEAR(iso.c_prime_n_per_mm_um, 14.47, 0.006);
  EXPECT_NEAR(iso.c_gamma_alpha_n_per_mm_um, 23.04, 0.006);
  EXPECT_NEAR(iso.c_prime_th_n_per_mm_um * iso.q_prime_mm_um_per_n, 1.0, 1e-12);
}

TEST(IsoMethodB, FzgTypeC) {
  // VALIDATION.md section 5: z 16/24, x 0.1817/0.1715, eps_alpha = 1.4625 (computed there),
  // c' = 12.31 and c_gamma_alpha = 16.57 N/(mm um), with x2 in the C7 and C9 terms.
  const ToothBlank p = Blank(16, 0.0045, 0.1817, 0.041318);
  const ToothBlank w = Blank(24, 0.0045, 0.1715, 0.059272);
  const IsoStiffness iso = IsoMethodB(p, w, 1.4625);
  EXPECT_NEAR(iso.c_prime_n_per_mm_um, 12.31, 0.006);
  EXPECT_NEAR(iso.c_gamma_alpha_n_per_mm_um, 16.57, 0.006);
}

TEST(IsoMethodB, TheSmallerGearIsGearOneWhicheverDrives) {
  // ISO 6336-1 numbers the smaller gear 1 in q' (C2/zn1, C4..C5 with x1). A speed-increasing
  // pair (60 teeth driving 20) is the same mesh as the reducer: the same c'. By hand for
  // x = 0: q' = 0.04723 + 0.15551/20 + 0.25791/60 = 0.059304 mm um/N, c'_th = 16.862,
  // c' = 0.8 * 0.975 * c'_th = 13.15 N/(mm um) (C_M = 0.8, C_R = 1, C_B = 0.975).
  const ToothBlank small = Blank(20, 0.003, 0.2, 0.0336);
  const ToothBlank large = Blank(60, 0.003, -0.1, 0.0927);
  const IsoStiffness reducer = IsoMethodB(small, large, 1.6);
  const IsoStiffness increaser = IsoMethodB(large, small, 1.6);
  EXPECT_NEAR(increaser.q_prime_mm_um_per_n, reducer.q_prime_mm_um_per_n, 1e-15);
  ToothBlank s0 = small, l0 = large;
  s0.profile_shift = l0.profile_shift = 0.0;
  EXPECT_NEAR(IsoMethodB(l0, s0, 1.6).q_prime_mm_um_per_n, 0.04723 + 0.15551 / 20 + 0.25791 / 60,
              1e-12);
  EXPECT_NEAR(IsoMethodB(l0, s0, 1.6).c_prime_n_per_mm_um, 13.15, 0.005);
}

TEST(IsoMethodB, BasicRackFactorFollowsTheRack) {
  // ISO 6336-1: C_B = [1 + 0.5 (1.2 - h_fP/m)] [1 - 0.02 (20 deg - alpha_n)].
  // h_fP = 1.25 m, 20 deg: C_B = 0.975. h_fP = 1.2 m, 25 deg: C_B = 1 * 1.1 = 1.1, and
  // q' does not depend on the rack, so c' scales by 1.1 / 0.975.
  const ToothBlank g = Blank(30, 0.003, 0.0, 0.048);
  ToothBlank g25 = g;
  g25.dedendum_coefficient = 1.2;
  g25.drive_pressure_angle_rad = g25.coast_pressure_angle_rad = DegToRad(25.0);
  const IsoStiffness a = IsoMethodB(g, g, 1.6);
  const IsoStiffness b = IsoMethodB(g25, g25, 1.6);
  EXPECT_NEAR(b.c_prime_n_per_mm_um / a.c_prime_n_per_mm_um, 1.1 / 0.975, 1e-12);
  // Different racks on the two gears: the mean of the two factors, (0.975 + 1.1) / 2.
  const IsoStiffness mixed = IsoMethodB(g, g25, 1.6);
  EXPECT_NEAR(mixed.c_prime_n_per_mm_um / a.c_prime_n_per_mm_um, 0.5 * (0.975 + 1.1) / 0.975,
              1e-12);
}

TEST(IsoMethodB, MaterialFactorForNonSteelPairs) {
  // ISO 6336-1: c' times E/E_st with E = 2 E1 E2 / (E1 + E2), E_st = 206 GPa. Steel (206 GPa)
  // with aluminium bronze (117 GPa): E = 2*206*117/323 = 149.238 GPa, factor 0.724458.
  const ToothBlank steel = Blank(35, 0.002, 0.0, 0.037);
  ToothBlank bronze = Blank(105, 0.002, 0.0, 0.107);
  const IsoStiffness ss = IsoMethodB(steel, Blank(105, 0.002, 0.0, 0.107), 1.7722);
  bronze.youngs_modulus_pa = 117e9;
  const IsoStiffness sb = IsoMethodB(steel, bronze, 1.7722);
  EXPECT_NEAR(sb.c_prime_n_per_mm_um / ss.c_prime_n_per_mm_um, 0.724458, 1e-6);
  EXPECT_EQ(sb.q_prime_mm_um_per_n, ss.q_prime_mm_um_per_n);
}

TEST(IsoMethodB, InternalWheelIsARack) {
  // ISO 6336-1 for internal gears: zn2 -> infinity, so C3/zn2 and C7 x2/zn2 vanish.
  ToothBlank p = Blank(20, 0.002, 0.0, 0.022);
  ToothBlank ring = Blank(60, 0.002, 0.0, 0.058);
  ring.internal = true;
  const IsoStiffness iso = IsoMethodB(p, ring, 1.7);
  EXPECT_NEAR(iso.q_prime_mm_um_per_n, 0.04723 + 0.15551 / 20.0, 1e-15);
}

TEST(IsoMethodB, RejectsBadInput) {
  const ToothBlank g = Blank(30, 0.003, 0.0, 0.048);
  EXPECT_THROW(IsoMethodB(g, g, 0.9), InputError);
  ToothBlank few = g;
  few.teeth = 2;
  EXPECT_THROW(IsoMethodB(few, g, 1.5), InputError);
  ToothBlank shifted = g;
  shifted.profile_shift = 1.2;  // x1 + x2 = 2.4 > 2.0, outside the q' fit
  try {
    IsoMethodB(shifted, shifted, 1.5);
    ADD_FAILURE() << "expected InputError";
  } catch (const InputError& e) {
    ASSERT_EQ(e.problems().size(), 1u);
    EXPECT_EQ(e.problems()[0].key, "gear.mesh_stiffness");
    EXPECT_EQ(e.problems()[0].value, "2.4");
  }
}

}  // namespace
}  // namespace tehl
