#include "ehl/banded_film_preconditioner.hpp"

#include <Eigen/LU>
#include <algorithm>
#include <cmath>
#include <cstddef>

#include "ehl/newton_system.hpp"
#include "tehl/ehl/elastic_deflection.hpp"

extern "C" {
// LAPACK's banded LU with partial pivoting (Fortran calling convention).
void dgbtrf_(const int* m, const int* n, const int* kl, const int* ku, double* ab,
             const int* ldab, int* ipiv, int* info);
}

namespace tehl::internal {

bool BandedFilmPreconditioner::Factorize(const NewtonSystem& sys, int band, std::string* why) {
  const int n = sys.n, m = n - 2;
  band = std::max(band, 1);
  n_ = n;
  band_ = band;
  size_ = 2 * m;
  kl_ = std::max(4, 2 * band);
  ku_ = std::max(3, 2 * band);
  // kc_q = (p_ref/h_ref) K_q and prefix sums pk[q + 1] = sum_{d <= q} kc_d.
  const double ks = sys.p_ref / sys.h_ref;
  kc_.assign(n, 0.0);
  std::vector<double> pk(n + 1, 0.0);
  if (sys.elastic)
    for (int q = 0; q < n; ++q) kc_[q] = ks * sys.elastic->Coefficient(q);
  for (int q = 0; q < n; ++q) pk[q + 1] = pk[q] + kc_[q];
  auto row_sum = [&](int c) {  // sum_{j=1..m} kc_|c-j|
    const int lo = 1, hi = m;
    if (hi < c) return pk[c - lo + 1] - pk[c - hi];
    if (lo > c) return pk[hi - c + 1] - pk[lo - c];
    return pk[c - lo + 1] + pk[hi - c + 1] - kc_[0];
  };
  // The second-differenced kernel d2[q] = kc_|q-1| - 2 kc_q + kc_q+1 (Toeplitz: the entry of
  // the film row of node i for P_j, q = |i - j| <= band).
  // |i - j| < m, so q + 1 <= m < n.
  const int qmax = std::min(band, m - 1);
  d2_.resize(qmax + 1);
  for (int q = 0; q <= qmax; ++q) d2_[q] = kc_[std::abs(q - 1)] - 2.0 * kc_[q] + kc_[q + 1];
  // The film row of node i puts on P_i the second difference of the whole kernel's row sums
  // less the rest of its band (the dropped tail's row sum on the diagonal).
  film_diag_.assign(m + 1, 0.0);
  for (int i = 1; i <= m; ++i) {
    double in_band = 0.0;
    for (int j = std::max(1, i - band); j <= std::min(m, i + band); ++j)
      in_band += d2_[std::abs(i - j)];
    const double total = row_sum(i - 1) - 2.0 * row_sum(i) + row_sum(i + 1);
    film_diag_[i] = kc_[1] - 2.0 * kc_[0] + kc_[1] + (total - in_band);
  }
  // Border rows on the P columns: the exact film rows of both ends and the load row.
  border_.resize(3, m);
  const double wload = sys.dx * sys.p_ref / sys.load;
  for (int j = 1; j <= m; ++j) {
    border_(0, j - 1) = -kc_[j];
    border_(1, j - 1) = -kc_[n - 1 - j];
    border_(2, j - 1) = wload;
  }
  bc_.setZero(size_, 3);
  // First the band LU pivoting within node pairs (pair_pivoted_band_lu.hpp), whose
  // substitution is about twice as fast (docs/performance.md); LAPACK's dgbtrf if one of its
  // pivots falls below the threshold (a tenth of its column by default).
  paired_ = false;
  if (pair_threshold_ >= 0) {
    pair_.Reset(size_, kl_, ku_);
    Assemble(sys, 1, [&](int row, int col, double v) { pair_.Add(row, col, v); });
    paired_ = pair_.Factorize(pair_threshold_);
  }
  if (!paired_) {
    ldab_ = 2 * kl_ + ku_ + 1;
    ab_.assign(static_cast<std::size_t>(ldab_) * size_, 0.0);
    ipiv_.resize(size_);
    bc_.setZero();
    Assemble(sys, 1, [&](int row, int col, double v) {
      ab_[static_cast<std::size_t>(col) * ldab_ + (kl_ + ku_ + row - col)] += v;
    });
    int info = 0;
    dgbtrf_(&size_, &size_, &kl_, &ku_, ab_.data(), &ldab_, ipiv_.data(), &info);
    if (info != 0) {
      *why = "newton_krylov: banded LU of the preconditioner failed (dgbtrf info " +
             std::to_string(info) + ")";
      return false;
    }
    MeasureFactors();
  }
  return FinishBorder(why);
}

bool BandedFilmPreconditioner::Refresh(const NewtonSystem& sys, int first_node, std::string* why) {
  if (!paired_ || sys.n != n_) return false;
  first_node = std::max(first_node, 1);
  if (first_node > n_ - 2) return true;
  const int row = 2 * (first_node - 1);
  pair_.ClearRowsFrom(row);
  bc_.bottomRows(size_ - row).setZero();
  Assemble(sys, first_node, [&](int r, int col, double v) { pair_.Add(r, col, v); });
  if (!pair_.RefactorizeFrom(row, pair_threshold_)) {
    paired_ = false;  // the factors are void: only Factorize again
    return false;
  }
  return FinishBorder(why);
}

// The Reynolds and film rows of nodes first_node .. n - 2 through `add` (core entries) and
// into bc_ (border columns).
template <typename Add>
void BandedFilmPreconditioner::Assemble(const NewtonSystem& sys, int first_node, Add&& add) {
  const int n = n_, m = n - 2, band = band_;
  auto hcol = [](int k) { return 2 * (k - 1); };      // core column of H_k, k = 1 .. m
  auto pcol = [](int k) { return 2 * (k - 1) + 1; };  // core column of P_k
  // Film change H_k in row `row` with weight v: core column or border column.
  auto add_h = [&](int row, int k, double v) {
    if (k == 0)
      bc_(row, 0) += v;
    else if (k == n - 1)
      bc_(row, 1) += v;
    else
      add(row, hcol(k), v);
  };
  for (int i = first_node; i <= m; ++i) {
    const int row = 2 * (i - 1);
    if (sys.cavitated[i]) {
      add(row, pcol(i), 1.0);
    } else {
      const double rs = (*sys.row_scale)[i];
      for (int q = 0; q < 4; ++q) {
        const int k = i - 2 + q;
        if (k < 0 || k >= n) continue;
        if (k >= 1 && k <= m) add(row, pcol(k), rs * sys.p_ref * (*sys.a)(i, q));
        add_h(row, k, rs * sys.h_ref * (*sys.b)(i, q));
      }
    }
    // Film row of node i: a second difference of H against the truncated kernel.
    const int frow = row + 1;
    add_h(frow, i - 1, 1.0);
    add_h(frow, i, -2.0);
    add_h(frow, i + 1, 1.0);
    for (int j = std::max(1, i - band); j <= std::min(m, i + band); ++j)
      if (j != i) add(frow, pcol(j), -d2_[std::abs(i - j)]);
    add(frow, pcol(i), -film_diag_[i]);
  }
}

// The bordered part: Y = C^{-1} B_c and the 3 x 3 Schur complement, after the core's LU.
bool BandedFilmPreconditioner::FinishBorder(std::string* why) {
  const int m = n_ - 2;
  Eigen::Matrix3d d;
  d << 1, 0, -1, 0, 1, -1, 0, 0, 0;
  y_ = bc_;
  for (int c = 0; c < 3; ++c)  // the H0 column has no core entries: its solve is zero
    if (!y_.col(c).isZero(0.0)) Substitute(y_.col(c).data());
  // S = D - B_r C^{-1} B_c, with B_r acting on the P rows of Y.
  yp_ = Eigen::Map<const Eigen::MatrixXd, 0, Eigen::Stride<Eigen::Dynamic, 2>>(
      y_.data() + 1, m, 3, Eigen::Stride<Eigen::Dynamic, 2>(y_.rows(), 2));
  const Eigen::Matrix3d s = d - border_ * yp_;
  Eigen::FullPivLU<Eigen::Matrix3d> lu(s);
  if (!lu.isInvertible()) {
    *why = "newton_krylov: the border of the banded preconditioner is singular";
    return false;
  }
  schur_inv_ = lu.inverse();
  work_.resize(size_);
  up_.resize(m);
  return true;
}

namespace {

// The substitution with packed factors (see BandedFilmPreconditioner::MeasureFactors). Both
// passes run along a serial chain: each unknown is final only once the previous column has
// updated it. The two unknowns next in line are kept in registers (c0, c1) and updated there,
// so the chain waits for one multiply-add per column instead of a vector store and the load
// of the next unknown; the rest of each column is a vector update off the chain. The back
// pass uses U scaled to a unit diagonal (its rows divided by U(i, i), the right-hand side
// scaled once), so that its chain has no multiplication either. Cloned for x86-64-v3 (AVX2 +
// FMA), chosen when the program starts on such a processor; the default clone is the SSE2
// code of a generic build.
__attribute__((target_clones("arch=x86-64-v3", "default"))) void SubstitutePacked(
    int n,
    const int* ipiv,
    const int* l_len,
    const int* u_len,
    const std::size_t* offset,
    const double* packed,
    const double* inv_diag,
    double* b) {
  if (n < 3) {  // too short for the register window below
    for (int j = 0; j + 1 < n; ++j) {
      const int l = ipiv[j] - 1;
      std::swap(b[l], b[j]);
      if (l_len[j] > 0) b[j + 1] -= packed[offset[j]] * b[j];
    }
    for (int j = n - 1; j >= 0; --j) {
      b[j] *= inv_diag[j];
      if (j > 0 && u_len[j] > 0) b[j - 1] -= packed[offset[j] + l_len[j]] * b[j];
    }
    return;
  }
  // Forward: unit lower factor with row interchanges. Entering column j, c0 and c1 hold
  // b[j] and b[j + 1]; memory holds b[k], k >= j + 2.
  double c0 = b[0], c1 = b[1];
  for (int j = 0; j + 1 < n; ++j) {
    const int l = ipiv[j] - 1;
    if (l != j) {  // an interchange: through memory
      b[j] = c0;
      b[j + 1] = c1;
      std::swap(b[j], b[l]);
      c0 = b[j];
      c1 = b[j + 1];
    }
    const double bj = c0;
    b[j] = bj;
    const int len = l_len[j];
    const double* col = packed + offset[j];
    double c2 = j + 2 < n ? b[j + 2] : 0.0;
    if (len >= 1) c1 -= col[0] * bj;
    if (len >= 2) c2 -= col[1] * bj;
    double* y = b + j + 1;
    for (int i = 2; i < len; ++i) y[i] -= col[i] * bj;
    c0 = c1;
    c1 = c2;
  }
  b[n - 1] = c0;
  // Back: unit upper factor on the scaled right-hand side. Entering column j, c0 and c1
  // hold b[j] and b[j - 1]; memory holds b[k], k <= j - 2.
  for (int j = 0; j < n; ++j) b[j] *= inv_diag[j];
  c0 = b[n - 1];
  c1 = b[n - 2];
  for (int j = n - 1; j >= 0; --j) {
    const double xj = c0;
    b[j] = xj;
    const int len = u_len[j];
    const double* col = packed + offset[j] + l_len[j];  // rows j - len .. j - 1
    double c2 = j >= 2 ? b[j - 2] : 0.0;
    if (len >= 1) c1 -= col[len - 1] * xj;
    if (len >= 2) c2 -= col[len - 2] * xj;
    double* y = b + j - len;
    for (int i = 0; i + 2 < len; ++i) y[i] -= col[i] * xj;
    c0 = c1;
    c1 = c2;
  }
}

}  // namespace

// Packs the factors dgbtrf leaves in ab_ (LAPACK band storage: row interchanges, the unit
// lower multipliers column by column, then the upper band of kl + ku superdiagonals) for the
// substitution: L's columns and U's columns (scaled by the reciprocals of U's diagonal, row
// by row) next to each other. Partial pivoting widens U's band from ku to kl + ku only where
// rows were interchanged, and the band storage keeps the zeros; packing only each column's
// nonzero span halves the memory the substitution streams through (at 4097 nodes U's columns
// span about 10 of the 32 superdiagonals).
void BandedFilmPreconditioner::MeasureFactors() {
  const int n = size_, kv = kl_ + ku_;
  inv_diag_.resize(n);
  u_len_.resize(n);
  l_len_.resize(n);
  offset_.resize(n);
  std::size_t total = 0;
  for (int j = 0; j < n; ++j) {
    const double* col = ab_.data() + static_cast<std::size_t>(j) * ldab_;
    inv_diag_[j] = 1.0 / col[kv];
    int above = std::min(j, kv);
    while (above > 0 && col[kv - above] == 0.0) --above;
    u_len_[j] = above;
    int below = std::min(kl_, n - 1 - j);
    while (below > 0 && col[kv + below] == 0.0) --below;
    l_len_[j] = below;
    offset_[j] = total;
    total += static_cast<std::size_t>(above + below);
  }
  packed_.resize(total);
  for (int j = 0; j < n; ++j) {
    const double* col = ab_.data() + static_cast<std::size_t>(j) * ldab_;
    double* out = packed_.data() + offset_[j];
    std::copy(col + kv + 1, col + kv + 1 + l_len_[j], out);
    out += l_len_[j];
    for (int k = 0, len = u_len_[j]; k < len; ++k)  // U(i, j) / U(i, i), i = j - len + k
      out[k] = col[kv - len + k] * inv_diag_[j - len + k];
  }
}

// The forward and back substitution of LAPACK's dgbtrs ("N", one right-hand side) on the
// packed factors. Written out because the reference BLAS behind dgbtrs spends more on one
// call per column (dger, dswap, dtbsv) than on the arithmetic of these short columns.
void BandedFilmPreconditioner::Substitute(double* b) const {
  if (paired_) {
    pair_.Solve(b);
    return;
  }
  SubstitutePacked(size_, ipiv_.data(), l_len_.data(), u_len_.data(), offset_.data(),
                   packed_.data(), inv_diag_.data(), b);
}

void BandedFilmPreconditioner::Solve(const Eigen::VectorXd& x, Eigen::VectorXd* y) const {
  const int m = n_ - 2;
  // Right-hand side: the Reynolds rows carry x, the film rows 0; the load row x[m].
  double* u = work_.data();
  for (int k = 0; k < m; ++k) {
    u[2 * k] = x[k];
    u[2 * k + 1] = 0.0;
  }
  Substitute(u);
  for (int k = 0; k < m; ++k) up_[k] = u[2 * k + 1];  // the P unknowns
  const Eigen::Vector3d g = Eigen::Vector3d(0.0, 0.0, x[m]) - border_ * up_;
  const Eigen::Vector3d s = schur_inv_ * g;
  y->resize(m + 1);
  y->head(m) = up_ - yp_ * s;
  (*y)[m] = s[2];
}

}  // namespace tehl::internal
