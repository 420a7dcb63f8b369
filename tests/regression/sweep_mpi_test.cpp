// `mpirun -n 2 tehl sweep` on loopback gives the index of the threaded run: the same
// numbers (1e-12 relative) and statuses; each scene is the same computation on whichever
// rank or thread runs it. Built only with TEHL_WITH_MPI.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>

#include "regression/sweep_support.hpp"
#include "unit/cli/run_tehl.hpp"

namespace tehl {
namespace {
namespace fs = std::filesystem;

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

  // Root in CI containers needs Open MPI's explicit consent; --oversubscribe lets two
  // ranks share fewer cores.
  const std::string cmd =
      "OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMPI_MCA_btl=self,vader,tcp '" +
      std::string(TEHL_MPIEXEC) + "' --oversubscribe -n 2 '" + TEHL_BINARY +
      "' sweep -j 1 -q -o '" + dir + "/mpi' '" + study + "' >'" + dir + "/mpi.out' 2>&1";
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

}  // namespace
}  // namespace tehl
