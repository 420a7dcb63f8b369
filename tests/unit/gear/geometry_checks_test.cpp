// Geometric validity: every problem tied to the key a user changes, with what to change.
#include "tehl/gear/geometry_checks.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "tehl/error.hpp"
#include "unit/gear/reference_pairs.hpp"

namespace tehl {
namespace {

using testing::Seed004Spec;

// The problems of a spec as "section.key" -> problem, errors and warnings apart.
struct Found {
  std::vector<GeometryProblem> errors, warnings;
  // The first error at the key whose text contains `text` (any error at the key if "").
  const GeometryProblem* Error(const std::string& full_key, const std::string& text = "") const {
    for (const auto& p : errors)
      if (p.section + "." + p.key == full_key &&
          (p.rule + " " + p.allowed).find(text) != std::string::npos)
        return &p;
    return nullptr;
  }
  const GeometryProblem* Warning(const std::string& full_key) const {
    for (const auto& p : warnings)
      if (p.section + "." + p.key == full_key) return &p;
    return nullptr;
  }
  std::string All() const {
    std::string s;
    for (const auto* v : {&errors, &warnings})
      for (const auto& p : *v) s += p.ToString() + "\n";
    return s;
  }
};

Found Check(const GearPairSpec& spec) {
  Found f;
  for (auto& p : CheckGeometry(GearPair(spec))) (p.warning ? f.warnings : f.errors).push_back(p);
  return f;
}

bool Mentions(const GeometryProblem* p, const std::string& text) {
  return p && (p->rule + " " + p->allowed).find(text) != std::string::npos;
}

TEST(CheckGeometry, ValidationPairsAreClean) {
  const Found seed = Check(Seed004Spec());
  EXPECT_TRUE(seed.errors.empty() && seed.warnings.empty()) << seed.All();
  const Found fzg = Check(testing::FzgCSpec());
  EXPECT_TRUE(fzg.errors.empty()) << fzg.All();
}

TEST(CheckGeometry, UndercutIsAnErrorUnlessAllowed) {
  // z = 12 at 20 deg: x_min = 1 - 12 sin^2(20)/2 = 0.2982 (ISO 53 rack, h_F0 = 1.0000).
  GearPairSpec s = Seed004Spec();
  s.pinion.teeth = 12;
  const Found f = Check(s);
  const GeometryProblem* p = f.Error("gear.pinion.profile_shift");
  ASSERT_TRUE(p) << f.All();
  EXPECT_TRUE(Mentions(p, "undercut")) << p->ToString();
  EXPECT_TRUE(Mentions(p, "x_min = 0.298")) << p->ToString();
  EXPECT_TRUE(Mentions(p, "allow_undercut")) << p->ToString();
  s.allow_undercut = true;
  const Found g = Check(s);
  EXPECT_FALSE(g.Error("gear.pinion.profile_shift")) << g.All();
  EXPECT_TRUE(g.Warning("gear.pinion.profile_shift")) << g.All();
  s.allow_undercut = false;
  s.pinion.profile_shift = 0.3;
  EXPECT_FALSE(Check(s).Error("gear.pinion.profile_shift"));
}

TEST(CheckGeometry, PointedTipIsAnErrorAndAThinLandAWarning) {
  // z = 12 with x = 0.9: the tooth runs to a point below r + m (1 + x).
  GearPairSpec s = Seed004Spec();
  s.pinion.teeth = 12;
  s.pinion.profile_shift = 0.9;
  const GearPair pair(s);
  ASSERT_LT(pair.pinion().pointed_tip_radius_m, pair.pinion().tip_radius_m);
  const Found f = Check(s);
  const GeometryProblem* p = f.Error("gear.pinion.profile_shift");
  ASSERT_TRUE(p) << f.All();
  EXPECT_TRUE(Mentions(p, "pointed")) << p->ToString();
  // A given tip radius just below the pointed radius leaves a land < 0.2 m: a warning at
  // the tip radius key.
  s.pinion.tip_radius_m = pair.pinion().pointed_tip_radius_m - 0.05e-3;
  const Found g = Check(s);
  EXPECT_FALSE(g.Error("gear.pinion.tip_radius_m")) << g.All();
  EXPECT_TRUE(Mentions(g.Warning("gear.pinion.tip_radius_m"), "thin top land")) << g.All();
}

TEST(CheckGeometry, InvoluteInterferenceNamesTheTipToChange) {
  // 12/100 teeth, undercut allowed: the wheel tip passes T1 (seed 000 eq. 3.36 < 0).
  GearPairSpec s = Seed004Spec();
  s.pinion.teeth = 12;
  s.wheel.teeth = 100;
  s.allow_undercut = true;
  const Found f = Check(s);
  const GeometryProblem* p = f.Error("gear.wheel.profile_shift");
  ASSERT_TRUE(p) << f.All();
  EXPECT_TRUE(Mentions(p, "involute interference")) << p->ToString();
  EXPECT_TRUE(Mentions(p, "beyond the tangent point T1")) << p->ToString();
  // Given as a tip radius, the problem sits on that key.
  s.wheel.tip_radius_m = 0.102;
  EXPECT_TRUE(Mentions(Check(s).Error("gear.wheel.tip_radius_m"), "involute interference"));
}

TEST(CheckGeometry, FilletInterferenceWhenTheMatingTipReachesBelowTheFormCircle) {
  // The internal 20/60 pair of contact_ratio_test with the standard ring tip 87 mm: the ring
  // tip passes T1 by 0.03 mm (interference); with 87.2 mm it stays above the base circle but
  // meets the pinion below its form circle r_F = 28.2301 mm (hand: r_F^2 = r_b^2 + (r sin a -
  // m / sin a)^2 = 28.19078^2 + 1.48919^2).
  GearPairSpec s = Seed004Spec();
  s.internal = true;
  s.pinion.teeth = 20;
  s.wheel.teeth = 60;
  s.module_m = 3e-3;
  EXPECT_TRUE(Mentions(Check(s).Error("gear.wheel.profile_shift"), "T1"));
  s.wheel.tip_radius_m = 87.2e-3;
  const Found f = Check(s);
  const GeometryProblem* p = f.Error("gear.wheel.tip_radius_m");
  ASSERT_TRUE(p) << f.All();
  EXPECT_TRUE(Mentions(p, "form circle r_F = 28.2301 mm")) << p->ToString();
  // A ring's tip must be moved outwards (a shorter ring tooth): A = sqrt(r_a2^2 - r_b2^2) -
  // T1T2 reaches the pinion's form circle at roll rho_F = 1.48947 mm (h_F0 = 0.99997 m), so
  // r_a2 >= sqrt(84.57234^2 + (20.52121 + 1.48947)^2) = 87.3896 mm (hand calculation).
  EXPECT_TRUE(Mentions(p, "a ring tip radius of at least 87.3896 mm")) << p->ToString();
  EXPECT_FALSE(Mentions(p, "smaller")) << p->ToString();
  s.wheel.tip_radius_m = 87.38e-3;
  EXPECT_TRUE(Mentions(Check(s).Error("gear.wheel.tip_radius_m"), "form circle"));
  s.wheel.tip_radius_m = 87.40e-3;
  EXPECT_FALSE(Check(s).Error("gear.wheel.tip_radius_m", "form circle")) << Check(s).All();
  s.wheel.tip_radius_m = 88e-3;
  EXPECT_TRUE(Check(s).errors.empty()) << Check(s).All();
}

TEST(CheckGeometry, FilletInterferenceOfAnExternalPairNamesTheLargestTipRadius) {
  // Seed 004 pair (VALIDATION.md section 5) with a long pinion tip, 37.9 mm: E = sqrt(37.9^2 -
  // 32.88924^2) = 18.833 mm from T1 leaves 29.05 mm to T2, below the wheel's form-circle roll
  // rho_F2 = 105 sin 20 - 0.99997 * 2 / sin 20 = 30.0643 mm (r_F2 = 103.1465 mm). Largest pinion
  // tip: sqrt(32.88924^2 + (47.88282 - 30.0643)^2) = 37.4057 mm (hand calculation).
  GearPairSpec s = Seed004Spec();
  s.pinion.tip_radius_m = 37.9e-3;
  const Found f = Check(s);
  const GeometryProblem* p = f.Error("gear.pinion.tip_radius_m", "form circle");
  ASSERT_TRUE(p) << f.All();
  EXPECT_TRUE(Mentions(p, "r_F = 103.1465 mm")) << p->ToString();
  EXPECT_TRUE(Mentions(p, "a pinion tip radius of at most 37.4057 mm")) << p->ToString();
  s.pinion.tip_radius_m = 37.41e-3;
  EXPECT_TRUE(Check(s).Error("gear.pinion.tip_radius_m", "form circle")) << Check(s).All();
  s.pinion.tip_radius_m = 37.40e-3;
  EXPECT_FALSE(Check(s).Error("gear.pinion.tip_radius_m", "form circle")) << Check(s).All();
}

TEST(CheckGeometry, ImpossibleAndOverlappingCenterDistances) {
  GearPairSpec s = Seed004Spec();
  s.center_distance_m = 0.130;  // below r_b1 + r_b2 = 131.56 mm
  const Found f = Check(s);
  ASSERT_TRUE(Mentions(f.Error("gear.center_distance_m"), "cannot mesh")) << f.All();
  EXPECT_TRUE(Mentions(f.Error("gear.center_distance_m"), "center_distance_m >= 0.140000"));
  s.center_distance_m = 0.13995;  // 50 um closer than the zero-backlash 140 mm
  const Found g = Check(s);
  EXPECT_TRUE(Mentions(g.Error("gear.center_distance_m"), "teeth overlap")) << g.All();
}

TEST(CheckGeometry, ContactRatioBelowOneIsAnErrorBelow1Point2AWarning) {
  GearPairSpec s = Seed004Spec();
  s.pinion.tip_radius_m = 0.0355;
  s.wheel.tip_radius_m = 0.1055;
  const Found f = Check(s);
  ASSERT_LT(GearPair(s).line(Flank::kDrive).contact_ratio, 1.0);
  // The tips are given: the problem names the key that was changed from the standard
  // (docs/gear.md section 3), and what to do with it.
  EXPECT_TRUE(Mentions(f.Error("gear.pinion.tip_radius_m"), "not continuous")) << f.All();
  EXPECT_TRUE(Mentions(f.Error("gear.pinion.tip_radius_m"), "larger tip radii (tip_radius_m)"))
      << f.All();
  s.pinion.tip_radius_m = 0.0362;
  s.wheel.tip_radius_m = 0.1062;
  const double eps = GearPair(s).line(Flank::kDrive).contact_ratio;
  ASSERT_GT(eps, 1.0);
  ASSERT_LT(eps, 1.2);
  EXPECT_TRUE(Mentions(Check(s).Warning("gear.pinion.tip_radius_m"), "< 1.2"));
  // Standard tips cut short by the addendum: that key is named, with its fix.
  GearPairSpec standard = Seed004Spec();
  standard.addendum_coefficient = 0.5;
  ASSERT_LT(GearPair(standard).line(Flank::kDrive).contact_ratio, 1.0);
  EXPECT_TRUE(Mentions(Check(standard).Error("gear.addendum_coefficient"), "longer addenda"))
      << Check(standard).All();
}

TEST(CheckGeometry, RackTipRadiusMustFitAnAsymmetricRack) {
  // 35/20 rack with h_fP = 1.25: tip width pi/2 - 1.25 (tan 35 + tan 20) = 0.2406 m; the
  // roundings need rho [(1 - sin 35)/cos 35 + (1 - sin 20)/cos 20] = 1.2208 rho: rho <= 0.197.
  GearPairSpec s = Seed004Spec();
  s.drive_pressure_angle_rad = DegToRad(35);
  const Found f = Check(s);
  EXPECT_TRUE(Mentions(f.Error("gear.root_fillet_coefficient"), "<= 0.197")) << f.All();
  s.root_fillet_coefficient = 0.19;
  EXPECT_FALSE(Check(s).Error("gear.root_fillet_coefficient"));
}

TEST(CheckGeometry, TipIntoRootIsAnError) {
  GearPairSpec s = Seed004Spec();
  s.pinion.tip_radius_m = 0.0376;  // clearance a - r_a1 - r_f2 = 140 - 37.6 - 102.5 < 0
  const Found f = Check(s);
  EXPECT_TRUE(f.Error("gear.pinion.tip_radius_m", "into the wheel's root circle")) << f.All();
}

TEST(RequireValidGeometry, ThrowsEveryErrorAndReturnsWarnings) {
  // 16/16 standard: both undercut (x_min = 1 - 16 sin^2(20)/2 = 0.064), no interference.
  GearPairSpec s = Seed004Spec();
  s.pinion.teeth = 16;
  s.wheel.teeth = 16;
  try {
    RequireValidGeometry(GearPair(s));
    FAIL();
  } catch (const InputError& e) {
    ASSERT_EQ(e.problems().size(), 2u) << e.what();
    EXPECT_EQ(e.problems()[0].key, "gear.pinion.profile_shift");
    EXPECT_EQ(e.problems()[1].key, "gear.wheel.profile_shift");
  }
  s.allow_undercut = true;
  EXPECT_EQ(RequireValidGeometry(GearPair(s)).size(), 2u);
}

// A ring's geometry runs the other way: its backlash e_w2 - s_w1 grows as the pinion moves
// toward its centre, its tip is its inner circle, and the pinion leaves both of its circles as
// the centre distance shrinks. The fixes the messages offer must say so. Internal pair of
// reference_pairs.hpp: 20/60, m = 3 mm, a = 60 mm, ring root r_f2 = 90 + 1.25 * 3 = 93.75 mm,
// pinion root r_f1 = 30 - 3.75 = 26.25 mm (hand calculation).
TEST(CheckGeometry, AnInternalPairsFixesPointTheRingsWay) {
  GearPairSpec s = testing::InternalSpec();
  const double a_free = GearPair(s).zero_backlash_center_distance_m();
  s.center_distance_m = a_free + 50e-6;
  ASSERT_LT(GearPair(s).backlash_m(), 0.0);  // a ring overlaps when the pinion moves out
  EXPECT_TRUE(Mentions(Check(s).Error("gear.center_distance_m", "overlap"),
                       "center_distance_m <= 0.060000"))
      << Check(s).All();
  s.center_distance_m = a_free - 50e-6;
  EXPECT_GT(GearPair(s).backlash_m(), 0.0);
  EXPECT_FALSE(Check(s).Error("gear.center_distance_m", "overlap")) << Check(s).All();

  // Pinion tip 34 mm: 0.25 mm beyond the ring's root circle (93.75 - 60 = 33.75 mm).
  s = testing::InternalSpec();
  s.pinion.tip_radius_m = 34e-3;
  const Found pinion = Check(s);
  const GeometryProblem* p = pinion.Error("gear.pinion.tip_radius_m", "root circle");
  ASSERT_TRUE(p) << pinion.All();
  EXPECT_TRUE(Mentions(p, "0.2500 mm into the ring's root circle")) << p->ToString();
  EXPECT_TRUE(Mentions(p, "a pinion tip radius of at most 33.7500 mm")) << p->ToString();
  EXPECT_TRUE(Mentions(p, "a smaller center_distance_m")) << p->ToString();

  // Ring tip 86 mm: 0.25 mm into the pinion's root circle (60 + 26.25 = 86.25 mm).
  s = testing::InternalSpec();
  s.wheel.tip_radius_m = 86e-3;
  const Found ring = Check(s);
  p = ring.Error("gear.wheel.tip_radius_m", "root circle");
  ASSERT_TRUE(p) << ring.All();
  EXPECT_TRUE(Mentions(p, "the ring tip reaches 0.2500 mm into the pinion's root circle"))
      << p->ToString();
  EXPECT_TRUE(Mentions(p, "a ring tip radius of at least 86.2500 mm")) << p->ToString();
  EXPECT_TRUE(Mentions(p, "a smaller center_distance_m")) << p->ToString();
  // Exactly on the root circle: no overlap.
  s.wheel.tip_radius_m = 86.25e-3;
  EXPECT_FALSE(Check(s).Error("gear.wheel.tip_radius_m", "root circle")) << Check(s).All();
}

// Below the base radii's sum there is no line of action: only that is reported, not tips
// "into the roots" computed from it.
TEST(CheckGeometry, AnImpossibleCentreDistanceIsReportedAlone) {
  GearPairSpec s = Seed004Spec();
  s.center_distance_m = 0.125;
  const Found f = Check(s);
  ASSERT_TRUE(f.Error("gear.center_distance_m", "cannot mesh")) << f.All();
  EXPECT_EQ(f.All().find("root circle"), std::string::npos) << f.All();
  EXPECT_EQ(f.All().find("interference"), std::string::npos) << f.All();
}

}  // namespace
}  // namespace tehl
