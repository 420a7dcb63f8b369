// Hdf5Writer: values and unit attributes read back with the HDF5 C API, nothing under the
// final name before Commit(), no file at all when abandoned, and the non-finite guard.
#include "tehl/io/hdf5_writer.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <limits>

#include "unit/io/hdf5_read.hpp"
#include "support/scratch_path.hpp"

namespace tehl {
namespace {
namespace fs = std::filesystem;
using testing::Hdf5Doubles;
using testing::Hdf5Exists;
using testing::Hdf5StringAttribute;
using testing::Hdf5Text;

TEST(Hdf5Writer, WritesVectorsMatricesTextAndUnitsThatReadBack) {
  const testing::ScratchDir dir("tehl_h5");
  const std::string path = dir.Path("ok.h5");
  fs::remove(path);
  {
    Hdf5Writer w(path);
    w.WriteVector("/cycle/h_min", {1e-6, 2e-6, 3.5e-7}, "m", "minimum film");
    w.WriteMatrix("/profiles/p", {1, 2, 3, 4, 5, 6}, 2, 3, "Pa", "pressure");
    w.WriteText("/case", "[gear]\nmodule_m = 0.002\n", "the case");
    w.WriteInts("/solver/iterations", {3, 4}, "iterations");
    w.WriteStrings("/solver/termination", {"converged", "max_iterations"}, "how it ended");
    w.SetAttribute("/cycle", "s_B", 4.56e-3, "m");
    EXPECT_FALSE(fs::exists(path));  // only the .part file while writing
    EXPECT_TRUE(fs::exists(w.temporary_path()));
    w.Commit();
  }
  ASSERT_TRUE(fs::exists(path));
  EXPECT_FALSE(fs::exists(path + ".part"));
  const hid_t f = H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  ASSERT_GE(f, 0);
  EXPECT_EQ(Hdf5Doubles(f, "/cycle/h_min"), (std::vector<double>{1e-6, 2e-6, 3.5e-7}));
  std::vector<hsize_t> dims;
  EXPECT_EQ(Hdf5Doubles(f, "/profiles/p", &dims), (std::vector<double>{1, 2, 3, 4, 5, 6}));
  EXPECT_EQ(dims, (std::vector<hsize_t>{2, 3}));
  EXPECT_EQ(Hdf5StringAttribute(f, "/cycle/h_min", "unit"), "m");
  EXPECT_EQ(Hdf5StringAttribute(f, "/cycle/h_min", "meaning"), "minimum film");
  EXPECT_EQ(Hdf5StringAttribute(f, "/profiles/p", "unit"), "Pa");
  EXPECT_EQ(Hdf5StringAttribute(f, "/solver/iterations", "unit"), "-");
  EXPECT_EQ(Hdf5StringAttribute(f, "/cycle", "s_B_unit"), "m");
  EXPECT_EQ(Hdf5Text(f, "/case"), "[gear]\nmodule_m = 0.002\n");
  EXPECT_TRUE(Hdf5Exists(f, "/solver/termination"));
  H5Fclose(f);
}

TEST(Hdf5Writer, AbandonedWriterLeavesNoFile) {
  const testing::ScratchDir dir("tehl_h5");
  const std::string path = dir.Path("abandoned.h5");
  {
    Hdf5Writer w(path);
    w.WriteVector("/cycle/s", {0.0, 1.0}, "m", "s");
  }  // no Commit(): an exception or early return
  EXPECT_FALSE(fs::exists(path));
  EXPECT_FALSE(fs::exists(path + ".part"));
}

TEST(Hdf5Writer, RefusesNonFiniteValuesNamingTheDataset) {
  const testing::ScratchDir dir("tehl_h5");
  const std::string path = dir.Path("nan.h5");
  Hdf5Writer w(path);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  try {
    w.WriteVector("/cycle/h_c", {1e-6, nan}, "m", "central film");
    FAIL() << "NaN written";
  } catch (const NonFiniteError& e) {
    EXPECT_NE(std::string(e.what()).find("/cycle/h_c[1]"), std::string::npos) << e.what();
  }
  EXPECT_THROW(w.WriteMatrix("/profiles/h", {1, 2, inf, 4}, 2, 2, "m", "film"), NonFiniteError);
  EXPECT_THROW(w.SetAttribute("/", "wall_time", -inf, "s"), NonFiniteError);
  w.Commit();
  const hid_t f = H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  ASSERT_GE(f, 0);
  EXPECT_FALSE(Hdf5Exists(f, "/cycle/h_c"));  // refused before anything was created
  EXPECT_FALSE(Hdf5Exists(f, "/profiles/h"));
  H5Fclose(f);
}

// A result file that cannot be created (a folder in the way of its temporary name) is an
// error of the folder: std::filesystem::filesystem_error naming the path (exit code 2 on the
// command line), not an internal error.
TEST(Hdf5Writer, AFileThatCannotBeCreatedIsAFilesystemError) {
  const testing::ScratchDir dir("tehl_h5");
  const std::string path = dir.Path("blocked.h5");
  fs::create_directories(path + ".part");
  try {
    Hdf5Writer w(path);
    FAIL() << "created";
  } catch (const fs::filesystem_error& e) {
    EXPECT_EQ(e.path1().string(), path + ".part");
    EXPECT_TRUE(e.code()) << e.what();
  }
  EXPECT_FALSE(fs::exists(path));
}

TEST(Hdf5Writer, MismatchedMatrixShapeIsRefused) {
  const testing::ScratchDir dir("tehl_h5");
  Hdf5Writer w(dir.Path("shape.h5"));
  EXPECT_THROW(w.WriteMatrix("/profiles/p", {1, 2, 3}, 2, 2, "Pa", "p"), std::runtime_error);
}

}  // namespace
}  // namespace tehl
