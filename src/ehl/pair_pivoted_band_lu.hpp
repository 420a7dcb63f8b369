// Band LU whose row interchanges stay inside pairs of rows (2k, 2k + 1), and its substitution
// in blocks of four columns. For the preconditioner of banded_film_preconditioner.hpp, whose
// unknowns come in pairs per node (H_k, P_k).
//
// Why: LAPACK's dgbtrf pivots over the whole band, and its row interchanges are applied only
// to the columns after the pivot's (A = P_0 L_0 P_1 L_1 ... U), so the substitution has to
// interleave them with the column updates; on the film system 75 % of the columns interchange
// (measured at 513 ... 8193 nodes), which sends the unknowns next in line through memory at
// nearly every column, and turning the factors into P A = L U spreads L over most of the
// matrix (an interchange can carry a multiplier one row further at every later column).
// Confined to a pair, an interchange is decided at the pair's first column and applied to the
// whole two rows, so each multiplier moves at most one row: P A = L U with P a product of
// disjoint pair swaps, L within kl + 1 subdiagonals and U within ku + 1 superdiagonals. The
// substitution then permutes the right-hand side once and runs two plain band triangles, in
// blocks of four unknowns whose updates of the rows below (above) are 4-wide vector chunks,
// each loaded and stored once per block at the address the previous block stored it.
//
// The price is a weaker pivot choice. The factorization gives up (returns false, and the
// caller falls back on dgbtrf) as soon as a pivot is smaller than `threshold` times the
// largest entry of its column below it; backward stability then holds with a growth of at
// most (1 + 1/threshold) per elimination step in the worst case (threshold partial pivoting,
// Duff, Erisman & Reid, "Direct Methods for Sparse Matrices", 2nd ed., section 5.4).
#pragma once

#include <cstddef>
#include <vector>

namespace tehl::internal {

class PairPivotedBandLu {
 public:
  // Storage for an n x n matrix (n even) with kl sub- and ku superdiagonals; zeroed.
  void Reset(int n, int kl, int ku);
  // A(i, j) += v, |i - j| within the band given to Reset.
  void Add(int i, int j, double v) { a_[Index(i, j)] += v; }
  // Factorizes in place. False if a pivot falls below `threshold` times the largest entry
  // below it in its column (the factors are then unusable).
  bool Factorize(double threshold);
  // Replacing the rows from `row` (even) on, after a successful Factorize: ClearRowsFrom(row),
  // Add the new entries of those rows, then RefactorizeFrom(row) eliminates again only from
  // about `row` - kl on, from the old factors of the rows before it. The result is the
  // factorization of the matrix with the new rows (up to rounding), at a fraction
  // (n - row + kl) / n of Factorize's cost. False as for Factorize.
  void ClearRowsFrom(int row);
  bool RefactorizeFrom(int row, double threshold);
  // b <- A^{-1} b (b of size n), after a successful Factorize.
  void Solve(double* b) const;
  int pair_swaps() const { return swaps_; }  // pairs whose rows were interchanged

 private:
  std::size_t Index(int i, int j) const {
    return static_cast<std::size_t>(j) * ld_ + (up_ + i - j);
  }
  void Pack(int from);
  int n_ = 0, kl_ = 0, ku_ = 0;
  int up_ = 0, ld_ = 0;  // storage: rows j - up_ ... j + (ld_ - 1 - up_) of column j
  int swaps_ = 0;
  bool factored_ = false;   // a_ holds the factors of a successful (Re)Factorize
  std::vector<double> a_;   // the matrix, then L (unit, below) and U (above and diagonal)
  std::vector<char> swap_;  // per pair: rows 2k and 2k + 1 interchanged
  // Blocked layout (Pack): L's column j at j ls_ (rows j + 1 ..., zero past the band); U with
  // unit diagonal, per block of four columns, upper_chunks_[b] chunks of four rows, from
  // upper_offset_[b]; 1 / U(j, j).
  int lq_ = 0, ls_ = 0;
  std::vector<double> lower_, upper_, inv_diag_;
  std::vector<int> upper_chunks_;
  std::vector<std::size_t> upper_offset_;
  int pad_ = 0;
  mutable std::vector<double> work_;
};

}  // namespace tehl::internal
