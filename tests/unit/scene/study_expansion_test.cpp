// Study files expand into scenes: grid and zip counts, ranges, overrides applied to the base
// case, every scene a valid case, problems at the study file's line (docs/studies.md); the
// scene checks leave nothing in the temporary folder, even when they fail.
#include <gtest/gtest.h>
#include <sys/resource.h>
#include <unistd.h>

#include <cerrno>
#include <cmath>
#include <csignal>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include "base/schema.hpp"
#include "scene/case_reader.hpp"
#include "support/scratch_path.hpp"
#include "tehl/error.hpp"
#include "tehl/scene/case_schema.hpp"
#include "tehl/scene/study.hpp"

namespace tehl {
namespace {
namespace fs = std::filesystem;

const std::string kBase = std::string(TEHL_SOURCE_DIR) + "/cases/seed004_sae40.toml";

std::string WriteStudy(const std::string& name, const std::string& body) {
  const fs::path dir = testing::ScratchPath("tehl_study", "dir");
  fs::create_directories(dir);
  const std::string path = (dir / name).string();
  std::ofstream(path) << "[study]\nbase = \"" << kBase << "\"\noutput = \"" << (dir / "out").string()
                      << "\"\n" << body;
  return path;
}

internal::Document SceneDoc(const StudyScene& s) {
  return internal::Document::ReadString(CaseSchema(), s.case_text, s.name);
}

TEST(StudyExpansion, GridIsTheCartesianProductWithTheLastEntryFastest) {
  const Study s = ReadStudy(WriteStudy("grid.toml",
                                       "[[vary]]\nkey = \"operating.power_w\"\n"
                                       "values = [5000, 10000]\n"
                                       "[[vary]]\nkey = \"numerics.grid_points\"\n"
                                       "values = [129, 257, 513]\n"));
  ASSERT_EQ(s.scenes.size(), 6u);  // 2 x 3
  EXPECT_EQ(s.mode, "grid");
  for (int i = 0; i < 6; ++i) {
    const internal::Document d = SceneDoc(s.scenes[i]);
    EXPECT_TRUE(d.problems().empty()) << s.scenes[i].case_text;
    EXPECT_DOUBLE_EQ(d.Real("operating", "power_w"), i < 3 ? 5000.0 : 10000.0) << i;
    EXPECT_EQ(d.Int("numerics", "grid_points"), std::vector<int>({129, 257, 513})[i % 3]) << i;
    // The rest is the base case: the seed 004 pair, 35/105 teeth, 1000 rpm.
    EXPECT_EQ(d.Int("gear.pinion", "teeth"), 35);
    EXPECT_EQ(d.Int("gear.wheel", "teeth"), 105);
    EXPECT_DOUBLE_EQ(d.Real("operating", "pinion_speed_rpm"), 1000.0);
    EXPECT_EQ(d.String("output", "name"), s.scenes[i].name);
  }
  EXPECT_EQ(s.scenes[5].name, "scene_0005");
}

TEST(StudyExpansion, ZipTakesTheListsInParallel) {
  const Study s = ReadStudy(WriteStudy("zip.toml",
                                       "mode = \"zip\"\n"  // still in [study]
                                       "[[vary]]\nkey = \"operating.power_w\"\n"
                                       "values = [5000.0, 10000.0, 20000.0]\nlabel = \"P\"\n"
                                       "[[vary]]\nkey = \"operating.pinion_speed_rpm\"\n"
                                       "values = [500.0, 1000.0, 2000.0]\n"));
  ASSERT_EQ(s.scenes.size(), 3u);
  EXPECT_EQ(s.parameters[0].label, "P");
  for (int i = 0; i < 3; ++i) {
    const internal::Document d = SceneDoc(s.scenes[i]);
    EXPECT_DOUBLE_EQ(d.Real("operating", "power_w"), std::vector<double>({5e3, 1e4, 2e4})[i]);
    EXPECT_DOUBLE_EQ(d.Real("operating", "pinion_speed_rpm"),
                     std::vector<double>({500, 1000, 2000})[i]);
  }
}

TEST(StudyExpansion, LinearAndLogarithmicRangesHitBothEnds) {
  const Study s = ReadStudy(WriteStudy("ranges.toml",
                                       "mode = \"zip\"\n"
                                       "[[vary]]\nkey = \"operating.power_w\"\n"
                                       "from = 1000.0\nto = 3000.0\ncount = 3\n"
                                       "[[vary]]\nkey = \"lubricant.inlet_temperature_k\"\n"
                                       "from = 300.0\nto = 363.0\ncount = 3\nlog = true\n"));
  ASSERT_EQ(s.scenes.size(), 3u);
  // Linear: 1000, 2000, 3000. Logarithmic: the middle value is the geometric mean
  // sqrt(300 * 363) = 330 (exactly: 300 * 363 = 108900 = 330^2).
  const std::vector<double> p = s.parameters[0].values_number, t = s.parameters[1].values_number;
  EXPECT_NEAR(p[1], 2000.0, 1e-12 * 2000.0);
  EXPECT_DOUBLE_EQ(p[2], 3000.0);
  EXPECT_NEAR(t[1], 330.0, 1e-12 * 330.0);
  EXPECT_DOUBLE_EQ(t[0], 300.0);
  EXPECT_DOUBLE_EQ(t[2], 363.0);
}

// Both ends of a range are the numbers written, bit for bit: exp(log(5e4)) is
// 50000.00000000001, which a script filtering the index by value would not find.
TEST(StudyExpansion, RangeEndsAreExactlyAsWritten) {
  const Study s = ReadStudy(WriteStudy("log_ends.toml",
                                       "[[vary]]\nkey = \"operating.power_w\"\n"
                                       "from = 5e4\nto = 2e5\ncount = 3\nlog = true\n"));
  const std::vector<double>& p = s.parameters[0].values_number;
  ASSERT_EQ(p.size(), 3u);
  EXPECT_EQ(p.front(), 5e4);
  EXPECT_EQ(p.back(), 2e5);
  EXPECT_EQ(s.parameters[0].values_toml.front(), "50000.0");
}

TEST(StudyExpansion, StringValuesAndLubricantNamesResolveForTheScene) {
  const Study s = ReadStudy(WriteStudy("oils.toml",
                                       "[[vary]]\nkey = \"lubricant.name\"\n"
                                       "values = [\"sae40\", \"sae90\"]\n"));
  ASSERT_EQ(s.scenes.size(), 2u);
  EXPECT_FALSE(s.parameters[0].numeric);
  WriteSceneFiles(s);
  for (int i = 0; i < 2; ++i) {
    // The scene file lives elsewhere than the base case: the lubricant is written as the
    // absolute path of the file the base case would have used, and the scene reads as is.
    const internal::Document d = internal::ReadCaseDocument(s.scenes[i].case_path);
    EXPECT_TRUE(d.problems().empty()) << (d.problems().empty() ? "" : d.problems()[0].ToString());
    const std::string name = d.String("lubricant", "name");
    EXPECT_TRUE(fs::path(name).is_absolute()) << name;
    EXPECT_EQ(fs::path(name).filename().string(), i == 0 ? "sae40.toml" : "sae90.toml");
  }
}

// The first InputProblem thrown by ReadStudy(path).
InputProblem FirstProblem(const std::string& path) {
  try {
    ReadStudy(path);
  } catch (const InputError& e) {
    return e.problems().at(0);
  }
  ADD_FAILURE() << "no InputError for " << path;
  return {};
}

TEST(StudyExpansion, UnknownCaseKeyIsReportedAtItsStudyLine) {
  // Lines: 1 [study], 2 base, 3 output, 4 [[vary]], 5 key.
  const std::string path = WriteStudy("unknown.toml",
                                      "[[vary]]\nkey = \"operating.power_kw\"\nvalues = [1.0]\n");
  const InputProblem p = FirstProblem(path);
  EXPECT_EQ(p.file, path);
  EXPECT_EQ(p.line, 5);
  EXPECT_EQ(p.key, "vary[1].key");
  EXPECT_NE(p.allowed.find("power_w"), std::string::npos) << p.allowed;
}

TEST(StudyExpansion, InvalidSceneIsReportedAtTheLineOfItsVaryEntry) {
  // Lines: 4 [[vary]], 5 key, 6 values. grid_points = 9 breaks the case rule: 0 (automatic) or
  // >= 17.
  const std::string path = WriteStudy(
      "bad_scene.toml", "[[vary]]\nkey = \"numerics.grid_points\"\nvalues = [129, 9]\n");
  const InputProblem p = FirstProblem(path);
  EXPECT_EQ(p.file, path);
  EXPECT_EQ(p.line, 6);
  EXPECT_EQ(p.key, "numerics.grid_points");
  EXPECT_EQ(p.value, "9");
  EXPECT_NE(p.rule.find("scene_0001"), std::string::npos) << p.rule;
}

TEST(StudyExpansion, CrossKeyConflictNamesTheVaryEntryOfTheSameSection) {
  // The base gives power_w; a torque on top gives the load twice: reported at the key line
  // of the [[vary]] entry in [operating] (line 5).
  const std::string path = WriteStudy(
      "twice.toml", "[[vary]]\nkey = \"operating.pinion_torque_nm\"\nvalues = [50.0]\n");
  const InputProblem p = FirstProblem(path);
  EXPECT_EQ(p.line, 5);
  EXPECT_EQ(p.key, "operating.pinion_torque_nm");
}

TEST(StudyExpansion, ZipListsOfUnequalLengthAreRejected) {
  const std::string path = WriteStudy("zip_bad.toml",
                                      "mode = \"zip\"\n[[vary]]\nkey = \"operating.power_w\"\n"
                                      "values = [1.0, 2.0]\n[[vary]]\n"
                                      "key = \"numerics.grid_points\"\nvalues = [129]\n");
  const InputProblem p = FirstProblem(path);
  EXPECT_EQ(p.line, 10);
  EXPECT_EQ(p.key, "vary[2].values");
}

// TMPDIR set to a fresh folder for the life of the object (the scene checks write there).
class ScratchTmpdir {
 public:
  ScratchTmpdir() : path_(testing::ScratchPath("tehl_study", "tmpdir")) {
    fs::create_directories(path_);
    if (const char* old = std::getenv("TMPDIR")) old_ = old;
    setenv("TMPDIR", path_.c_str(), 1);
  }
  ~ScratchTmpdir() {
    if (old_.empty())
      unsetenv("TMPDIR");
    else
      setenv("TMPDIR", old_.c_str(), 1);
  }
  const std::string& path() const { return path_; }

