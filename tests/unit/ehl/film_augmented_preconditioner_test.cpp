// The solve of the augmented preconditioner (film_augmented_preconditioner.hpp) with the
// triangular factors taken out of UMFPACK. With a half-band >= n nothing is truncated, so
// eliminating the film unknowns reproduces the Jacobian J of newton_system.hpp exactly
// (derivation in film_augmented_preconditioner.hpp) and the solve is a direct solve of J.
#include "ehl/film_augmented_preconditioner.hpp"

#include <gtest/gtest.h>

#include <Eigen/LU>
#include <cstdio>
#include <random>
#include <string>

#include "ehl/newton_system.hpp"
#include "tehl/ehl/elastic_deflection.hpp"

namespace tehl {
namespace {

// A Newton system with random Reynolds stencils of order-one scaled entries (as the solver's
// row weights make them) and the real elastic kernel; the last fifth of the rows cavitated.
struct RandomSystem {
  explicit RandomSystem(int n)
      : kernel(n, 1e-6, 226.4e9, FftPlanEffort::kEstimate), a(n, 4), b(n, 4), c(n) {
    std::mt19937 rng(11);
    std::uniform_real_distribution<double> u(0.5, 1.5);
    const double p_ref = 1e9, h_ref = 1e-7;  // [Pa], [m]
    for (int i = 0; i < n; ++i) {
      a.row(i) << 0.1 * u(rng), -1.0 * u(rng), 2.0 * u(rng), -1.0 * u(rng);
      b.row(i) << 0.5 * u(rng), -2.0 * u(rng), 1.5 * u(rng), 0.0;
      a.row(i) /= p_ref;
      b.row(i) /= h_ref;
      c[i] = -1.0 / (2.0 * u(rng));
    }
    sys.n = n;
    sys.dx = 1e-6;
    sys.p_ref = p_ref;
    sys.h_ref = h_ref;
    sys.row_scale = &c;
    sys.load = 1e5;
    sys.a = &a;
    sys.b = &b;
    sys.elastic = &kernel;
    sys.cavitated.assign(n, 0);
    for (int i = n - n / 5; i < n - 1; ++i) sys.cavitated[i] = 1;
    rhs.resize(n - 1);
    for (int i = 0; i < n - 1; ++i) rhs[i] = u(rng) - 1.0;
  }
  ElasticDeflection kernel;
  Eigen::Matrix<double, Eigen::Dynamic, 4> a, b;
  Eigen::VectorXd c, rhs;
  internal::NewtonSystem sys;
};

// Backward error of the full-band solve: ||J y - r|| / (||J|| ||y||) with y = M^{-1} r. A
// backward-stable LU solve leaves O(eps) times a modest growth factor; the elimination of
// the film unknowns through the second-difference chains of the hierarchy adds one more
// factor of the chain length (<= 16 per level, 2 levels at these n), so 1e-12 is a safe bound
// (measured 1.4e-15 and 2.5e-15). UMFPACK's row scales applied as multipliers instead of
// divisors give 4e-4 .. 9e-4, a wrong permutation or factor entry more; factor values rounded
// to float give 4e-8 .. 5e-8. The relative forward error against
// Eigen's dense LU of J is bounded by cond(J) (3.6e4 at n = 300, 4.9e4 at n = 513, by SVD;
// tests/verification/ehl_linear_solvers_test.cpp) times that: 1e-12 * 5e4 < 1e-7.
void ExpectDirectSolveOfJ(int n) {
  RandomSystem rs(n);
  const Eigen::MatrixXd j = rs.sys.Dense();
  internal::FilmAugmentedPreconditioner pre;
  std::string why;
  ASSERT_TRUE(pre.Factorize(rs.sys, n, &why)) << why;
  Eigen::VectorXd y;
  pre.Solve(rs.rhs, &y);
  const double backward = (j * y - rs.rhs).norm() / (j.norm() * y.norm());
  const Eigen::VectorXd y_lu = j.partialPivLu().solve(rs.rhs);
  const double forward = (y - y_lu).norm() / y_lu.norm();
  std::printf("n = %d: backward error %.3g, forward error vs dense LU %.3g\n", n, backward,
              forward);
  EXPECT_LE(backward, 1e-12);
  EXPECT_LE(forward, 1e-7);
  // The same factorization solves again with the same result (buffers reused, no state
  // carried between solves), and the input may alias the output.
  Eigen::VectorXd again = rs.rhs;
  pre.Solve(again, &again);
  EXPECT_EQ((again - y).lpNorm<Eigen::Infinity>(), 0.0);
  // A second factorization with another cavitated set (same pattern) solves that system.
  rs.sys.cavitated[n / 2] = 1;
  ASSERT_TRUE(pre.Factorize(rs.sys, n, &why)) << why;
  pre.Solve(rs.rhs, &y);
  const Eigen::MatrixXd j2 = rs.sys.Dense();
  EXPECT_LE((j2 * y - rs.rhs).norm() / (j2.norm() * y.norm()), 1e-12);
}

TEST(FilmAugmentedPreconditioner, FullBandSolveIsADirectSolveOfTheJacobian) {
  ExpectDirectSolveOfJ(300);  // n - 1 not a multiple of the strides: clamped neighbours
  ExpectDirectSolveOfJ(513);
}

}  // namespace
}  // namespace tehl
