// Checkpoints of the mesh cycle: a `tehl run` killed with SIGKILL after a checkpoint and rerun
// with --resume ends with the result of an uninterrupted run (isothermal and thermal), solving
// only the steps after the checkpoint; a complete result is left alone by --resume.
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <filesystem>

#include "mesh_cycle_runs.hpp"
#include "tehl/ehl/line_contact_solver.hpp"
#include "tehl/lubricant/lubricant.hpp"

namespace tehl {
namespace {
namespace fs = std::filesystem;
using testing::ReducedCase;
using testing::RunAndKillAfterCheckpoint;
using testing::TempDirFor;

MeshCycleResult RunInProcess(const std::string& case_path, const std::string& dir, bool resume) {
  MeshCycleRunOptions o;
  o.quiet = true;
  o.output_dir = dir;
  o.resume = resume;
  o.checkpoint_every = 5;
  return RunMeshCycle(case_path, o);
}

void ExpectSameCycle(const MeshCycleResult& a, const MeshCycleResult& b, bool thermal) {
  ASSERT_EQ(a.steps.size(), b.steps.size());
  // The restored run rebuilds its factorizations, so the two agree to the solver tolerance,
  // not bit for bit. Isothermal: Newton 1e-8 on the scaled residual, so 1e-6 in the film.
  // Thermal: each run stops once the coupling moves T by less than dT = 0.01 K
  // (LineContactSolver::Options::thermal_tolerance_k), and the energy solves of the early
  // coupling iterations are inexact, so the two temperatures may differ by about dT. The
  // film sees T through the viscosity, d ln eta = -beta dT with beta = -d ln eta / dT of the
  // oil at the step's (p_max, T_max) (lubricants/sae40.toml), and film thickness and pressure
  // respond to eta with a relative sensitivity below 1 (h ~ eta^0.7 in the Moes and
  // Hamrock-Dowson fits): |relative difference| <= beta dT.
  const Lubricant oil =
      Lubricant::FromFile(std::string(TEHL_SOURCE_DIR) + "/lubricants/sae40.toml");
  const double dt_k = LineContactSolver::Options{}.thermal_tolerance_k;
  for (size_t k = 0; k < a.steps.size(); ++k) {
    const MeshCycleStep &x = a.steps[k], &y = b.steps[k];
    double rel = 1e-6;
    if (thermal) {
      const auto v = oil.viscosity().Evaluate(x.p_max_pa, x.t_max_k);
      rel = std::max(rel, -v.deta_dT / v.eta_pa_s * dt_k);
    }
    EXPECT_EQ(x.s_m, y.s_m) << k;
    EXPECT_NEAR(x.h_min_m, y.h_min_m, rel * x.h_min_m) << k;
    EXPECT_NEAR(x.h_c_m, y.h_c_m, rel * x.h_c_m) << k;
    EXPECT_NEAR(x.p_max_pa, y.p_max_pa, rel * x.p_max_pa) << k;
    EXPECT_NEAR(x.t_max_k, y.t_max_k, 0.05) << k;
    EXPECT_NEAR(x.friction_coefficient, y.friction_coefficient,
                1e-4 * x.friction_coefficient + 1e-9)
        << k;
  }
}

class MeshCycleResume : public ::testing::TestWithParam<bool> {};

TEST_P(MeshCycleResume, KilledRunResumesToTheUninterruptedResult) {
  const bool thermal = GetParam();
  const std::string case_path = ReducedCase(
      "seed004_sae40",
      {{"grid_points", "129"}, {"steps", "40"}, {"thermal", thermal ? "true" : "false"}});
  const std::string ref_dir = TempDirFor("resume_ref"), dir = TempDirFor("resume_killed");
  const MeshCycleResult ref = RunInProcess(case_path, ref_dir, false);
  ASSERT_TRUE(ref.converged());
  EXPECT_EQ(ref.Restarts(), 0) << "a time step was restarted from the steady film";

  RunAndKillAfterCheckpoint(case_path, dir);
  const std::string stem = fs::path(case_path).stem().string();
  EXPECT_FALSE(fs::exists(dir + "/" + stem + ".h5"));
  const MeshCycleResult resumed = RunInProcess(case_path, dir, true);
  ASSERT_TRUE(resumed.converged());
  EXPECT_EQ(resumed.Restarts(), 0) << "a time step was restarted from the steady film";
  EXPECT_GT(resumed.resumed_from_step, 1);  // steps before the checkpoint were not solved again
  EXPECT_EQ(resumed.resumed_from_step % 5, 1);
  ExpectSameCycle(ref, resumed, thermal);
  EXPECT_TRUE(fs::exists(dir + "/" + stem + ".h5"));
  EXPECT_FALSE(fs::exists(dir + "/" + stem + ".checkpoint"));  // spent
  EXPECT_FALSE(fs::exists(dir + "/" + stem + ".checkpoint.rows"));

  // A complete result is left alone.
  const auto mtime = fs::last_write_time(dir + "/" + stem + ".h5");
  const MeshCycleResult again = RunInProcess(case_path, dir, true);
  EXPECT_TRUE(again.already_complete);
  EXPECT_EQ(fs::last_write_time(dir + "/" + stem + ".h5"), mtime);
}

INSTANTIATE_TEST_SUITE_P(IsothermalAndThermal, MeshCycleResume, ::testing::Bool());

// A checkpoint that cannot be written (here a folder in the way of the journal) does not stop
// the run: it goes on without checkpoints and writes its result.
TEST(MeshCycleResumeGuard, AnUnwritableCheckpointDoesNotStopTheRun) {
  const std::string dir = TempDirFor("resume_unwritable");
  const std::string a = ReducedCase("seed004_sae40", {{"grid_points", "129"}, {"steps", "20"}});
  const std::string stem = fs::path(a).stem().string();
  fs::create_directories(dir + "/" + stem + ".checkpoint.rows");
  MeshCycleResult r;
  ASSERT_NO_THROW(r = RunInProcess(a, dir, false));
  EXPECT_TRUE(r.converged());
  EXPECT_EQ(r.Restarts(), 0) << "a time step was restarted from the steady film";
  EXPECT_TRUE(fs::exists(dir + "/" + stem + ".h5"));
  EXPECT_FALSE(fs::exists(dir + "/" + stem + ".checkpoint"));
}

// A cycle CSV that cannot be written (a folder in the way of its temporary name) leaves no
// result behind that --resume would take for a finished run: the HDF5 file is committed only
// after the CSV, and the checkpoint stays, so the resumed run writes both.
TEST(MeshCycleResumeGuard, AFailedCycleCsvLeavesTheRunResumable) {
  const std::string dir = TempDirFor("resume_csv_blocked");
  const std::string a = ReducedCase("seed004_sae40", {{"grid_points", "129"}, {"steps", "20"}});
  const std::string stem = fs::path(a).stem().string();
  const std::string blocked = dir + "/" + stem + "_cycle.csv.part";
  fs::create_directories(blocked);
  EXPECT_THROW(RunInProcess(a, dir, false), fs::filesystem_error);
  EXPECT_FALSE(fs::exists(dir + "/" + stem + ".h5"));
  EXPECT_TRUE(fs::exists(dir + "/" + stem + ".checkpoint"));
  fs::remove_all(blocked);
  const MeshCycleResult r = RunInProcess(a, dir, true);
  EXPECT_FALSE(r.already_complete);
  EXPECT_GT(r.resumed_from_step, 0);
  EXPECT_TRUE(fs::exists(dir + "/" + stem + ".h5"));
  EXPECT_TRUE(fs::exists(dir + "/" + stem + "_cycle.csv"));
}

// A checkpoint of another case is not used: the run starts at A.
TEST(MeshCycleResumeGuard, CheckpointOfAnotherCaseIsIgnored) {
  const std::string dir = TempDirFor("resume_other");
  const std::string a = ReducedCase("seed004_sae40", {{"grid_points", "129"}, {"steps", "20"}});
  RunAndKillAfterCheckpoint(a, dir);
  // The same file name with another load: a different case text.
  const std::string text = testing::ReadText(a);
  std::ofstream(a) << std::regex_replace(text, std::regex("power_w = [^\n]*"), "power_w = 12000.0");
  const MeshCycleResult r = RunInProcess(a, dir, true);
  ASSERT_TRUE(r.converged());
  EXPECT_EQ(r.Restarts(), 0) << "a time step was restarted from the steady film";
  EXPECT_EQ(r.resumed_from_step, 0);
}

}  // namespace
}  // namespace tehl
