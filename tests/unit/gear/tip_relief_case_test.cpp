// Tip relief in a gear case: the keys, their rules, and the largest relief that keeps the
// tracked pair loaded, each reported at its file:line and key.
#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <string>

#include "scene/dynamic_load.hpp"
#include "scene/gear_case.hpp"
#include "tehl/gear/operating_point.hpp"
#include "tehl/gear/path_of_contact.hpp"
#include "tehl/scene/case_schema.hpp"

namespace tehl::internal {
namespace {

// The seed 004 pair (aluminium bronze, 10 kW at 1000 rpm) with the given extra keys.
std::string ReliefCase(const std::string& gear,
                       const std::string& pinion,
                       const std::string& wheel,
                       const std::string& effects = "") {
  const std::string bronze = "youngs_modulus_pa = 117e9\npoisson_ratio = 0.34\n";
  return "[gear]\nmodule_m = 0.002\nface_width_m = 0.025\n" + gear + "[gear.pinion]\nteeth = 35\n" +
         bronze + pinion + "[gear.wheel]\nteeth = 105\n" + bronze + wheel +
         "[operating]\npinion_speed_rpm = 1000.0\npower_w = 10000.0\n"
         "[lubricant]\nname = \"sae40\"\n" +
         effects;
}

Document ReadCase(const std::string& text) {
  return Document::ReadString(CaseSchema(), text, "r.toml");
}

std::string Problems(const Document& d) {
  std::string s;
  for (const auto& p : d.problems()) s += p.ToString() + "\n";
  return s;
}

std::string Relief(double amount_m, double length_m) {
  char text[120];
  std::snprintf(text, sizeof text, "tip_relief_m = %.17g\ntip_relief_length_m = %.17g\n", amount_m,
                length_m);
  return text;
}

TEST(TipReliefCase, AGearsOwnShapeOverridesThePairs) {
  Document doc = ReadCase(ReliefCase("tip_relief_shape = \"linear\"\n",
                                     Relief(8e-6, 2e-3) + "tip_relief_shape = \"parabolic\"\n",
                                     Relief(5e-6, 1.5e-3)));
  const auto c = ReadGearCase(doc);
  ASSERT_TRUE(doc.problems().empty()) << Problems(doc);
  ASSERT_TRUE(c);
  EXPECT_EQ(c->tip_relief.pinion_shape, ReliefShape::kParabolic);
  EXPECT_EQ(c->tip_relief.wheel_shape, ReliefShape::kLinear);
  Document bad = ReadCase(
      ReliefCase("", Relief(8e-6, 2e-3) + "tip_relief_shape = \"cubic\"\n", Relief(5e-6, 1.5e-3)));
  ReadGearCase(bad);
  ASSERT_FALSE(bad.problems().empty());
  EXPECT_EQ(bad.problems().front().key, "gear.pinion.tip_relief_shape") << Problems(bad);
}

TEST(TipReliefCase, KeysReachTheGearCase) {
  Document doc = ReadCase(
      ReliefCase("tip_relief_shape = \"parabolic\"\n", Relief(8e-6, 2e-3), Relief(5e-6, 1.5e-3)));
  const auto c = ReadGearCase(doc);
  ASSERT_TRUE(doc.problems().empty()) << Problems(doc);
  ASSERT_TRUE(c);
  EXPECT_EQ(c->tip_relief.pinion_shape, ReliefShape::kParabolic);
  EXPECT_EQ(c->tip_relief.wheel_shape, ReliefShape::kParabolic);
  EXPECT_DOUBLE_EQ(c->tip_relief.pinion_amount_m, 8e-6);
  EXPECT_DOUBLE_EQ(c->tip_relief.pinion_length_m, 2e-3);
  EXPECT_DOUBLE_EQ(c->tip_relief.wheel_amount_m, 5e-6);
  EXPECT_DOUBLE_EQ(c->tip_relief.wheel_length_m, 1.5e-3);
  // The cycle table of `tehl gear --csv` shares the load with the relief: the pair at A
  // carries less than without it.
  Document plain_doc = ReadCase(ReliefCase("", "", ""));
  const auto plain = ReadGearCase(plain_doc);
  ASSERT_TRUE(plain);
  EXPECT_LT(GearCaseCycle(*c, 11).front().share, GearCaseCycle(*plain, 11).front().share - 0.05);
}

TEST(TipReliefCase, AnAmountNeedsALengthWithinThePath) {
  Document doc = ReadCase(ReliefCase("", "tip_relief_m = 5e-6\n", Relief(5e-6, 0.5)));
  ReadGearCase(doc);
  ASSERT_EQ(doc.problems().size(), 2u) << Problems(doc);
  EXPECT_EQ(doc.problems()[0].key, "gear.pinion.tip_relief_length_m");
  EXPECT_EQ(doc.problems()[1].key, "gear.wheel.tip_relief_length_m");
  EXPECT_NE(doc.problems()[1].rule.find("longer than the path"), std::string::npos);
}

TEST(TipReliefCase, NegativeAmountsAreRejectedByTheSchema) {
  Document doc = ReadCase(ReliefCase("", Relief(-1e-6, 1e-3), ""));
  ASSERT_FALSE(doc.problems().empty());
  EXPECT_EQ(doc.problems().front().key, "gear.pinion.tip_relief_m") << Problems(doc);
}

TEST(TipReliefCase, NeedsStiffnessSharing) {
  Document linear = ReadCase(ReliefCase("load_sharing = \"linear\"\n", Relief(5e-6, 1e-3), ""));
  ReadGearCase(linear);
  ASSERT_EQ(linear.problems().size(), 1u) << Problems(linear);
  EXPECT_EQ(linear.problems()[0].key, "gear.load_sharing");
}

TEST(TipReliefCase, TheTorsionalDynamicsSeeTheRelief) {
  // With dynamic_load the torsional mesh carries the relief: at the pair's first contact the
  // load factor compares its relieved dynamic and static loads (both small there).
  Document doc = ReadCase(
      ReliefCase("", Relief(8e-6, 2e-3), Relief(8e-6, 2e-3), "[effects]\ndynamic_load = true\n"));
  const auto c = ReadGearCase(doc);
  ASSERT_TRUE(doc.problems().empty()) << Problems(doc);
  ASSERT_TRUE(c && c->dynamic_load);
  EXPECT_TRUE(c->dynamic_load->mesh().relief().Active());
  EXPECT_DOUBLE_EQ(c->dynamic_load->mesh().relief().wheel_amount_m, 8e-6);
}

TEST(TipReliefCase, AReliefThatLiftsThePairOffShortensTheSolvedPath) {
  // Too much wheel relief lifts the pair off near A: the films are solved from A', where the
  // pair's share reaches kMinFilmShare. relief_limit_a_m is the largest amount that keeps
  // the pair loaded to A: 10 % below it the pair keeps several % of the load at A and the
  // solved path starts there, 2 % above it the path starts after A.
  const double length = 2e-3;
  Document doc = ReadCase(ReliefCase("", "", Relief(30e-6, length)));
  const auto c = ReadGearCase(doc);
  ASSERT_TRUE(doc.problems().empty()) << Problems(doc);
  ASSERT_TRUE(c);
  const PathOfContact path(*c->pair, c->operating.pinion_speed_rad_s);
  const double force = NominalToothLoad(*c->pair, c->operating).normal_force_n;
  EXPECT_GT(c->loaded_path.begin_m, 0.0);
  EXPECT_LT(c->loaded_path.begin_m, length);
  EXPECT_EQ(c->loaded_path.end_m, path.length_m());  // no pinion relief
  EXPECT_NEAR(
      RelievedLoadShare(path, c->loaded_path.begin_m, c->pair_stiffness, c->tip_relief, force)
          .share,
      kMinFilmShare, 1e-6);
  // Seed 004 at 10 kW: F_bt = 2903.5 N on one pair of about 2e8 N/m closes some 15 um.
  const double limit = c->relief_limit_a_m;
  EXPECT_GT(limit, 8e-6);
  EXPECT_LT(limit, 25e-6);
  for (const auto& [factor, starts_at_a] : {std::pair{0.9, true}, std::pair{1.02, false}}) {
    Document d = ReadCase(ReliefCase("", "", Relief(factor * limit, length)));
    const auto near = ReadGearCase(d);
    ASSERT_TRUE(d.problems().empty()) << Problems(d);
    EXPECT_EQ(near->loaded_path.begin_m == 0.0, starts_at_a) << "factor " << factor;
  }
}

TEST(TipReliefCase, AWheelReliefOverThePathLeavesTheSingleContactPart) {
  // 1 mm of wheel relief over (nearly) the whole path: in A..B the partner at s + p_b always
  // has the smaller gap and takes the whole load, so the tracked pair is loaded from B (where
  // it is alone) to E (where the entering partner has the larger gap).
  Document doc = ReadCase(ReliefCase("", "", Relief(1e-3, 10.4e-3)));
  const auto c = ReadGearCase(doc);
  ASSERT_TRUE(doc.problems().empty()) << Problems(doc);
  const PathOfContact path(*c->pair, c->operating.pinion_speed_rad_s);
  EXPECT_NEAR(c->loaded_path.begin_m, path.s_b_m(), 1e-8);
  EXPECT_EQ(c->loaded_path.end_m, path.length_m());
}

TEST(TipReliefCase, TheTransmissionErrorIsTheCommonApproach) {
  // Without relief the static transmission error is F_bt / k_mesh; with relief the approach
  // of the relieved balance, which is larger wherever a relieved pair shares the load, and
  // equal in single contact (the one pair carries F_bt either way).
  Document plain_doc = ReadCase(ReliefCase("", "", ""));
  const auto plain = ReadGearCase(plain_doc);
  Document doc = ReadCase(ReliefCase("", Relief(10e-6, 4.5e-3), Relief(10e-6, 4.5e-3)));
  const auto relieved = ReadGearCase(doc);
  ASSERT_TRUE(plain && relieved);
  const double force = NominalToothLoad(*plain->pair, plain->operating).normal_force_n;
  const auto a = GearCaseCycle(*plain, 41), b = GearCaseCycle(*relieved, 41);
  ASSERT_EQ(a.size(), b.size());
  for (size_t i = 0; i < a.size(); ++i) {
    EXPECT_NEAR(a[i].transmission_error_m, force / a[i].mesh_stiffness_n_per_m, 1e-18);
    if (a[i].contact.pairs_in_contact == 1)
      EXPECT_NEAR(b[i].transmission_error_m, a[i].transmission_error_m, 1e-15);
    else
      EXPECT_GT(b[i].transmission_error_m, a[i].transmission_error_m);
  }
}

}  // namespace
}  // namespace tehl::internal
