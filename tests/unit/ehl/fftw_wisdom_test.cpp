// FFTW wisdom kept across processes (src/ehl/fftw_wisdom.hpp). Each test starts from FFTW's
// wisdom as the earlier ones left it, so each plans sizes of its own.
#include "ehl/fftw_wisdom.hpp"

#include <fftw3.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "support/scratch_path.hpp"
#include "tehl/ehl/elastic_deflection.hpp"

namespace tehl {
namespace {

// FFTW_WISDOM_ONLY builds a plan only from wisdom: a null plan means FFTW has none for it.
bool HasWisdomFor(int m) {
  double* in = fftw_alloc_real(m);
  fftw_complex* out = fftw_alloc_complex(m / 2 + 1);
  fftw_plan p = fftw_plan_dft_r2c_1d(m, in, out, FFTW_MEASURE | FFTW_WISDOM_ONLY);
  const bool found = p != nullptr;
  if (p) fftw_destroy_plan(p);
  fftw_free(in);
  fftw_free(out);
  return found;
}

// A measured deflection leaves its plans in the process's wisdom; written out, forgotten and
// read back, the file supplies the plan of that size (and of no other).
TEST(FftwWisdom, MeasuredPlansSurviveAnExportAndImport) {
  const testing::ScratchDir dir("tehl_wisdom");
  const std::string path = dir.Path("wisdom");
  const int m = ElasticDeflection(257, 1e-6, 226.4e9, FftPlanEffort::kEstimate).fft_size();
  const int other = ElasticDeflection(513, 1e-6, 226.4e9, FftPlanEffort::kEstimate).fft_size();
  ASSERT_FALSE(HasWisdomFor(m));  // estimated plans leave no wisdom that measured ones use
  { ElasticDeflection k(257, 1e-6, 226.4e9, FftPlanEffort::kMeasure); }
  ASSERT_TRUE(HasWisdomFor(m));
  ASSERT_TRUE(internal::ExportWisdom(path));
  std::ifstream in(path);
  std::string head;
  std::getline(in, head);
  EXPECT_EQ(head.rfind("(fftw-3", 0), 0u) << head;
  EXPECT_FALSE(std::filesystem::exists(path + ".tmp." + std::to_string(getpid())));
  fftw_forget_wisdom();
  EXPECT_FALSE(HasWisdomFor(m));
  ASSERT_TRUE(internal::ImportWisdom(path));
  EXPECT_TRUE(HasWisdomFor(m));
  EXPECT_FALSE(HasWisdomFor(other));
}

// A missing file or one that is not FFTW wisdom is refused, and leaves the wisdom as it was;
// an export into a directory that does not exist fails without leaving a file.
TEST(FftwWisdom, RefusesMissingAndForeignFiles) {
  const testing::ScratchDir dir("tehl_wisdom");
  const std::string path = dir.Path("foreign");
  EXPECT_FALSE(internal::ImportWisdom(path));
  std::ofstream(path) << "[numerics]\ngrid_points = 513\n";
  EXPECT_FALSE(internal::ImportWisdom(path));
  const std::string nowhere = dir.Path("no_such_dir/wisdom");
  EXPECT_FALSE(internal::ExportWisdom(nowhere));
  EXPECT_FALSE(std::filesystem::exists(nowhere));
}

// With TEHL_FFTW_WISDOM set, a measured deflection of a new size writes the file (its
// planning measured new plans), which a later process imports before planning.
TEST(FftwWisdom, TheEnvironmentVariableNamesTheFileWritten) {
  const testing::ScratchDir dir("tehl_wisdom");
  const std::string path = dir.Path("env");
  ASSERT_EQ(setenv("TEHL_FFTW_WISDOM", path.c_str(), 1), 0);
  EXPECT_EQ(internal::WisdomFile(), path);
  int m = 0;
  {
    ElasticDeflection k(1025, 1e-6, 226.4e9, FftPlanEffort::kMeasure);
    m = k.fft_size();
  }
  EXPECT_TRUE(std::filesystem::exists(path));
  fftw_forget_wisdom();
  EXPECT_TRUE(internal::ImportWisdom(path));
  EXPECT_TRUE(HasWisdomFor(m));
  unsetenv("TEHL_FFTW_WISDOM");
}

}  // namespace
}  // namespace tehl
