// What a run's profiles cost: `case --check` notes profiles above 1 GB with their size, and a
// plan whose profiles would not fit in the machine's memory is bad input at the key that
// makes them large, before any film is solved.
#include "scene/profile_memory.hpp"

#include <gtest/gtest.h>

#include <fstream>
#include <string>

#include "unit/cli/run_tehl.hpp"

namespace tehl {
namespace {

// The seed 004 pair (35/105 teeth, m = 2 mm, SAE 40, isothermal) with extra sections.
std::string GearCase(const std::string& extra) {
  return "[gear]\nmodule_m = 0.002\nface_width_m = 0.025\n"
         "[gear.pinion]\nteeth = 35\n[gear.wheel]\nteeth = 105\n"
         "[operating]\npinion_speed_rpm = 1000.0\npower_w = 10000.0\n"
         "[lubricant]\nname = \"sae40\"\n" +
         extra;
}

testing::RunResult Check(const std::string& name, const std::string& text) {
  const std::string path = testing::UniqueTempPath(name);
  std::ofstream(path) << text;
  return testing::RunTehl("case --check '" + path + "'");
}

// Counting: 8 bytes per double; p and h per node and film; thermal adds T_mid, T1, T2 and,
// with the field, film_nodes more.
TEST(ProfileMemory, BytesCountEveryKeptArray) {
  EXPECT_EQ(internal::ProfileBytes(1000, 10, false, 11, false), 8.0 * 2 * 1000 * 10);
  EXPECT_EQ(internal::ProfileBytes(1000, 10, true, 11, false), 8.0 * 5 * 1000 * 10);
  EXPECT_EQ(internal::ProfileBytes(1000, 10, true, 11, true), 8.0 * 16 * 1000 * 10);
  // The field is a thermal array: an isothermal run keeps none.
  EXPECT_EQ(internal::ProfileBytes(1000, 10, false, 11, true), 8.0 * 2 * 1000 * 10);
}

// 700 steps (701 films) on 200001 nodes, isothermal: 8 x 2 x 200001 x 701 bytes = 2.09 GB.
TEST(ProfileMemory, LargeProfilesAreNotedWithTheirSize) {
  const testing::RunResult r =
      Check("big_profiles.toml", GearCase("[numerics]\ngrid_points = 200001\nsteps = 700\n"));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("701 films on 200001 nodes keep 2.09 GB of profiles (p, h) in memory"),
            std::string::npos)
      << r.out;
  // The default grid and steps keep a few MB: no note.
  const testing::RunResult small = Check("small_profiles.toml", GearCase(""));
  ASSERT_EQ(small.exit_code, 0) << small.err;
  EXPECT_EQ(small.out.find("of profiles"), std::string::npos) << small.out;
}

// 9e6 steps on 999999 nodes: 8 x 2 x 999999 x 9000001 bytes = 134 TB, beyond any machine this
// runs on; the case sets grid_points, so the problem is named there.
TEST(ProfileMemory, ProfilesBeyondTheMachinesMemoryAreBadInput) {
  const testing::RunResult r =
      Check("huge_profiles.toml", GearCase("[numerics]\ngrid_points = 999999\nsteps = 9000000\n"));
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find("numerics.grid_points = 999999: the run's profiles would take"),
            std::string::npos)
      << r.err;
  EXPECT_NE(r.err.find("of this machine's memory"), std::string::npos) << r.err;
  // Without grid_points the step count is named; a [contact] table's too.
  const testing::RunResult steps =
      Check("huge_steps.toml", GearCase("[numerics]\nsteps = 9000000\n"));
  EXPECT_EQ(steps.exit_code, 2) << steps.err;
  EXPECT_NE(steps.err.find("numerics.steps = 9000000: the run's profiles"), std::string::npos)
      << steps.err;
  const testing::RunResult disc = Check(
      "huge_disc.toml",
      "[contact]\nradius_1_m = 0.02\nradius_2_m = 0.02\nspeed_1_m_s = 1.0\nspeed_2_m_s = 1.0\n"
      "load_n_per_m = 1e5\ntime_s = [0.0, 0.001]\nload_table_n_per_m = [1e5, 1e5]\n"
      "steps = 9000000\n[lubricant]\nname = \"sae40\"\n"
      "[numerics]\ngrid_points = 999999\n");
  EXPECT_EQ(disc.exit_code, 2) << disc.err;
  EXPECT_NE(disc.err.find("numerics.grid_points = 999999: the run's profiles"), std::string::npos)
      << disc.err;
}

}  // namespace
}  // namespace tehl
