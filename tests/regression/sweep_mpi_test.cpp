// `mpirun -n 2 tehl sweep` on loopback gives the index of the threaded run: the same
// numbers (1e-12 relative) and statuses; each scene is the same computation on whichever
// rank or thread runs it. An error on one rank ends every rank, reported once, instead of
// leaving the others waiting. Built only with TEHL_WITH_MPI.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>

#include "regression/sweep_support.hpp"
#include "unit/cli/run_tehl.hpp"

namespace tehl {
namespace {
namespace fs = std::filesystem;

// The start of an mpirun command line, run by `runner` (e.g. "timeout 60 "): root in CI
// containers needs Open MPI's explicit consent; --oversubscribe lets two ranks share fewer
// cores.
std::string MpiRun(const std::string& runner = "") {
  return "OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMPI_MCA_btl=self,vader,tcp " +
         runner + "'" + std::string(TEHL_MPIEXEC) + "' --oversubscribe ";
}

struct MpiResult {
  int exit_code = -1;  // 124: still running after a minute (the ranks hang)
  std::string output;  // stdout and stderr of all ranks
};

// Runs `ranks` (an mpirun argument list) under a one-minute limit.
MpiResult RunRanks(const std::string& ranks, const std::string& dir) {
  const std::string out = dir + "/ranks.out";
  const int status =
      std::system((MpiRun("timeout -k 10 60 ") + ranks + " >'" + out + "' 2>&1").c_str());
  MpiResult r;
  if (status != -1 && WIFEXITED(status)) r.exit_code = WEXITSTATUS(status);
  r.output = testing::ReadAll(out);
  return r;
}

size_t Count(const std::string& text, const std::string& what) {
  size_t n = 0;
  for (size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

TEST(SweepMpi, TwoRanksGiveTheIndexOfTheThreadedRun) {
  const std::string study = testing::ReducedStudy(
      "sweep_mpi",
      "[[vary]]\nkey = \"operating.pinion_speed_rpm\"\nvalues = [500.0, 1000.0, 1500.0]\n");
  const std::string dir = fs::path(study).parent_path().string();
  // One set of FFTW plans for both runs: FFTW_MEASURE picks its plans by timing them, so two
  // processes can round differently (p_max of the third scene differed by 1.1e-12 relative
  // between runs on a loaded machine). The threaded run writes the plans, the ranks read them.
  ASSERT_EQ(setenv("TEHL_FFTW_WISDOM", (dir + "/fftw.wisdom").c_str(), 1), 0);
  const testing::RunResult threads =
      testing::RunTehl("sweep -j 2 -q -o '" + dir + "/threads' '" + study + "'");
  ASSERT_TRUE(threads.exited);
  ASSERT_EQ(threads.exit_code, 0) << threads.err;

  const std::string cmd = MpiRun() + "-n 2 '" + TEHL_BINARY + "' sweep -j 1 -q -o '" + dir +
                          "/mpi' '" + study + "' >'" + dir + "/mpi.out' 2>&1";
  const int status = std::system(cmd.c_str());
  unsetenv("TEHL_FFTW_WISDOM");
  ASSERT_EQ(status, 0) << testing::ReadAll(dir + "/mpi.out");

  const testing::IndexTable a = testing::ReadIndex(dir + "/threads/index.h5");
  const testing::IndexTable b = testing::ReadIndex(dir + "/mpi/index.h5");
  ASSERT_EQ(a.scene.size(), 3u);
  EXPECT_EQ(a.scene, b.scene);
  EXPECT_EQ(a.status, b.status);
  const double rel = 1e-12;
  testing::ExpectClose(b.h_min_min, a.h_min_min, rel, "h_min_min");
  testing::ExpectClose(b.h_c_pitch, a.h_c_pitch, rel, "h_c_pitch");
  testing::ExpectClose(b.h_c_min, a.h_c_min, rel, "h_c_min");
  testing::ExpectClose(b.p_max_max, a.p_max_max, rel, "p_max_max");
  testing::ExpectClose(b.t_max_max, a.t_max_max, rel, "T_max_max");
  testing::ExpectClose(b.mu_mean, a.mu_mean, rel, "mu_mean");
  testing::ExpectClose(b.mu_max, a.mu_max, rel, "mu_max");
  for (const auto& s : a.status) EXPECT_EQ(s, "ok");
}

// Rank 0 cannot write the scene files (a file in the place of the scenes folder) while rank 1
// waits to run its scenes: both end, with rank 0's report.
TEST(SweepMpi, SceneFilesThatCannotBeWrittenEndEveryRank) {
  const std::string study = testing::ReducedStudy(
      "sweep_mpi_write",
      "[[vary]]\nkey = \"operating.pinion_speed_rpm\"\nvalues = [500.0, 1000.0]\n");
  const std::string dir = fs::path(study).parent_path().string();
  fs::create_directories(dir + "/out");
  std::ofstream(dir + "/out/scenes") << "not a folder\n";
  const MpiResult r = RunRanks(
      "-n 2 '" + std::string(TEHL_BINARY) + "' sweep -q -o '" + dir + "/out' '" + study + "'", dir);
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_EQ(Count(r.output, "cannot write the results"), 1u) << r.output;
  EXPECT_NE(r.output.find(dir + "/out/scenes"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("stopped on rank 0 of 2"), std::string::npos) << r.output;
  EXPECT_FALSE(fs::exists(dir + "/out/index.h5"));
}

// Rank 1 alone cannot read its study (here: it is given another, missing file) while rank 0
// goes on to wait for it: both end, with rank 1's report.
TEST(SweepMpi, AStudyThatOneRankCannotReadEndsEveryRank) {
  const std::string study = testing::ReducedStudy(
      "sweep_mpi_read",
      "[[vary]]\nkey = \"operating.pinion_speed_rpm\"\nvalues = [500.0, 1000.0]\n");
  const std::string dir = fs::path(study).parent_path().string();
  const std::string tehl = "'" + std::string(TEHL_BINARY) + "' sweep -q -o '" + dir + "/out' '";
  const MpiResult r =
      RunRanks("-n 1 " + tehl + study + "' : -n 1 " + tehl + dir + "/missing.toml'", dir);
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find(dir + "/missing.toml"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("stopped on rank 1 of 2"), std::string::npos) << r.output;
  EXPECT_FALSE(fs::exists(dir + "/out/index.h5"));
}

}  // namespace
}  // namespace tehl
