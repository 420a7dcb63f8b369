// [numerics] failed_step (src/scene/step_restart.hpp): a transient step that does not converge
// either stops the run ("stop") or is replaced by the steady film at its time, flagged, and the
// run marches on ("steady_restart", the default).
//
// The case is the seed 004 contact across B, where the load moves onto one tooth pair: the
// conditions of steps 64..70 of the 2049-node thermal cycle (docs/thermal.md, "The seed 004
// cycle at full resolution": step 70 fails there), as a [contact] run of two aluminium bronze
// discs with the pinion's and the wheel's radii of curvature at s = 4.70 mm, SAE 40 at
// 313.15 K, Newtonian and thermal, on 1025 nodes with 12 time steps. A step after the load
// jump does not converge: the squeeze spike heats the Newtonian film faster than the
// pressure/temperature coupling follows.
#include <gtest/gtest.h>
#include <hdf5.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "support/csv_cells.hpp"
#include "support/scratch_path.hpp"
#include "tehl/scene/contact_scene.hpp"
#include "tehl/scene/mesh_cycle_scene.hpp"
#include "unit/cli/run_tehl.hpp"
#include "unit/io/hdf5_read.hpp"

namespace tehl {
namespace {
namespace fs = std::filesystem;

#ifndef TEHL_SLOW_TESTS  // the slow build (step_restart_slow_test) holds only the 2049-node run
// Steps 64..70 of the 2049-node cycle: time since step 64 [s], load [N/m], pinion and wheel
// surface speeds [m/s] (the cycle's own CSV; B lies between the second and third entries).
constexpr double kTime[] = {
    0, 2.036627e-05, 4.091775e-05, 6.146924e-05, 8.202072e-05, 1.025722e-04, 1.231237e-04};
constexpr double kLoad[] = {68267.0, 68632.6, 116138.8, 116138.8, 116138.8, 116138.8, 116138.8};
constexpr double kU1[] = {1.149347, 1.156692, 1.164105, 1.171517, 1.178929, 1.186342, 1.193754};
constexpr double kU2[] = {1.288310, 1.285862, 1.283391, 1.280920, 1.278449, 1.275979, 1.273508};

std::string Table(const double* v, int n) {
  std::string s = "[";
  char buf[32];
  for (int i = 0; i < n; ++i) {
    std::snprintf(buf, sizeof buf, "%.17g", v[i]);
    s += (i ? ", " : "") + std::string(buf);
  }
  return s + "]";
}

// The case; steps = 0 gives the steady film at the table's load `w_steady` and speeds
// `u1_steady`, `u2_steady` instead (same grid: the grid is sized by the largest load).
std::string AcrossB(const fs::path& dir,
                    const std::string& name,
                    const std::string& failed_step,
                    int steps,
                    double w_steady = 0,
                    double u1_steady = 0,
                    double u2_steady = 0) {
  const fs::path path = dir / (name + ".toml");
  std::ofstream f(path);
  f << "[contact]\nradius_1_m = 0.01119\nradius_2_m = 0.03669\n"
    << "youngs_modulus_1_pa = 117e9\npoisson_ratio_1 = 0.34\n"
    << "youngs_modulus_2_pa = 117e9\npoisson_ratio_2 = 0.34\n"
    << "density_1_kg_m3 = 7890.0\ndensity_2_kg_m3 = 7890.0\n"
    << "conductivity_1_w_mk = 55.0\nconductivity_2_w_mk = 55.0\n"
    << "heat_capacity_1_j_kgk = 375.0\nheat_capacity_2_j_kgk = 375.0\n";
  if (steps > 0) {
    const int n = static_cast<int>(std::size(kTime));
    f << "speed_1_m_s = " << kU1[0] << "\nspeed_2_m_s = " << kU2[0]
      << "\nload_n_per_m = " << kLoad[0] << "\ntime_s = " << Table(kTime, n)
      << "\nload_table_n_per_m = " << Table(kLoad, n) << "\nspeed_1_table_m_s = " << Table(kU1, n)
      << "\nspeed_2_table_m_s = " << Table(kU2, n) << "\nsteps = " << steps << "\n";
  } else {
    char buf[160];
    std::snprintf(buf, sizeof buf,
                  "speed_1_m_s = %.17g\nspeed_2_m_s = %.17g\nload_n_per_m = %.17g\n", u1_steady,
                  u2_steady, w_steady);
    f << buf;
  }
  f << "[lubricant]\nname = \"sae40\"\ninlet_temperature_k = 313.15\n"
    << "[effects]\nthermal = true\n"
    << "[numerics]\ngrid_points = 1025\nfailed_step = \"" << failed_step << "\"\n";
  return path.string();
}

ContactRunResult RunCase(const std::string& case_path, const fs::path& dir) {
  ContactRunOptions o;
  o.quiet = true;
  o.output_dir = dir.string();
  return RunContactCase(case_path, o);
}

// The index of a study over failed_step on the case across B (`tehl sweep`): the "stop" scene
// is not converged, the "steady_restart" scene is ok with one restarted step, and the sweep's
// summary says so.
TEST(StepRestart, AStudyIndexCountsTheRestartedSteps) {
  const fs::path dir = testing::ScratchPath("tehl_step_restart", "study");
  fs::create_directories(dir);
  AcrossB(dir, "base", "stop", 12);
  const fs::path study = dir / "failed_step.toml";
  std::ofstream(study) << "[study]\nbase = \"base.toml\"\noutput = \"" << (dir / "out").string()
                       << "\"\n[[vary]]\nkey = \"numerics.failed_step\"\n"
                       << "values = [\"stop\", \"steady_restart\"]\n";
  const testing::RunResult run = testing::RunTehl("sweep -q -j 2 '" + study.string() + "'");
  ASSERT_TRUE(run.exited);
  EXPECT_EQ(run.exit_code, 1) << run.err;  // the "stop" scene did not converge
  EXPECT_NE(run.out.find("2 scenes: 1 ok, 1 not converged"), std::string::npos) << run.out;
  EXPECT_NE(run.out.find("note: 1 scene(s) have time steps that did not converge"),
            std::string::npos)
      << run.out;
  const auto cells = testing::ReadCsvCells((dir / "out" / "index.csv").string());
  ASSERT_EQ(cells.size(), 3u);
  auto col = [&](const std::string& name) {
    const auto it = std::find(cells[0].begin(), cells[0].end(), name);
    EXPECT_NE(it, cells[0].end()) << name;
    return static_cast<size_t>(it - cells[0].begin());
  };
  const size_t status = col("status"), restarts = col("steady_restarts");
  EXPECT_EQ(cells[1][status], "not_converged");
  EXPECT_EQ(std::stod(cells[1][restarts]), 0.0);
  EXPECT_EQ(cells[2][status], "ok");
  EXPECT_EQ(std::stod(cells[2][restarts]), 1.0);
  fs::remove_all(dir);
}

int FirstRestart(const ContactRunResult& r) {
  for (size_t k = 0; k < r.steps.size(); ++k)
    if (r.steps[k].restarted()) return static_cast<int>(k);
  return -1;
}

TEST(StepRestart, AFailedStepIsReplacedByTheSteadyFilmAndTheRunGoesOn) {
  const fs::path dir = testing::ScratchPath("tehl_step_restart", "across_b");
  fs::create_directories(dir);

  // "stop": the run ends at the failed step, nothing is flagged as restarted.
  const ContactRunResult stopped = RunCase(AcrossB(dir, "stop", "stop", 12), dir);
  ASSERT_FALSE(stopped.converged());
  const int failed = static_cast<int>(stopped.steps.size()) - 1;
  ASSERT_GE(failed, 3) << "the jump comes after the second table entry";
  const LineContactSolver::Summary& why = stopped.steps.back().summary;
  EXPECT_FALSE(why.usable());
  EXPECT_EQ(FirstRestart(stopped), -1);

  // The default: the same step fails, its film is the steady one, and every later step is a
  // converged transient step again.
  const ContactRunResult r = RunCase(AcrossB(dir, "restart", "steady_restart", 12), dir);
  ASSERT_TRUE(r.converged()) << r.steps.back().summary.message;
  ASSERT_EQ(r.steps.size(), 13u);
  ASSERT_EQ(FirstRestart(r), failed);
  const ContactStepRecord& k = r.steps[failed];
  EXPECT_EQ(k.restart_reason, ToString(why.termination) + ": " + why.message);
  EXPECT_TRUE(k.summary.usable());
  for (size_t j = failed + 1; j < r.steps.size(); ++j)
    EXPECT_TRUE(r.steps[j].summary.usable() && !r.steps[j].restarted()) << "step " << j;

  // The steps CSV flags that row, and only it.
  const auto cells = testing::ReadCsvCells(r.history_csv);
  ASSERT_EQ(cells.size(), r.steps.size() + 1);
  const auto col = std::find(cells[0].begin(), cells[0].end(), "steady_restart") - cells[0].begin();
  ASSERT_LT(static_cast<size_t>(col), cells[0].size());
  for (size_t j = 0; j < r.steps.size(); ++j)
    EXPECT_EQ(std::stod(cells[j + 1][col]), static_cast<int>(j) == failed ? 1.0 : 0.0) << j;

  // The restarted row is the steady film at its time: a steady run under the same conditions
  // gives the same film up to the thermal coupling's tolerance (it stops at 0.01 K per
  // iteration; with beta = 0.046 1/K of SAE 40 and h ~ eta^0.7, 0.01 K moves h by about
  // 3e-4, and T_max by that 0.01 K give or take a few iterations' worth).
  const ContactRunResult steady =
      RunCase(AcrossB(dir, "steady", "steady_restart", 0, k.load_n_per_m, k.u1_m_s, k.u2_m_s), dir);
  ASSERT_TRUE(steady.converged());
  const ContactStepRecord& s = steady.steps.back();
  EXPECT_NEAR(k.h_c_m / s.h_c_m, 1.0, 1e-3);
  EXPECT_NEAR(k.h_min_m / s.h_min_m, 1.0, 1e-3);
  EXPECT_NEAR(k.p_max_pa / s.p_max_pa, 1.0, 1e-3);
  EXPECT_NEAR(k.t_max_k, s.t_max_k, 0.1);
  std::printf(
      "failed step %d (t = %.4g s): restarted h_c %.6g m, T_max %.3f K; steady h_c %.6g m, "
      "T_max %.3f K; next step h_c %.6g m\n",
      failed, k.time_s, k.h_c_m, k.t_max_k, s.h_c_m, s.t_max_k, r.steps[failed + 1].h_c_m);
  fs::remove_all(dir);
}

// failed_step = "steady_restart_or_skip": a time step whose steady film fails too is left
// failed and the run goes on from the last converged film. Steel discs (R1 = R2 = 20 mm,
// SAE 40, isothermal, 257 nodes, 4 steps of 0.1 ms) at 100 kN/m and 1 m/s, with a load table
// that puts 30 MN/m (p_H about 10 GPa, under the b <= 0.2 R limit of the case reader) at the
// times of the steps listed in `overloaded`: neither the transient step nor the steady film
// (from the state before it, nor cold) converges there.
std::string Overloaded(const fs::path& dir,
                       const std::string& failed_step,
                       const std::vector<int>& overloaded) {
  std::string loads;
  for (int k = 0; k <= 4; ++k) {
    const bool heavy = std::find(overloaded.begin(), overloaded.end(), k) != overloaded.end();
    loads += std::string(k ? ", " : "") + (heavy ? "3.0e7" : "1.0e5");
  }
  const fs::path path =
      dir / ("overloaded_" + failed_step + std::to_string(overloaded.size()) + ".toml");
  std::ofstream(path) << "[contact]\nradius_1_m = 0.02\nradius_2_m = 0.02\n"
                      << "youngs_modulus_1_pa = 210e9\npoisson_ratio_1 = 0.3\n"
                      << "youngs_modulus_2_pa = 210e9\npoisson_ratio_2 = 0.3\n"
                      << "speed_1_m_s = 1.0\nspeed_2_m_s = 1.0\nload_n_per_m = 1.0e5\n"
                      << "time_s = [0, 1e-4, 2e-4, 3e-4, 4e-4]\nload_table_n_per_m = [" << loads
                      << "]\nsteps = 4\n[lubricant]\nname = \"sae40\"\n"
                      << "[numerics]\ngrid_points = 257\nfailed_step = \"" << failed_step << "\"\n";
  return path.string();
}

TEST(StepRestart, SkippingLeavesAStepWhoseSteadyFilmFailsTooAndGoesOn) {
  const fs::path dir = testing::ScratchPath("tehl_step_restart", "skip");
  fs::create_directories(dir);
  // "steady_restart" stops at step 2 and says how to go on.
  const ContactRunResult stopped = RunCase(Overloaded(dir, "steady_restart", {2}), dir);
  ASSERT_EQ(stopped.steps.size(), 3u);
  EXPECT_FALSE(stopped.steps[2].summary.usable());
  EXPECT_NE(stopped.steps[2].summary.message.find("steady_restart_or_skip"), std::string::npos)
      << stopped.steps[2].summary.message;

  const std::string skipping = Overloaded(dir, "steady_restart_or_skip", {2});
  const ContactRunResult r = RunCase(skipping, dir);
  ASSERT_EQ(r.steps.size(), 5u);
  EXPECT_FALSE(r.converged());
  EXPECT_EQ(r.Restarts(), 0);
  for (size_t k = 0; k < r.steps.size(); ++k)
    EXPECT_EQ(r.steps[k].summary.usable(), k != 2)
        << "step " << k << ": " << r.steps[k].summary.message;
  // Steps 3 and 4 go on from the film of step 1, under the same conditions (100 kN/m, 1 m/s,
  // a steady film since step 0): the same film, already converged.
  EXPECT_NEAR(r.steps[3].h_c_m / r.steps[1].h_c_m, 1.0, 1e-9);
  EXPECT_NEAR(r.steps[4].p_max_pa / r.steps[1].p_max_pa, 1.0, 1e-9);
  EXPECT_EQ(r.steps[2].restart_reason, "");
  // The failed row holds the film the step was left with: the solver's ladder of 1, 2 and 4
  // substeps reached the first quarter of the 300-fold load rise, 1e5 + (3e7 - 1e5) / 4 =
  // 7.575e6 N/m, and failed on the second. Its load error is that film's against the step's
  // load, 1 - 7.575e6 / 3e7 = 0.7475 (a load error of 0 once said the row carried its load).
  EXPECT_NEAR(r.steps[2].summary.load_error, 0.7475, 1e-4);
  EXPECT_GT(r.steps[2].p_max_pa, 5 * r.steps[1].p_max_pa);  // not step 1's film
  // The steps CSV says which row failed.
  const auto cells = testing::ReadCsvCells(r.history_csv);
  ASSERT_EQ(cells.size(), 6u);
  const auto col = std::find(cells[0].begin(), cells[0].end(), "termination") - cells[0].begin();
  ASSERT_LT(static_cast<size_t>(col), cells[0].size());
  for (size_t k = 0; k < r.steps.size(); ++k)
    EXPECT_EQ(cells[k + 1][col] == "converged", k != 2) << k << ": " << cells[k + 1][col];
  // `tehl run`: not converged (exit 1), naming the failed step; the final film is reported.
  const testing::RunResult run =
      testing::RunTehl("run -q -o '" + dir.string() + "' '" + skipping + "'");
  ASSERT_TRUE(run.exited);
  EXPECT_EQ(run.exit_code, 1) << run.err;
  EXPECT_NE(run.err.find("step 2 (t = 0.0002 s) did not converge"), std::string::npos) << run.err;
  EXPECT_NE(run.out.find("h_c = "), std::string::npos) << run.out;

  // Three failed steps in a row end the run there.
  const ContactRunResult three = RunCase(Overloaded(dir, "steady_restart_or_skip", {1, 2, 3}), dir);
  ASSERT_EQ(three.steps.size(), 4u);
  for (size_t k = 1; k < 4; ++k) EXPECT_FALSE(three.steps[k].summary.usable()) << k;
  const testing::RunResult run3 =
      testing::RunTehl("run -q -o '" + dir.string() + "' '" +
                       Overloaded(dir, "steady_restart_or_skip", {1, 2, 3}) + "'");
  EXPECT_EQ(run3.exit_code, 1) << run3.err;
  EXPECT_NE(run3.err.find("3 steps did not converge (step 1 (t = 0.0001 s), step 2"),
            std::string::npos)
      << run3.err;
  fs::remove_all(dir);
}

// The thermal seed 004 cycle on 513 nodes with 600 steps (cases/seed004_sae40.toml with
// [numerics] steps = 600): one step after B does not converge (docs/thermal.md, "The seed 004
// cycle at full resolution"). `tehl run` completes the cycle (exit 0), notes the restart, and
// every result names the restarted step: /solver/steady_restart and /solver/restart_reason,
// the root's steady_restarts, the CSV's steady_restart column. With failed_step = "stop" the
// same cycle ends at that step.
std::string SeedCycle(const fs::path& dir, const std::string& name, const std::string& failed) {
  std::ifstream in(std::string(TEHL_SOURCE_DIR) + "/cases/seed004_sae40.toml");
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const std::string grid = "grid_points = 513\n";
  const size_t at = text.find(grid);
  EXPECT_NE(at, std::string::npos) << "the seed 004 case sets grid_points = 513";
  text.replace(at, grid.size(), grid + "steps = 600\nfailed_step = \"" + failed + "\"\n");
  const fs::path path = dir / (name + ".toml");
  std::ofstream(path) << text;
  return path.string();
}

TEST(StepRestart, ACycleNamesItsRestartedStepInEveryResult) {
  const fs::path dir = testing::ScratchPath("tehl_step_restart", "cycle");
  fs::create_directories(dir);
  const testing::RunResult run = testing::RunTehl(
      "run -q '" + SeedCycle(dir, "restart", "steady_restart") + "' -o '" + dir.string() + "'");
  ASSERT_TRUE(run.exited);
  EXPECT_EQ(run.exit_code, 0) << run.err;
  EXPECT_NE(run.out.find("time steps did not converge; each such film is the steady one"),
            std::string::npos)
      << run.out;

  const hid_t f = H5Fopen((dir / "restart.h5").string().c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  ASSERT_GE(f, 0);
  EXPECT_EQ(testing::Hdf5StringAttribute(f, "/", "converged"), "true");
  const std::vector<double> flag = testing::Hdf5Doubles(f, "/solver/steady_restart");
  const std::vector<std::string> reason = testing::Hdf5Strings(f, "/solver/restart_reason");
  const std::vector<std::string> term = testing::Hdf5Strings(f, "/solver/termination");
  double restarts_attr = -1;
  {
    const hid_t a = H5Aopen_by_name(f, "/", "steady_restarts", H5P_DEFAULT, H5P_DEFAULT);
    ASSERT_GE(a, 0);
    H5Aread(a, H5T_NATIVE_DOUBLE, &restarts_attr);
    H5Aclose(a);
  }
  H5Fclose(f);
  ASSERT_EQ(flag.size(), 601u);
  ASSERT_EQ(reason.size(), flag.size());
  int restarts = 0, first = -1;
  for (size_t k = 0; k < flag.size(); ++k) {
    EXPECT_EQ(term[k], "converged") << k;
    EXPECT_EQ(reason[k].empty(), flag[k] == 0.0) << k << ": " << reason[k];
    if (flag[k] == 0.0) continue;
    ++restarts;
    if (first < 0) first = static_cast<int>(k);
    EXPECT_NE(reason[k].find("coupling"), std::string::npos) << reason[k];
  }
  EXPECT_GE(restarts, 1);
  EXPECT_EQ(restarts_attr, restarts);
  const auto cells = testing::ReadCsvCells((dir / "restart_cycle.csv").string());
  ASSERT_EQ(cells.size(), flag.size() + 1);
  const auto column = std::find(cells[0].begin(), cells[0].end(), "steady_restart");
  ASSERT_NE(column, cells[0].end());
  const size_t j = column - cells[0].begin();
  for (size_t k = 0; k < flag.size(); ++k) EXPECT_EQ(std::stod(cells[k + 1][j]), flag[k]) << k;

  // `tehl plot` lists the restarted step and marks it on the figures along the path.
  const testing::RunResult plot = testing::RunTehl("plot '" + (dir / "restart.h5").string() +
                                                   "' -o '" + (dir / "png").string() + "'");
  ASSERT_TRUE(plot.exited);
  EXPECT_EQ(plot.exit_code, 0) << plot.err;
  EXPECT_NE(plot.err.find(std::to_string(restarts) +
                          " step(s) did not converge and show the steady film"),
            std::string::npos)
      << plot.err;
  EXPECT_TRUE(fs::exists(dir / "png" / "restart_thermal.png"));

  MeshCycleRunOptions o;
  o.quiet = true;
  o.write_files = false;
  const MeshCycleResult stopped = RunMeshCycle(SeedCycle(dir, "stop", "stop"), o);
  EXPECT_FALSE(stopped.converged());
  EXPECT_EQ(static_cast<int>(stopped.steps.size()) - 1, first);
  EXPECT_EQ(stopped.Restarts(), 0);
  std::printf("restarted steps: %d, the first at step %d; \"stop\" ends at step %zu\n", restarts,
              first, stopped.steps.size() - 1);
  fs::remove_all(dir);
}

#else
// The thermal seed 004 cycle itself on 2049 nodes (150 steps, about 70 s): it stopped at step
// 70, just after B, before failed_step existed (docs/thermal.md, "The seed 004 cycle at full
// resolution"); now it runs to E with the failed step restarted, and every other step is a
// converged transient step.
TEST(StepRestart, Seed004ThermalCycleOn2049NodesRunsToE) {
  const fs::path dir = testing::ScratchPath("tehl_step_restart", "seed2049");
  fs::create_directories(dir);
  std::ifstream in(std::string(TEHL_SOURCE_DIR) + "/cases/seed004_sae40.toml");
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const std::string grid = "grid_points = 513";
  const size_t at = text.find(grid);
  ASSERT_NE(at, std::string::npos);
  text.replace(at, grid.size(), "grid_points = 2049");
  const fs::path path = dir / "seed2049.toml";
  std::ofstream(path) << text;
  MeshCycleRunOptions o;
  o.quiet = true;
  o.write_files = false;
  const MeshCycleResult r = RunMeshCycle(path.string(), o);
  ASSERT_TRUE(r.converged()) << r.steps.back().summary.message;
  EXPECT_GE(r.Restarts(), 1);
  EXPECT_LE(r.Restarts(), 3);
  for (size_t k = 0; k < r.steps.size(); ++k)
    if (r.steps[k].restarted()) {
      EXPECT_GT(r.steps[k].s_m, r.s_b_m) << "a restart before B, at step " << k;
      std::printf("step %zu (s = %.4g mm) restarted: %s\n", k, r.steps[k].s_m * 1e3,
                  r.steps[k].restart_reason.c_str());
    }
  fs::remove_all(dir);
}
#endif

}  // namespace
}  // namespace tehl
