// Gear pair geometry: radii, centre distance, working pressure angle, backlash, undercut.
#include "tehl/gear/gear_pair.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <limits>
#include <string>
#include <utility>

#include "tehl/error.hpp"
#include "tehl/gear/involute.hpp"
#include "tehl/gear/path_of_contact.hpp"
#include "unit/gear/reference_pairs.hpp"

namespace tehl {
namespace {

using testing::FzgCSpec;
using testing::Seed004Spec;

TEST(GearPair, Seed004RadiiAndCenterDistance) {
  // VALIDATION.md section 5: a = 140 mm. Radii by hand: r = z m / 2 = 35 / 105 mm,
  // r_a = r + m = 37 / 107 mm, r_f = r - 1.25 m = 32.5 / 102.5 mm,
  // r_b = r cos 20 deg = 32.889 / 98.668 mm.
  const GearPair p(Seed004Spec());
  EXPECT_NEAR(p.center_distance_m(), 0.140, 1e-15);
  EXPECT_NEAR(p.pinion().pitch_radius_m, 0.035, 1e-15);
  EXPECT_NEAR(p.wheel().pitch_radius_m, 0.105, 1e-15);
  EXPECT_NEAR(p.pinion().tip_radius_m, 0.037, 1e-15);
  EXPECT_NEAR(p.wheel().tip_radius_m, 0.107, 1e-15);
  EXPECT_NEAR(p.pinion().root_radius_m, 0.0325, 1e-15);
  EXPECT_NEAR(p.pinion().drive.base_radius_m, 0.035 * std::cos(DegToRad(20)), 1e-15);
  EXPECT_NEAR(p.wheel().drive.base_radius_m, 0.105 * std::cos(DegToRad(20)), 1e-15);
  EXPECT_NEAR(p.line(Flank::kDrive).working_pressure_angle_rad, DegToRad(20), 1e-12);
  EXPECT_NEAR(p.backlash_m(), 0.0, 1e-15);
  EXPECT_NEAR(p.center_distance_modification(), 0.0, 1e-12);
  // Pitch thickness of a standard tooth: pi m / 2.
  EXPECT_NEAR(p.pinion().reference_thickness_m, kPi * 1e-3, 1e-15);
}

TEST(GearPair, FzgCWorkingPressureAngleFromTheCenterDistance) {
  // VALIDATION.md section 5 (computed): alpha_w = 22.4389 deg, p_b = 13.285 mm. That value is
  // the zero-backlash angle of the shifts (22.43891 deg, next test); from a = 91.5 mm by hand:
  // cos a' = 90 cos 20 / 91.5 = 0.9242878, a' = 22.43879 deg. Both round to 22.4389 within
  // 1.2e-4 deg.
  const GearPair p(FzgCSpec());
  EXPECT_NEAR(RadToDeg(p.line(Flank::kDrive).working_pressure_angle_rad), 22.43879, 0.5e-5);
  EXPECT_NEAR(RadToDeg(p.line(Flank::kDrive).working_pressure_angle_rad), 22.4389, 1.2e-4);
  EXPECT_NEAR(p.line(Flank::kDrive).base_pitch_m, 13.285e-3, 5e-7);
  EXPECT_NEAR(p.center_distance_m(), 91.5e-3, 1e-15);
  // The given tip radii are r + m (1 + x): 41.318 / 59.272 mm (VALIDATION.md section 5).
  GearPairSpec s = FzgCSpec();
  s.pinion.tip_radius_m = s.wheel.tip_radius_m = 0;
  const GearPair q(s);
  EXPECT_NEAR(q.pinion().tip_radius_m, 41.318e-3, 5e-7);
  EXPECT_NEAR(q.wheel().tip_radius_m, 59.272e-3, 5e-7);
}

TEST(GearPair, FzgCShiftsMeshAtTheTestRigCenterDistance) {
  // Without the centre distance, the zero-backlash distance of x1 + x2 = 0.3532 is the rig's
  // 91.5 mm to the 4 decimals of the shifts. By hand: inv a' = inv 20 + 2 tan 20 (0.3532)/40
  // = 0.0213321, a' = 22.43891 deg, a = 90 cos 20 / cos a' = 91.50008 mm.
  GearPairSpec s = FzgCSpec();
  s.center_distance_m = 0;
  const GearPair p(s);
  EXPECT_NEAR(p.center_distance_m(), 91.5e-3, 0.3e-6);
  EXPECT_NEAR(RadToDeg(p.line(Flank::kDrive).working_pressure_angle_rad), 22.4389, 0.5e-4);
  EXPECT_NEAR(p.backlash_m(), 0.0, 1e-12);
  // With the given distance the backlash is the same tiny amount (negative, within 1e-4 m).
  const GearPair q(FzgCSpec());
  EXPECT_LT(std::abs(q.backlash_m()), 1e-4 * 4.5e-3);
}

TEST(GearPair, ShiftedPairMatchesKhkExample) {
  // KHK Gear Technical Reference, profile-shifted spur gears example (as tabulated by
  // bolsover.com "Profile Shifted External Spur Gears"): m = 3 mm, 20 deg, z = 12/24,
  // x = 0.6/0.36: inv(alpha_w) = 0.034317 (printed, from a = 56.5), alpha_w = 26.0888 deg,
  // y = 0.83333, a = 56.500 mm; with the printed outside diameters 44.840 / 79.400 mm the
  // contact ratio is 1.202.
  GearPairSpec s;
  s.pinion.teeth = 12;
  s.wheel.teeth = 24;
  s.module_m = 3e-3;
  s.face_width_m = 10e-3;
  s.pinion.profile_shift = 0.6;
  s.wheel.profile_shift = 0.36;
  s.pinion.tip_radius_m = 22.420e-3;
  s.wheel.tip_radius_m = 39.700e-3;
  const GearPair p(s);
  // Zero-backlash solve: inv a' = inv 20 + 2 tan 20 (0.96)/36 = 0.0343161 (hand).
  EXPECT_NEAR(Involute(p.line(Flank::kDrive).working_pressure_angle_rad), 0.0343161, 1e-7);
  EXPECT_NEAR(p.center_distance_m(), 56.500e-3, 0.5e-6);
  EXPECT_NEAR(p.center_distance_modification(), 0.83333, 0.5e-4);
  EXPECT_NEAR(RadToDeg(p.line(Flank::kDrive).working_pressure_angle_rad), 26.0888, 3e-4);
  EXPECT_NEAR(p.line(Flank::kDrive).contact_ratio, 1.202, 0.5e-3);
}

TEST(GearPair, CenterDistanceGivesBacklashAndWorkingAngle) {
  // Standard seed 004 pair pulled apart by 0.1 mm: cos(a_w) = 140 cos 20 / 140.1. Backlash on
  // the working circle by hand: with x = 0 the angular thickness at r_w is
  // psi = pi/z + 2 (inv 20 - inv a_w), so j = r_w1 (2 pi/z1 - psi1) - r_w2 psi2
  // = pi (r_w1/z1 - r_w2/z2) + 2 (r_w1 + r_w2)(inv a_w - inv 20) = 2 a (inv a_w - inv 20),
  // because r_w1/z1 = r_w2/z2 and r_w1 + r_w2 = a.
  GearPairSpec s = Seed004Spec();
  s.center_distance_m = 0.1401;
  const GearPair p(s);
  const double aw = std::acos(0.140 * std::cos(DegToRad(20)) / 0.1401);
  EXPECT_NEAR(p.line(Flank::kDrive).working_pressure_angle_rad, aw, 1e-14);
  EXPECT_NEAR(p.backlash_m(), 2 * 0.1401 * (Involute(aw) - Involute(DegToRad(20))), 1e-15);
  EXPECT_GT(p.backlash_m(), 0.0);
}

TEST(GearPair, UndercutLimitReproducesMinimumTeethTable) {
  // Seed 000 Table 4.9 (Mabie & Reinholtz): least teeth without undercut against a rack:
  // 14.5 deg full depth 32, 20 deg full depth 18, 20 deg stub 14, 25 deg full depth 12.
  // Rack proportions of seed 000 Tables 4.1-4.2 (addendum a, dedendum b, fillet r_f, x 1/P).
  // The table's rule takes the addendum a for the depth where the rack's straight flank
  // ends; with these racks that depth, h_F0 = b - r_f (1 - sin phi), is 1.0003, 1.0526,
  // 0.8000 and 1.0768, so z_min = 2 h_F0 / sin^2(phi) = 31.9, 18.0, 13.7 and 12.06: the table
  // for the first three, and 13 at 25 deg, where 12 teeth are undercut by 0.005 modules (the
  // table's a = 1 gives 11.2). With the ISO 53 rack (h_fP = 1.25, rho_fP = 0.38) 25 deg
  // gives h_F0 = 1.0306 and 11.5: 12, the table.
  struct Row {
    double deg, addendum, dedendum, fillet;
    int z_min;
  };
  const Row rows[] = {{14.5, 1.0, 1.157, 0.209, 32},
                      {20, 1.0, 1.25, 0.300, 18},
                      {20, 0.8, 1.0, 0.304, 14},
                      {25, 1.0, 1.25, 0.300, 13},
                      {25, 1.0, 1.25, 0.380, 12}};
  for (const Row& r : rows) {
    auto undercut = [&](int z) {
      GearPairSpec s = Seed004Spec();
      s.pinion.teeth = z;
      s.drive_pressure_angle_rad = s.coast_pressure_angle_rad = DegToRad(r.deg);
      s.addendum_coefficient = r.addendum;
      s.dedendum_coefficient = r.dedendum;
      s.root_fillet_coefficient = r.fillet;
      return GearPair(s).pinion().drive.undercut;
    };
    EXPECT_FALSE(undercut(r.z_min)) << r.deg << " deg, z = " << r.z_min;
    EXPECT_TRUE(undercut(r.z_min - 1)) << r.deg << " deg, z = " << r.z_min - 1;
  }
}

TEST(GearPair, UndercutFollowsTheToolsStraightFlank) {
  // z = 18, x = 0, 20 deg, h_fP = 1.25. A rack with tip radius rho_fP = 0.1 ends its
  // straight flank at h_F0 = 1.25 - 0.1 (1 - sin 20 deg) = 1.18420 below the reference line,
  // beyond the interference point (r sin^2(alpha) / m = 9 sin^2 20 deg = 1.05280): undercut,
  // x_min = 1.18420 - 1.05280 = 0.13140. A sharp tool (rho_fP = 0) at z = 17: x_min = 1.25 -
  // 17 sin^2(20 deg) / 2 = 0.25569, so x = 0.05 is undercut. The ISO 53 rack (rho_fP = 0.38)
  // keeps z = 18, x = 0 free of undercut (x_min = -0.05285).
  auto pinion = [](int z, double x, double rho) {
    GearPairSpec s = Seed004Spec();
    s.pinion.teeth = z;
    s.pinion.profile_shift = x;
    s.dedendum_coefficient = 1.25;
    s.root_fillet_coefficient = rho;
    return GearPair(s).pinion().drive;
  };
  const double sin2 = std::pow(std::sin(DegToRad(20.0)), 2);
  const FlankGeometry blunt = pinion(18, 0.0, 0.1);
  EXPECT_NEAR(blunt.min_shift_no_undercut, 1.25 - 0.1 * (1 - std::sin(DegToRad(20))) - 9 * sin2,
              1e-14);
  EXPECT_NEAR(blunt.min_shift_no_undercut, 0.13140, 5e-6);
  EXPECT_TRUE(blunt.undercut);
  const FlankGeometry sharp = pinion(17, 0.05, 0.0);
  EXPECT_NEAR(sharp.min_shift_no_undercut, 0.25569, 5e-6);
  EXPECT_TRUE(sharp.undercut);
  EXPECT_FALSE(pinion(18, 0.0, 0.38).undercut);
}

TEST(GearPair, ThicknessAtRadiusFollowsSeed000Eq213) {
  // t_B = 2 R_B [t_A/(2 R_A) + inv(phi_A) - inv(phi_B)] (seed 000 eq. 2.13), by hand at
  // R_B = r_a for the seed 004 pinion: t_A = pi m / 2, R_A = 35 mm, phi_B = acos(r_b / r_a).
  const GearPair p(Seed004Spec());
  const double rb = 0.035 * std::cos(DegToRad(20));
  const double phi = std::acos(rb / 0.037);
  const double t = 2 * 0.037 * (kPi * 1e-3 / 0.070 + Involute(DegToRad(20)) - Involute(phi));
  EXPECT_NEAR(p.pinion().ThicknessAtRadius(0.037), t, 1e-15);
  EXPECT_NEAR(p.pinion().tip_thickness_m, t, 1e-15);
  EXPECT_NEAR(p.pinion().ThicknessAtRadius(p.pinion().pointed_tip_radius_m), 0.0, 1e-12);
}

TEST(GearPair, InternalRingRadiiAndThickness) {
  // Ring z = 60, m = 3 mm, x = 0: tip (inner) r_a = 90 - 3 = 87 mm, root 90 + 3.75 mm; its
  // space at the pitch circle is pi m / 2, so is its tooth; the ring tooth thickens outwards.
  GearPairSpec s = Seed004Spec();
  s.internal = true;
  s.pinion.teeth = 20;
  s.wheel.teeth = 60;
  s.module_m = 3e-3;
  const GearPair p(s);
  EXPECT_NEAR(p.wheel().tip_radius_m, 0.087, 1e-15);
  EXPECT_NEAR(p.wheel().root_radius_m, 0.09375, 1e-15);
  EXPECT_NEAR(p.reference_center_distance_m(), 0.060, 1e-15);
  EXPECT_NEAR(p.center_distance_m(), 0.060, 1e-15);
  EXPECT_NEAR(p.wheel().ThicknessAtRadius(0.090), kPi * 1.5e-3, 1e-15);
  EXPECT_GT(p.wheel().ThicknessAtRadius(0.093), p.wheel().ThicknessAtRadius(0.088));
}

TEST(GearPair, RejectsValuesNoGearCanHave) {
  GearPairSpec s = Seed004Spec();
  s.pinion.teeth = 2;
  s.module_m = -1;
  try {
    GearPair p(s);
    FAIL() << "accepted";
  } catch (const InputError& e) {
    ASSERT_EQ(e.problems().size(), 2u);
    EXPECT_EQ(e.problems()[0].key, "gear.pinion.teeth");
    EXPECT_EQ(e.problems()[1].key, "gear.module_m");
  }
  GearPairSpec ring = Seed004Spec();
  ring.internal = true;
  ring.wheel.teeth = 30;
  EXPECT_THROW(GearPair{ring}, InputError);
}

// Non-finite and physically impossible values of a programmatic spec are input errors at
// their key, never a domain_error deep inside or a NaN contact ratio; a negative tip radius
// is not taken as "absent".
TEST(GearPair, RejectsNonFiniteAndImpossibleValuesAtTheirKeys) {
  const double inf = std::numeric_limits<double>::infinity(), nan = std::nan("");
  const std::pair<std::string, std::function<void(GearPairSpec&)>> cases[] = {
      {"gear.pinion.profile_shift", [&](GearPairSpec& s) { s.pinion.profile_shift = nan; }},
      {"gear.wheel.profile_shift", [&](GearPairSpec& s) { s.wheel.profile_shift = inf; }},
      {"gear.module_m", [&](GearPairSpec& s) { s.module_m = inf; }},
      {"gear.face_width_m", [&](GearPairSpec& s) { s.face_width_m = inf; }},
      {"gear.addendum_coefficient", [&](GearPairSpec& s) { s.addendum_coefficient = inf; }},
      {"gear.pinion.tip_radius_m", [&](GearPairSpec& s) { s.pinion.tip_radius_m = -0.037; }},
      {"gear.wheel.tip_radius_m", [&](GearPairSpec& s) { s.wheel.tip_radius_m = nan; }},
      {"gear.pinion.youngs_modulus_pa",
       [&](GearPairSpec& s) { s.pinion.material.youngs_modulus_pa = -206e9; }},
      {"gear.wheel.poisson_ratio", [&](GearPairSpec& s) { s.wheel.material.poisson_ratio = 0.6; }},
      {"gear.center_distance_m", [&](GearPairSpec& s) { s.center_distance_m = nan; }},
  };
  for (const auto& [key, spoil] : cases) {
    GearPairSpec s = Seed004Spec();
    spoil(s);
    try {
      GearPair p(s);
      ADD_FAILURE() << key << " accepted";
    } catch (const InputError& e) {
      ASSERT_EQ(e.problems().size(), 1u) << e.what();
      EXPECT_EQ(e.problems()[0].key, key) << e.what();
    }
  }
  const GearPair pair(Seed004Spec());
  EXPECT_THROW(PathOfContact(pair, inf), InputError);
  EXPECT_THROW(PathOfContact(pair, nan), InputError);
}

}  // namespace
}  // namespace tehl
