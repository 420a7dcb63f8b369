// The two linear solvers of the Newton iteration (DESIGN.md section 5: dense LU as the
// reference, Newton-Krylov with FFT Jacobian-vector products for large grids) solve the same
// discrete equations, so they must end at the same pressure to the solver tolerance:
// max |p_dense - p_nk| / max p <= 1e-8, and the same central film (1e-8 relative).
// Case: M = 20, L = 10 (VALIDATION.md section 3, p_H = 0.80 GPa).
#include <gtest/gtest.h>

#include <cstdio>

#include "ehl/film_augmented_preconditioner.hpp"
#include "ehl/newton_system.hpp"
#include "support/random_newton_system.hpp"
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
TEST(LinearSolversVerification, DenseAndNewtonKrylovAgreeOn1025Nodes) { ExpectSameSolution(1025); }
// Two settings that change only how the Newton steps are computed (a preconditioner, FFTW's
// plans) must end at the same film: the Moes point on n nodes, cold, then (warm) re-solved at
// +1 % load; p within the tolerance of the test above.
void ExpectSameFilm(const LineContactSolver::Options (&options)[2], int n, bool warm) {
  const MoesPoint mp{20, 10};
  FilmState states[2];
  for (int k = 0; k < 2; ++k) {
    MoesSolver ms(mp, n, options[k]);
    ContactConditions c = mp.Conditions();
    LineContactSolver::Summary sum = ms.solver.SolveSteady(c, &states[k]);
    if (warm && sum.usable()) {
      c.load_n_per_m *= 1.01;
      sum = ms.solver.SolveSteady(c, &states[k]);
    }
    ASSERT_TRUE(sum.usable()) << sum.BriefReport();
    std::printf("setting %d: %s\n", k, sum.BriefReport().c_str());
  }
  const double rel =
      (states[0].p_pa - states[1].p_pa).lpNorm<Eigen::Infinity>() / states[0].MaxPressure();
  std::printf("max |dp| / max p = %.3g\n", rel);
  EXPECT_LE(rel, 1e-8);
}

LineContactSolver::Options NewtonKrylov() {
  LineContactSolver::Options o;
  o.linear_solver = LinearSolverKind::kNewtonKrylov;
  return o;
}

// From 2049 nodes the two-level preconditioner puts wide coarse hats in the inlet
// (preconditioner_inlet_hats, coarse_correction.hpp). The dense comparison at 4097 nodes
// below covers the same path.
TEST(LinearSolversVerification, InletHatsLeaveTheSolutionUnchangedOn2049Nodes) {
  LineContactSolver::Options o[2] = {NewtonKrylov(), NewtonKrylov()};
  o[0].preconditioner_inlet_hats = 1;
  o[1].preconditioner_inlet_hats = 8;
  ExpectSameFilm(o, 2049, false);
}

// The outlet refresh of the band (preconditioner_outlet_refresh) acts on a kept
// factorization: the warm solve is where it refreshes.
TEST(LinearSolversVerification, OutletRefreshLeavesTheSolutionUnchangedOn2049Nodes) {
  LineContactSolver::Options o[2] = {NewtonKrylov(), NewtonKrylov()};
  o[0].preconditioner_outlet_refresh = 0;
  o[1].preconditioner_outlet_refresh = 16;
  ExpectSameFilm(o, 2049, true);
}

// FFTW's planning effort (Options::fft_plan_effort) changes the rounding of the deflection.
// kEstimate first: FFTW would reuse a measured plan of the same size for it.
TEST(LinearSolversVerification, FftPlanEffortLeavesTheSolutionUnchanged) {
  LineContactSolver::Options o[2];
  o[0].fft_plan_effort = FftPlanEffort::kEstimate;
  o[1].fft_plan_effort = FftPlanEffort::kMeasure;
  ExpectSameFilm(o, 1025, false);
}

// 4097 nodes: dense LU takes about a minute here, so the test is labelled slow
// (ehl_linear_solvers_slow_test).
#ifdef TEHL_SLOW_TESTS
TEST(LinearSolversVerification, DenseAndNewtonKrylovAgreeOn4097Nodes) { ExpectSameSolution(4097); }
#endif

// The augmented preconditioner is exact when nothing is truncated: eliminating the film
// unknowns from the untruncated film rows gives H = H0 + (p_ref/h_ref) K P (each level's rows
// are Dirichlet second differences between nodes of higher levels, the top level is exact),
// i.e. exactly the Jacobian J of newton_system.hpp. So with a half-band >= n the solve must
// invert NewtonSystem::Dense() up to rounding (derivation in film_augmented_preconditioner.hpp):
// cond(J) = 3.6e4 (n = 300) and 4.9e4 (n = 513) by SVD, and the second-difference chains of
// the augmented matrix amplify rounding further (measured 1e-9 .. 1e-8); a wrong row gives
// errors of order 0.1 - 1. Tolerance 1e-6. n - 1 = 299 is not a multiple of the level strides
// (16, 256), which exercises the clamped right neighbours; some rows are cavitated.
void ExpectExactWithFullBand(int n) {
  testing::RandomNewtonSystem rs(n, 7);
  internal::NewtonSystem& sys = rs.sys;
  const Eigen::VectorXd x = rs.RandomVector();
  Eigen::VectorXd y;
  const Eigen::VectorXd jx = sys.Dense() * x;
  internal::FilmAugmentedPreconditioner pre;
  std::string why;
  ASSERT_TRUE(pre.Factorize(sys, n, &why)) << why;
  pre.Solve(jx, &y);
  const double err = (y - x).norm() / x.norm();
  std::printf("n = %d: ||M^-1 J x - x|| / ||x|| = %.3g\n", n, err);
  EXPECT_LE(err, 1e-6);
  // The same factorization pattern is reused when the cavitated set changes.
  sys.cavitated[n / 2] = 1;
  ASSERT_TRUE(pre.Factorize(sys, n, &why)) << why;
  EXPECT_EQ(pre.symbolic_analyses(), 1);
  pre.Solve(sys.Dense() * x, &y);
  EXPECT_LE((y - x).norm() / x.norm(), 1e-6);
}

TEST(LinearSolversVerification, AugmentedPreconditionerIsExactWithFullBand) {
  ExpectExactWithFullBand(300);
  ExpectExactWithFullBand(513);
}

}  // namespace
}  // namespace tehl
