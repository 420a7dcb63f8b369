// Band LU with interchanges inside row pairs (src/ehl/pair_pivoted_band_lu.hpp).
#include "ehl/pair_pivoted_band_lu.hpp"

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <random>
#include <string>
#include <vector>

namespace tehl {
namespace {

using internal::PairPivotedBandLu;

// A = P D with D strictly diagonally dominant by rows and by columns within the band (diagonal
// 4 (kl + ku + 1), other entries in (-1, 1)) and P interchanging each row pair (2k, 2k + 1)
// with probability 1/2. Gaussian elimination keeps column dominance in every Schur complement,
// so at each pair's first column the larger of the two candidates is D's diagonal: the
// factorization must undo exactly P's interchanges and needs no other pivoting.
struct PairPermutedBand {
  PairPermutedBand(int n, int kl, int ku, unsigned seed) : a(Eigen::MatrixXd::Zero(n, n)) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    for (int i = 0; i < n; ++i)
      for (int j = std::max(0, i - kl); j <= std::min(n - 1, i + ku); ++j)
        a(i, j) = i == j ? 4.0 * (kl + ku + 1) * (u(rng) < 0 ? -1.0 : 1.0) : u(rng);
    for (int k = 0; 2 * k + 1 < n; ++k)
      if (u(rng) < 0) {
        a.row(2 * k).swap(a.row(2 * k + 1));
        ++swapped;
      }
  }
  // Rows 2k and 2k + 1 of a band matrix span columns i - kl ... i + ku each, so A's band is
  // (kl + 1, ku + 1): the storage the factorization is given is the band of D.
  void Load(PairPivotedBandLu* lu, int kl, int ku) const {
    const int n = static_cast<int>(a.rows());
    lu->Reset(n, kl, ku);
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j)
        if (a(i, j) != 0.0) lu->Add(i, j, a(i, j));
  }
  Eigen::MatrixXd a;
  int swapped = 0;
};

// Every length modulo 4 (the substitution works in blocks of four, the pairs leave an odd
// last row alone), narrow and wide bands: the solve is backward stable to round-off (the
// dominance bounds the growth by 2; Higham, "Accuracy and Stability of Numerical
// Algorithms", 2nd ed., theorem 9.9: |L||U| stays of the order of |A|), and it matches
// Eigen's dense partial-pivoting LU to the condition number (<= 3 here) times that.
TEST(PairPivotedBandLu, SolvesPairPermutedBandSystemsLikeDenseLu) {
  struct Shape {
    int kl, ku;
  };
  for (const Shape sh : {Shape{1, 1}, Shape{3, 2}, Shape{4, 3}, Shape{16, 16}, Shape{17, 9}})
    for (int n : {1, 2, 3, 4, 5, 6, 7, 8, 9, 13, 64, 101, 514}) {
      const PairPermutedBand m(n, sh.kl, sh.ku, 7 * n + sh.kl);
      PairPivotedBandLu lu;
      m.Load(&lu, sh.kl, sh.ku);
      ASSERT_TRUE(lu.Factorize(0.1)) << "n " << n << " kl " << sh.kl;
      EXPECT_EQ(lu.pair_swaps(), m.swapped) << "n " << n << " kl " << sh.kl;
      std::mt19937 rng(n);
      std::uniform_real_distribution<double> u(-1.0, 1.0);
      Eigen::VectorXd b(n);
      for (int i = 0; i < n; ++i) b[i] = u(rng);
      Eigen::VectorXd x = b;
      lu.Solve(x.data());
      const double backward = (m.a * x - b).norm() / (m.a.norm() * x.norm());
      const Eigen::VectorXd x_lu = m.a.partialPivLu().solve(b);
      EXPECT_LE(backward, 1e-15 * n + 1e-15) << "n " << n << " kl " << sh.kl;
      EXPECT_LE((x - x_lu).norm(), 1e-13 * x_lu.norm()) << "n " << n << " kl " << sh.kl;
      // The same factors solve again (the work vector's padding must come back clean).
      Eigen::VectorXd again = b;
      lu.Solve(again.data());
      EXPECT_EQ((again - x).lpNorm<Eigen::Infinity>(), 0.0);
    }
}

