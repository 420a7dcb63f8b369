// `tehl run --resume` with a checkpoint that cannot be trusted
// (src/scene/mesh_cycle_checkpoint.hpp, docs/results.md "Checkpoints and --resume"): a checkpoint
// or rows file with changed bytes, a checkpoint holding a non-finite film, one of another format
// version, or a folder in the place of the checkpoint. None of them is used, stderr says why, and
// the run starts at A and ends with the result of an uninterrupted run (exit 0); none of them is an
// internal error (exit 3). The runs are the seed 004 cycle, isothermal, on 129 nodes with 20 steps
// (well under a second each).
#include <gtest/gtest.h>
#include <hdf5.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <limits>
#include <string>
#include <vector>

#include "mesh_cycle_runs.hpp"
#include "scene/mesh_cycle_checkpoint.hpp"
#include "unit/cli/run_tehl.hpp"
#include "unit/io/hdf5_read.hpp"

namespace tehl {
namespace {
namespace fs = std::filesystem;
using testing::ReducedCase;
using testing::RunTehl;
using testing::TempDirFor;

// A killed run's files: the case, its output folder and the checkpoint in it.
struct Killed {
  std::string case_path, dir, checkpoint;
};

std::string SmallCase() {
  return ReducedCase("seed004_sae40",
                     {{"grid_points", "129"}, {"steps", "20"}, {"thermal", "false"}});
}

// A run of `case_path` killed right after its first checkpoint (at step 5).
Killed KilledAfterCheckpoint(const std::string& case_path, const std::string& dir) {
  testing::RunAndKillAfterCheckpoint(case_path, dir);
  return {case_path, dir, dir + "/" + fs::path(case_path).stem().string() + ".checkpoint"};
}

// Inverts the bits of `n` bytes of `path` from `offset` on.
void FlipBytes(const std::string& path, std::uintmax_t offset, int n) {
  std::fstream f(path, std::ios::binary | std::ios::in | std::ios::out);
  ASSERT_TRUE(f) << path;
  for (int i = 0; i < n; ++i) {
    f.seekg(static_cast<std::streamoff>(offset + i));
    const char c = static_cast<char>(f.get() ^ 0xff);
    f.seekp(static_cast<std::streamoff>(offset + i));
    f.put(c);
  }
  ASSERT_TRUE(f) << path;
}

// Writes the bit pattern of a quiet NaN over the 8 bytes of `path` from `offset`.
void WriteNan(const std::string& path, std::uintmax_t offset) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  std::fstream f(path, std::ios::binary | std::ios::in | std::ios::out);
  f.seekp(static_cast<std::streamoff>(offset));
  f.write(reinterpret_cast<const char*>(&nan), sizeof nan);
  ASSERT_TRUE(f) << path;
}

testing::RunResult Resume(const Killed& k) {
  return RunTehl("run '" + k.case_path + "' -o '" + k.dir + "' --resume --checkpoint-every 5");
}

// The run after a refused checkpoint started at A and has the uninterrupted run's films.
void ExpectFreshResult(const Killed& k, const testing::RunResult& r) {
  ASSERT_TRUE(r.exited) << "killed by signal " << r.signal << "\n" << r.err;
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.out.find("resumed from the checkpoint"), std::string::npos) << r.out;
  EXPECT_NE(r.err.find("; starting at A"), std::string::npos) << r.err;
  MeshCycleRunOptions o;
  o.quiet = true;
  o.write_files = false;
  const MeshCycleResult ref = RunMeshCycle(k.case_path, o);
  ASSERT_TRUE(ref.converged());
  const std::string h5 = k.dir + "/" + fs::path(k.case_path).stem().string() + ".h5";
  const hid_t file = H5Fopen(h5.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  ASSERT_GE(file, 0) << h5;
  const std::vector<double> h_min = testing::Hdf5Doubles(file, "/cycle/h_min");
  H5Fclose(file);
  ASSERT_EQ(h_min.size(), ref.steps.size());
  for (size_t i = 0; i < h_min.size(); ++i)
    EXPECT_NEAR(h_min[i], ref.steps[i].h_min_m, 1e-9 * ref.steps[i].h_min_m) << i;
  EXPECT_FALSE(fs::exists(k.checkpoint));  // the result is complete: the checkpoint is spent
}

// The killed run's checkpoint as written is used: the tests below change only what they say.
TEST(CheckpointIntegrity, AnIntactCheckpointIsResumed) {
  const Killed k = KilledAfterCheckpoint(SmallCase(), TempDirFor("ck_intact"));
  const testing::RunResult r = Resume(k);
  ASSERT_TRUE(r.exited);
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("resumed from the checkpoint at step 6"), std::string::npos) << r.out;
  EXPECT_EQ(r.err.find("warning"), std::string::npos) << r.err;
}

