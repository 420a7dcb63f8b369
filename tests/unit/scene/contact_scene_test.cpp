// The [contact] scene end to end: `tehl run` on the shipped disc cases and on bad input.
#include "tehl/scene/contact_scene.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include "tehl/units.hpp"

namespace tehl {
namespace {
namespace fs = std::filesystem;

fs::path TempDir(const std::string& name) {
  fs::path d = fs::temp_directory_path() / ("tehl_contact_" + name);
  fs::remove_all(d);
  fs::create_directories(d);
  return d;
}

int RunTehl(const std::string& args, std::string* output) {
  const std::string cmd = std::string(TEHL_BINARY) + " " + args + " 2>&1";
  FILE* pipe = popen(cmd.c_str(), "r");
  char buf[512];
  output->clear();
  while (fgets(buf, sizeof buf, pipe)) *output += buf;
  const int status = pclose(pipe);
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

TEST(ContactScene, SteadyDiscCaseConvergesAndWritesItsFiles) {
  ContactRunOptions o;
  o.quiet = true;
  o.output_dir = TempDir("steady").string();
  const ContactRunResult r =
      RunContactCase(std::string(TEHL_SOURCE_DIR) + "/cases/disc_steady.toml", o);
  ASSERT_TRUE(r.converged());
  ASSERT_EQ(r.steps.size(), 1u);
  EXPECT_TRUE(fs::exists(r.profile_csv));
  EXPECT_FALSE(fs::exists(r.profile_csv + ".tmp"));
  // Film above the Hertz zone: h_min < h_c, and the peak pressure is at least p_H of
  // w = 100 kN/m on R = 10 mm steel (VALIDATION.md section 1: p_H = sqrt(w E'/(2 pi R))).
  const auto& s = r.steps[0];
  EXPECT_LT(s.h_min_m, s.h_c_m);
  const double e_prime = ReducedModulus(206e9, 0.3, 206e9, 0.3);
  EXPECT_GT(s.p_max_pa, 0.99 * LineContactHertz(1e5, 0.01, e_prime).max_pressure_pa);
  // The profile file has one row per node and a header.
  std::ifstream in(r.profile_csv);
  std::string line;
  int rows = -1;
  while (std::getline(in, line)) ++rows;
  EXPECT_EQ(rows, 513);
}

TEST(ContactScene, LoadDoublingConvergesAtEveryStepAndThinsTheFilm) {
  ContactRunOptions o;
  o.quiet = true;
  o.output_dir = TempDir("step").string();
  const ContactRunResult r =
      RunContactCase(std::string(TEHL_SOURCE_DIR) + "/cases/disc_load_step.toml", o);
  ASSERT_TRUE(r.converged());
  EXPECT_EQ(r.steps.size(), 101u);
  // Higher load, thinner film (seed 004 trend 4): the end state at 2w has a smaller h_c.
  EXPECT_LT(r.steps.back().h_c_m, r.steps.front().h_c_m);
}

TEST(ContactScene, MovingWavinessMakesThePressureRippleAndConvergesEveryStep) {
  ContactRunOptions o;
  o.quiet = true;
  o.output_dir = TempDir("rough").string();
  const ContactRunResult r =
      RunContactCase(std::string(TEHL_SOURCE_DIR) + "/cases/disc_rough.toml", o);
  ASSERT_TRUE(r.converged());
  // Seed 004 trend 3: roughness dominates the pressure ripple. A 0.1 um waviness passing
  // through a 0.6 GPa contact moves p_max by well over 10 % between steps, while the smooth
  // steady film has one p_max.
  double lo = 1e300, hi = 0;
  for (size_t k = r.steps.size() / 2; k < r.steps.size(); ++k) {
    lo = std::min(lo, r.steps[k].p_max_pa);
    hi = std::max(hi, r.steps[k].p_max_pa);
  }
  EXPECT_GT((hi - lo) / lo, 0.1);
}

// An effect the case cannot have: the Ree-Eyring film with a lubricant that has no [eyring]
// section is rejected at its line before any solve.
TEST(ContactScene, EffectWithoutItsDataExitsWithCode2) {
  std::string out;
  const fs::path d = TempDir("bad");
  const fs::path bad = d / "eyring.toml";
  std::ofstream(bad) << "[contact]\nradius_1_m = 0.02\nspeed_1_m_s = 1.0\nspeed_2_m_s = 1.0\n"
                        "load_n_per_m = 1e5\n[lubricant]\nname = \"reference_z068\"\n[effects]\n"
                        "non_newtonian = true\n";
  EXPECT_EQ(RunTehl("run " + bad.string(), &out), 2) << out;
  EXPECT_NE(out.find(bad.string() + ":9: effects.non_newtonian = true"), std::string::npos) << out;
}

}  // namespace
}  // namespace tehl
