// The [dynamics] section and the dynamic_load effect of a gear case (src/scene/dynamic_load.*):
// defaults from the blanks and the geometry, the cycle rows' dynamic w, and bad input.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <regex>
#include <sstream>

#include "scene/case_reader.hpp"
#include "scene/dynamic_load.hpp"
#include "scene/gear_case.hpp"
#include "support/scratch_path.hpp"
#include "tehl/drive/dynamic_response.hpp"
#include "tehl/error.hpp"
#include "tehl/units.hpp"

namespace tehl {
namespace {

std::string CaseText(const std::string& name) {
  std::ifstream in(std::string(TEHL_SOURCE_DIR) + "/cases/" + name + ".toml");
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

// Writes `text` (a case) beside the shipped cases' lubricants and reads it as a gear case.
std::string WriteCase(const std::string& text, const std::string& name) {
  const std::string path = testing::ScratchPath("tehl_dyn", name + ".toml");
  std::ofstream(path) << std::regex_replace(text, std::regex("name = \"sae40\""),
                                            "name = \"" TEHL_SOURCE_DIR "/lubricants/sae40.toml\"");
  return path;
}

std::string Set(std::string text, const std::string& key, const std::string& value) {
  return std::regex_replace(text, std::regex("(^|\n)" + key + " = [^\n]*"),
                            "$1" + key + " = " + value);
}

internal::GearCase Read(const std::string& path) {
  internal::Document doc = internal::ReadCaseDocument(path);
  std::optional<internal::GearCase> c = internal::ReadGearCase(doc);
  doc.ThrowIfProblems();
  return *c;
}

TEST(DynamicsCase, InertiasOfSolidDiscsAndBacklashFromTheGeometry) {
  // Seed 004 pair, rho = 7890 kg/m^3, b = 25 mm, pitch radii 35 and 105 mm:
  // J = pi rho b r^4 / 2 = 4.64953e-4 and 3.76612e-2 kg m^2 (by hand). The standard centre
  // distance is the zero-backlash distance: backlash 0 when not given.
  std::string text = CaseText("seed004_sae40_dynamic");
  text = std::regex_replace(text, std::regex("\nbacklash_m = [^\n]*"), "");
  internal::Document doc = internal::ReadCaseDocument(WriteCase(text, "blanks"));
  std::optional<internal::GearCase> c = internal::ReadGearCase(doc);
  ASSERT_TRUE(c && c->pair);
  const internal::DynamicsCase d = internal::ReadDynamicsCase(doc, *c);
  EXPECT_TRUE(doc.problems().empty());
  EXPECT_NEAR(d.params.pinion_inertia_kg_m2, 4.64953e-4, 1e-9);
  EXPECT_NEAR(d.params.wheel_inertia_kg_m2, 3.76612e-2, 1e-7);
  EXPECT_TRUE(d.backlash_from_geometry);
  EXPECT_NEAR(d.params.backlash_m, 0.0, 1e-12);
  EXPECT_EQ(d.params.friction, FrictionLaw::kBuckingham);
  EXPECT_EQ(d.params.damping_ratio, 0.05);
}

TEST(DynamicsCase, BacklashOfAWiderCentreDistanceIsAlongTheLineOfAction) {
  // a = 140.1 mm instead of 140: j_bn = j_t cos(alpha_wt), j_t of the gear pair.
  std::string text = CaseText("seed004_sae40_dynamic");
  text = std::regex_replace(text, std::regex("\nbacklash_m = [^\n]*"), "");
  text =
      std::regex_replace(text, std::regex("\\[gear\\]\n"), "[gear]\ncenter_distance_m = 0.1401\n");
  internal::Document doc = internal::ReadCaseDocument(WriteCase(text, "wide"));
  std::optional<internal::GearCase> c = internal::ReadGearCase(doc);
  ASSERT_TRUE(c && c->pair) << (doc.problems().empty() ? "" : doc.problems()[0].ToString());
  const internal::DynamicsCase d = internal::ReadDynamicsCase(doc, *c);
  const double jt = c->pair->backlash_m();
  EXPECT_GT(jt, 0);
  EXPECT_NEAR(d.params.backlash_m,
              jt * std::cos(c->pair->line(Flank::kDrive).working_pressure_angle_rad), 1e-15);
}

TEST(DynamicLoadEffect, LoadedSharingNeedsTheTorsionalModelWithCornerContact) {
  // The film's dynamic load is the static share times the ratio of the tracked pair's
  // dynamic to quasi-static load: with load_sharing = "loaded" (corner contact in the static
  // sharing) and corner_contact = false in the torsional model, the stepped model's spike
  // (x1.69 at A at 10 rpm) would be applied on top of a share that already ramps.
  std::string text = Set(CaseText("seed004_sae40_dynamic"), "load_sharing", "\"loaded\"");
  text = std::regex_replace(text, std::regex("\\[dynamics\\]\n"),
                            "[dynamics]\ncorner_contact = false\n");
  try {
    Read(WriteCase(text, "loaded_no_corner"));
    ADD_FAILURE() << "the case was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("dynamics.corner_contact = false"), std::string::npos)
        << e.what();
  }
  // With the corner contact in both (the default), it is accepted and quasi-static at 1 rpm.
  std::string both = Set(CaseText("seed004_sae40_dynamic"), "load_sharing", "\"loaded\"");
  both = Set(Set(both, "pinion_speed_rpm", "1.0"), "power_w", "10.0");
  const internal::GearCase c = Read(WriteCase(both, "loaded_corner"));
  ASSERT_TRUE(c.dynamic_load);
  for (double s : {0.0, 0.3e-3, 5.0e-3, 10.0e-3})
    EXPECT_NEAR(c.dynamic_load->LoadFactorAt(s, false), 1.0, 0.03) << "s " << s;
}

TEST(DynamicLoadEffect, CycleRowsCarryTheDynamicLoadAtTheCaseSpeed) {
  // Same case with and without the effect: every row's w is the static w times F/F_s of the
  // periodic response at that s, and at 1000 rpm (near f_n/8; dynamic load factor 1.14 with
  // corner contact, docs/dynamics.md) w differs by more than 5 %
  // somewhere.
  const std::string text = CaseText("seed004_sae40_dynamic");
  const internal::GearCase dyn = Read(WriteCase(text, "on"));
  const internal::GearCase stat = Read(WriteCase(Set(text, "dynamic_load", "false"), "off"));
  ASSERT_TRUE(dyn.dynamic_load);
  EXPECT_FALSE(stat.dynamic_load);
  const auto rd = internal::GearCaseCycle(dyn, 201);
  const auto rs = internal::GearCaseCycle(stat, 201);
  ASSERT_EQ(rd.size(), rs.size());
  double largest = 0;
  for (size_t i = 0; i < rd.size(); ++i) {
    const double s = rd[i].contact.s_m;
    EXPECT_NEAR(rd[i].load_n_per_m, rs[i].load_n_per_m * dyn.dynamic_load->LoadFactorAt(s, s > 0),
                1e-9 * rs[i].load_n_per_m);
    EXPECT_GT(rd[i].load_n_per_m, 0.0);
    largest = std::max(largest, std::abs(rd[i].load_n_per_m / rs[i].load_n_per_m - 1));
  }
  EXPECT_GT(largest, 0.05);
}

TEST(DynamicLoadEffect, AtVeryLowSpeedTheCycleLoadIsTheStaticLoad) {
  // 1 rpm: quasi-static; away from the 1 % of the period after each stiffness jump the
  // dynamic w equals the static w to 1 % (friction off: it shifts the static balance).
  // 10 W at 1 rpm: the torque of the case (10 kW at 1000 rpm).
  std::string text = Set(CaseText("seed004_sae40_dynamic"), "pinion_speed_rpm", "1.0");
  text = Set(text, "power_w", "10.0");
  text = Set(text, "friction", "\"none\"");
  const internal::GearCase c = Read(WriteCase(text, "slow"));
  ASSERT_TRUE(c.dynamic_load);
  const TorsionalMesh& mesh = c.dynamic_load->mesh();
  int compared = 0;
  for (int i = 0; i <= 400; ++i) {
    const double s = mesh.length_m() * i / 400;
    const double phase = std::fmod(s, mesh.base_pitch_m());
    const MeshSegment& seg = mesh.segments()[mesh.SegmentAt(phase)];
    if (phase - seg.begin_m < 0.01 * mesh.base_pitch_m()) continue;
    EXPECT_NEAR(c.dynamic_load->LoadFactorAt(s, false), 1.0, 0.01) << "s = " << s;
    ++compared;
  }
  EXPECT_GT(compared, 300);
}

void ExpectProblem(const std::string& text, const std::string& key, const std::string& name) {
  const std::string path = WriteCase(text, name);
  try {
    Read(path);
    ADD_FAILURE() << "no problem reported for " << key;
  } catch (const InputError& e) {
    bool found = false;
    for (const InputProblem& p : e.problems())
      found = found ||
              (p.key == key && p.file == path && (p.line > 0 || key == "effects.dynamic_load"));
    EXPECT_TRUE(found) << e.what();
  }
}

TEST(DynamicsCase, RejectsBadValuesAtTheirLine) {
  const std::string text = CaseText("seed004_sae40_dynamic");
  ExpectProblem(Set(text, "damping_ratio", "1.5"), "dynamics.damping_ratio", "zeta");
  // Undamped, the response to the mesh's excitation never settles into a period (it ran
  // 5000 periods and ended "not periodic").
  ExpectProblem(Set(text, "damping_ratio", "0"), "dynamics.damping_ratio", "undamped");
  ExpectProblem(Set(text, "friction", "\"coulomb\""), "dynamics.friction", "law");
  ExpectProblem(Set(text, "backlash_m", "-1e-6"), "dynamics.backlash_m", "negative");
  // 0.1 mm written as 0.1 m: no backlash along the line of action reaches the base pitch
  // p_b = pi m cos(alpha) = 5.9043 mm of the seed 004 pair (VALIDATION.md section 5).
  ExpectProblem(Set(text, "backlash_m", "0.1"), "dynamics.backlash_m", "millimetres");
  ExpectProblem(Set(text, "backlash_m", "5.905e-3"), "dynamics.backlash_m", "pitch");
  ExpectProblem(text + "friction_coefficient = 0.1\n", "dynamics.friction_coefficient", "mu");
  ExpectProblem(text + "relative_tolerance = 0.01\n", "dynamics.relative_tolerance", "rtol");
}

TEST(DynamicsCase, BacklashBelowTheBasePitchIsAccepted) {
  // Just below p_b = 5.9043 mm (VALIDATION.md section 5): accepted as given.
  const std::string text = CaseText("seed004_sae40_dynamic");
  internal::Document doc =
      internal::ReadCaseDocument(WriteCase(Set(text, "backlash_m", "5.9e-3"), "wide_play"));
  std::optional<internal::GearCase> c = internal::ReadGearCase(doc);
  ASSERT_TRUE(c && c->pair);
  const internal::DynamicsCase d = internal::ReadDynamicsCase(doc, *c);
  for (const auto& p : doc.problems()) EXPECT_NE(p.key, "dynamics.backlash_m") << p.rule;
  EXPECT_DOUBLE_EQ(d.params.backlash_m, 5.9e-3);
}

TEST(DynamicLoadEffect, RejectsACaseWhoseTeethUnloadAtItsSpeed) {
  // The resonance case with the default damping 0.05: the teeth separate (docs/dynamics.md).
  ExpectProblem(Set(CaseText("seed004_sae40_dynamic_resonance"), "damping_ratio", "0.05"),
                "effects.dynamic_load", "separates");
}

// Two code paths for the tracked pair's dynamic load: the film's (the case's static sharing
// times the tracked pair's dynamic-to-static ratio, scene/dynamic_load.cpp) and the torsional
// model's own (TrackedPairLoad, `tehl dynamics`' path file). With load_sharing = "loaded" the
// case's static sharing is the model's (the same corner contact), so the two must agree at
// every s, also in B-D where the entering pair's corner takes part of the load (share about
// 0.69 there at 1000 rpm: docs/gear.md, docs/dynamics.md). The path file used to take the
// share without the corners: 4.8 % above the film's load in B-D.
TEST(DynamicLoadEffect, TheFilmsLoadIsTheModelsTrackedPairLoadWithLoadedSharing) {
  const std::string text = Set(CaseText("seed004_sae40_dynamic"), "load_sharing", "\"loaded\"");
  const internal::GearCase c = Read(WriteCase(text, "loaded_path"));
  ASSERT_TRUE(c.dynamic_load);
  const auto rows = internal::GearCaseCycle(c, 201);
  const auto model = TrackedPairLoad(c.dynamic_load->response(), c.spec.face_width_m, 201);
  const double g = c.dynamic_load->mesh().length_m(), pb = c.dynamic_load->mesh().base_pitch_m();
  int compared = 0;
  double min_share = 1;
  for (const auto& row : rows) {
    const double s = row.contact.s_m;
    if (std::abs(s - pb) < 1e-6 * g || std::abs(s - (g - pb)) < 1e-6 * g) continue;  // B, D
    for (const PairLoadPoint& p : model)
      if (std::abs(p.s_m - s) < 1e-12 * g) {
        EXPECT_NEAR(p.dynamic_n_per_m, row.load_n_per_m, 1e-9 * row.load_n_per_m) << "s " << s;
        min_share = std::min(min_share, p.share);
        ++compared;
        break;
      }
  }
  EXPECT_GT(compared, 150);
  EXPECT_LT(min_share, 0.75);  // the corners' part in B-D is in the comparison
}

}  // namespace
}  // namespace tehl
