// `tehl sweep` end to end at reduced resolution (seed 004 SAE 40 case, 129 nodes, 40 steps):
// the index against the scenes run one by one (and rebuilt unchanged by --resume), a scene
// that does not converge recorded while the others complete, and --resume after the sweep was
// killed.
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <fcntl.h>

#include <chrono>
#include <filesystem>
#include <map>
#include <sstream>
#include <string>
#include <thread>

#include "regression/sweep_support.hpp"
#include "support/csv_cells.hpp"
#include "tehl/scene/mesh_cycle_scene.hpp"
#include "unit/cli/run_tehl.hpp"

namespace tehl {
namespace {
namespace fs = std::filesystem;
using testing::ReadIndex;

std::string OutDir(const std::string& study) {
  return (fs::path(study).parent_path() / "out").string();
}

using testing::CsvCells;

TEST(Sweep, IndexEqualsTheScenesRunOneByOne) {
  const std::string study = testing::ReducedStudy(
      "sweep_index", "[[vary]]\nkey = \"operating.power_w\"\nvalues = [5000.0, 10000.0, 15000.0]\n");
  const std::string out = OutDir(study);
  const testing::RunResult r = testing::RunTehl("sweep -j 2 -q -o '" + out + "' '" + study + "'");
  ASSERT_TRUE(r.exited) << r.err;
  ASSERT_EQ(r.exit_code, 0) << r.out << r.err;
  const testing::IndexTable t = ReadIndex(out + "/index.h5");
  ASSERT_EQ(t.scene.size(), 3u);
  for (int i = 0; i < 3; ++i) {
    EXPECT_EQ(t.status[i], "ok");
    EXPECT_EQ(t.computed[i], 1.0);
    // Reference: the same scene file run by the library in this process, summarized by
    // definition (docs/studies.md): min of h_min, h_c at PitchStep(), min of h_c, max of p_max.
    MeshCycleRunOptions o;
    o.quiet = true;
    o.write_files = false;
    char name[32];
    std::snprintf(name, sizeof name, "scene_%04d.toml", i);
    const MeshCycleResult m = RunMeshCycle(out + "/scenes/" + name, o);
    ASSERT_TRUE(m.converged());
    double h_min = 1e300, h_c_min = 1e300, p_max = 0;
    for (const auto& k : m.steps) {
      h_min = std::min(h_min, k.h_min_m);
      h_c_min = std::min(h_c_min, k.h_c_m);
      p_max = std::max(p_max, k.p_max_pa);
    }
    const double rel = 1e-12;
    EXPECT_NEAR(t.h_min_min[i], h_min, rel * h_min) << name;
    EXPECT_NEAR(t.h_c_pitch[i], m.steps[m.PitchStep()].h_c_m, rel * h_min) << name;
    EXPECT_NEAR(t.h_c_min[i], h_c_min, rel * h_c_min) << name;
    EXPECT_NEAR(t.p_max_max[i], p_max, rel * p_max) << name;
    EXPECT_TRUE(fs::exists(t.result[i])) << t.result[i];
  }
  // Seed 004 conclusion 4.3: more load, thinner film and higher pressure.
  EXPECT_GT(t.h_min_min[0], t.h_min_min[2]);
  EXPECT_LT(t.p_max_max[0], t.p_max_max[2]);
  // The CSV index: a header and one row per scene.
  const std::string csv = testing::ReadAll(out + "/index.csv");
  EXPECT_EQ(std::count(csv.begin(), csv.end(), '\n'), 4) << csv;
  EXPECT_EQ(csv.rfind("scene,operating.power_w,h_min_min_m", 0), 0u) << csv;
  // The grid of each scene: the reduced case's grid_points (the grid of the mesh cycle above).
  const auto rows = CsvCells(csv);
  const size_t ig = std::find(rows[0].begin(), rows[0].end(), "grid_points") - rows[0].begin();
  ASSERT_LT(ig, rows[0].size());
  MeshCycleRunOptions quiet;
  quiet.quiet = true;
  quiet.write_files = false;
  const MeshCycleResult first = RunMeshCycle(out + "/scenes/scene_0000.toml", quiet);
  for (size_t k = 1; k < rows.size(); ++k)
    EXPECT_EQ(rows[k][ig], std::to_string(first.x_m.size())) << k;

  // --resume over the finished sweep rebuilds every row from the result files: each column
  // equals the fresh row (wall time included: both are the HDF5 wall_time attribute), except
  // `computed`, 1 then 0.
  const testing::RunResult again =
      testing::RunTehl("sweep --resume -j 2 -q -o '" + out + "' '" + study + "'");
  ASSERT_TRUE(again.exited) << again.err;
  ASSERT_EQ(again.exit_code, 0) << again.out << again.err;
  const auto fresh = CsvCells(csv), resumed = CsvCells(testing::ReadAll(out + "/index.csv"));
  ASSERT_EQ(resumed.size(), fresh.size());
  ASSERT_EQ(resumed[0], fresh[0]);
  const auto& head = fresh[0];
  const size_t ic = std::find(head.begin(), head.end(), "computed") - head.begin();
  ASSERT_LT(ic, head.size());
  for (size_t k = 1; k < fresh.size(); ++k) {
    ASSERT_EQ(resumed[k].size(), head.size()) << k;
    EXPECT_EQ(fresh[k][ic], "1") << k;
    EXPECT_EQ(resumed[k][ic], "0") << k;
    for (size_t j = 0; j < head.size(); ++j)
      if (j != ic) {
        EXPECT_EQ(resumed[k][j], fresh[k][j]) << "row " << k << " column " << head[j];
      }
  }
}

TEST(Sweep, SceneThatDoesNotConvergeIsRecordedAndTheOthersComplete) {
  // One Newton iteration cannot solve the steady film at A: scene 1 ends not converged.
  const std::string study = testing::ReducedStudy(
      "sweep_fail", "[[vary]]\nkey = \"numerics.max_newton_iterations\"\nvalues = [100, 1, 100]\n");
  const std::string out = OutDir(study);
  const testing::RunResult r = testing::RunTehl("sweep -j 2 -q -o '" + out + "' '" + study + "'");
  ASSERT_TRUE(r.exited) << r.err;
  EXPECT_EQ(r.exit_code, 1) << r.out << r.err;  // a scene not usable: exit 1
  const testing::IndexTable t = ReadIndex(out + "/index.h5");
  ASSERT_EQ(t.status.size(), 3u);
  EXPECT_EQ(t.status[0], "ok");
  EXPECT_EQ(t.status[1], "not_converged");
  EXPECT_EQ(t.status[2], "ok");
  EXPECT_GT(t.h_min_min[0], 0.0);
  EXPECT_EQ(t.h_min_min[0], t.h_min_min[2]);  // the same case, twice
}

// Modification time of a file [ns since the epoch].
long long MtimeNs(const std::string& path) {
  struct stat st {};
  if (stat(path.c_str(), &st) != 0) return -1;
  return static_cast<long long>(st.st_mtim.tv_sec) * 1000000000LL + st.st_mtim.tv_nsec;
}

// --resume in the folder of another study (same scene names, other scenes) must not read the
// other study's results back as its own: each result keeps the fingerprint of its scene's
// case file, and a result of another scene is run again. The index then equals that of the
// study run in a folder of its own.
TEST(Sweep, ResumeInTheFolderOfAnotherStudyRunsItsOwnScenes) {
  const std::string first = testing::ReducedStudy(
      "sweep_other_a", "[[vary]]\nkey = \"operating.power_w\"\nvalues = [10000.0]\n");
  const std::string second = testing::ReducedStudy(
      "sweep_other_b", "[[vary]]\nkey = \"operating.power_w\"\nvalues = [4000.0]\n");
  const std::string shared = OutDir(first), own = OutDir(second);
  ASSERT_EQ(testing::RunTehl("sweep -q -o '" + shared + "' '" + first + "'").exit_code, 0);
  const testing::RunResult r =
      testing::RunTehl("sweep --resume -q -o '" + shared + "' '" + second + "'");
  ASSERT_EQ(r.exit_code, 0) << r.out << r.err;
  ASSERT_EQ(testing::RunTehl("sweep -q -o '" + own + "' '" + second + "'").exit_code, 0);
  const testing::IndexTable resumed = ReadIndex(shared + "/index.h5");
  const testing::IndexTable fresh = ReadIndex(own + "/index.h5");
  ASSERT_EQ(resumed.scene.size(), 1u);
  ASSERT_EQ(fresh.scene.size(), 1u);
  EXPECT_EQ(resumed.computed[0], 1.0);
  EXPECT_NEAR(resumed.h_min_min[0], fresh.h_min_min[0], 1e-9 * fresh.h_min_min[0]);
  // A second --resume of the same study reuses its own result.
  ASSERT_EQ(testing::RunTehl("sweep --resume -q -o '" + shared + "' '" + second + "'").exit_code,
            0);
  EXPECT_EQ(ReadIndex(shared + "/index.h5").computed[0], 0.0);
}

TEST(Sweep, ResumeAfterKillRunsOnlyTheUnfinishedScenes) {
  const std::string study = testing::ReducedStudy(
      "sweep_resume",
      "[[vary]]\nkey = \"operating.power_w\"\nvalues = [4000.0, 6000.0, 8000.0, 10000.0]\n");
  const std::string out = OutDir(study);
  // A sweep on one thread, killed (SIGKILL) as soon as its first result file appears.
  const pid_t pid = fork();
  ASSERT_GE(pid, 0);
  if (pid == 0) {
    const int devnull = open("/dev/null", O_WRONLY);
    dup2(devnull, 1);
    dup2(devnull, 2);
    execl(TEHL_BINARY, "tehl", "sweep", "-j", "1", "-q", "-o", out.c_str(), study.c_str(),
          static_cast<char*>(nullptr));
    _exit(127);
  }
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(120);
  while (!fs::exists(out + "/scenes/scene_0000.h5") && std::chrono::steady_clock::now() < deadline)
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  kill(pid, SIGKILL);
  int status = 0;
  waitpid(pid, &status, 0);
  ASSERT_TRUE(WIFSIGNALED(status)) << "the sweep ended before it could be killed";
  ASSERT_FALSE(fs::exists(out + "/index.h5"));  // the index comes only at the end

  std::map<int, long long> finished;  // scene -> mtime of its result before the rerun
  for (int i = 0; i < 4; ++i) {
    const std::string h5 = out + "/scenes/scene_000" + std::to_string(i) + ".h5";
    if (fs::exists(h5)) finished[i] = MtimeNs(h5);
  }
  ASSERT_GE(finished.size(), 1u);
  ASSERT_LT(finished.size(), 4u);

  const testing::RunResult r =
      testing::RunTehl("sweep --resume -j 2 -q -o '" + out + "' '" + study + "'");
  ASSERT_TRUE(r.exited) << r.err;
  ASSERT_EQ(r.exit_code, 0) << r.out << r.err;
  const testing::IndexTable t = ReadIndex(out + "/index.h5");
  ASSERT_EQ(t.scene.size(), 4u);
  for (int i = 0; i < 4; ++i) {
    EXPECT_EQ(t.status[i], "ok") << i;
    const bool was_done = finished.count(i) > 0;
    EXPECT_EQ(t.computed[i], was_done ? 0.0 : 1.0) << "scene " << i;
    if (was_done) {
      EXPECT_EQ(MtimeNs(t.result[i]), finished[i]) << "scene " << i << " rerun";
    }
    if (i > 0) {
      EXPECT_LT(t.h_min_min[i], t.h_min_min[i - 1]) << "load rises with the scene";
    }
  }
}

}  // namespace
}  // namespace tehl
