// The local time error estimate of transient steps (Summary::time_error, Milne's device:
// docs/theory.md, "Time-step error") and the substeps it asks for (Options::time_tolerance).
// Case: M = 20, L = 10 (VALIDATION.md section 3, p_H = 0.80 GPa) on 257 nodes; times in
// contact transit times t_b = b/um.
//   (a) On the smooth load w(t) = w0 (1 + 0.3 sin(pi t/T)), T = 8 t_b, the estimate falls as
//       dt^3 for BDF2 and dt^2 for BDF1 (the orders of their local truncation errors, e.g.
//       Hairer & Wanner, Solving ODEs II, section III.5).
//   (b) It is the local error: one step of 8 reference steps from the reference run's own
//       levels misses the reference's rho h by what the estimate says.
//   (c) After a sudden load rise the controlled step takes substeps, each within the
//       tolerance, and its film is closer to that of 256 steps than the film of one step; a load
//       that jumps at the start of the step (Step's c_start) holds over all the substeps.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>
#include <vector>

#include "verification/ehl_moes_point.hpp"

namespace tehl {
namespace {

using testing::MoesPoint;
using testing::MoesSolver;

constexpr int kNodes = 257;
const MoesPoint kPoint{20, 10};

double Period() { return 8.0 * kPoint.TransitTime(); }
double SineLoad(double t) { return 1.0 + 0.3 * std::sin(std::numbers::pi * t / Period()); }

struct Level {
  FilmState state;
  LineContactSolver::TransientHistory history;
  double time_error = -1;
};

// `steps` equal steps of the sine load from the steady film at w0; entry k is the level after
// k steps (entry 0 the start).
std::vector<Level> SineLoadRun(TimeScheme scheme, int steps) {
  LineContactSolver::Options o;
  o.time_scheme = scheme;
  o.tolerance = 1e-11;  // far below the time errors measured
  MoesSolver ms(kPoint, kNodes, o, /*transient=*/true);
  std::vector<Level> run(1);
  const LineContactSolver::Summary s0 =
      ms.solver.SolveSteady(kPoint.Conditions(1.0), &run[0].state);
  EXPECT_TRUE(s0.usable()) << s0.BriefReport();
  ms.solver.BeginTransient(kPoint.Conditions(1.0), run[0].state);
  run[0].history = ms.solver.SaveTransient();
  const double dt = Period() / steps;
  for (int k = 1; k <= steps; ++k) {
    Level next{run.back().state, {}, -1};
    const LineContactSolver::Summary sum =
        ms.solver.Step(kPoint.Conditions(SineLoad(k * dt)), dt, &next.state);
    EXPECT_TRUE(sum.usable()) << "step " << k << ": " << sum.BriefReport();
    EXPECT_EQ(sum.substeps, 1);
    next.history = ms.solver.SaveTransient();
    next.time_error = sum.time_error;
    run.push_back(std::move(next));
  }
  return run;
}

// The geometric mean of the estimates over the middle half of the period, T/4 .. 3T/4, for
// 16, 32 and 64 steps, and its order in dt from each halving. (A single step's estimate
// scatters about the trend: the outlet's cavitation boundary crosses nodes, which is not smooth
// in time, and at T/2 the load's third derivative vanishes.)
void ExpectEstimateOrder(TimeScheme scheme, double order, double tolerance) {
  std::vector<double> e;
  for (int steps : {16, 32, 64}) {
    const std::vector<Level> run = SineLoadRun(scheme, steps);
    double sum = 0;
    int count = 0;
    for (int k = steps / 4; k <= 3 * steps / 4; ++k) {
      EXPECT_GT(run[k].time_error, 0.0) << steps << " steps, step " << k;
      sum += std::log(run[k].time_error);
      ++count;
    }
    e.push_back(std::exp(sum / count));
  }
  const double q1 = std::log2(e[0] / e[1]), q2 = std::log2(e[1] / e[2]);
  std::printf(
      "time_error, geometric mean over T/4 .. 3T/4: %.3e (16 steps) %.3e (32) %.3e (64); "
      "orders %.3f %.3f\n",
      e[0], e[1], e[2], q1, q2);
  EXPECT_NEAR(q1, order, tolerance);
  EXPECT_NEAR(q2, order, tolerance);
}

TEST(TimeErrorEstimate, FallsAsTheCubeOfTheStepForBdf2) {
  ExpectEstimateOrder(TimeScheme::kBdf2, 3, 0.3);
}

TEST(TimeErrorEstimate, FallsAsTheSquareOfTheStepForBdf1) {
  ExpectEstimateOrder(TimeScheme::kBdf1, 2, 0.2);
}

TEST(TimeErrorEstimate, IsTheLocalErrorOfTheStep) {
  // Reference: 128 steps. The step of 8 reference steps from t_3 to t_4 = T/4 (t_j = j T/16)
  // starts from the reference's film at t_3 with its rho h at t_1, t_2, t_3 as history; the
  // rho h it ends with differs from the reference's at t_4 by its local error (the
  // reference's own error is smooth in time and enters both alike).
  const std::vector<Level> ref = SineLoadRun(TimeScheme::kBdf2, 128);
  const int m = 8;  // reference steps per step
  const double dt = Period() / 16;
  MoesSolver ms(kPoint, kNodes, {}, /*transient=*/true);
  LineContactSolver::TransientHistory h;
  h.levels = 3;
  h.q1 = ref[3 * m].history.q1;
  h.q2 = ref[2 * m].history.q1;
  h.q3 = ref[1 * m].history.q1;
  h.dt_prev_s = h.dt_prev2_s = dt;
  h.c_prev = kPoint.Conditions(SineLoad(3 * dt));
  ms.solver.BeginTransient(h.c_prev, ref[3 * m].state);
  ms.solver.RestoreTransient(h);
  FilmState st = ref[3 * m].state;
  const LineContactSolver::Summary step =
      ms.solver.Step(kPoint.Conditions(SineLoad(4 * dt)), dt, &st);
  ASSERT_TRUE(step.usable()) << step.BriefReport();
  const Eigen::VectorXd& q = ms.solver.SaveTransient().q1;
  const Eigen::VectorXd& q_ref = ref[4 * m].history.q1;
  // The estimate's norm: root mean square of the relative error over the loaded nodes.
  double sum = 0;
  int count = 0;
  for (int i = 1; i + 1 < q.size(); ++i)
    if (st.p_pa[i] > 0) {
      sum += std::pow((q[i] - q_ref[i]) / q_ref[i], 2);
      ++count;
    }
  ASSERT_GT(count, 0);
  const double actual = std::sqrt(sum / count);
  std::printf("step T/16 to T/4: estimated local error %.3e, actual %.3e (ratio %.3f)\n",
              step.time_error, actual, step.time_error / actual);
  EXPECT_NEAR(step.time_error / actual, 1.0, 0.3);
}

// H_c at the end of a step of 2 t_b that raises the load from w0 to 1.5 w0, after three
// steps at w0 from the steady film; *substeps and *error from that step's Summary. With
// `jump` the load is 1.5 w0 from the start of the step (Step's c_start), otherwise it ramps
// across the step. `pieces` > 1 takes the step as that many equal steps without control (the
// load as it is at the end of each; after a jump the history starts afresh at the jump, as the
// controlled step does).
double LoadRiseHc(
    double time_tolerance, int* substeps, double* error, bool jump = false, int pieces = 1) {
  LineContactSolver::Options o;
  o.time_tolerance = pieces > 1 ? 0.0 : time_tolerance;
  MoesSolver ms(kPoint, kNodes, o, /*transient=*/true);
  FilmState st;
  EXPECT_TRUE(ms.solver.SolveSteady(kPoint.Conditions(1.0), &st).usable());
  ms.solver.BeginTransient(kPoint.Conditions(1.0), st);
  const double dt = 2.0 * kPoint.TransitTime();
  for (int k = 0; k < 3; ++k) {
    const LineContactSolver::Summary sum = ms.solver.Step(kPoint.Conditions(1.0), dt, &st);
    EXPECT_TRUE(sum.usable()) << sum.BriefReport();
  }
  const ContactConditions risen = kPoint.Conditions(1.5);
  LineContactSolver::Summary sum;
  if (pieces > 1 && jump) ms.solver.BeginTransient(risen, st);
  for (int k = 1; k <= pieces; ++k) {
    const double f = jump ? 1.5 : 1.0 + 0.5 * k / pieces;
    sum = ms.solver.Step(kPoint.Conditions(f), dt / pieces, &st,
                         jump && pieces == 1 ? &risen : nullptr);
    EXPECT_TRUE(sum.usable()) << sum.BriefReport();
  }
  *substeps = sum.substeps;
  *error = sum.time_error;
  return ms.Hc(st);
}

TEST(TimeTolerance, SubstepsAfterALoadRiseBringTheFilmToTheFineStepOne) {
  int n_ref = 0, n_one = 0, n_tol = 0;
  double e_ref = 0, e_one = 0, e_tol = 0;
  const double reference = LoadRiseHc(0.0, &n_ref, &e_ref, false, 256);
  const double one = LoadRiseHc(0.0, &n_one, &e_one);
  const double tol = 1e-3;
  const double controlled = LoadRiseHc(tol, &n_tol, &e_tol);
  std::printf(
      "H_c after the load rise: %.8f (1 step, time_error %.3e), %.8f (%d substeps at "
      "tolerance %.0e, largest time_error %.3e), %.8f (256 steps)\n",
      one, e_one, controlled, n_tol, tol, e_tol, reference);
  EXPECT_EQ(n_one, 1);
  EXPECT_GT(e_one, tol);
  EXPECT_GT(n_tol, 1);
  EXPECT_LE(e_tol, tol);
  EXPECT_LT(std::abs(controlled - reference), 0.25 * std::abs(one - reference));
}

// A load that jumps at the start of a step (c_start) holds over all its substeps: the
// controlled step follows 256 steps at the new load (from the jump), not the ramp.
TEST(TimeTolerance, SubstepsAfterAJumpHoldTheNewLoad) {
  int n = 0;
  double e = 0;
  const double stepped = LoadRiseHc(0.0, &n, &e, /*jump=*/true, /*pieces=*/256);
  const double jump = LoadRiseHc(1e-5, &n, &e, /*jump=*/true);
  const int n_jump = n;
  const double ramp = LoadRiseHc(1e-5, &n, &e, /*jump=*/false);
  std::printf(
      "H_c after the rise: %.10f (256 steps at 1.5 w0), %.10f (controlled, load from the "
      "start, %d substeps), %.10f (controlled, load ramped, %d substeps)\n",
      stepped, jump, n_jump, ramp, n);
  EXPECT_LT(std::abs(jump / stepped - 1.0), 0.1 * std::abs(ramp / stepped - 1.0));
}

// After a load drop (1.5 w0 -> w0 at the start of a step of 2 t_b) the controlled step
// converges as the tolerance falls, each tenth of the tolerance changing H_min less than the
// one before. (Equal steps do not: 256 and 1024 steps give H_min 3.596 and 3.696, and steps of
// 1/4096 of it fail to converge; docs/theory.md, "Time-step error".)
TEST(TimeTolerance, AControlledStepAfterALoadDropConvergesWithTheTolerance) {
  std::vector<double> h_min;
  for (double tolerance : {1e-5, 1e-6, 1e-7}) {
    LineContactSolver::Options o;
    o.time_tolerance = tolerance;
    MoesSolver ms(kPoint, kNodes, o, /*transient=*/true);
    FilmState st;
    ASSERT_TRUE(ms.solver.SolveSteady(kPoint.Conditions(1.5), &st).usable());
    ms.solver.BeginTransient(kPoint.Conditions(1.5), st);
    const double dt = 2.0 * kPoint.TransitTime();
    for (int k = 0; k < 3; ++k)
      ASSERT_TRUE(ms.solver.Step(kPoint.Conditions(1.5), dt, &st).usable());
    const ContactConditions low = kPoint.Conditions(1.0);
    const LineContactSolver::Summary sum = ms.solver.Step(low, dt, &st, &low);
    ASSERT_TRUE(sum.usable()) << sum.BriefReport();
    h_min.push_back(ms.Hmin(st));
    std::printf("tolerance %.0e: H_min %.8f, H_c %.8f after the drop, %d substeps\n", tolerance,
                h_min.back(), ms.Hc(st), sum.substeps);
  }
  const double d1 = std::abs(h_min[1] - h_min[0]), d2 = std::abs(h_min[2] - h_min[1]);
  EXPECT_LT(d2, 0.5 * d1);
  EXPECT_LT(d2 / h_min[2], 1e-3);
}

}  // namespace
}  // namespace tehl
