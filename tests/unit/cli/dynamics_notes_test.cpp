// Notes that `tehl dynamics` adds to its report: asymmetric teeth striking their back flanks,
// which the torsional model puts on the drive flanks' mesh (docs/dynamics.md, "Model").
#include <gtest/gtest.h>

#include <string>

#include "run_tehl.hpp"

namespace tehl::testing {
namespace {

const std::string kNote = "note: asymmetric teeth strike their back flanks";

std::string Case(const std::string& name) {
  return std::string(TEHL_SOURCE_DIR) + "/cases/" + name + ".toml";
}

TEST(DynamicsNotes, AsymmetricTeethOnTheirBackFlanksAreNoted) {
  // cases/asymmetric_35_20.toml at 7000 rpm, near its resonance: the teeth strike their back
  // flanks over 39 % of the period (docs/dynamics.md). K = cos 20 / cos 35 = 1.1472 (seed 000
  // eq. 3.23).
  const ScratchDir dir("tehl_dyn_notes");
  const RunResult r = RunTehl("dynamics '" + Case("asymmetric_35_20") + "' --speeds 7000:7000:1 " +
                              "--no-plot --threads 1 -o '" + dir.Path("out") + "'");
  ASSERT_TRUE(r.exited && r.exit_code == 0) << r.out << r.err;
  EXPECT_NE(r.out.find(kNote), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("K = 1.1472 times"), std::string::npos) << r.out;
}

TEST(DynamicsNotes, TeethOnTheirDriveFlanksGetNoNote) {
  // At the case's 1000 rpm the asymmetric pair stays on its drive flanks (DLF 1.17,
  // docs/dynamics.md); the symmetric resonance case with damping 0.15 does so at 7500 rpm.
  const ScratchDir dir("tehl_dyn_notes");
  for (const char* name : {"asymmetric_35_20", "seed004_sae40_dynamic_resonance"}) {
    const RunResult r =
        RunTehl("dynamics '" + Case(name) + "' --no-plot -o '" + dir.Path("out") + "'");
    ASSERT_TRUE(r.exited && r.exit_code == 0) << r.out << r.err;
    EXPECT_EQ(r.out.find(kNote), std::string::npos) << r.out;
  }
}

}  // namespace
}  // namespace tehl::testing
