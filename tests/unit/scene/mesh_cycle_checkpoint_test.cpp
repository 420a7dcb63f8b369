// Checkpoints of the mesh cycle (src/scene/mesh_cycle_checkpoint.hpp): the rows and profiles go
// to an append-only journal, so each checkpoint writes only what was solved since the last one;
// what is read back is the whole result; a journal tail that no checkpoint committed (a run
// killed between the append and the rename) is ignored and cut off, and a journal of another
// run is refused. The kill-and-resume test of a real run is tests/regression/
// mesh_cycle_resume_test.cpp.
#include "scene/mesh_cycle_checkpoint.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <limits>
#include <stdexcept>
#include <string>

#include "support/scratch_path.hpp"

namespace tehl {
namespace {
namespace fs = std::filesystem;
using internal::CheckpointRowsPath;
using internal::CheckpointWriter;
using internal::ReadCheckpoint;

constexpr int kNodes = 33, kFilmNodes = 5;

// Step k of a synthetic thermal run: every value distinct, so a row out of place shows.
void AddStep(MeshCycleResult* r, int k) {
  MeshCycleStep s;
  s.s_m = 1e-4 * k;
  s.h_min_m = 1e-7 * (k + 1);
  s.t_max_k = 313.15 + k;
  s.zone = k < 5 ? "A-B" : "B-D";
  s.summary.iterations = k;
  s.summary.message = "step " + std::to_string(k);
  s.summary.outlet_cut = k % 3 == 1;
  // The same length on every row (the journal test below compares bytes per row).
  s.restart_reason = std::string("restart ") + static_cast<char>('a' + k % 26);
  r->steps.push_back(s);
  auto row = [&](double base) {
    std::vector<double> v(kNodes);
    for (int i = 0; i < kNodes; ++i) v[i] = base + 1e-3 * i + k;
    return v;
  };
  r->p_pa.push_back(row(1e8));
  r->h_m.push_back(row(1e-6));
  r->t_mid_k.push_back(row(320));
  r->t1_k.push_back(row(315));
  r->t2_k.push_back(row(316));
  r->t_field_k.push_back(std::vector<double>(kNodes * kFilmNodes, 330.0 + k));
}

FilmState State(double scale) {
  FilmState s;
  s.p_pa = Eigen::VectorXd::LinSpaced(kNodes, 0, 1e9 * scale);
  s.h_m = Eigen::VectorXd::Constant(kNodes, 5e-7 * scale);
  s.h0_m = -1e-6 * scale;
  s.time_s = 2e-3 * scale;
  s.temperature.t_k = Eigen::MatrixXd::Constant(kNodes, kFilmNodes, 350 * scale);
  s.temperature.t1_k = Eigen::VectorXd::Constant(kNodes, 340 * scale);
  // The solids' heat history: this level's travels, two earlier levels (the last steady).
  s.temperature.travel1_m = 2e-5 * scale;
  s.temperature.travel2_m = 3e-5 * scale;
  s.temperature.speed1_m_s = 1.1 * scale;
  s.temperature.speed2_m_s = 0.9 * scale;
  for (double travel : {1e-5 * scale, std::numeric_limits<double>::infinity()}) {
    SolidFluxLevel l;
    l.q1_w_m2 = Eigen::VectorXd::LinSpaced(kNodes, 1e6, 2e7 * scale);
    l.q2_w_m2 = Eigen::VectorXd::LinSpaced(kNodes, -1e6, 3e7 * scale);
    l.travel1_m = travel;
    l.travel2_m = 1.5 * travel;
    l.speed1_m_s = 1.2 * scale;
    l.speed2_m_s = 0.8 * scale;
    s.temperature.earlier.push_back(l);
  }
  return s;
}

LineContactSolver::TransientHistory History(double scale) {
  LineContactSolver::TransientHistory h;
  h.levels = 2;
  h.q1 = Eigen::VectorXd::Constant(kNodes, 1e-3 * scale);
  h.q2 = Eigen::VectorXd::Constant(kNodes, 2e-3 * scale);
  h.dt_prev_s = 1e-5 * scale;
  h.c_prev.load_n_per_m = 1e5 * scale;
  h.t_prev_k = Eigen::MatrixXd::Constant(kNodes, kFilmNodes, 345 * scale);
  return h;
}

void ExpectSameRows(const MeshCycleResult& a, const MeshCycleResult& b) {
  ASSERT_EQ(a.steps.size(), b.steps.size());
  for (size_t k = 0; k < a.steps.size(); ++k) {
    EXPECT_EQ(a.steps[k].s_m, b.steps[k].s_m) << k;
    EXPECT_EQ(a.steps[k].h_min_m, b.steps[k].h_min_m) << k;
    EXPECT_EQ(a.steps[k].t_max_k, b.steps[k].t_max_k) << k;
    EXPECT_EQ(a.steps[k].zone, b.steps[k].zone) << k;
    EXPECT_EQ(a.steps[k].summary.iterations, b.steps[k].summary.iterations) << k;
    EXPECT_EQ(a.steps[k].summary.message, b.steps[k].summary.message) << k;
    EXPECT_EQ(a.steps[k].restart_reason, b.steps[k].restart_reason) << k;
    EXPECT_EQ(a.steps[k].summary.outlet_cut, b.steps[k].summary.outlet_cut) << k;
  }
  EXPECT_EQ(a.p_pa, b.p_pa);
  EXPECT_EQ(a.h_m, b.h_m);
  EXPECT_EQ(a.t_mid_k, b.t_mid_k);
  EXPECT_EQ(a.t1_k, b.t1_k);
  EXPECT_EQ(a.t2_k, b.t2_k);
  EXPECT_EQ(a.t_field_k, b.t_field_k);
}

std::string NewCheckpointPath() {
  const fs::path dir = testing::ScratchPath("tehl_checkpoint", "dir");
  fs::create_directories(dir);
  return (dir / "cycle.checkpoint").string();
}

TEST(MeshCycleCheckpoint, CheckpointsInStepsReadBackTheWholeResult) {
  const std::string path = NewCheckpointPath();
  CheckpointWriter w(path);
  MeshCycleResult r;
  for (int k = 0; k < 12; ++k) {
    AddStep(&r, k);
    if (k == 2 || k == 6) w.Write(42, k + 1, 0.5 * k, r, State(k), History(k));
  }
  w.Write(42, 12, 6.0, r, State(1.5), History(2.5));
  const auto c = ReadCheckpoint(path);
  ASSERT_TRUE(c.has_value());
  EXPECT_EQ(c->fingerprint, 42u);
  EXPECT_EQ(c->next_step, 12);
  EXPECT_EQ(c->elapsed_s, 6.0);
  ExpectSameRows(r, c->result);
  EXPECT_EQ(c->state.p_pa, State(1.5).p_pa);
  EXPECT_EQ(c->state.h0_m, State(1.5).h0_m);
  EXPECT_EQ(c->state.temperature.t_k, State(1.5).temperature.t_k);
  EXPECT_EQ(c->state.temperature.t1_k, State(1.5).temperature.t1_k);
  EXPECT_EQ(c->state.temperature.travel1_m, State(1.5).temperature.travel1_m);
  EXPECT_EQ(c->state.temperature.travel2_m, State(1.5).temperature.travel2_m);
  EXPECT_EQ(c->state.temperature.speed1_m_s, State(1.5).temperature.speed1_m_s);
  EXPECT_EQ(c->state.temperature.speed2_m_s, State(1.5).temperature.speed2_m_s);
  ASSERT_EQ(c->state.temperature.earlier.size(), 2u);
  const FilmState expected = State(1.5);
  for (int j = 0; j < 2; ++j) {
    const SolidFluxLevel &got = c->state.temperature.earlier[j],
                         &want = expected.temperature.earlier[j];
    EXPECT_EQ(got.q1_w_m2, want.q1_w_m2) << j;
    EXPECT_EQ(got.q2_w_m2, want.q2_w_m2) << j;
    EXPECT_EQ(got.travel1_m, want.travel1_m) << j;
    EXPECT_EQ(got.travel2_m, want.travel2_m) << j;
    EXPECT_EQ(got.speed1_m_s, want.speed1_m_s) << j;
    EXPECT_EQ(got.speed2_m_s, want.speed2_m_s) << j;
  }
  EXPECT_EQ(c->history.levels, 2);
  EXPECT_EQ(c->history.q2, History(2.5).q2);
  EXPECT_EQ(c->history.dt_prev_s, History(2.5).dt_prev_s);
  EXPECT_EQ(c->history.c_prev.load_n_per_m, History(2.5).c_prev.load_n_per_m);
  EXPECT_EQ(c->history.t_prev_k, History(2.5).t_prev_k);

  w.Remove();
  EXPECT_FALSE(fs::exists(path));
  EXPECT_FALSE(fs::exists(CheckpointRowsPath(path)));
}

// The cost of a checkpoint must not grow with the rows already written: each appends the same
// number of bytes for the same number of new rows, and the checkpoint file keeps its size.
TEST(MeshCycleCheckpoint, EachCheckpointWritesOnlyTheRowsSinceTheLastOne) {
  const std::string path = NewCheckpointPath();
  CheckpointWriter w(path);
  MeshCycleResult r;
  std::vector<std::uintmax_t> journal, checkpoint;
  for (int k = 0; k < 40; ++k) {
    AddStep(&r, k);
    if ((k + 1) % 10 == 0) {
      w.Write(7, k + 1, 0.0, r, State(1), History(1));
      journal.push_back(fs::file_size(CheckpointRowsPath(path)));
      checkpoint.push_back(fs::file_size(path));
    }
  }
  ASSERT_EQ(journal.size(), 4u);
  // The rows of one step: 6 profiles (5 of kNodes values, the field kNodes x kFilmNodes).
  const std::uintmax_t profile_bytes = sizeof(double) * (5 * kNodes + kNodes * kFilmNodes);
  for (size_t i = 2; i < journal.size(); ++i) {
    EXPECT_EQ(journal[i] - journal[i - 1], journal[1] - journal[0]) << i;
    EXPECT_GT(journal[i] - journal[i - 1], 10 * profile_bytes) << i;
  }
  for (size_t i = 1; i < checkpoint.size(); ++i) EXPECT_EQ(checkpoint[i], checkpoint[0]) << i;
  EXPECT_LT(checkpoint[0], 10 * profile_bytes);  // holds the state, not the rows
}

// Killed after appending to the journal but before the checkpoint was renamed: the extra bytes
// are not part of the checkpoint, and a continued run cuts them off before appending.
TEST(MeshCycleCheckpoint, AnUncommittedJournalTailIsIgnoredAndCutOff) {
  const std::string path = NewCheckpointPath();
  MeshCycleResult r;
  {
    CheckpointWriter w(path);
    for (int k = 0; k < 5; ++k) AddStep(&r, k);
    w.Write(3, 5, 1.0, r, State(1), History(1));
  }
  std::ofstream(CheckpointRowsPath(path), std::ios::binary | std::ios::app)
      << "rows of steps 5-9 that no checkpoint committed";
  auto c = ReadCheckpoint(path);
  ASSERT_TRUE(c.has_value());
  ExpectSameRows(r, c->result);

  CheckpointWriter resumed(path);
  resumed.ContinueFrom(*c);
  for (int k = 5; k < 9; ++k) AddStep(&r, k);
  resumed.Write(3, 9, 2.0, r, State(2), History(2));
  c = ReadCheckpoint(path);
  ASSERT_TRUE(c.has_value());
  ExpectSameRows(r, c->result);
  EXPECT_EQ(c->next_step, 9);
}

// A fresh run starts its own journal. Killed before its first checkpoint was renamed, it
// leaves the checkpoint of the earlier run beside the new journal: that pair is refused.
TEST(MeshCycleCheckpoint, TheJournalOfAnotherRunIsRefused) {
  const std::string path = NewCheckpointPath();
  MeshCycleResult earlier, later;
  for (int k = 0; k < 8; ++k) AddStep(&earlier, k);
  CheckpointWriter(path).Write(5, 8, 1.0, earlier, State(1), History(1));
  const std::string kept = path + ".earlier";
  fs::copy_file(path, kept);
  for (int k = 0; k < 9; ++k) AddStep(&later, k);
  CheckpointWriter(path).Write(5, 9, 1.0, later, State(1), History(1));
  fs::copy_file(kept, path, fs::copy_options::overwrite_existing);
  EXPECT_FALSE(ReadCheckpoint(path).has_value());
}

// A journal that lost committed rows while the run went on (deleted or cut by hand) is not
// extended into a file that no checkpoint could read: the writer says so (the run then goes on
// without checkpoints, tests/regression/mesh_cycle_resume_test.cpp).
TEST(MeshCycleCheckpoint, AJournalThatLostCommittedRowsIsNotExtended) {
  const std::string path = NewCheckpointPath();
  CheckpointWriter w(path);
  MeshCycleResult r;
  for (int k = 0; k < 3; ++k) AddStep(&r, k);
  w.Write(1, 3, 1.0, r, State(1), History(1));
  fs::remove(CheckpointRowsPath(path));
  AddStep(&r, 3);
  EXPECT_THROW(w.Write(1, 4, 2.0, r, State(1), History(1)), std::runtime_error);
}

TEST(MeshCycleCheckpoint, AMissingOrShortJournalIsRefused) {
  const std::string path = NewCheckpointPath();
  MeshCycleResult r;
  for (int k = 0; k < 4; ++k) AddStep(&r, k);
  CheckpointWriter(path).Write(1, 4, 1.0, r, State(1), History(1));
  ASSERT_TRUE(ReadCheckpoint(path).has_value());
  fs::resize_file(CheckpointRowsPath(path), fs::file_size(CheckpointRowsPath(path)) - 1);
  EXPECT_FALSE(ReadCheckpoint(path).has_value());
  fs::remove(CheckpointRowsPath(path));
  EXPECT_FALSE(ReadCheckpoint(path).has_value());
}

}  // namespace
}  // namespace tehl
