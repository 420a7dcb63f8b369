// Transient isothermal EHL line contact (DESIGN.md sections 4-5: squeeze term d(rho h)/dt by
// BDF1/BDF2). Case: M = 20, L = 10 (VALIDATION.md section 3, p_H = 0.80 GPa) on 257 nodes;
// times in contact transit times t_b = b/um.
//   (a) Under constant conditions the transient equations have the steady film as their fixed
//       point: marching from the steady film at 0.8 w ends at the steady solve at w (1e-6).
//   (b) BDF2 is second order in time, BDF1 first order (textbook truncation errors
//       O(dt^2), O(dt)), measured on the smooth load w(t) = w0 (1 + 0.3 sin(pi t/T)) over
//       one period T = 8 t_b. (With T = 4 t_b the error of h_c(T) is not monotone in dt:
//       its dt^2 coefficient nearly vanishes at that instant, and the ratios of successive
//       differences from 16 to 2048 steps are 3.74, 1.88, 7.16, 3.50, 3.33, 3.73; at T = 8 t_b
//       they are 3.79, 4.04, 4.07, 4.15 -- docs/validation.md.)
//   (c) A sudden doubling of the load is integrated at every step (substeps allowed) and the
//       film settles to the steady solution at 2 w.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>

#include "verification/ehl_moes_point.hpp"

