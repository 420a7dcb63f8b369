// The CSV table writer: header and values round-trip, a non-finite value names its column and
// leaves no file.
#include "io/csv_table.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>

#include "tehl/io/hdf5_writer.hpp"
#include "support/scratch_path.hpp"

namespace tehl::internal {
namespace {
namespace fs = std::filesystem;

TEST(CsvTable, WritesHeaderAndRows) {
  const testing::ScratchDir dir("tehl_csv");
  const std::string path = dir.Path("table.csv");
  WriteCsvTable(path, {{"s_m", {0.0, 1e-3}}, {"h_c_m", {8e-7, 9e-7}}});
  std::ifstream in(path);
  std::string header, row1, row2;
  std::getline(in, header);
  std::getline(in, row1);
  std::getline(in, row2);
  EXPECT_EQ(header, "s_m,h_c_m");
  double a = 0, b = 0;
  char comma = 0;
  std::istringstream(row2) >> a >> comma >> b;
  EXPECT_DOUBLE_EQ(a, 1e-3);
  EXPECT_DOUBLE_EQ(b, 9e-7);
  EXPECT_FALSE(fs::exists(path + ".part"));
}

TEST(CsvTable, NonFiniteValueIsRefusedAndNothingIsWritten) {
  const testing::ScratchDir dir("tehl_csv");
  const std::string path = dir.Path("nan.csv");
  fs::remove(path);
  try {
    WriteCsvTable(path, {{"p_max_pa", {1.0, std::numeric_limits<double>::infinity()}}});
    FAIL() << "Inf written";
  } catch (const NonFiniteError& e) {
    EXPECT_NE(std::string(e.what()).find("p_max_pa[1]"), std::string::npos) << e.what();
  }
  EXPECT_FALSE(fs::exists(path));
}

// A table that cannot be written (here a folder in the way of its temporary file) is an
// error of the folder, not of tehl: std::filesystem::filesystem_error naming the path, which
// the command line reports with exit code 2.
TEST(CsvTable, AnUnwritablePathIsAFilesystemError) {
  const testing::ScratchDir dir("tehl_csv");
  const std::string path = dir.Path("blocked.csv");
  fs::create_directories(path + ".part");
  try {
    WriteCsvTable(path, {{"s_m", {0.0}}});
    FAIL() << "written";
  } catch (const fs::filesystem_error& e) {
    EXPECT_EQ(e.path1().string(), path + ".part");
    EXPECT_TRUE(e.code()) << e.what();
  }
  EXPECT_FALSE(fs::exists(path));
}

}  // namespace
}  // namespace tehl::internal
