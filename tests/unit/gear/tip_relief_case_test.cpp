// Tip relief in a gear case: the keys, their rules, and the largest relief that keeps the
// tracked pair loaded, each reported at its file:line and key.
#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <string>

#include "scene/gear_case.hpp"
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

TEST(TipReliefCase, KeysReachTheGearCase) {
  Document doc = ReadCase(
      ReliefCase("tip_relief_shape = \"parabolic\"\n", Relief(8e-6, 2e-3), Relief(5e-6, 1.5e-3)));
  const auto c = ReadGearCase(doc);
  ASSERT_TRUE(doc.problems().empty()) << Problems(doc);
  ASSERT_TRUE(c);
  EXPECT_EQ(c->tip_relief.shape, ReliefShape::kParabolic);
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

TEST(TipReliefCase, NeedsStiffnessSharingAndNoTorsionalDynamics) {
  Document linear = ReadCase(ReliefCase("load_sharing = \"linear\"\n", Relief(5e-6, 1e-3), ""));
  ReadGearCase(linear);
  ASSERT_EQ(linear.problems().size(), 1u) << Problems(linear);
  EXPECT_EQ(linear.problems()[0].key, "gear.load_sharing");
  Document dynamic =
      ReadCase(ReliefCase("", Relief(5e-6, 1e-3), "", "[effects]\ndynamic_load = true\n"));
  ReadGearCase(dynamic);
  ASSERT_FALSE(dynamic.problems().empty());
  EXPECT_EQ(dynamic.problems()[0].key, "effects.dynamic_load") << Problems(dynamic);
}

TEST(TipReliefCase, TheLargestReliefThatKeepsThePairLoadedIsTheAllowedOne) {
  // Too much wheel relief lifts the pair off near A; the message gives the limit, and
  // reliefs 2 % either side of it are accepted and rejected.
  const double length = 2e-3;
  Document doc = ReadCase(ReliefCase("", "", Relief(30e-6, length)));
  ReadGearCase(doc);
  ASSERT_EQ(doc.problems().size(), 1u) << Problems(doc);
  const InputProblem& p = doc.problems()[0];
  EXPECT_EQ(p.key, "gear.wheel.tip_relief_m");
  EXPECT_GT(p.line, 0);
  const auto at = p.allowed.find("tip_relief_m < ");
  ASSERT_NE(at, std::string::npos) << p.allowed;
  const double limit = std::strtod(p.allowed.c_str() + at + 15, nullptr);
  // Seed 004 at 10 kW: F_bt = 2903.5 N on one pair of about 2e8 N/m closes some 15 um.
  EXPECT_GT(limit, 8e-6);
  EXPECT_LT(limit, 25e-6);
  Document below = ReadCase(ReliefCase("", "", Relief(0.98 * limit, length)));
  ReadGearCase(below);
  EXPECT_TRUE(below.problems().empty()) << Problems(below);
  Document above = ReadCase(ReliefCase("", "", Relief(1.02 * limit, length)));
  ReadGearCase(above);
  EXPECT_EQ(above.problems().size(), 1u) << Problems(above);
}

}  // namespace
}  // namespace tehl::internal