// Replacing the rows from an even row on and eliminating again from there gives the factors
// of the new matrix: the solve agrees with a fresh factorization of it to round-off (both are
// backward stable, the condition number is <= 3; see the test above), and the interchanges are
// the new matrix's, for splits near the start, in the middle, within a band of the end and past
// it, with the old and the new rows interchanged in different pairs.
TEST(PairPivotedBandLu, RefactorizingFromARowMatchesAFreshFactorization) {
  struct Shape {
    int kl, ku;
  };
  for (const Shape sh : {Shape{1, 1}, Shape{4, 3}, Shape{16, 16}, Shape{17, 9}})
    for (int n : {9, 64, 101, 514})
      for (int row :
           {0, 2, n / 2 / 2 * 2, (n - sh.kl) / 2 * 2, n - 1 - (n - 1) % 2, n / 2 * 2 + 2}) {
        if (row < 0) continue;
        const PairPermutedBand old_m(n, sh.kl, sh.ku, 3 * n + sh.kl);
        const PairPermutedBand new_m(n, sh.kl, sh.ku, 5 * n + sh.ku + 1);
        Eigen::MatrixXd mixed = old_m.a;
        int swapped = 0;
        for (int k = 0; 2 * k + 1 < n; ++k) {
          if (2 * k >= row) mixed.middleRows(2 * k, 2) = new_m.a.middleRows(2 * k, 2);
          const auto& src = 2 * k >= row ? new_m.a : old_m.a;
          // A pair is interchanged where its first row's diagonal entry sits one column on.
          swapped += std::abs(src(2 * k, 2 * k)) < std::abs(src(2 * k, 2 * k + 1));
        }
        if (n % 2 == 1 && n - 1 >= row) mixed.row(n - 1) = new_m.a.row(n - 1);
        PairPivotedBandLu lu;
        old_m.Load(&lu, sh.kl, sh.ku);
        ASSERT_TRUE(lu.Factorize(0.1));
        lu.ClearRowsFrom(row);
        for (int i = row; i < n; ++i)
          for (int j = 0; j < n; ++j)
            if (mixed(i, j) != 0.0) lu.Add(i, j, mixed(i, j));
        const std::string at = "n " + std::to_string(n) + " kl " + std::to_string(sh.kl) + " row " +
                               std::to_string(row);
        ASSERT_TRUE(lu.RefactorizeFrom(row, 0.1)) << at;
        EXPECT_EQ(lu.pair_swaps(), swapped) << at;
        Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(n, -1.0, 1.0).array().sin(), x = b;
        lu.Solve(x.data());
        EXPECT_LE((mixed * x - b).norm(), 1e-15 * n * mixed.norm() * x.norm()) << at;
        PairPivotedBandLu fresh;
        PairPermutedBand m = old_m;
        m.a = mixed;
        m.Load(&fresh, sh.kl, sh.ku);
        ASSERT_TRUE(fresh.Factorize(0.1));
        Eigen::VectorXd y = b;
        fresh.Solve(y.data());
        EXPECT_LE((x - y).norm(), 1e-13 * y.norm()) << at;
      }
  PairPivotedBandLu lu;  // an odd row, or nothing factorized yet: refused
  lu.Reset(8, 1, 1);
  for (int i = 0; i < 8; ++i) lu.Add(i, i, 1.0);
  EXPECT_FALSE(lu.RefactorizeFrom(2, 0.1));
  ASSERT_TRUE(lu.Factorize(0.1));
  EXPECT_FALSE(lu.RefactorizeFrom(3, 0.1));
}

// A pivot below `threshold` times the largest entry under it refuses the factorization (the
// preconditioner then falls back on dgbtrf); a lower threshold accepts the same matrix.
TEST(PairPivotedBandLu, RefusesAPivotBelowTheThreshold) {
  const int n = 8, kl = 2, ku = 2;
  Eigen::MatrixXd a = Eigen::MatrixXd::Zero(n, n);
  for (int i = 0; i < n; ++i) {
    a(i, i) = 4.0;
    if (i + 1 < n) a(i, i + 1) = a(i + 1, i) = 1.0;
  }
  // Column 0: the pair offers 1e-3 and 1, row 2 (outside the pair) 20. After rows 0 and 1
  // are interchanged, column 1's pivot is 1 - 4e-3 = 0.996 against 1 - 20 * 4 = -79 below it.
  a(0, 0) = 1e-3;
  a(2, 0) = 20.0;
  auto load = [&](PairPivotedBandLu* lu) {
    lu->Reset(n, kl, ku);
    for (int i = 0; i < n; ++i)
      for (int j = std::max(0, i - kl); j <= std::min(n - 1, i + ku); ++j)
        if (a(i, j) != 0.0) lu->Add(i, j, a(i, j));
  };
  PairPivotedBandLu lu;
  load(&lu);
  EXPECT_FALSE(lu.Factorize(0.1));  // column 0: 1 < 0.1 * 20
  load(&lu);
  EXPECT_FALSE(lu.Factorize(0.02));  // column 0 passes, column 1: 0.996 < 0.02 * 79
  load(&lu);
  ASSERT_TRUE(lu.Factorize(0.005));  // rows 0 and 1 interchanged, later pivots pass
  EXPECT_EQ(lu.pair_swaps(), 1);
  Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(n, -1.0, 2.0), x = b;
  lu.Solve(x.data());
  EXPECT_LE((a * x - b).norm(), 1e-13 * b.norm());
  // A zero pivot is refused whatever the threshold.
  Eigen::MatrixXd z = Eigen::MatrixXd::Zero(4, 4);
  z(0, 1) = z(1, 0) = z(2, 3) = z(3, 2) = 1.0;
  z(1, 1) = 0.0;
  lu.Reset(4, 1, 1);
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j)
      if (z(i, j) != 0.0) lu.Add(i, j, z(i, j));
  // Column 0: pair (1, 0) swapped in; column 1 then has the old row 0's 1 on the diagonal;
  // the same for the second pair: this permutation matrix factorizes.
  EXPECT_TRUE(lu.Factorize(0.0));
  lu.Reset(3, 1, 1);  // rows 0 and 1 interchanged, row 2 all zero: singular
  lu.Add(0, 1, 1.0);
  lu.Add(1, 0, 1.0);
  EXPECT_FALSE(lu.Factorize(0.0));
}

}  // namespace
}  // namespace tehl
