// The scene pool of a study: a scene's own failure is its row; an exception of the pool (a
// scene id out of range, the progress callback) reaches the caller once every thread is
// joined; a scene's fingerprint leaves no temporary file behind.
#include "tehl/scene/study_run.hpp"

#include <gtest/gtest.h>

#include <atomic>
#include <filesystem>
#include <stdexcept>
#include <string>

#include "support/scratch_path.hpp"

namespace tehl {
namespace {
namespace fs = std::filesystem;

// A contact study of `n` scenes in `dir` whose case files do not exist: each scene fails at once.
Study MissingScenes(const testing::ScratchDir& dir, int n) {
  Study s;
  s.gear = false;
  s.output_dir = dir.Path("out");
  fs::create_directories(s.ScenesDir());
  for (int i = 0; i < n; ++i) {
    StudyScene sc;
    sc.id = i;
    sc.name = "scene_000" + std::to_string(i);
    sc.case_path = (fs::path(s.ScenesDir()) / (sc.name + ".toml")).string();
    s.scenes.push_back(sc);
  }
  return s;
}

TEST(RunStudyScenes, ASceneThatFailsIsARowAndTheOthersGoOn) {
  const testing::ScratchDir dir("tehl_study_run");
  const Study s = MissingScenes(dir, 3);
  SweepOptions o;
  o.threads = 2;
  const std::vector<SceneRow> rows = RunStudyScenes(s, {0, 1, 2}, o);
  ASSERT_EQ(rows.size(), 3u);
  for (int i = 0; i < 3; ++i) {
    EXPECT_EQ(rows[i].scene, i);
    EXPECT_EQ(rows[i].status.rfind("failed", 0), 0u) << rows[i].status;
  }
}

TEST(RunStudyScenes, AnExceptionOfTheCallbackReachesTheCallerAfterTheThreadsAreJoined) {
  const testing::ScratchDir dir("tehl_study_run");
  const Study s = MissingScenes(dir, 4);
  SweepOptions o;
  o.threads = 2;
  std::atomic<int> calls{0};
  o.on_scene = [&](const SceneRow&, int, int) {
    ++calls;
    throw std::runtime_error("progress line not written");
  };
  try {
    RunStudyScenes(s, {0, 1, 2, 3}, o);
    FAIL() << "no exception";
  } catch (const std::runtime_error& e) {
    EXPECT_STREQ(e.what(), "progress line not written");
  }
  // After the first exception no thread takes another scene: at most one per thread.
  EXPECT_GE(calls.load(), 1);
  EXPECT_LE(calls.load(), 2);
}

TEST(RunStudyScenes, ASceneIdOutOfRangeIsAnErrorOfTheCaller) {
  const testing::ScratchDir dir("tehl_study_run");
  const Study s = MissingScenes(dir, 1);
  SweepOptions o;
  o.threads = 2;
  EXPECT_THROW(RunStudyScenes(s, {7, 0}, o), std::out_of_range);
  EXPECT_THROW(RunStudyScenes(s, {0, 7}, o), std::out_of_range);
}

// A folder under the fingerprint's name: the scene runs (and fails here) without it, and its
// temporary file goes.
TEST(RunStudyScene, AFingerprintThatCannotBeKeptLeavesNoTemporaryFile) {
  const testing::ScratchDir dir("tehl_study_run");
  const Study s = MissingScenes(dir, 1);
  const std::string fingerprint = s.ResultPath(s.scenes[0]) + ".case";
  fs::create_directories(fingerprint + "/inside");
  const SceneRow r = RunStudyScene(s, s.scenes[0], false);
  EXPECT_EQ(r.status.rfind("failed", 0), 0u) << r.status;
  EXPECT_TRUE(fs::is_directory(fingerprint + "/inside"));
  EXPECT_FALSE(fs::exists(fingerprint + ".part"));
}

}  // namespace
}  // namespace tehl
