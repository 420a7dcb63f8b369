// The solve of the augmented preconditioner (film_augmented_preconditioner.hpp) with the
// triangular factors taken out of UMFPACK. With a half-band >= n nothing is truncated, so
// eliminating the film unknowns reproduces the Jacobian J of newton_system.hpp exactly
// (derivation in film_augmented_preconditioner.hpp) and the solve is a direct solve of J.
#include "ehl/film_augmented_preconditioner.hpp"

#include <gtest/gtest.h>

#include <Eigen/LU>
#include <cstdio>
#include <string>

#include "ehl/newton_system.hpp"
#include "support/random_newton_system.hpp"

namespace tehl {
namespace {

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
  testing::RandomNewtonSystem rs(n, 11);
  const Eigen::VectorXd rhs = rs.RandomVector();
  const Eigen::MatrixXd j = rs.sys.Dense();
  internal::FilmAugmentedPreconditioner pre;
  std::string why;
  ASSERT_TRUE(pre.Factorize(rs.sys, n, &why)) << why;
  Eigen::VectorXd y;
  pre.Solve(rhs, &y);
  const double backward = (j * y - rhs).norm() / (j.norm() * y.norm());
  const Eigen::VectorXd y_lu = j.partialPivLu().solve(rhs);
  const double forward = (y - y_lu).norm() / y_lu.norm();
  std::printf("n = %d: backward error %.3g, forward error vs dense LU %.3g\n", n, backward,
              forward);
  EXPECT_LE(backward, 1e-12);
  EXPECT_LE(forward, 1e-7);
  // The same factorization solves again with the same result (buffers reused, no state
  // carried between solves), and the input may alias the output.
  Eigen::VectorXd again = rhs;
  pre.Solve(again, &again);
  EXPECT_EQ((again - y).lpNorm<Eigen::Infinity>(), 0.0);
  // A second factorization with another cavitated set (same pattern) solves that system.
  rs.sys.cavitated[n / 2] = 1;
  ASSERT_TRUE(pre.Factorize(rs.sys, n, &why)) << why;
  pre.Solve(rhs, &y);
  const Eigen::MatrixXd j2 = rs.sys.Dense();
  EXPECT_LE((j2 * y - rhs).norm() / (j2.norm() * y.norm()), 1e-12);
}

TEST(FilmAugmentedPreconditioner, FullBandSolveIsADirectSolveOfTheJacobian) {
  ExpectDirectSolveOfJ(300);  // n - 1 not a multiple of the strides: clamped neighbours
  ExpectDirectSolveOfJ(513);
}

}  // namespace
}  // namespace tehl
