// The [contact] case of one point of a gear's path (`tehl run --at`): the flanks' radii,
// speeds and load there against involute geometry worked by hand, the written file read back
// by the [contact] reader, and the points refused.
#include "tehl/scene/path_point_case.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

#include "scene/case_reader.hpp"
#include "scene/contact_case.hpp"
#include "support/scratch_path.hpp"
#include "tehl/error.hpp"
#include "tehl/units.hpp"

namespace tehl {
namespace {
namespace fs = std::filesystem;

// A steel pair, m = 3 mm, z = 21 / 63, alpha = 20 deg, no shift, standard centre distance;
// 1500 rpm and 200 N m on the pinion, b = 20 mm.
constexpr double kM = 3e-3, kAlpha = 20 * kPi / 180, kB = 0.02;
constexpr int kZ1 = 21, kZ2 = 63;
constexpr double kRpm = 1500, kTorque = 200;

fs::path Dir(const std::string& name) {
  const fs::path d = testing::ScratchPath("tehl_path_point", name);
  fs::create_directories(d);
  return d;
}

std::string GearCase(const fs::path& dir,
                     const std::string& extra_gear = "",
                     const std::string& extra = "") {
  const fs::path p = dir / "pair.toml";
  std::ofstream(p) << "[gear]\nmodule_m = 0.003\nface_width_m = 0.02\n"
                   << extra_gear
                   << "[gear.pinion]\nteeth = 21\nyoungs_modulus_pa = 2.1e11\n"
                      "[gear.wheel]\nteeth = 63\nconductivity_w_mk = 40.0\n"
                      "[operating]\npinion_speed_rpm = 1500.0\npinion_torque_nm = 200.0\n"
                      "[lubricant]\nname = \"sae40\"\n"
                      "[numerics]\ngrid_points = 257\nsteps = 40\n"
                   << extra;
  return p.string();
}

// Involute geometry of the pair (external, no shift, addendum m): rho1 along the line of
// action from T1 at A, B, C, D, E; rho2 = a sin(alpha) - rho1.
struct Hand {
  double rb1 = kM * kZ1 / 2 * std::cos(kAlpha), rb2 = kM * kZ2 / 2 * std::cos(kAlpha);
  double line = (kM * (kZ1 + kZ2) / 2) * std::sin(kAlpha);  // T1 T2
  double pb = kPi * kM * std::cos(kAlpha);
  double Rho1(char p) const {
    const double ra1 = kM * kZ1 / 2 + kM, ra2 = kM * kZ2 / 2 + kM;
    const double a = line - std::sqrt(ra2 * ra2 - rb2 * rb2);  // A: the wheel's tip
    const double e = std::sqrt(ra1 * ra1 - rb1 * rb1);         // E: the pinion's tip
    switch (p) {
      case 'A':
        return a;
      case 'B':
        return e - pb;
      case 'C':
        return kM * kZ1 / 2 * std::sin(kAlpha);
      case 'D':
        return a + pb;
      default:
        return e;
    }
  }
  double w1() const { return kRpm * 2 * kPi / 60; }
  double w2() const { return w1() * kZ1 / kZ2; }
  double Load() const { return kTorque / rb1 / kB; }  // F_bt / b [N/m]
};

internal::ContactInputs ReadBack(const std::string& path) {
  internal::Document doc = internal::ReadCaseDocument(path);
  internal::ContactInputs in = internal::ReadContact(doc);
  doc.ThrowIfProblems();
  return in;
}

TEST(PathPointCase, RadiiSpeedsAndLoadAtTheNamedPointsMatchTheInvoluteGeometry) {
  const fs::path dir = Dir("named");
  const std::string gear = GearCase(dir);
  const Hand h;
  for (char p : std::string("ABCDE")) {
    const PathPointCase c =
        WriteContactCaseAtPoint(gear, std::string(1, p), (dir / "out").string());
    const double rho1 = h.Rho1(p), rho2 = h.line - rho1;
    EXPECT_NEAR(c.s_m, rho1 - h.Rho1('A'), 1e-12) << p;
    EXPECT_NEAR(c.reduced_radius_m, rho1 * rho2 / (rho1 + rho2), 1e-12) << p;
    EXPECT_NEAR(c.u1_m_s, h.w1() * rho1, 1e-12) << p;
    EXPECT_NEAR(c.u2_m_s, h.w2() * rho2, 1e-12) << p;
    // B, C and D carry the whole load (single contact; B and D on that side); A and E are
    // shared with another pair.
    if (p == 'A' || p == 'E') {
      EXPECT_EQ(c.pairs_in_contact, 2) << p;
      EXPECT_GT(c.load_share, 0.05) << p;
      EXPECT_LT(c.load_share, 0.95) << p;
    } else {
      EXPECT_EQ(c.pairs_in_contact, 1) << p;
      EXPECT_NEAR(c.load_share, 1.0, 1e-12) << p;
    }
    EXPECT_NEAR(c.load_n_per_m, c.load_share * h.Load(), 1e-9 * h.Load()) << p;
    EXPECT_EQ(fs::path(c.case_path).filename().string(), std::string("pair_at_") + p + ".toml");

    // The written case is a [contact] case with those values, the materials of each gear.
    const internal::ContactInputs in = ReadBack(c.case_path);
    EXPECT_NEAR(in.r1, rho1, 1e-15) << p;
    EXPECT_NEAR(in.r2, rho2, 1e-15) << p;
    EXPECT_EQ(in.u1.front(), c.u1_m_s) << p;  // shortest round-trip literals
    EXPECT_EQ(in.u2.front(), c.u2_m_s) << p;
    EXPECT_EQ(in.w.front(), c.load_n_per_m) << p;
    EXPECT_EQ(in.steps, 0);
    // E' of 210 GPa (pinion) and 206 GPa (wheel), nu = 0.3: 2 / E' = sum (1 - nu^2) / E.
    EXPECT_NEAR(in.e_prime, 2.0 / (0.91 / 2.1e11 + 0.91 / 2.06e11), 1e-3);
  }
  // At the pitch point the flanks roll: both speeds are the pitch-line speed.
  const PathPointCase c = WriteContactCaseAtPoint(gear, "c", (dir / "out").string());
  EXPECT_EQ(c.u1_m_s, c.u2_m_s);
  EXPECT_NEAR(c.u1_m_s, h.w1() * kM * kZ1 / 2 * std::sin(kAlpha), 1e-12);
  EXPECT_EQ(c.srr, 0.0);
}

TEST(PathPointCase, ADistanceFromAInMillimetresOrMetres) {
  const fs::path dir = Dir("distance");
  const std::string gear = GearCase(dir);
  const Hand h;
  const PathPointCase mm = WriteContactCaseAtPoint(gear, "2.5mm", (dir / "out").string());
  const PathPointCase m = WriteContactCaseAtPoint(gear, "0.0025m", (dir / "out").string());
  EXPECT_NEAR(mm.s_m, 2.5e-3, 1e-15);
  EXPECT_EQ(mm.reduced_radius_m, m.reduced_radius_m);
  const double rho1 = h.Rho1('A') + 2.5e-3, rho2 = h.line - rho1;
  EXPECT_NEAR(mm.reduced_radius_m, rho1 * rho2 / (rho1 + rho2), 1e-12);
  EXPECT_EQ(fs::path(mm.case_path).filename().string(), "pair_at_s2.5mm.toml");
  EXPECT_EQ(fs::path(m.case_path).filename().string(), "pair_at_s0.0025m.toml");
}

// The other sections are the gear case's: lubricant (made absolute), effects and numerics;
// the cycle's steps and the dynamic load are not a [contact] case's.
TEST(PathPointCase, KeepsTheFilmSectionsOfTheGearCase) {
  const fs::path dir = Dir("sections");
  const std::string gear = GearCase(dir, "", "[effects]\nthermal = true\nnon_newtonian = true\n");
  const PathPointCase c = WriteContactCaseAtPoint(gear, "A", (dir / "out").string());
  internal::Document doc = internal::ReadCaseDocument(c.case_path);
  doc.ThrowIfProblems();
  EXPECT_TRUE(doc.Bool("effects", "thermal"));
  EXPECT_TRUE(doc.Bool("effects", "non_newtonian"));
  EXPECT_EQ(doc.Int("numerics", "grid_points"), 257);
  EXPECT_EQ(doc.Int("numerics", "steps"), 0);
  EXPECT_TRUE(fs::path(doc.String("lubricant", "name")).is_absolute());
  EXPECT_FALSE(doc.HasSection("gear"));
  EXPECT_FALSE(doc.HasSection("operating"));
  EXPECT_EQ(doc.Real("contact", "conductivity_2_w_mk"), 40.0);
  EXPECT_EQ(doc.Real("contact", "youngs_modulus_1_pa"), 2.1e11);
}

// An internal pair: the ring's flank is concave, 1/R = 1/rho1 - 1/rho2; the case carries it
// as body 1 of radius R on a plane. (The ring tip is cut to 92.5 mm, clear of the pinion's
// fillet: the standard 91.5 mm tip interferes; ISO stiffness: the potential-energy model has
// no ring teeth.)
TEST(PathPointCase, AnInternalPairFoldsTheRingsCurvatureIntoR) {
  const fs::path dir = Dir("internal");
  const fs::path p = dir / "ring.toml";
  std::ofstream(p) << "[gear]\nmodule_m = 0.003\nface_width_m = 0.02\ninternal = true\n"
                      "mesh_stiffness = \"iso\"\n"
                      "[gear.pinion]\nteeth = 21\n[gear.wheel]\nteeth = 63\ntip_radius_m = 0.0925\n"
                      "[operating]\npinion_speed_rpm = 1500.0\npinion_torque_nm = 200.0\n"
                      "[lubricant]\nname = \"sae40\"\n";
  const PathPointCase c = WriteContactCaseAtPoint(p.string(), "C", (dir / "out").string());
  EXPECT_TRUE(c.internal);
  // At C: rho1 = r1 sin(alpha), rho2 = r2 sin(alpha) on the ring.
  const double rho1 = kM * kZ1 / 2 * std::sin(kAlpha), rho2 = kM * kZ2 / 2 * std::sin(kAlpha);
  EXPECT_NEAR(c.reduced_radius_m, rho1 * rho2 / (rho2 - rho1), 1e-12);
  const internal::ContactInputs in = ReadBack(c.case_path);
  EXPECT_EQ(in.r2, 0.0);
  EXPECT_NEAR(in.ReducedRadius(), c.reduced_radius_m, 1e-15);
}

void ExpectRefused(const std::string& gear, const std::string& at, const std::string& rule) {
  try {
    WriteContactCaseAtPoint(gear, at, "");
    ADD_FAILURE() << at << " was accepted";
  } catch (const InputError& e) {
    ASSERT_EQ(e.problems().size(), 1u) << e.what();
    EXPECT_EQ(e.problems()[0].key, "--at");
    EXPECT_NE(e.problems()[0].rule.find(rule), std::string::npos) << e.what();
    EXPECT_FALSE(e.problems()[0].allowed.empty());
  }
}

TEST(PathPointCase, PointsOffThePathOrWithoutAUnitAreRefused) {
  const fs::path dir = Dir("refused");
  const std::string gear = GearCase(dir);
  for (const char* at : {"F", "2.5", "2.5 inch", "mm", "", "x2mm", "nanmm"})
    ExpectRefused(gear, at, "not a point of the path");
  for (const char* at : {"-1mm", "40mm", "1m"}) ExpectRefused(gear, at, "outside the path");
  // A tip relief of 40 um over 1.5 mm on the wheel lifts the pair off at A.
  const fs::path rdir = Dir("relief");
  const fs::path p = rdir / "relieved.toml";
  std::ofstream(p)
      << "[gear]\nmodule_m = 0.003\nface_width_m = 0.02\n"
         "[gear.pinion]\nteeth = 21\n"
         "[gear.wheel]\nteeth = 63\ntip_relief_m = 4e-5\ntip_relief_length_m = 0.0015\n"
         "[operating]\npinion_speed_rpm = 1500.0\npinion_torque_nm = 200.0\n"
         "[lubricant]\nname = \"sae40\"\n";
  ExpectRefused(p.string(), "A", "tip relief");
  EXPECT_NO_THROW(WriteContactCaseAtPoint(p.string(), "C", (rdir / "out").string()));
}

TEST(PathPointCase, AContactCaseHasNoPath) {
  const fs::path dir = Dir("contact");
  const fs::path p = dir / "disc.toml";
  std::ofstream(p) << "[contact]\nradius_1_m = 0.02\nspeed_1_m_s = 1.0\nspeed_2_m_s = 1.0\n"
                      "load_n_per_m = 1e5\n[lubricant]\nname = \"sae40\"\n";
  try {
    WriteContactCaseAtPoint(p.string(), "C", "");
    ADD_FAILURE() << "a [contact] case was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("[gear]"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace tehl