// Bytes changed in the middle of the checkpoint (the film state or the solver history) are
// found by its checksum: the run starts at A instead of continuing from a wrong film.
TEST(CheckpointIntegrity, ADamagedCheckpointIsNotUsed) {
  const Killed k = KilledAfterCheckpoint(SmallCase(), TempDirFor("ck_damaged"));
  FlipBytes(k.checkpoint, fs::file_size(k.checkpoint) / 2, 8);
  const testing::RunResult r = Resume(k);
  EXPECT_NE(r.err.find("warning: the checkpoint " + k.checkpoint +
                       " is not used: the file is damaged (its checksum does not match its "
                       "contents)"),
            std::string::npos)
      << r.err;
  ExpectFreshResult(k, r);
}

// The NaN written into a checkpoint: a NaN written over a value of the checkpoint.
TEST(CheckpointIntegrity, ANanWrittenIntoTheCheckpointIsFound) {
  const Killed k = KilledAfterCheckpoint(SmallCase(), TempDirFor("ck_nan"));
  WriteNan(k.checkpoint, fs::file_size(k.checkpoint) / 2);
  const testing::RunResult r = Resume(k);
  EXPECT_NE(r.err.find("checkpoint " + k.checkpoint + " is not used: the file is damaged"),
            std::string::npos)
      << r.err;
  ExpectFreshResult(k, r);
}

// A garbled rows file: a NaN over the last film thickness it holds (an isothermal journal ends
// with the h profile of the last step, then the four counts of the empty temperature arrays),
// which used to be copied into /profiles/h unseen.
TEST(CheckpointIntegrity, ADamagedRowsFileIsNotUsed) {
  const Killed k = KilledAfterCheckpoint(SmallCase(), TempDirFor("ck_rows"));
  const std::string rows = internal::CheckpointRowsPath(k.checkpoint);
  WriteNan(rows, fs::file_size(rows) - 4 * sizeof(std::int64_t) - sizeof(double));
  const testing::RunResult r = Resume(k);
  EXPECT_NE(r.err.find("warning: the checkpoint " + k.checkpoint + " is not used: its rows file " +
                       rows + " is damaged"),
            std::string::npos)
      << r.err;
  ExpectFreshResult(k, r);
}

// Bytes flipped in the middle of the rows file likewise.
TEST(CheckpointIntegrity, FlippedBytesInTheRowsFileAreFound) {
  const Killed k = KilledAfterCheckpoint(SmallCase(), TempDirFor("ck_rows_flip"));
  const std::string rows = internal::CheckpointRowsPath(k.checkpoint);
  FlipBytes(rows, fs::file_size(rows) / 2, 3);
  const testing::RunResult r = Resume(k);
  EXPECT_NE(r.err.find("its rows file " + rows + " is damaged"), std::string::npos) << r.err;
  ExpectFreshResult(k, r);
}

