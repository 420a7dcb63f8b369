// The scene side of the gear layer: case-file sections to gear structs, and every geometric
// problem reported at its file:line and key with what to change.
#include "scene/gear_case.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "tehl/gear/mesh_cycle.hpp"
#include "tehl/gear/mesh_stiffness.hpp"
#include "tehl/gear/path_of_contact.hpp"
#include "tehl/gear/tooth_blank.hpp"
#include "tehl/scene/case_schema.hpp"
#include "tehl/units.hpp"

namespace tehl::internal {
namespace {

// A gear case text: the seed 004 pair unless the fragments override keys. Line numbers
// below refer to this layout (line 1 = "[gear]").
std::string CaseText(const std::string& gear_extra,
                     const std::string& pinion_extra,
                     const std::string& wheel_extra = "") {
  return "[gear]\n"                  // 1
         "module_m = 0.002\n"        // 2
         "face_width_m = 0.025\n" +  // 3
         gear_extra +                //
         "[gear.pinion]\n"           //
         "teeth = 35\n" +            //
         pinion_extra +              //
         "[gear.wheel]\n"            //
         "teeth = 105\n" +           //
         wheel_extra +               //
         "[operating]\n"
         "pinion_speed_rpm = 1000.0\n"
         "power_w = 10000.0\n"
         "[lubricant]\n"
         "name = \"sae40\"\n";
}

Document Read(const std::string& text) {
  return Document::ReadString(CaseSchema(), text, "g.toml");
}

std::string All(const Document& d) {
  std::string s;
  for (const auto& p : d.problems()) s += p.ToString() + "\n";
  return s;
}

TEST(GearCase, BuildsTheSeed004PairAndOperatingPoint) {
  Document doc = Read(CaseText("", "youngs_modulus_pa = 117e9\npoisson_ratio = 0.34\n",
                               "youngs_modulus_pa = 117e9\npoisson_ratio = 0.34\n"));
  const auto c = ReadGearCase(doc);
  ASSERT_TRUE(doc.problems().empty()) << All(doc);
  ASSERT_TRUE(c && c->pair);
  // VALIDATION.md section 5: T1 = 95.49 N m at 10 kW and 1000 rpm; eps_alpha = 1.7722.
  EXPECT_NEAR(c->operating.pinion_torque_nm, 95.49, 0.005);
  EXPECT_NEAR(c->operating.pinion_speed_rad_s, RpmToRadPerS(1000), 1e-12);
  EXPECT_NEAR(c->pair->line(Flank::kDrive).contact_ratio, 1.7722, 0.5e-4);
  EXPECT_EQ(c->spec.coast_pressure_angle_rad, c->spec.drive_pressure_angle_rad);
  EXPECT_EQ(c->load_sharing, LoadSharing::kStiffness);
  EXPECT_EQ(c->mesh_stiffness, "potential_energy");
  ASSERT_TRUE(c->pair_stiffness);
  EXPECT_GT(c->pair_stiffness(0.035, 0.105), 0.0);
  // E' of two UNS C61300 bodies: 2 / (2 (1 - 0.34^2) / 117 GPa) = 132.29 GPa.
  EXPECT_NEAR(c->ReducedModulusPa(), 117e9 / (1 - 0.34 * 0.34), 1e3);
  const auto rows = GearCaseCycle(*c, 51);
  EXPECT_EQ(rows.size(), 55u);
}

TEST(GearCase, IsoPairStiffnessGivesTheIsoMeshStiffnessAsItsMean) {
  // ISO 6336-1 method B: c_gamma_alpha = c' (0.75 eps_alpha + 0.25) is the mean mesh
  // stiffness; a constant pair stiffness k has the period mean k eps_alpha (docs/gear.md), so
  // k = c_gamma_alpha b / eps_alpha. Seed 004 in steel (E = 206 GPa, nu = 0.3).
  Document doc = Read(CaseText("mesh_stiffness = \"iso\"\n", ""));
  const auto c = ReadGearCase(doc);
  ASSERT_TRUE(doc.problems().empty()) << All(doc);
  ASSERT_TRUE(c && c->pair && c->pair_stiffness);
  const double eps = c->pair->line(Flank::kDrive).contact_ratio;
  const IsoStiffness iso = IsoMethodB(PinionBlank(*c->pair), WheelBlank(*c->pair), eps);
  EXPECT_NEAR(iso.c_gamma_alpha_n_per_mm_um / iso.c_prime_n_per_mm_um, 0.75 * eps + 0.25, 1e-12);
  const double k = c->pair_stiffness(0.035, 0.105);
  EXPECT_NEAR(k * eps, iso.c_gamma_alpha_n_per_mm_um * 1e9 * 0.025, 1e-9 * k * eps);
  const PathOfContact path(*c->pair, c->operating.pinion_speed_rad_s);
  EXPECT_NEAR(SummarizeMeshStiffness(path, c->pair_stiffness).mean_n_per_m, k * eps, 1e-3 * k);
}

TEST(GearCase, LoadedSharingFollowsCornersAsFarAsAHeavyLoadNeeds) {
  // The 12/36 pair of cases/hard/few_teeth_z12.toml (bronze, x = +-0.3) at 25 kW and
  // 1000 rpm: the static approach reaches 110 um, beyond the 0.05 m_n = 100 um to which
  // corner contact is followed at ordinary loads; the case follows it to ten times the
  // softest single pair's approach, so the share stays continuous along the path (a cut
  // at 100 um made it jump by 0.041 at s = 3.965 mm).
  const std::string text =
      "[gear]\nmodule_m = 0.002\nface_width_m = 0.025\nload_sharing = \"loaded\"\n"
      "[gear.pinion]\nteeth = 12\nprofile_shift = 0.3\nyoungs_modulus_pa = 117e9\n"
      "poisson_ratio = 0.34\n[gear.wheel]\nteeth = 36\nprofile_shift = -0.3\n"
      "youngs_modulus_pa = 117e9\npoisson_ratio = 0.34\n[operating]\n"
      "pinion_speed_rpm = 1000.0\npower_w = 25000.0\n[lubricant]\nname = \"sae40\"\n";
  Document doc = Read(text);
  const auto c = ReadGearCase(doc);
  ASSERT_TRUE(doc.problems().empty()) << All(doc);
  ASSERT_TRUE(c && c->corner_contact);
  EXPECT_GT(CornerMaxGap(*c), 0.05 * 0.002);
  const auto rows = GearCaseCycle(*c, 4001);
  double te_max = 0, jump = 0;
  for (size_t i = 0; i < rows.size(); ++i) {
    te_max = std::max(te_max, rows[i].transmission_error_m);
    if (i > 0) jump = std::max(jump, std::abs(rows[i].share - rows[i - 1].share));
  }
  EXPECT_GT(te_max, 0.05 * 0.002);  // the load is heavy enough to pass the module rule
  EXPECT_LT(jump, 0.005);           // 2.2 um samples along a ramp of about 0.7 per mm
}

TEST(GearCase, UndercutIsReportedAtTheShiftWithFileAndLine) {
  // Line 5 is "teeth = 12", line 6 "profile_shift = 0.1".
  std::string text = CaseText("", "profile_shift = 0.1\n");
  text.replace(text.find("teeth = 35"), 10, "teeth = 12");
  Document doc = Read(text);
  ReadGearCase(doc);
  ASSERT_FALSE(doc.problems().empty());
  const InputProblem& p = doc.problems().front();
  EXPECT_EQ(p.file, "g.toml");
  EXPECT_EQ(p.line, 6) << All(doc);
  EXPECT_EQ(p.key, "gear.pinion.profile_shift");
  EXPECT_EQ(p.value, "0.1");
  EXPECT_NE(p.rule.find("undercut"), std::string::npos) << p.ToString();
  EXPECT_NE(p.allowed.find("allow_undercut = true"), std::string::npos) << p.ToString();
}

TEST(GearCase, ProblemOnAnAbsentKeyPointsAtItsSection) {
  // Interference of a 12/105 pair with undercut allowed: the fix is the wheel tip, which is
  // not written, so the problem points at the [gear.wheel] line.
  std::string text = CaseText("allow_undercut = true\n", "");
  text.replace(text.find("teeth = 35"), 10, "teeth = 12");
  Document doc = Read(text);
  ReadGearCase(doc);
  bool found = false;
  for (const auto& p : doc.problems())
    if (p.key == "gear.wheel.profile_shift" &&
        p.rule.find("involute interference") != std::string::npos) {
      found = true;
      EXPECT_EQ(p.line, 7) << p.ToString();  // "[gear.wheel]"
    }
  EXPECT_TRUE(found) << All(doc);
}

TEST(GearCase, EveryGeometricProblemAtOnce) {
  // A given centre distance that overlaps the teeth and a contact ratio below 1.
  Document doc = Read(CaseText("center_distance_m = 0.1399\n", "tip_radius_m = 0.0355\n",
                               "tip_radius_m = 0.1055\n"));
  ReadGearCase(doc);
  std::string keys;
  for (const auto& p : doc.problems()) keys += p.key + " ";
  EXPECT_NE(keys.find("gear.center_distance_m"), std::string::npos) << All(doc);
  EXPECT_NE(keys.find("gear.pinion.tip_radius_m"), std::string::npos) << All(doc);
}

TEST(GearCase, StiffnessMethodOutsideItsRangeIsReportedAtItsKey) {
  // Kuang-Yang is a fit for steel gears (seed 000 section 2.2): bronze is rejected by the
  // method, and the problem carries the case line of mesh_stiffness (line 4).
  Document doc = Read(CaseText("mesh_stiffness = \"kuang_yang\"\n", "youngs_modulus_pa = 117e9\n"));
  ReadGearCase(doc);
  ASSERT_FALSE(doc.problems().empty());
  EXPECT_EQ(doc.problems().front().key, "gear.mesh_stiffness") << All(doc);
  EXPECT_EQ(doc.problems().front().line, 4);
}

TEST(GearCase, LinearSharingNeedsAContactRatioBelowTwo) {
  // 80/120 teeth at 14.5 deg with long addenda (h_aP = 1.2, h_fP = 1.45, rho_fP = 0.2 m):
  // a valid pair with eps_alpha > 2.
  std::string text = CaseText(
      "load_sharing = \"linear\"\npressure_angle_deg = 14.5\n"
      "addendum_coefficient = 1.2\ndedendum_coefficient = 1.45\n"
      "root_fillet_coefficient = 0.2\n",
      "");
  text.replace(text.find("teeth = 35"), 10, "teeth = 80");
  text.replace(text.find("teeth = 105"), 11, "teeth = 120");
  Document doc = Read(text);
  ReadGearCase(doc);
  ASSERT_FALSE(doc.problems().empty());
  EXPECT_EQ(doc.problems().front().key, "gear.load_sharing") << All(doc);
}

TEST(GearCase, AContactCaseIsNotAGearCase) {
  Document doc = Read(
      "[contact]\nradius_1_m = 0.01\nspeed_1_m_s = 1.0\nspeed_2_m_s = 1.0\n"
      "load_n_per_m = 1e5\n[lubricant]\nname = \"sae40\"\n");
  EXPECT_FALSE(ReadGearCase(doc).has_value());
  EXPECT_FALSE(doc.problems().empty());
}

}  // namespace
}  // namespace tehl::internal
