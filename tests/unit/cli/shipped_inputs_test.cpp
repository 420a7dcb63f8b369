// Every shipped case and study is valid input to the real program: `tehl case --check` of each
// file of cases/ and `tehl sweep --dry-run` of each study of cases/studies/ exit with 0. A
// new input check that refused a shipped file (as a rule on tip relief once refused a point
// of cases/studies/tip_relief.toml) fails here.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

#include "unit/cli/run_tehl.hpp"

namespace tehl {
namespace {
namespace fs = std::filesystem;

std::vector<std::string> TomlFiles(const std::string& folder) {
  std::vector<std::string> files;
  for (const auto& e : fs::directory_iterator(std::string(TEHL_SOURCE_DIR) + "/" + folder))
    if (e.is_regular_file() && e.path().extension() == ".toml") files.push_back(e.path());
  std::sort(files.begin(), files.end());
  return files;
}

TEST(ShippedInputs, EveryCaseFilePassesTheCheck) {
  const std::vector<std::string> cases = TomlFiles("cases");
  ASSERT_GE(cases.size(), 10u);
  for (const std::string& f : cases) {
    const testing::RunResult r = testing::RunTehl("case --check '" + f + "'");
    ASSERT_TRUE(r.exited) << f;
    EXPECT_EQ(r.exit_code, 0) << f << "\n" << r.err;
  }
}

TEST(ShippedInputs, EveryStudyExpandsToValidScenes) {
  const std::vector<std::string> studies = TomlFiles("cases/studies");
  ASSERT_GE(studies.size(), 8u);
  for (const std::string& f : studies) {
    const testing::RunResult r = testing::RunTehl(
        "sweep --dry-run -q -o '" + testing::UniqueTempPath("study") + "' '" + f + "'");
    ASSERT_TRUE(r.exited) << f;
    EXPECT_EQ(r.exit_code, 0) << f << "\n" << r.err;
  }
}

}  // namespace
}  // namespace tehl