// A folder where the checkpoint should be is treated as no checkpoint (it used to end the run
// with exit 3, "internal error: basic_filebuf::underflow error reading the file"): the run
// starts at A, goes on without checkpoints (it cannot write them) and writes its result.
TEST(CheckpointIntegrity, AFolderInPlaceOfTheCheckpointIsNotAnInternalError) {
  const std::string case_path = SmallCase();
  const std::string dir = TempDirFor("ck_folder");
  const Killed k{case_path, dir, dir + "/" + fs::path(case_path).stem().string() + ".checkpoint"};
  fs::create_directories(k.checkpoint);
  const testing::RunResult r = Resume(k);
  ASSERT_TRUE(r.exited);
  EXPECT_NE(r.exit_code, 3) << r.err;
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.err.find("warning: the checkpoint " + k.checkpoint +
                       " is not used: it is a folder, not a "
                       "file"),
            std::string::npos)
      << r.err;
  EXPECT_NE(r.err.find("the run goes on without checkpoints"), std::string::npos) << r.err;
  EXPECT_TRUE(fs::is_directory(k.checkpoint));  // not removed: tehl did not make it
  EXPECT_FALSE(fs::exists(k.checkpoint + ".part"));
  EXPECT_FALSE(fs::exists(internal::CheckpointRowsPath(k.checkpoint)));
  EXPECT_TRUE(fs::exists(dir + "/" + fs::path(case_path).stem().string() + ".h5"));
  // Without --resume too.
  const testing::RunResult fresh = RunTehl("run '" + case_path + "' -o '" + dir + "' -q");
  ASSERT_TRUE(fresh.exited);
  EXPECT_EQ(fresh.exit_code, 0) << fresh.err;
}

// In process: a checkpoint written with a non-finite film, and one of another format version.
MeshCycleResult OneRow() {
  MeshCycleResult r;
  MeshCycleStep s;
  s.h_min_m = 1e-7;
  r.steps.push_back(s);
  r.p_pa.push_back({0.0, 1e8, 0.0});
  r.h_m.push_back({2e-7, 1e-7, 2e-7});
  return r;
}

FilmState Film(double p_mid) {
  FilmState s;
  s.p_pa = Eigen::VectorXd::Constant(3, 0.0);
  s.p_pa(1) = p_mid;
  s.h_m = Eigen::VectorXd::Constant(3, 1e-7);
  return s;
}

// What ReadCheckpoint says about `path` (empty when it has nothing to say), and whether it
// read it.
std::string ReadReportingProblem(const std::string& path, bool* read) {
  std::string problem;
  *read = internal::ReadCheckpoint(path, &problem).has_value();
  return problem;
}

TEST(CheckpointIntegrity, ANonFiniteFilmIsRefused) {
  const std::string dir = TempDirFor("ck_nonfinite");
  fs::create_directories(dir);
  const std::string path = dir + "/film.checkpoint";
  internal::CheckpointWriter(path).Write(1, 1, 0.5, OneRow(), Film(1e8), {});
  bool read = false;
  std::string err = ReadReportingProblem(path, &read);
  ASSERT_TRUE(read) << err;
  EXPECT_EQ(err, "");
  internal::CheckpointWriter(path).Write(1, 1, 0.5, OneRow(),
                                         Film(std::numeric_limits<double>::infinity()), {});
  err = ReadReportingProblem(path, &read);
  EXPECT_FALSE(read);
  EXPECT_EQ(err, "it holds a non-finite pressure");
  std::string problem;
  EXPECT_FALSE(internal::ReadCheckpoint(path + ".none", &problem).has_value());
  EXPECT_EQ(problem, "");  // no checkpoint: nothing to report
}

TEST(CheckpointIntegrity, ACheckpointOfAnotherVersionIsNamedSo) {
  const std::string dir = TempDirFor("ck_version");
  fs::create_directories(dir);
  const std::string path = dir + "/film.checkpoint";
  internal::CheckpointWriter(path).Write(1, 1, 0.5, OneRow(), Film(1e8), {});
  {
    std::fstream f(path, std::ios::binary | std::ios::in | std::ios::out);
    f.seekp(7);
    f.put('9');
  }
  bool read = false;
  const std::string err = ReadReportingProblem(path, &read);
  EXPECT_FALSE(read);
  EXPECT_NE(err.find("it was written by another version of tehl (format TEHLCKP9; "
                     "this version reads TEHLCKPA)"),
            std::string::npos)
      << err;
}

}  // namespace
}  // namespace tehl
