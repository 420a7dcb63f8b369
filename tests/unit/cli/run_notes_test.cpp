// Notes that `tehl run` adds to its report: the outlet pressure spike that the grid does not
// resolve (include/tehl/ehl/outlet_spike.hpp).
#include <gtest/gtest.h>

#include <fstream>
#include <string>

#include "run_tehl.hpp"

namespace tehl::testing {
namespace {

// Two 40 mm steel discs at p_H = 0.8 GPa in rolling (the disc of docs/thermal.md, "Open
// points"): on 513 nodes the isothermal spike spans 2.6 cells at half height (docs/accuracy.md
// measures its height 23 % low there). `elastic` false gives a rigid film with no spike.
std::string DiscCase(bool elastic, const std::string& out_dir) {
  const std::string path = UniqueTempPath("disc.toml");
  std::ofstream(path) << "[contact]\nradius_1_m = 0.04\nradius_2_m = 0.04\n"
                         "speed_1_m_s = 4.881\nspeed_2_m_s = 4.881\nload_n_per_m = "
                      << (elastic ? "355238.0" : "2000.0")
                      << "\n[lubricant]\nname = \"sae40\"\n[effects]\ntransient = false\n"
                         "elastic = "
                      << (elastic ? "true" : "false") << "\n[numerics]\ngrid_points = 513\n"
                      << "[output]\ndirectory = \"" << out_dir << "\"\n";
  return path;
}

TEST(RunNotes, AnUnresolvedOutletSpikeIsNoted) {
  const std::string dir = UniqueTempPath("out");
  const RunResult r = RunTehl("run -q '" + DiscCase(true, dir) + "'");
  ASSERT_TRUE(r.exited);
  ASSERT_EQ(r.exit_code, 0) << r.out << r.err;
  EXPECT_NE(r.out.find("note: the outlet pressure spike"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("not grid-converged"), std::string::npos) << r.out;
}

TEST(RunNotes, ARigidFilmGetsNoSpikeNote) {
  const std::string dir = UniqueTempPath("out");
  const RunResult r = RunTehl("run -q '" + DiscCase(false, dir) + "'");
  ASSERT_TRUE(r.exited);
  ASSERT_EQ(r.exit_code, 0) << r.out << r.err;
  EXPECT_EQ(r.out.find("note:"), std::string::npos) << r.out;
}

}  // namespace
}  // namespace tehl::testing
