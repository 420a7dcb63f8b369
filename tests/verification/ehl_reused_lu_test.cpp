// The reused-LU linear solver (GMRES preconditioned by the LU of an earlier Jacobian) gives
// the film of the dense reference, steady and along a transient, while factorizing rarely.
#include <gtest/gtest.h>

#include <cmath>

#include "ehl_moes_point.hpp"

namespace tehl {
namespace {

using testing::MoesPoint;
using testing::MoesSolver;

LineContactSolver::Options With(LinearSolverKind k) {
  LineContactSolver::Options o;
  o.linear_solver = k;
  return o;
}

double RelativePressureDifference(const FilmState& a, const FilmState& b) {
  return (a.p_pa - b.p_pa).lpNorm<Eigen::Infinity>() / a.p_pa.lpNorm<Eigen::Infinity>();
}

TEST(ReusedLuVerification, SteadyAndWarmSolvesEqualTheDenseReference) {
  const MoesPoint mp{20.0, 10.0};
  MoesSolver dense(mp, 513, With(LinearSolverKind::kDense));
  MoesSolver reused(mp, 513, With(LinearSolverKind::kReusedLu));
  FilmState sd, sr;
  ASSERT_TRUE(dense.solver.SolveSteady(mp.Conditions(), &sd).usable());
  ASSERT_TRUE(reused.solver.SolveSteady(mp.Conditions(), &sr).usable());
  // Both stop at the scaled residual 1e-8 (a pressure correction below 1e-8 p_H).
  EXPECT_LT(RelativePressureDifference(sd, sr), 1e-8);
  // Warm re-solve after a 1 % load change: GMRES on the old factorization.
  ASSERT_TRUE(dense.solver.SolveSteady(mp.Conditions(1.01), &sd).usable());
  const auto sum = reused.solver.SolveSteady(mp.Conditions(1.01), &sr);
  ASSERT_TRUE(sum.usable()) << sum.BriefReport();
  EXPECT_GT(sum.krylov_iterations, 0);
  EXPECT_LT(RelativePressureDifference(sd, sr), 1e-8);
}

TEST(ReusedLuVerification, TransientLoadChangeFollowsTheDenseReference) {
  const MoesPoint mp{20.0, 10.0};
  MoesSolver dense(mp, 257, With(LinearSolverKind::kDense), true);
  MoesSolver reused(mp, 257, With(LinearSolverKind::kReusedLu), true);
  FilmState sd, sr;
  ASSERT_TRUE(dense.solver.SolveSteady(mp.Conditions(), &sd).usable());
  ASSERT_TRUE(reused.solver.SolveSteady(mp.Conditions(), &sr).usable());
  dense.solver.BeginTransient(mp.Conditions(), sd);
  reused.solver.BeginTransient(mp.Conditions(), sr);
  const double dt = mp.Hertz().half_width_m / mp.um_m_s() / 4;
  for (int k = 1; k <= 20; ++k) {
    const double f = 1.0 + 0.3 * std::sin(3.14159265358979 * k / 20.0);
    ASSERT_TRUE(dense.solver.Step(mp.Conditions(f), dt, &sd).usable()) << k;
    ASSERT_TRUE(reused.solver.Step(mp.Conditions(f), dt, &sr).usable()) << k;
    EXPECT_LT(RelativePressureDifference(sd, sr), 1e-7) << "step " << k;
    EXPECT_NEAR(dense.Hc(sd), reused.Hc(sr), 1e-7 * dense.Hc(sd)) << "step " << k;
  }
}

}  // namespace
}  // namespace tehl
