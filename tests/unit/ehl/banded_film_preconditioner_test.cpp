// The one-level augmented preconditioner as a bordered band LU (banded_film_preconditioner.hpp)
// and the coarse-space correction it is used with (coarse_correction.hpp).
#include "ehl/banded_film_preconditioner.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

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

// Refresh from node k: the Reynolds rows of nodes k .. n - 2 of a new system, the rows before
// them of the old one, eliminated again from about k on. It must precondition exactly like a
// fresh factorization of that mixed system (the same matrix, so the same solve up to rounding
// of the reconstructed Schur rows: 1e-12 relative), for k at the first node, in the middle,
// just before the cavitated outlet of either system (the new one cavitates 7 nodes earlier),
// and at the last node; a factorization by dgbtrf (no pair interchanges) refuses it.
TEST(BandedFilmPreconditioner, RefreshFromANodeEqualsAFreshFactorizationOfTheMixedSystem) {
  const int n = 513, band = 8;
  testing::RandomNewtonSystem old_s(n, 5), new_s(n, 9);
  for (int i = n - n / 5 - 7; i < n - n / 5; ++i) new_s.sys.cavitated[i] = 1;
  for (int k : {1, 256, n - n / 5 - 20, n - n / 5 - 3, n - 2}) {
    internal::BandedFilmPreconditioner refreshed, fresh;  // pair interchanges, as above
    refreshed.set_pair_pivot_threshold(0.0);
    fresh.set_pair_pivot_threshold(0.0);
    std::string why;
    ASSERT_TRUE(refreshed.Factorize(old_s.sys, band, &why)) << why;
    ASSERT_TRUE(refreshed.paired());
    ASSERT_TRUE(refreshed.Refresh(new_s.sys, k, &why)) << "k " << k << " " << why;
    Eigen::Matrix<double, Eigen::Dynamic, 4> a = old_s.a, b = old_s.b;
    Eigen::VectorXd c = old_s.c;
    internal::NewtonSystem mixed = old_s.sys;
    mixed.a = &a;
    mixed.b = &b;
    mixed.row_scale = &c;
    for (int i = k; i < n; ++i) {
      a.row(i) = new_s.a.row(i);
      b.row(i) = new_s.b.row(i);
      c[i] = new_s.c[i];
      mixed.cavitated[i] = new_s.sys.cavitated[i];
    }
    ASSERT_TRUE(fresh.Factorize(mixed, band, &why)) << why;
    const Eigen::VectorXd x = new_s.RandomVector();
    Eigen::VectorXd y_refreshed, y_fresh;
    refreshed.Solve(x, &y_refreshed);
    fresh.Solve(x, &y_fresh);
    EXPECT_LE((y_refreshed - y_fresh).norm(), 1e-12 * y_fresh.norm()) << "k " << k;
    // ... and not like the old system's factorization (the test can tell them apart).
    if (k < n - 2) {
      internal::BandedFilmPreconditioner stale;
      stale.set_pair_pivot_threshold(0.0);
      ASSERT_TRUE(stale.Factorize(old_s.sys, band, &why));
      Eigen::VectorXd y_stale;
      stale.Solve(x, &y_stale);
      EXPECT_GT((y_stale - y_fresh).norm(), 1e-6 * y_fresh.norm()) << "k " << k;
    }
  }
  internal::BandedFilmPreconditioner lapack;
  lapack.set_pair_pivot_threshold(-1.0);
  std::string why;
  ASSERT_TRUE(lapack.Factorize(old_s.sys, band, &why));
  EXPECT_FALSE(lapack.Refresh(new_s.sys, 256, &why));
}

