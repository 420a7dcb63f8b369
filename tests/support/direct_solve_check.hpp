// A preconditioner that keeps every entry of the kernel (half-band >= n) is a direct solve of
// the Newton system's Jacobian J (newton_system.hpp): the check shared by the tests of the
// augmented preconditioners (film_augmented_preconditioner_test.cpp,
// banded_film_preconditioner_test.cpp), each with the bounds its own analysis gives.
#pragma once

#include <gtest/gtest.h>

#include <Eigen/LU>
#include <cstdio>
#include <string>

#include "ehl/newton_system.hpp"
#include "support/random_newton_system.hpp"

namespace tehl::testing {

// Backward error ||J y - r|| / (||J|| ||y||) of y = M^{-1} r <= backward_bound, and the
// forward error against Eigen's dense LU of J <= forward_bound; the same factorization solves
// again with the same result (input aliasing the output), and a refactorization with another
// cavitated set solves that system.
template <class Preconditioner>
void ExpectDirectSolveOfJ(int n, double backward_bound, double forward_bound) {
  RandomNewtonSystem rs(n, 11);
  const Eigen::VectorXd rhs = rs.RandomVector();
  const Eigen::MatrixXd j = rs.sys.Dense();
  Preconditioner pre;
  std::string why;
  ASSERT_TRUE(pre.Factorize(rs.sys, n, &why)) << why;
  Eigen::VectorXd y;
  pre.Solve(rhs, &y);
  const double backward = (j * y - rhs).norm() / (j.norm() * y.norm());
  const Eigen::VectorXd y_lu = j.partialPivLu().solve(rhs);
  const double forward = (y - y_lu).norm() / y_lu.norm();
  std::printf("n = %d: backward error %.3g, forward error vs dense LU %.3g\n", n, backward,
              forward);
  EXPECT_LE(backward, backward_bound);
  EXPECT_LE(forward, forward_bound);
  Eigen::VectorXd again = rhs;
  pre.Solve(again, &again);
  EXPECT_EQ((again - y).lpNorm<Eigen::Infinity>(), 0.0);
  rs.sys.cavitated[n / 2] = 1;
  ASSERT_TRUE(pre.Factorize(rs.sys, n, &why)) << why;
  pre.Solve(rhs, &y);
  const Eigen::MatrixXd j2 = rs.sys.Dense();
  EXPECT_LE((j2 * y - rhs).norm() / (j2.norm() * y.norm()), backward_bound);
}

}  // namespace tehl::testing
