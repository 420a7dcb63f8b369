#include "ehl/pair_pivoted_band_lu.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

namespace tehl::internal {
namespace {

// Four doubles as one GCC vector: AVX2 registers in the x86-64-v3 clone, pairs of SSE2
// registers in the default one. V4u is the same vector at any double's address (unaligned
// loads and stores through a pointer cast). Written inline in the kernels, without helper
// functions: a function taking or returning V4 has another ABI without AVX, which clang
// rejects in the default clone.
typedef double V4 __attribute__((vector_size(32)));
typedef double V4u __attribute__((vector_size(32), aligned(8), may_alias));

// Unit lower triangle, blocks of four columns j0 .. j0 + 3 (j0 = 0, 4, ...): the block's own
// unknowns by a 4 x 4 triangular solve, then rows j0 + 4 ... j0 + 3 + 4 lq in chunks of four.
// The chunk holding the next block's unknowns subtracts the last unknown of this block last,
// so the next block waits for one multiply-add after it.
__attribute__((target_clones("arch=x86-64-v3", "default"))) void ForwardBlocks(
    int blocks, int lq, int ls, const double* lower, double* b) {
  for (int blk = 0; blk < blocks; ++blk) {
    const int j0 = 4 * blk;
    const double* l0 = lower + static_cast<std::size_t>(j0) * ls;
    const double* l1 = l0 + ls;
    const double* l2 = l1 + ls;
    const double* l3 = l2 + ls;
    double* y = b + j0;
    const double y0 = y[0];
    const double y1 = y[1] - l0[0] * y0;
    const double y2 = (y[2] - l0[1] * y0) - l1[0] * y1;
    const double y3 = ((y[3] - l0[2] * y0) - l1[1] * y1) - l2[0] * y2;
    y[1] = y1;
    y[2] = y2;
    y[3] = y3;
    const V4 s0 = {y0, y0, y0, y0}, s1 = {y1, y1, y1, y1};
    const V4 s2 = {y2, y2, y2, y2}, s3 = {y3, y3, y3, y3};
    double* r = y + 4;
    for (int q = 0; q < lq; ++q) {
      const int o = 4 * q;
      V4 acc = *reinterpret_cast<const V4u*>(r + o);
      acc = acc - *reinterpret_cast<const V4u*>(l0 + 3 + o) * s0;
      acc = acc - *reinterpret_cast<const V4u*>(l1 + 2 + o) * s1;
      acc = acc - *reinterpret_cast<const V4u*>(l2 + 1 + o) * s2;
      *reinterpret_cast<V4u*>(r + o) = acc - *reinterpret_cast<const V4u*>(l3 + o) * s3;
    }
  }
}

// Unit upper triangle, blocks of four columns j0 .. j0 - 3 (j0 = 4 blk + 3, from the last
// block): the mirror image of ForwardBlocks, each block with its own number of chunks.
__attribute__((target_clones("arch=x86-64-v3", "default"))) void BackBlocks(
    int blocks, const int* chunks, const std::size_t* offset, const double* upper, double* b) {
  for (int blk = blocks - 1; blk >= 0; --blk) {
    const int j0 = 4 * blk + 3, nq = chunks[blk], s = 4 * nq + 3;
    const double* u0 = upper + offset[blk];  // column j0, rows j0 - s ... j0 - 1
    const double* u1 = u0 + s;
    const double* u2 = u1 + s;
    const double* u3 = u2 + s;
    double* x = b + j0;
    const double x0 = x[0];
    const double x1 = x[-1] - u0[s - 1] * x0;
    const double x2 = (x[-2] - u0[s - 2] * x0) - u1[s - 1] * x1;
    const double x3 = ((x[-3] - u0[s - 3] * x0) - u1[s - 2] * x1) - u2[s - 1] * x2;
    x[-1] = x1;
    x[-2] = x2;
    x[-3] = x3;
    const V4 s0 = {x0, x0, x0, x0}, s1 = {x1, x1, x1, x1};
    const V4 s2 = {x2, x2, x2, x2}, s3 = {x3, x3, x3, x3};
    for (int q = 0; q < nq; ++q) {
      const int k = s - 7 - 4 * q;  // entry of column j0 for row j0 - 7 - 4 q
      double* r = x - 7 - 4 * q;
      V4 acc = *reinterpret_cast<const V4u*>(r);
      acc = acc - *reinterpret_cast<const V4u*>(u0 + k) * s0;
      acc = acc - *reinterpret_cast<const V4u*>(u1 + k + 1) * s1;
      acc = acc - *reinterpret_cast<const V4u*>(u2 + k + 2) * s2;
      *reinterpret_cast<V4u*>(r) = acc - *reinterpret_cast<const V4u*>(u3 + k + 3) * s3;
    }
  }
}

// Right-looking elimination in the band storage of PairPivotedBandLu (A(i, j) at
// j ld + up + i - j, kl + 1 = `below` rows under the diagonal, ku + 1 = `above` over it).
// Returns the number of interchanged pairs, or -1 if a pivot fails the threshold.
// Starts at column `start` (even; the columns before it are already eliminated) and toggles
// the interchange flag of every pair it interchanges.
__attribute__((target_clones("arch=x86-64-v3", "default"))) int Eliminate(int n,
                                                                          int start,
                                                                          int below,
                                                                          int above,
                                                                          int ld,
                                                                          int up,
                                                                          double* a,
                                                                          char* swapped,
                                                                          double threshold) {
  auto at = [&](int i, int j) -> double& {
    return a[static_cast<std::size_t>(j) * ld + (up + i - j)];
  };
  int swaps = 0;
  for (int j = start; j < n; ++j) {
    const int last_row = std::min(n - 1, j + below), last_col = std::min(n - 1, j + above);
    if (j % 2 == 0 && j + 1 < n && std::abs(at(j + 1, j)) > std::abs(at(j, j))) {
      // Interchange rows j and j + 1 over every column either can reach.
      for (int c = std::max(0, j - below); c <= last_col; ++c) {
        const bool in_j = j - c <= below && c - j <= above;
        const bool in_j1 = j + 1 - c <= below && c - j - 1 <= above;
        if (in_j && in_j1)
          std::swap(at(j, c), at(j + 1, c));
        else if ((in_j && at(j, c) != 0.0) || (in_j1 && at(j + 1, c) != 0.0))
          return -1;  // would leave the band (not reached with this storage; kept exact)
      }
      swapped[j / 2] ^= 1;
      ++swaps;
    }
    double* col = &at(j, j);  // col[i - j] = A(i, j), i = j .. j + below
    const double pivot = col[0];
    const int rows = last_row - j;
    double largest = 0.0;
    for (int i = 1; i <= rows; ++i) largest = std::max(largest, std::abs(col[i]));
    if (!(std::abs(pivot) > 0.0) || std::abs(pivot) < threshold * largest) return -1;
    const double inv = 1.0 / pivot;
    for (int i = 1; i <= rows; ++i) col[i] *= inv;
    for (int c = j + 1; c <= last_col; ++c) {
      double* target = &at(j, c);  // target[i - j] = A(i, c)
      const double t = target[0];
      if (t == 0.0) continue;
      for (int i = 1; i <= rows; ++i) target[i] -= col[i] * t;
    }
  }
  return swaps;
}

}  // namespace

void PairPivotedBandLu::Reset(int n, int kl, int ku) {
  n_ = n;
  kl_ = kl;
  ku_ = ku;
  up_ = ku + 1;        // room for a row moved up by its pair's interchange
  ld_ = up_ + kl + 2;  // diagonal, then kl + 1 rows below
  a_.assign(static_cast<std::size_t>(ld_) * n, 0.0);
}

bool PairPivotedBandLu::Factorize(double threshold) {
  swap_.assign((n_ + 1) / 2, 0);
  swaps_ = Eliminate(n_, 0, kl_ + 1, ku_ + 1, ld_, up_, a_.data(), swap_.data(), threshold);
  factored_ = swaps_ >= 0;
  if (!factored_) return false;
  Pack(0);
  return true;
}

void PairPivotedBandLu::ClearRowsFrom(int row) {
  for (int j = std::max(0, row - (kl_ + 1)); j < n_; ++j)
    for (int i = std::max(row, j - up_); i <= std::min(n_ - 1, j + ld_ - 1 - up_); ++i)
      a_[Index(i, j)] = 0.0;
}

// The rows from `row` on hold a new matrix's entries (ClearRowsFrom, Add); the rows before
// it, the factors of the old one. Elimination step j touches rows j + 1 ... j + below, so the
// steps before j0 = row - below (rounded down to a pair) saw only old rows, and their
// multipliers and rows of U stand. Step j0 then needs the rows j0 ... row - 1 as the steps
// before it left them, in their (interchanged) pair order: from the old factors,
//   S(i, c) = sum_{j0 <= j <= min(i, c)} L(i, j) U(j, c)   (L(i, i) = 1),
// the part of (P A)(i, c) = sum_j L(i, j) U(j, c) that the steps from j0 on remove. The rows
// from `row` on are untouched by the steps before j0 (j + below < row), and the old pair
// order of the pairs from `row` on is void: their rows come in natural order.
bool PairPivotedBandLu::RefactorizeFrom(int row, double threshold) {
  if (!factored_ || row < 0 || row % 2 != 0) return false;
  if (row >= n_) return true;
  const int below = kl_ + 1, above = ku_ + 1;
  const int j0 = std::max(0, row - below) / 2 * 2;
  for (int k = row / 2; k < static_cast<int>(swap_.size()); ++k) swap_[k] = 0;
  auto in_band = [&](int i, int j) { return i - j <= ld_ - 1 - up_ && j - i <= up_; };
  auto get = [&](int i, int j) { return in_band(i, j) ? a_[Index(i, j)] : 0.0; };
  const int rows = row - j0, width = below + above + 2;  // columns i - below .. i + above
  std::vector<double> s(static_cast<std::size_t>(rows) * width, 0.0);
  for (int i = j0; i < row; ++i)
    for (int c = std::max(j0, i - below); c <= std::min(n_ - 1, i + above); ++c) {
      double acc = c >= i ? get(i, c) : get(i, c) * get(c, c);  // j = min(i, c)
      for (int j = std::max({j0, i - below, c - above}); j < std::min(i, c); ++j)
        acc += get(i, j) * get(j, c);
      s[static_cast<std::size_t>(i - j0) * width + (c - i + below)] = acc;
    }
  for (int i = j0; i < row; ++i)
    for (int c = std::max(j0, i - below); c <= std::min(n_ - 1, i + above); ++c)
      if (in_band(i, c))
        a_[Index(i, c)] = s[static_cast<std::size_t>(i - j0) * width + (c - i + below)];
  factored_ = Eliminate(n_, j0, below, above, ld_, up_, a_.data(), swap_.data(), threshold) >= 0;
  if (!factored_) return false;
  swaps_ = 0;
  for (char f : swap_) swaps_ += f;
  Pack(j0);
  return true;
}

// The factors in the blocked layout of the substitution kernels above. From column `from` on
// only, if the layout of the last Pack has room for those columns (the widths of L and of
// each block of U fit); otherwise all of it.
void PairPivotedBandLu::Pack(int from) {
  const int n = n_, below = kl_ + 1, above = ku_ + 1;
  const int blocks = (n + 3) / 4, cols = 4 * blocks;
  from = std::clamp(from, 0, n) / 4 * 4;  // whole blocks
  auto lower_width = [&](int j) {
    for (int t = std::min(below, n - 1 - j); t > 0; --t)
      if (a_[Index(j + t, j)] != 0.0) return t;
    return 0;
  };
  auto upper_length = [&](int j) {
    int len = std::min(j, above);
    while (len > 0 && a_[Index(j - len, j)] == 0.0) --len;
    return len;
  };
  auto block_reach = [&](int blk) {  // chunks of four rows block blk's columns reach above it
    const int j0 = 4 * blk + 3;
    int reach = 0;
    for (int c = 0; c < 4; ++c)
      if (j0 - c < n) reach = std::max(reach, upper_length(j0 - c) + c - 3);
    return (reach + 3) / 4;
  };
  bool fits = from > 0 && static_cast<int>(upper_chunks_.size()) == blocks;
  int wl = 0;
  for (int j = from; j < n && fits; ++j) wl = std::max(wl, lower_width(j));
  fits = fits && wl <= 4 * lq_;
  for (int blk = from / 4; blk < blocks && fits; ++blk)
    fits = block_reach(blk) <= upper_chunks_[blk];
  if (!fits) {
    from = 0;
    wl = 0;
    for (int j = 0; j < n; ++j) wl = std::max(wl, lower_width(j));
    lq_ = std::max(1, (wl + 3) / 4);
    ls_ = 4 * lq_ + 3;
    lower_.assign(static_cast<std::size_t>(cols) * ls_, 0.0);
    upper_chunks_.resize(blocks);
    upper_offset_.resize(blocks);
    std::size_t total = 0;
    for (int blk = 0; blk < blocks; ++blk) {
      // Column j0 - c reaches row j0 - c - ulen; the chunks cover rows j0 - 4 ... j0 - 3 - 4 nq.
      upper_chunks_[blk] = block_reach(blk);
      upper_offset_[blk] = total;
      total += 4 * static_cast<std::size_t>(4 * upper_chunks_[blk] + 3);
    }
    upper_.assign(total, 0.0);
    inv_diag_.resize(n);
  }
  const int width = std::min(4 * lq_, below);
  for (int j = from; j < n; ++j) {
    double* out = lower_.data() + static_cast<std::size_t>(j) * ls_;
    std::fill(out, out + ls_, 0.0);
    for (int t = 0; t < std::min(width, n - 1 - j); ++t) out[t] = a_[Index(j + 1 + t, j)];
  }
  for (int j = from; j < n; ++j) inv_diag_[j] = 1.0 / a_[Index(j, j)];
  int max_chunks = 0;
  for (int blk = 0; blk < blocks; ++blk) max_chunks = std::max(max_chunks, upper_chunks_[blk]);
  for (int blk = from / 4; blk < blocks; ++blk) {
    const int j0 = 4 * blk + 3, s = 4 * upper_chunks_[blk] + 3;
    double* block = upper_.data() + upper_offset_[blk];
    std::fill(block, block + 4 * static_cast<std::size_t>(s), 0.0);
    for (int c = 0; c < 4; ++c) {
      const int j = j0 - c;
      if (j >= n) continue;
      double* out = block + static_cast<std::size_t>(c) * s;
      for (int t = 0, len = upper_length(j); t < len; ++t) {  // row i = j - 1 - t at s - 1 - t
        const int i = j - 1 - t;
        out[s - 1 - t] = a_[Index(i, j)] * inv_diag_[i];
      }
    }
  }
  pad_ = 4 * std::max(lq_, max_chunks) + 8;
  work_.resize(static_cast<std::size_t>(cols) + 2 * pad_, 0.0);
}

void PairPivotedBandLu::Solve(double* b) const {
  const int blocks = (n_ + 3) / 4;
  double* w = work_.data() + pad_;
  // Rows outside 0 .. n - 1 stay zero: the blocks past either end read them as zero unknowns
  // (their multipliers are zero), so nothing leaks into the solution.
  std::fill(work_.begin(), work_.begin() + pad_, 0.0);
  std::fill(work_.begin() + pad_ + n_, work_.end(), 0.0);
  std::copy_n(b, n_, w);
  for (int k = 0; 2 * k + 1 < n_; ++k)
    if (swap_[k]) std::swap(w[2 * k], w[2 * k + 1]);
  ForwardBlocks(blocks, lq_, ls_, lower_.data(), w);
  for (int i = 0; i < n_; ++i) w[i] *= inv_diag_[i];
  BackBlocks(blocks, upper_chunks_.data(), upper_offset_.data(), upper_.data(), w);
  std::copy_n(w, n_, b);
}

}  // namespace tehl::internal
