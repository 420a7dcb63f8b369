// What `tehl dynamics` reports of the back flanks: for asymmetric teeth the coast flanks'
// own mesh (docs/dynamics.md, "Back flanks").
#include <gtest/gtest.h>

#include <fstream>
#include <regex>
#include <string>

#include "run_tehl.hpp"
#include "support/scratch_path.hpp"

namespace tehl::testing {
namespace {

std::string Case(const std::string& name) {
  return std::string(TEHL_SOURCE_DIR) + "/cases/" + name + ".toml";
}

TEST(DynamicsReport, AsymmetricTeethStrikeTheirCoastFlanksOnTheirOwnMesh) {
  // cases/asymmetric_35_20.toml near its resonance strikes its back flanks. They are the
  // coast flanks: K = cos 20 / cos 35 = 1.1472 (seed 000 eq. 3.23), and the case's coast
  // contact ratio, from the gear core's coast line, is reported with them.
  const ScratchDir dir("tehl_dyn_report");
  const RunResult r = RunTehl("dynamics '" + Case("asymmetric_35_20") + "' --speeds 7400:7400:1 " +
                              "--no-plot --threads 1 -o '" + dir.Path("out") + "'");
  ASSERT_TRUE(r.exited && r.exit_code == 0) << r.out << r.err;
  EXPECT_NE(r.out.find("back flanks (the coast flanks, 20.0 deg): base circles K = 1.1472"),
            std::string::npos)
      << r.out;
  EXPECT_EQ(r.out.find("approximate"), std::string::npos) << r.out;
  const RunResult g = RunTehl("gear '" + Case("asymmetric_35_20") + "'");
  ASSERT_TRUE(g.exited && g.exit_code == 0) << g.out << g.err;
  std::smatch eps;
  ASSERT_TRUE(std::regex_search(g.out, eps, std::regex("coast flank: .*eps_alpha = ([0-9.]+)")))
      << g.out;
  EXPECT_NE(r.out.find("contact ratio " + eps[1].str()), std::string::npos) << eps[1] << "\n"
                                                                            << r.out;
  // `tehl gear` gives the coast flanks' mesh stiffness per unit face width (the gear core's
  // sampling along the coast path); the dynamics' back-flank mesh (its Chebyshev interpolant)
  // has the same mean over the 25 mm face.
  std::smatch gear_mean, dyn_mean;
  ASSERT_TRUE(std::regex_search(g.out, gear_mean, std::regex("coast flanks +([0-9.]+)"))) << g.out;
  ASSERT_TRUE(std::regex_search(r.out, dyn_mean,
                                std::regex("back flanks .*mesh stiffness mean ([0-9.e+]+)")))
      << r.out;
  EXPECT_NEAR(std::stod(gear_mean[1]) * 1e6 * 25.0 / std::stod(dyn_mean[1]), 1.0, 1e-3);
  const RunResult symmetric = RunTehl("gear '" + Case("seed004_sae40") + "'");
  EXPECT_EQ(symmetric.out.find("coast flanks"), std::string::npos) << symmetric.out;
}

TEST(DynamicsReport, ContinuationSweepsWriteTheirOwnTablesAndNeedSpeeds) {
  const ScratchDir dir("tehl_dyn_report");
  const std::string out = dir.Path("out");
  const RunResult up =
      RunTehl("dynamics '" + Case("seed004_sae40") +
              "' --speeds 1000:3000:1000 --sweep-start up --no-plot -o '" + out + "'");
  ASSERT_TRUE(up.exited && up.exit_code == 0) << up.out << up.err;
  EXPECT_NE(up.out.find("sweep (continuation up): 3 speeds"), std::string::npos) << up.out;
  EXPECT_TRUE(std::ifstream(out + "/seed004_sae40_dynamics_sweep_up.csv").good());
  for (const std::string& bad : {std::string(" --sweep-start up"),
                                 std::string(" --speeds 1000:2000:500 --sweep-start sideways")}) {
    const RunResult r =
        RunTehl("dynamics '" + Case("seed004_sae40") + "'" + bad + " --no-plot -o '" + out + "'");
    EXPECT_TRUE(r.exited && r.exit_code == 2) << bad << "\n" << r.out << r.err;
    EXPECT_NE(r.err.find("--sweep-start"), std::string::npos) << r.err;
  }
}

// cases/asymmetric_35_20.toml without corner contact: at zero backlash near its resonance the
// response grows without bound (docs/dynamics.md "Back flanks"). The sweep says so and marks
// those speeds, its largest load factor is that of a periodic response, and a case whose own
// speed diverges fails (exit 1) naming it.
TEST(DynamicsReport, AResponseGrowingWithoutBoundIsNamedAndLeftOutOfThePeak) {
  const ScratchDir dir("tehl_dyn_report");
  std::ifstream in(Case("asymmetric_35_20"));
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  text = std::regex_replace(text, std::regex("name = \"sae40\""),
                            "name = \"" TEHL_SOURCE_DIR "/lubricants/sae40.toml\"");
  const std::string path = dir.Path("nocorner.toml");
  std::ofstream(path) << text << "\n[dynamics]\ncorner_contact = false\n";
  const std::string out = dir.Path("out");
  const RunResult r =
      RunTehl("dynamics '" + path + "' --speeds 6800:7100:100 --no-plot -o '" + out + "'");
  ASSERT_TRUE(r.exited && r.exit_code == 0) << r.out << r.err;
  EXPECT_NE(r.out.find("the response grows without bound"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("largest dynamic load factor"), std::string::npos) << r.out;
  std::ifstream csv(out + "/nocorner_dynamics_sweep.csv");
  std::string header;
  std::getline(csv, header);
  EXPECT_NE(header.find(",diverged"), std::string::npos) << header;

  const std::string fast = dir.Path("nocorner_fast.toml");
  std::ofstream(fast) << std::regex_replace(text, std::regex("pinion_speed_rpm = 1000.0"),
                                            "pinion_speed_rpm = 7000.0")
                      << "\n[dynamics]\ncorner_contact = false\n";
  const RunResult f = RunTehl("dynamics '" + fast + "' --no-plot -o '" + out + "'");
  ASSERT_TRUE(f.exited);
  EXPECT_EQ(f.exit_code, 1) << f.out << f.err;
  EXPECT_NE(f.err.find("at the case's speed the response grows without bound"), std::string::npos)
      << f.err;
  // A sweep asked for still runs (its speeds are other runs); the exit stays 1.
  const RunResult fs =
      RunTehl("dynamics '" + fast + "' --speeds 6000:6200:100 --no-plot -o '" + out + "'");
  ASSERT_TRUE(fs.exited);
  EXPECT_EQ(fs.exit_code, 1) << fs.out << fs.err;
  EXPECT_NE(fs.out.find("sweep: 3 speeds"), std::string::npos) << fs.out;
  EXPECT_TRUE(std::ifstream(out + "/nocorner_fast_dynamics_sweep.csv").good());
}

// The films' dynamic load (effect dynamic_load) cannot be carried where the drive flanks
// unload; `tehl run` refuses such a case, and the message sends the user to `tehl dynamics`,
// which therefore runs it: the resonance case with damping 0.02 separates over about a third
// of its period.
TEST(DynamicsReport, RunsACaseWhoseFilmsCouldNotCarryTheDynamicLoad) {
  const ScratchDir dir("tehl_dyn_report");
  std::ifstream in(Case("seed004_sae40_dynamic_resonance"));
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  text = std::regex_replace(text, std::regex("name = \"sae40\""),
                            "name = \"" TEHL_SOURCE_DIR "/lubricants/sae40.toml\"");
  text = std::regex_replace(text, std::regex("damping_ratio = 0.15"), "damping_ratio = 0.02");
  const std::string path = dir.Path("separating.toml");
  std::ofstream(path) << text;
  const RunResult check = RunTehl("case --check '" + path + "'");
  EXPECT_EQ(check.exit_code, 2) << check.out << check.err;  // the films' case is refused
  const RunResult r = RunTehl("dynamics '" + path + "' --no-plot -o '" + dir.Path("out") + "'");
  ASSERT_TRUE(r.exited);
  EXPECT_EQ(r.exit_code, 0) << r.out << r.err;
  EXPECT_NE(r.out.find("min F = 0.0000 N; separated"), std::string::npos) << r.out;
}

}  // namespace
}  // namespace tehl::testing