namespace tehl {
namespace {

using testing::MoesPoint;
using testing::MoesSolver;

constexpr int kNodes = 257;
const MoesPoint kPoint{20, 10};

double TransitTime() { return kPoint.TransitTime(); }

double SteadyHc(double load_factor) {
  MoesSolver ms(kPoint, kNodes);
  FilmState st;
  const LineContactSolver::Summary sum = ms.solver.SolveSteady(kPoint.Conditions(load_factor), &st);
  EXPECT_TRUE(sum.usable()) << sum.BriefReport();
  return ms.Hc(st);
}

// Marches from the steady film at w0 * start_factor under constant load w0 * end_factor for
// `steps` steps of dt; returns H_c after each step. Every step must be usable.
std::vector<double> MarchConstantLoad(double start_factor, double end_factor, double dt,
                                      int steps, int* max_substeps) {
  MoesSolver ms(kPoint, kNodes, {}, /*transient=*/true);
  FilmState st;
  const LineContactSolver::Summary s0 =
      ms.solver.SolveSteady(kPoint.Conditions(start_factor), &st);
  EXPECT_TRUE(s0.usable()) << s0.BriefReport();
  ms.solver.BeginTransient(kPoint.Conditions(start_factor), st);
  std::vector<double> hc;
  *max_substeps = 1;
  for (int k = 0; k < steps; ++k) {
    const LineContactSolver::Summary sum =
        ms.solver.Step(kPoint.Conditions(end_factor), dt, &st);
    EXPECT_TRUE(sum.usable()) << "step " << k << ": " << sum.BriefReport();
    if (!sum.usable()) break;
    EXPECT_TRUE(st.p_pa.allFinite() && st.h_m.allFinite());
    *max_substeps = std::max(*max_substeps, sum.substeps);
    hc.push_back(ms.Hc(st));
  }
  return hc;
}

TEST(TransientVerification, ConstantLoadMarchesToTheSteadySolution) {
  const double target = SteadyHc(1.0);
  int substeps = 0;
  const std::vector<double> hc = MarchConstantLoad(0.8, 1.0, TransitTime(), 200, &substeps);
  ASSERT_EQ(hc.size(), 200u);
  for (int k : {0, 9, 49, 99, 199})
    std::printf("step %3d: H_c / H_c,steady - 1 = %+.3e\n", k + 1, hc[k] / target - 1.0);
  EXPECT_NEAR(hc.back() / target, 1.0, 1e-6);
}

TEST(TransientVerification, SuddenLoadDoublingConvergesAtEveryStepAndSettles) {
  const double target = SteadyHc(2.0);
  int substeps = 0;
  const std::vector<double> hc = MarchConstantLoad(1.0, 2.0, TransitTime(), 200, &substeps);
  ASSERT_EQ(hc.size(), 200u);
  for (int k : {0, 9, 49, 99, 199})
    std::printf("step %3d: H_c / H_c,steady(2w) - 1 = %+.3e\n", k + 1, hc[k] / target - 1.0);
  std::printf("largest number of substeps: %d\n", substeps);
  EXPECT_NEAR(hc.back() / target, 1.0, 1e-6);
}

// A step that needs substeps ends with a history whose last interval is a substep. The
// next whole step would then be a variable-step BDF2 step at the ratio `substeps` (4 after 4
// substeps), beyond the zero-stability bound 1 + sqrt(2) of variable-step BDF2 (Grigorieff
// 1983), which amplifies the substeps' errors (docs/theory.md, "Squeeze term"). The history
// must keep the whole-step levels instead: rho h at the start of the step as q2 (and the level
// before it as q3), dt as the last interval.
TEST(TransientVerification, AfterSubstepsTheHistoryKeepsTheWholeStepLevels) {
  // The steady film at a tenth of the load, then transient steps with a Newton budget of 15
  // iterations, and the whole load in one step (p_H 0.25 -> 0.8 GPa): in one piece that step
  // takes 18 iterations, so it is split.
  FilmState st;
  ASSERT_TRUE(MoesSolver(kPoint, kNodes).solver.SolveSteady(kPoint.Conditions(0.1), &st).usable());
  LineContactSolver::Options o;
  o.max_iterations = 15;
  MoesSolver ms(kPoint, kNodes, o, /*transient=*/true);
  ms.solver.BeginTransient(kPoint.Conditions(0.1), st);
  const double dt = TransitTime();
  ASSERT_TRUE(ms.solver.Step(kPoint.Conditions(0.1), dt, &st).usable());
  const LineContactSolver::TransientHistory before = ms.solver.SaveTransient();
  ASSERT_EQ(before.levels, 2);
  const LineContactSolver::Summary jump = ms.solver.Step(kPoint.Conditions(1.0), dt, &st);
  ASSERT_TRUE(jump.usable()) << jump.BriefReport();
  std::printf("load x 10 in one step: %d substeps, %d Newton iterations\n", jump.substeps,
              jump.total_iterations);
  ASSERT_GT(jump.substeps, 1);
  const LineContactSolver::TransientHistory after = ms.solver.SaveTransient();
  EXPECT_EQ(after.levels, 3);
  EXPECT_EQ(after.dt_prev_s, dt);
  EXPECT_EQ(after.dt_prev2_s, before.dt_prev_s);
  ASSERT_EQ(after.q2.size(), before.q1.size());
  ASSERT_EQ(after.q3.size(), before.q2.size());
  EXPECT_EQ((after.q2 - before.q1).cwiseAbs().maxCoeff(), 0.0);
  EXPECT_EQ((after.q3 - before.q2).cwiseAbs().maxCoeff(), 0.0);
  // And the march goes on: the next whole steps converge.
  for (int k = 0; k < 3; ++k)
    EXPECT_TRUE(ms.solver.Step(kPoint.Conditions(1.0), dt, &st).usable()) << k;
}

// H_c at t = T after `steps` equal steps of the load w0 (1 + 0.3 sin(pi t/T)), T = 8 t_b,
// starting from the steady film at w0.
double SineLoadHc(TimeScheme scheme, int steps) {
  LineContactSolver::Options o;
  o.time_scheme = scheme;
  o.tolerance = 1e-11;  // far below the time error of the finest run
  MoesSolver ms(kPoint, kNodes, o, /*transient=*/true);
  FilmState st;
  const LineContactSolver::Summary s0 = ms.solver.SolveSteady(kPoint.Conditions(1.0), &st);
  EXPECT_TRUE(s0.usable()) << s0.BriefReport();
  ms.solver.BeginTransient(kPoint.Conditions(1.0), st);
  const double period = 8.0 * TransitTime(), dt = period / steps;
  for (int k = 1; k <= steps; ++k) {
    const double f = 1.0 + 0.3 * std::sin(std::numbers::pi * k * dt / period);
    const LineContactSolver::Summary sum = ms.solver.Step(kPoint.Conditions(f), dt, &st);
    EXPECT_TRUE(sum.usable()) << "step " << k << ": " << sum.BriefReport();
    if (!sum.usable()) return std::nan("");
  }
  return ms.Hc(st);
}

TEST(TransientVerification, Bdf2IsSecondOrderInTime) {
  // Errors against a reference with a 4x smaller step than the finest run: with e = C dt^2
  // the estimate log2((e(dt) - e_ref)/(e(dt/2) - e_ref)) is log2(63/15) = 2.07.
  const double h16 = SineLoadHc(TimeScheme::kBdf2, 16), h32 = SineLoadHc(TimeScheme::kBdf2, 32);
  const double h64 = SineLoadHc(TimeScheme::kBdf2, 64), ref = SineLoadHc(TimeScheme::kBdf2, 128);
  const double q = std::log2(std::abs(h16 - ref) / std::abs(h32 - ref));
  const double q3 = std::log2(std::abs(h16 - h32) / std::abs(h32 - h64));
  std::printf("BDF2: H_c(T) = %.10f (16) %.10f (32) %.10f (64) %.10f (128); order vs reference "
              "%.3f, from differences %.3f\n",
              h16, h32, h64, ref, q, q3);
  EXPECT_GE(q, 1.8);
  EXPECT_LE(q, 2.3);
}

TEST(TransientVerification, Bdf1IsFirstOrderInTime) {
  // Three runs, order log2((h_16 - h_32)/(h_32 - h_64)) (unbiased for e = C dt).
  const double h16 = SineLoadHc(TimeScheme::kBdf1, 16), h32 = SineLoadHc(TimeScheme::kBdf1, 32);
  const double h64 = SineLoadHc(TimeScheme::kBdf1, 64);
  const double q = std::log2(std::abs(h16 - h32) / std::abs(h32 - h64));
  std::printf("BDF1: H_c(T) = %.10f (16) %.10f (32) %.10f (64); order %.3f\n", h16, h32, h64, q);
  EXPECT_GE(q, 0.8);
  EXPECT_LE(q, 1.2);
}

}  // namespace
}  // namespace tehl
