// Warm starts after a change of the contact conditions (docs/theory.md, "Warm starts").
// Newton's complementarity moves a growing pressure zone by about one grid cell per iteration,
// so on a fine grid a re-solve from the previous film after a load change needed an iteration
// per cell the outlet moved (measured at M = 20, L = 10, +1 % load: 9, 13, 14 Newton iterations
// at 4097, 8193, 16385 nodes). Started from the previous film scaled by Hertz similarity
// (half-width ~ sqrt(w R), peak ~ sqrt(w / R)) the count stays that of a cold fine-grid solve.
// The converged film does not depend on the start (the problem has one solution), so both
// starts must end at the cold solve's film to the solver tolerance.
#include <gtest/gtest.h>

#include <cstdio>

#include "verification/ehl_moes_point.hpp"

namespace tehl {
namespace {

using testing::MoesPoint;
using testing::MoesSolver;

// A fresh solve at the new load (grid sequencing, no warm start): the reference film.
FilmState ColdFilm(const MoesPoint& mp, int n, double load_factor) {
  MoesSolver ms(mp, n);
  FilmState st;
  const auto sum = ms.solver.SolveSteady(mp.Conditions(load_factor), &st);
  EXPECT_TRUE(sum.usable()) << sum.BriefReport();
  return st;
}

// Re-solves at +10 % load from the film at the old load on n nodes: Newton iterations of the
// plain start [0] and of the predicted start [1]; both films equal the cold solve's.
void ReSolveAfterLoadChange(int n, int iterations[2]) {
  const MoesPoint mp{20, 10};  // VALIDATION.md section 3 table point
  const FilmState cold = ColdFilm(mp, n, 1.1);
  MoesSolver ms(mp, n);
  FilmState base;
  ASSERT_TRUE(ms.solver.SolveSteady(mp.Conditions(), &base).usable());
  ASSERT_TRUE(base.solved_for.has_value());
  for (int predicted : {0, 1}) {
    FilmState st = base;
    if (!predicted) st.solved_for.reset();  // plain warm start from the old film
    const auto sum = ms.solver.SolveSteady(mp.Conditions(1.1), &st);
    ASSERT_TRUE(sum.usable()) << sum.BriefReport();
    iterations[predicted] = sum.total_iterations;
    std::printf("n = %d, +10 %% load, %s start: %s\n", n, predicted ? "predicted" : "plain",
                sum.BriefReport().c_str());
    EXPECT_NEAR(ms.Hc(st) / ms.Hc(cold), 1.0, 1e-6);
    EXPECT_NEAR(ms.Hmin(st) / ms.Hmin(cold), 1.0, 1e-6);
  }
}

TEST(WarmStartVerification, SteadyReSolveAfterLoadChangeNeedsFewNewtonIterations) {
  // +10 % load moves the outlet by about 10 cells on 1025 nodes and 20 on 2049.
  int coarse[2] = {0, 0}, fine[2] = {0, 0};
  ReSolveAfterLoadChange(1025, coarse);
  ReSolveAfterLoadChange(2049, fine);
  // The plain start pays about one iteration per cell the outlet moved; the predicted one
  // starts within a cell or two (measured: 10 and 57 plain, 5-6 and 7-9 predicted, the spread
  // from the reused preconditioner's age).
  EXPECT_LT(coarse[1], coarse[0]);
  EXPECT_LT(3 * fine[1], fine[0]);
}

TEST(WarmStartVerification, SuddenLoadDropConvergesInOneStep) {
  // The seed 004 cycle's load falls to about 0.6 of its value at D (one tooth pair takes
  // over from two). A transient step through such a drop on 1025 nodes.
  const MoesPoint mp{20, 10};
  const int n = 1025;
  int iterations[2];
  for (bool predict : {false, true}) {
    LineContactSolver::Options opt;
    opt.predict_hertz_similar = predict;
    MoesSolver ms(mp, n, opt, /*transient=*/true);
    FilmState st;
    ASSERT_TRUE(ms.solver.SolveSteady(mp.Conditions(), &st).usable());
    ms.solver.BeginTransient(mp.Conditions(), st);
    // The seed 004 cycle's step at D is about 0.18 b / um (dt 2e-5 s, b 142 um, um 1.25 m/s).
    const double dt = 0.2 * mp.Hertz().half_width_m / mp.um_m_s();
    const auto sum = ms.solver.Step(mp.Conditions(0.6), dt, &st);
    std::printf("n = %d, load x 0.6 in one step, %s start: %s\n", n,
                predict ? "predicted" : "plain", sum.BriefReport().c_str());
    ASSERT_TRUE(sum.usable()) << sum.BriefReport();
    EXPECT_EQ(sum.substeps, 1);
    iterations[predict] = sum.total_iterations;
  }
  // Right after the drop the squeeze film keeps part of the old footprint, so the scaled
  // film is only a better start, not the answer.
  EXPECT_LT(iterations[1], iterations[0]);
}

}  // namespace
}  // namespace tehl
