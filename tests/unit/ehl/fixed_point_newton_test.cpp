// Newton-Krylov on x = G(x) (src/ehl/fixed_point_newton.hpp) on maps whose fixed points are
// known in closed form, including repelling ones that the plain iteration cannot reach.
#include "ehl/fixed_point_newton.hpp"

#include <gtest/gtest.h>

#include <Eigen/LU>

#include <cmath>

namespace tehl::internal {
namespace {

// G(x) = 3x - x^3 per component: fixed points 0 and +-sqrt(2) (3x - x^3 = x <=> x^2 = 2);
// G'(sqrt 2) = 3 - 3 * 2 = -3, so x <- G(x) moves away from sqrt(2) by a factor 3 per step.
bool Cubic(const Eigen::VectorXd& x, Eigen::VectorXd* g) {
  *g = 3 * x - x.cwiseProduct(x).cwiseProduct(x);
  return true;
}

TEST(FixedPointNewton, FindsARepellingFixedPointThePlainIterationLeaves) {
  Eigen::VectorXd plain = Eigen::VectorXd::Constant(3, 1.40), g;
  const double root = std::sqrt(2.0);
  const double start_error = std::abs(plain[0] - root);
  for (int k = 0; k < 3; ++k) {
    Cubic(plain, &g);
    plain = g;
  }
  EXPECT_GT(std::abs(plain[0] - root), 10 * start_error);  // diverges (factor ~3 per step)

  FixedPointNewtonOptions o;
  o.tolerance = 1e-10;
  o.fd_step = 1e-7;
  Eigen::VectorXd x = Eigen::VectorXd::Constant(3, 1.2);
  const FixedPointNewtonResult r = SolveFixedPoint(Cubic, o, &x);
  ASSERT_TRUE(r.converged) << r.message;
  for (int i = 0; i < 3; ++i) EXPECT_NEAR(x[i], root, 1e-9);
  EXPECT_LT(r.residual, 1e-10);
  EXPECT_LE(r.newton_iterations, 8);  // quadratic convergence from 0.21 away
  ASSERT_GE(r.history.size(), 2u);
  // Quadratic: once below 1e-2 the next residual is below the square times a modest factor
  // (|F''| / |F'| ~ 6 sqrt(2) / 4 here), until round-off.
  for (size_t k = 1; k < r.history.size(); ++k)
    if (r.history[k - 1] < 1e-2 && r.history[k - 1] > 1e-6) {
      EXPECT_LT(r.history[k], 10 * r.history[k - 1] * r.history[k - 1]);
    }
}

// A linear map with one eigenvalue above 1 (a positive loop gain: no under-relaxation of the
// plain iteration converges) and a spread of contracting ones: the fixed point solves
// (I - A) x = b exactly. Newton needs one step (GMRES is exact on a linear operator in at
// most as many iterations as distinct eigenvalues).
TEST(FixedPointNewton, SolvesALinearMapWithAnEigenvalueAboveOne) {
  const int n = 40;
  Eigen::VectorXd lambda(n);
  for (int i = 0; i < n; ++i) lambda[i] = i == 0 ? 1.5 : 0.9 * i / n;
  // A = Q diag(lambda) Q^T with a fixed orthogonal Q (Householder reflection of a ramp).
  Eigen::VectorXd v = Eigen::VectorXd::LinSpaced(n, 1.0, 2.0);
  v.normalize();
  const Eigen::MatrixXd q = Eigen::MatrixXd::Identity(n, n) - 2 * v * v.transpose();
  const Eigen::MatrixXd a = q * lambda.asDiagonal() * q.transpose();
  const Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(n, -1.0, 3.0);
  const Eigen::VectorXd exact = (Eigen::MatrixXd::Identity(n, n) - a).partialPivLu().solve(b);
  const FixedPointMap map = [&](const Eigen::VectorXd& x, Eigen::VectorXd* g) {
    *g = a * x + b;
    return true;
  };
  FixedPointNewtonOptions o;
  o.tolerance = 1e-9;
  o.fd_step = 1.0;  // exact for a linear map
  o.max_krylov_iterations = n;
  o.krylov_tolerance = 1e-12;
  o.max_step = 1e9;
  Eigen::VectorXd x = Eigen::VectorXd::Zero(n);
  const FixedPointNewtonResult r = SolveFixedPoint(map, o, &x);
  ASSERT_TRUE(r.converged) << r.message;
  EXPECT_EQ(r.newton_iterations, 1);
  EXPECT_LT((x - exact).cwiseAbs().maxCoeff(), 1e-9 * exact.cwiseAbs().maxCoeff());
}

// Where G cannot be evaluated (here x > 1.6, beyond which a physical map would fail) the
// step is shortened; every evaluation stays inside [lower, upper].
TEST(FixedPointNewton, ShortensStepsWhereTheMapFailsAndKeepsTheBounds) {
  int refused = 0;
  const FixedPointMap map = [&](const Eigen::VectorXd& x, Eigen::VectorXd* g) {
    EXPECT_GE(x.minCoeff(), 0.5);
    EXPECT_LE(x.maxCoeff(), 2.0);
    if (x.maxCoeff() > 1.6) {
      ++refused;
      return false;
    }
    return Cubic(x, g);
  };
  FixedPointNewtonOptions o;
  o.tolerance = 1e-10;
  o.fd_step = 1e-7;
  o.lower = 0.5;
  o.upper = 2.0;
  // F(x) = G(x) - x = 2x - x^3: at x = 1, F = 1 and F' = 2 - 3 = -1, so the Newton step goes
  // to 2 (the upper bound), where the map refuses; half of it, 1.5, has |F| = 0.375 < 1.
  Eigen::VectorXd x = Eigen::VectorXd::Constant(2, 1.0);
  const FixedPointNewtonResult r = SolveFixedPoint(map, o, &x);
  ASSERT_TRUE(r.converged) << r.message;
  EXPECT_NEAR(x[0], std::sqrt(2.0), 1e-9);
  EXPECT_GE(refused, 1);
}

// G(x) = x + 1 has no fixed point: the solve stops with converged = false and says why,
// with a finite iterate.
TEST(FixedPointNewton, ReportsAMapWithoutFixedPoint) {
  const FixedPointMap map = [](const Eigen::VectorXd& x, Eigen::VectorXd* g) {
    *g = x.array() + 1.0;
    return true;
  };
  FixedPointNewtonOptions o;
  Eigen::VectorXd x = Eigen::VectorXd::Zero(4);
  const FixedPointNewtonResult r = SolveFixedPoint(map, o, &x);
  EXPECT_FALSE(r.converged);
  EXPECT_FALSE(r.message.empty());
  EXPECT_NEAR(r.residual, 1.0, 1e-12);
  EXPECT_TRUE(x.allFinite());
}

// G(x) = x + 1 + exp(-x) has no fixed point, and |G(x) - x| = 1 + exp(-x) keeps falling
// towards 1 as x grows. Newton on F = G - x from x = 0 (G' - I = -exp(-x), by a forward
// difference with fd_step 1e-2): step 1 goes to x = 2.0 (|F| 2 -> 1.13), step 2 to x = 10.5
// (|F| -> 1 + 2.7e-5, 12 % lower), step 3 is capped at max_step = 50 (x = 60.5, |F| lower by
// 2.7e-5 relative), and step 4 changes |F| by less than rounding. Steps 3 and 4 are the
// stall_steps = 2 steps below the 0.1 % decrease: the solve stops after 4 steps and says why.
// Without the stall test it creeps on through rounding-level decreases.
TEST(FixedPointNewton, StopsWhenStepsNoLongerLowerTheResidual) {
  const FixedPointMap map = [](const Eigen::VectorXd& x, Eigen::VectorXd* g) {
    *g = x.array() + 1.0 + (-x.array()).exp();
    return true;
  };
  FixedPointNewtonOptions o;
  Eigen::VectorXd x = Eigen::VectorXd::Zero(1);
  const FixedPointNewtonResult r = SolveFixedPoint(map, o, &x);
  EXPECT_FALSE(r.converged);
  EXPECT_EQ(r.newton_iterations, 2 + o.stall_steps);
  EXPECT_NE(r.message.find("stalled"), std::string::npos) << r.message;
  EXPECT_NEAR(r.residual, 1.0, 1e-12);
  EXPECT_GT(x[0], 60.0);  // past the capped step 3 (step 4 moves by rounding noise)

  o.stall_steps = 1000;  // the stall test off
  x.setZero();
  const FixedPointNewtonResult all = SolveFixedPoint(map, o, &x);
  EXPECT_FALSE(all.converged);
  EXPECT_GT(all.newton_iterations, 20) << all.message;
  EXPECT_GT(all.map_evaluations, 5 * r.map_evaluations);
}

// A map that fails at the start is reported at once.
TEST(FixedPointNewton, ReportsAMapThatFailsAtTheStart) {
  const FixedPointMap map = [](const Eigen::VectorXd&, Eigen::VectorXd*) { return false; };
  Eigen::VectorXd x = Eigen::VectorXd::Zero(2);
  const FixedPointNewtonResult r = SolveFixedPoint(map, FixedPointNewtonOptions{}, &x);
  EXPECT_FALSE(r.converged);
  EXPECT_EQ(r.map_evaluations, 1);
  EXPECT_NE(r.message.find("start"), std::string::npos);
}

}  // namespace
}  // namespace tehl::internal
