// The one-level augmented preconditioner as a bordered band LU (banded_film_preconditioner.hpp)
// and the coarse-space correction it is used with (coarse_correction.hpp).
#include "ehl/banded_film_preconditioner.hpp"

#include <gtest/gtest.h>

#include <cstdio>

#include "ehl/coarse_correction.hpp"
#include "ehl/newton_system.hpp"
#include "support/direct_solve_check.hpp"
#include "support/random_newton_system.hpp"

namespace tehl {
namespace {

// With a half-band >= n nothing is truncated: the film rows are the second differences of
// H = H0 + (p_ref/h_ref) K P between the two exact end rows, so eliminating H reproduces J of
// newton_system.hpp and the solve is a direct solve of J. Bound on the backward error
// ||J y - r|| / (||J|| ||y||): LAPACK's banded LU with partial pivoting is backward stable
// (O(eps) times a modest growth factor), and recovering H through one chain of n second
// differences amplifies by up to the chain's condition, ~n^2/8 (3.3e4 at n = 513): with
// eps = 2.2e-16 that is 7e-12, so 1e-10 leaves room for the growth factor (measured 2.5e-14
// and 1.1e-13). The forward error against dense LU is bounded by cond(J) (<= 5e4 at these n,
// film_augmented_preconditioner_test.cpp) times that: 5e-6.
// Both factorizations of the core: interchanges within node pairs (accepting any nonzero
// pivot, so that this random system takes that path) and LAPACK's dgbtrf.
template <int kThresholdTimes10>
struct BandedWithThreshold : internal::BandedFilmPreconditioner {
  BandedWithThreshold() { set_pair_pivot_threshold(0.1 * kThresholdTimes10); }
  bool Factorize(const internal::NewtonSystem& s, int band, std::string* why) {
    const bool ok = internal::BandedFilmPreconditioner::Factorize(s, band, why);
    EXPECT_EQ(paired(), kThresholdTimes10 >= 0);
    return ok;
  }
};

TEST(BandedFilmPreconditioner, FullBandSolveIsADirectSolveOfTheJacobian) {
  testing::ExpectDirectSolveOfJ<BandedWithThreshold<0>>(300, 1e-10, 5e-6);
  testing::ExpectDirectSolveOfJ<BandedWithThreshold<0>>(513, 1e-10, 5e-6);
  testing::ExpectDirectSolveOfJ<BandedWithThreshold<-10>>(300, 1e-10, 5e-6);
  testing::ExpectDirectSolveOfJ<BandedWithThreshold<-10>>(513, 1e-10, 5e-6);
}

// The coarse matrix E = W^T J Z built from the hat-smoothed kernel equals the product formed
// column by column with the Jacobian's own (FFT) product, and the correction C = Z E^{-1} W^T
// is a Galerkin projection: W^T (x - J C x) = 0 for any x.
void ExpectGalerkinProduct(int n, int g) {
  testing::RandomNewtonSystem rs(n, 5);
  internal::CoarseCorrection cc;
  ASSERT_TRUE(cc.Build(rs.sys, g));
  const int nc = (n - 1) / g - 1, m = n - 2;
  ASSERT_EQ(cc.coarse_size(), nc + 1);
  // Z and W: hats centred at nodes (c + 1) g (unknown index node - 1), then e_H0 / e_load.
  Eigen::MatrixXd z = Eigen::MatrixXd::Zero(m + 1, nc + 1);
  for (int c = 0; c < nc; ++c)
    for (int node = 1; node <= m; ++node) {
      const double d = std::abs(node - (c + 1) * g);
      if (d < g) z(node - 1, c) = 1.0 - d / g;
    }
  z(m, nc) = 1.0;
  Eigen::MatrixXd jz(m + 1, nc + 1);
  for (int c = 0; c <= nc; ++c) {
    Eigen::VectorXd col;
    rs.sys.Apply(z.col(c), &col);
    jz.col(c) = col;
  }
  const Eigen::MatrixXd e = z.transpose() * jz;
  const double err = (cc.matrix() - e).cwiseAbs().maxCoeff() / e.cwiseAbs().maxCoeff();
  std::printf("max |E - W^T J Z| / max |E| = %.3g\n", err);
  EXPECT_LE(err, 1e-12);  // both sum the same kernel products; the FFT adds ~1e-15
  const Eigen::VectorXd x = rs.RandomVector();
  Eigen::VectorXd cx, jcx;
  cc.Apply(x, &cx);
  rs.sys.Apply(cx, &jcx);
  const Eigen::VectorXd coarse_residual = z.transpose() * (x - jcx);
  EXPECT_LE(coarse_residual.norm(), 1e-10 * (z.transpose() * x).norm());
}

TEST(CoarseCorrection, CoarseMatrixIsTheGalerkinProductOfTheJacobian) {
  ExpectGalerkinProduct(513, 16);
}

// The hat-smoothed kernel comes from prefix sums over the whole grid: on a large grid their
// differences must still keep double precision.
TEST(CoarseCorrection, GalerkinProductHoldsOnALargeGrid) { ExpectGalerkinProduct(8193, 64); }

// The solver's rule (coarse_correction.hpp): c to about 2c coarse pressures (the floor of the
// stride adds up to 10 %: 272 of them at 4097 nodes for c = 128), one per 16 cells in
// between; stride 2 when the grid has fewer than 2 (c + 1) cells.
TEST(CoarseCorrection, StrideGivesBetweenCAndAbout2CCoarsePressures) {
  for (int c : {16, 128}) {
    for (int n = 129; n <= 65537; n = 2 * n - 1) {
      const int g = internal::CoarseStride(n, c);
      const int nc = (n - 1) / g - 1;  // hats inside the grid (CoarseCorrection::Build)
      if (n - 1 < 2 * (c + 1)) {
        EXPECT_EQ(g, 2) << n;
        continue;
      }
      EXPECT_GE(nc, c) << "n " << n << " c " << c;
      EXPECT_LE(nc, 2.2 * c) << "n " << n << " c " << c;
    }
  }
}

}  // namespace
}  // namespace tehl
