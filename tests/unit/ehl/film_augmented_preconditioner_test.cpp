// The solve of the augmented preconditioner (film_augmented_preconditioner.hpp) with the
// triangular factors taken out of UMFPACK. With a half-band >= n nothing is truncated, so
// eliminating the film unknowns reproduces the Jacobian J of newton_system.hpp exactly
// (derivation in film_augmented_preconditioner.hpp) and the solve is a direct solve of J.
#include "ehl/film_augmented_preconditioner.hpp"

#include <gtest/gtest.h>

#include "support/direct_solve_check.hpp"

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
TEST(FilmAugmentedPreconditioner, FullBandSolveIsADirectSolveOfTheJacobian) {
  using internal::FilmAugmentedPreconditioner;
  // n - 1 not a multiple of the strides: clamped neighbours.
  testing::ExpectDirectSolveOfJ<FilmAugmentedPreconditioner>(300, 1e-12, 1e-7);
  testing::ExpectDirectSolveOfJ<FilmAugmentedPreconditioner>(513, 1e-12, 1e-7);
}

}  // namespace
}  // namespace tehl
