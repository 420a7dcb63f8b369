// What `tehl run` says about results that are not what they seem: a Newtonian friction
// coefficient beyond any lubricant (no flash temperature from it), steps split into
// substeps by the Newton limit, and an inlet far from the temperature where the lubricant's
// exponential law holds.
#include <gtest/gtest.h>

#include <fstream>
#include <iterator>
#include <string>

#include "run_tehl.hpp"

namespace tehl::testing {
namespace {

// An isothermal Newtonian film in sliding (steel discs R1 = R2 = 20 mm, w = 355.2 kN/m,
// u1 = 3, u2 = 1 m/s, SAE 40) has mu far above the 0.2 that lubricants' limiting shear
// stress allows (the friction note): the report says the mu is not physical and gives no
// flash temperature from it, instead of headlining one.
TEST(RunCaveats, AnUnphysicalNewtonianMuGivesNoFlashTemperature) {
  const std::string dir = UniqueTempPath("out");
  const std::string path = UniqueTempPath("sliding.toml");
  std::ofstream(path) << "[contact]\nradius_1_m = 0.02\nradius_2_m = 0.02\n"
                         "speed_1_m_s = 3.0\nspeed_2_m_s = 1.0\nload_n_per_m = 355200.0\n"
                         "[lubricant]\nname = \"sae40\"\n[effects]\ntransient = false\n"
                         "[numerics]\ngrid_points = 257\n[output]\ndirectory = \""
                      << dir << "\"\n";
  const RunResult r = RunTehl("run -q '" + path + "'");
  ASSERT_TRUE(r.exited);
  ASSERT_EQ(r.exit_code, 0) << r.out << r.err;
  EXPECT_NE(r.out.find("not physical: note below); no flash temperature from it"),
            std::string::npos)
      << r.out;
  EXPECT_EQ(r.out.find("flash temperature (Blok"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("note: the Newtonian film's friction coefficient"), std::string::npos)
      << r.out;
}

// A Newton iteration limit below what a step needs splits that step into substeps (the
// retry of LineContactSolver::Step), which changes the films by the time error: the run
// says so. Seed 004, thermal with the Ree-Eyring film, 257 nodes, 80 steps and at most 8
// Newton iterations: step 37 (s = 4.83 mm, just after B, where the load jumps) is split.
TEST(RunCaveats, StepsSplitByTheNewtonLimitAreNoted) {
  std::ifstream in(std::string(TEHL_SOURCE_DIR) + "/cases/seed004_sae40.toml");
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const auto at = text.find("grid_points = 513");
  ASSERT_NE(at, std::string::npos);
  text.replace(at, 17, "grid_points = 257\nsteps = 80\nmax_newton_iterations = 8");
  const auto th = text.find("thermal = true");
  ASSERT_NE(th, std::string::npos);
  text.replace(th, 14, "thermal = true\nnon_newtonian = true");
  const std::string dir = UniqueTempPath("out"), path = UniqueTempPath("split.toml");
  std::ofstream(path) << text << "[output]\ndirectory = \"" << dir << "\"\n";
  const RunResult r = RunTehl("run -q '" + path + "'");
  ASSERT_TRUE(r.exited);
  ASSERT_EQ(r.exit_code, 0) << r.out << r.err;
  EXPECT_NE(r.out.find("did not converge as one step and was split into substeps"),
            std::string::npos)
      << r.out;
  // With the default limit (100) the steps stay whole and nothing is noted.
  text.replace(text.find("max_newton_iterations = 8"), 25, "max_newton_iterations = 100");
  std::ofstream(path) << text << "[output]\ndirectory = \"" << dir << "\"\n";
  const RunResult whole = RunTehl("run -q '" + path + "'");
  ASSERT_EQ(whole.exit_code, 0) << whole.out << whole.err;
  EXPECT_EQ(whole.out.find("split into substeps"), std::string::npos) << whole.out;
}

// An inlet 50 K above the lubricant's reference temperature takes its roelands_gamma law
// beyond where one gamma describes the oil: `case --check` and the run say so; 20 K does not.
TEST(RunCaveats, AnInletFarFromTheGammaLawsReferenceIsNoted) {
  for (const char* t : {"363.15", "333.15"}) {
    std::ifstream in(std::string(TEHL_SOURCE_DIR) + "/cases/seed004_sae40.toml");
    std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    const auto at = text.find("inlet_temperature_k = 313.15");
    ASSERT_NE(at, std::string::npos);
    text.replace(at, 28, std::string("inlet_temperature_k = ") + t);
    const std::string path = UniqueTempPath("hot.toml");
    std::ofstream(path) << text;
    const RunResult r = RunTehl("case --check '" + path + "'");
    ASSERT_EQ(r.exit_code, 0) << r.out << r.err;
    const bool noted =
        r.out.find("is 50 K above the lubricant's reference temperature") != std::string::npos;
    EXPECT_EQ(noted, std::string(t) == "363.15") << r.out;
  }
}

}  // namespace
}  // namespace tehl::testing