// The coarse matrix E = W^T J Z built from the hat-smoothed kernel equals the product formed
// column by column with the Jacobian's own (FFT) product, and the correction C = Z E^{-1} W^T
// is a Galerkin projection: W^T (x - J C x) = 0 for any x.
// With wide_multiple m > 1 the hats below node wide_until are m G wide (coarse_correction.hpp);
// Z is built here from that rule, hat by hat, independently of the library's merge P.
void ExpectGalerkinProduct(int n, int g, int wide_until = 0, int m = 1) {
  testing::RandomNewtonSystem rs(n, 5);
  internal::CoarseCorrection cc;
  ASSERT_TRUE(cc.Build(rs.sys, g, wide_until, m));
  const int lattice = (n - 1) / g - 1, nm = n - 2;
  std::vector<int> centre;  // hat centres (nodes)
  if (m > 1)
    for (int j = m; j <= lattice && j * g < wide_until; j += m) centre.push_back(j * g);
  for (int j = centre.empty() ? 1 : centre.back() / g + 1; j <= lattice; ++j)
    centre.push_back(j * g);
  const int nc = static_cast<int>(centre.size());
  ASSERT_EQ(cc.coarse_size(), nc + 1);
  // Z and W: hats between neighbouring centres (node 0 and node (lattice + 1) g close the
  // ends), then e_H0 / e_load (unknown index node - 1).
  Eigen::MatrixXd z = Eigen::MatrixXd::Zero(nm + 1, nc + 1);
  for (int c = 0; c < nc; ++c) {
    const int a = c ? centre[c - 1] : 0, b = c + 1 < nc ? centre[c + 1] : (lattice + 1) * g;
    for (int node = a + 1; node < b; ++node)
      z(node - 1, c) = node <= centre[c] ? double(node - a) / (centre[c] - a)
                                         : double(b - node) / (b - centre[c]);
  }
  z(nm, nc) = 1.0;
  Eigen::MatrixXd jz(nm + 1, nc + 1);
  for (int c = 0; c <= nc; ++c) {
    Eigen::VectorXd col;
    rs.sys.Apply(z.col(c), &col);
    jz.col(c) = col;
  }
  const Eigen::MatrixXd e = z.transpose() * jz;
  const double err = (cc.matrix() - e).cwiseAbs().maxCoeff() / e.cwiseAbs().maxCoeff();
  std::printf("%d coarse pressures: max |E - W^T J Z| / max |E| = %.3g\n", nc, err);
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

// Hats 8 G wide up to node 200 (the last wide hat then also reaches the first narrow centre),
// and a switch point that falls between wide centres.
TEST(CoarseCorrection, WideInletHatsGiveTheGalerkinProductOfTheirSpace) {
  ExpectGalerkinProduct(513, 4, 200, 8);
  ExpectGalerkinProduct(1025, 7, 333, 3);
}

TEST(CoarseCorrection, GalerkinProductHoldsOnALargeGrid) { ExpectGalerkinProduct(8193, 64); }

// ElasticZoneStart: the first fluid row whose film coupling sum |b| / sum |a| exceeds 1e-6 of
// the largest. Rows here: |a| = 1 everywhere, |b| = 10^(-12 + 12 i / 200) up to node 200 and 1
// beyond, so the ratio first exceeds 1e-6 where -12 + 12 i / 200 > -6, at i = 101; the
// cavitated tail (largest |b| there, 1e3) must not count, and a rigid system has no zone.
TEST(CoarseCorrection, ElasticZoneStartsWhereTheFilmCouplingReachesAMillionth) {
  testing::RandomNewtonSystem rs(257, 3);
  for (int i = 0; i < 257; ++i) {
    const double scale = i < 200 ? std::pow(10.0, -12.0 + 12.0 * i / 200) : 1.0;
    for (int q = 0; q < 4; ++q) {
      rs.a(i, q) = (q % 2 ? -0.25 : 0.25);
      rs.b(i, q) = (q % 2 ? 0.25 : -0.25) * (rs.sys.cavitated[i] ? 1e3 : scale);
    }
  }
  EXPECT_EQ(internal::ElasticZoneStart(rs.sys), 101);
  rs.sys.elastic = nullptr;
  EXPECT_EQ(internal::ElasticZoneStart(rs.sys), 0);
}

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
