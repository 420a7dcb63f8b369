// Every file of tests/malformed/ is rejected by the real program: exit code 2 (never a crash,
// never another code) and a message at the file, line and key named in the file's first
// line, "# ERROR <key> at line <n>: <what is wrong>" ("line -" for a problem without a line,
// such as a missing section).
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <ostream>
#include <regex>
#include <string>
#include <vector>

#include "unit/cli/run_tehl.hpp"

namespace tehl {
namespace {
namespace fs = std::filesystem;

struct MalformedFile {
  std::string kind;  // "case", "lubricant", "study" or "train"
  std::string path;  // absolute
};

std::vector<MalformedFile> Corpus() {
  std::vector<MalformedFile> files;
  for (const char* kind : {"case", "lubricant", "study", "train"}) {
    const fs::path dir = fs::path(TEHL_SOURCE_DIR) / "tests" / "malformed" / kind;
    if (!fs::is_directory(dir)) continue;
    for (const auto& e : fs::directory_iterator(dir))
      if (e.is_regular_file()) files.push_back({kind, e.path().string()});
  }
  std::sort(files.begin(), files.end(),
            [](const auto& a, const auto& b) { return a.path < b.path; });
  return files;
}

// Shown by GoogleTest instead of the bytes of the struct.
void PrintTo(const MalformedFile& f, std::ostream* os) { *os << f.path; }

struct Expectation {
  std::string key, line, what;
};

bool ParseHeader(const std::string& path, Expectation* e) {
  std::ifstream in(path, std::ios::binary);
  std::string first;
  std::getline(in, first);
  static const std::regex header(R"(^# ERROR (\S+) at line (\d+|-): (.+)$)");
  std::smatch m;
  if (!std::regex_match(first, m, header)) return false;
  *e = {m[1], m[2], m[3]};
  return true;
}

class MalformedInput : public ::testing::TestWithParam<MalformedFile> {};

TEST_P(MalformedInput, ExitsWithCodeTwoAndNamesFileLineAndKey) {
  const MalformedFile& f = GetParam();
  Expectation e;
  ASSERT_TRUE(ParseHeader(f.path, &e))
      << f.path << ": the first line must be \"# ERROR <key> at line <n|->: <what>\"";
  const std::string args =
      f.kind == "case"    ? "case --check '" + f.path + "'"
      : f.kind == "study" ? "sweep --dry-run -q -o '" + testing::UniqueTempPath("study") +
                                "' '" + f.path + "'"
      : f.kind == "train" ? "train '" + f.path + "'"
                          : "lubricant '" + f.path + "'";
  const testing::RunResult r = testing::RunTehl(args);
  ASSERT_TRUE(r.exited) << f.path << ": killed by signal " << r.signal << "\n" << r.err;
  EXPECT_EQ(r.exit_code, 2) << f.path << "\n" << r.err;
  const std::string where = e.line == "-" ? f.path + ": " : f.path + ":" + e.line + ": ";
  EXPECT_NE(r.err.find(where + e.key), std::string::npos)
      << "expected \"" << where << e.key << "\" (" << e.what << ") in stderr:\n"
      << r.err;
}

std::string TestName(const ::testing::TestParamInfo<MalformedFile>& info) {
  std::string name = info.param.kind + "_" + fs::path(info.param.path).stem().string();
  for (char& c : name)
    if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
  return name;
}

INSTANTIATE_TEST_SUITE_P(Corpus, MalformedInput, ::testing::ValuesIn(Corpus()), TestName);

TEST(MalformedCorpus, HasAtLeastTwentyFiveFilesOfBothKinds) {
  const auto files = Corpus();
  EXPECT_GE(files.size(), 25u);
  const auto count = [&](const char* kind) {
    return std::count_if(files.begin(), files.end(), [&](const auto& f) { return f.kind == kind; });
  };
  EXPECT_GE(count("case"), 10);
  EXPECT_GE(count("lubricant"), 10);
  EXPECT_GE(count("study"), 8);
  EXPECT_GE(count("train"), 8);
}

// Controls: well-formed inputs pass, so the rejections above come from the defects.
TEST(MalformedCorpus, ShippedLubricantsAreAccepted) {
  for (const char* name : {"sae40", "sae90", "reference_z068"}) {
    const testing::RunResult r = testing::RunTehl(std::string("lubricant ") + name);
    ASSERT_TRUE(r.exited) << name;
    EXPECT_EQ(r.exit_code, 0) << name << "\n" << r.err;
  }
}

TEST(MalformedCorpus, TheGearCaseTheCorpusIsBuiltOnIsAccepted) {
  // The case files of the corpus are this case with one defect each.
  const std::string path = testing::UniqueTempPath("well_formed_case.toml");
  std::ofstream(path) << "[gear]\nmodule_m = 0.002\nface_width_m = 0.025\n"
                         "[gear.pinion]\nteeth = 35\n[gear.wheel]\nteeth = 105\n"
                         "[operating]\npinion_speed_rpm = 1000.0\npower_w = 10000.0\n"
                         "[lubricant]\nname = \"sae40\"\n[numerics]\ngrid_points = 513\n";
  const testing::RunResult r = testing::RunTehl("case --check '" + path + "'");
  std::remove(path.c_str());
  ASSERT_TRUE(r.exited);
  EXPECT_EQ(r.exit_code, 0) << r.err;
}

TEST(CaseCheck, MinimalGearCaseWithoutOptionalSectionsIsAccepted) {
  // [numerics] is optional (case schema): its defaults (grid_points = 513) must apply when
  // the section is absent, so a case without it is valid.
  const std::string path = testing::UniqueTempPath("minimal_case.toml");
  std::ofstream(path) << "[gear]\nmodule_m = 0.002\nface_width_m = 0.025\n"
                         "[gear.pinion]\nteeth = 35\n[gear.wheel]\nteeth = 105\n"
                         "[operating]\npinion_speed_rpm = 1000.0\npower_w = 10000.0\n"
                         "[lubricant]\nname = \"sae40\"\n";
  const testing::RunResult r = testing::RunTehl("case --check '" + path + "'");
  std::remove(path.c_str());
  ASSERT_TRUE(r.exited);
  EXPECT_EQ(r.exit_code, 0) << r.err;
}

}  // namespace
}  // namespace tehl