 private:
  std::string path_, old_;
};

TEST(StudyExpansion, TheSceneChecksLeaveNothingInTheTemporaryFolder) {
  const std::string study = WriteStudy(
      "tmp_clean.toml", "[[vary]]\nkey = \"operating.power_w\"\nvalues = [5000, 10000]\n");
  const ScratchTmpdir tmp;
  EXPECT_EQ(ReadStudy(study).scenes.size(), 2u);
  EXPECT_TRUE(fs::is_empty(tmp.path()));
}

// A scene file that cannot be written for its check (here: files limited to 64 bytes, as a full
// disk would) is a filesystem_error naming it, not made-up problems of the case, and the
// folder of the checks goes with it.
TEST(StudyExpansion, ASceneFileThatCannotBeWrittenIsAFilesystemErrorAndLeavesNoFolder) {
  const std::string study = WriteStudy(
      "tmp_full.toml", "[[vary]]\nkey = \"operating.power_w\"\nvalues = [5000, 10000]\n");
  const ScratchTmpdir tmp;
  rlimit old{};
  ASSERT_EQ(getrlimit(RLIMIT_FSIZE, &old), 0);
  rlimit small = old;
  small.rlim_cur = 64;
  const auto old_handler = std::signal(SIGXFSZ, SIG_IGN);  // EFBIG instead of the signal
  ASSERT_EQ(setrlimit(RLIMIT_FSIZE, &small), 0);
  std::string thrown;
  try {
    ReadStudy(study);
  } catch (const fs::filesystem_error& e) {
    thrown = "filesystem_error " + e.path1().string() + ": " + e.code().message();
    EXPECT_EQ(e.code().value(), EFBIG) << e.what();
    EXPECT_EQ(e.path1().filename().string(), "scene_0000.toml") << e.what();
  } catch (const std::exception& e) {
    thrown = std::string("other: ") + e.what();
  }
  setrlimit(RLIMIT_FSIZE, &old);
  std::signal(SIGXFSZ, old_handler);
  EXPECT_EQ(thrown.rfind("filesystem_error", 0), 0u) << thrown;
  EXPECT_TRUE(fs::is_empty(tmp.path()));
}

}  // namespace
}  // namespace tehl
