// The two linear solvers of the Newton iteration (DESIGN.md section 5: dense LU as the
// reference, Newton-Krylov with FFT Jacobian-vector products for large grids) solve the same
// discrete equations, so they must end at the same pressure to the solver tolerance:
// max |p_dense - p_nk| / max p <= 1e-8, and the same central film (1e-8 relative).
// Case: M = 20, L = 10 (VALIDATION.md section 3, p_H = 0.80 GPa).
#include <gtest/gtest.h>

#include <cstdio>

#include "verification/ehl_moes_point.hpp"

namespace tehl {
namespace {

using testing::MoesPoint;
using testing::MoesSolver;

void ExpectSameSolution(int n) {
  const MoesPoint mp{20, 10};
  FilmState states[2];
  double hc[2];
  const LinearSolverKind kinds[2] = {LinearSolverKind::kDense, LinearSolverKind::kNewtonKrylov};
  for (int k = 0; k < 2; ++k) {
    LineContactSolver::Options o;
    o.linear_solver = kinds[k];
    MoesSolver ms(mp, n, o);
    const LineContactSolver::Summary sum = ms.solver.SolveSteady(mp.Conditions(), &states[k]);
    ASSERT_TRUE(sum.usable()) << ToString(kinds[k]) << ": " << sum.BriefReport();
    EXPECT_EQ(sum.linear_solver, ToString(kinds[k]));
    hc[k] = ms.Hc(states[k]);
    std::printf("n = %d, %s: H_c = %.12f, %s\n", n, ToString(kinds[k]).c_str(), hc[k],
                sum.BriefReport().c_str());
  }
  const double dp = (states[0].p_pa - states[1].p_pa).lpNorm<Eigen::Infinity>();
  const double rel = dp / states[0].MaxPressure();
  std::printf("n = %d: max |dp| / max p = %.3g, |dH_c| / H_c = %.3g\n", n, rel,
              std::abs(hc[0] - hc[1]) / hc[0]);
  EXPECT_LE(rel, 1e-8) << "n = " << n;
  EXPECT_NEAR(hc[1] / hc[0], 1.0, 1e-8) << "n = " << n;
}

TEST(LinearSolversVerification, DenseAndNewtonKrylovAgreeOn257Nodes) { ExpectSameSolution(257); }
TEST(LinearSolversVerification, DenseAndNewtonKrylovAgreeOn513Nodes) { ExpectSameSolution(513); }
TEST(LinearSolversVerification, DenseAndNewtonKrylovAgreeOn1025Nodes) {
  ExpectSameSolution(1025);
}
// Known failure, kept visible: on 4097 nodes GMRES with the banded preconditioner stalls
// (relative residual 0.37 after 400 iterations with band 24, 0.097 with 48, 0.077 with 96) and
// the solve ends in linear_solver_failed after the continuation stages (65 s); dense LU
// converges in 4 iterations (docs/validation.md). Run with --gtest_also_run_disabled_tests.
TEST(LinearSolversVerification, DISABLED_DenseAndNewtonKrylovAgreeOn4097Nodes) {
  ExpectSameSolution(4097);
}

}  // namespace
}  // namespace tehl
