#include "ehl/film_augmented_preconditioner.hpp"

#include <umfpack.h>

#include <Eigen/Sparse>
#include <algorithm>
#include <stdexcept>
#include <string>
#include <vector>

#include "ehl/newton_system.hpp"
#include "tehl/ehl/elastic_deflection.hpp"

namespace tehl::internal {
namespace {
// Stride ratio between the levels of film rows (film_augmented_preconditioner.hpp). Measured at
// n = 8193, half-band 8 (GMRES iterations per Newton step / UMFPACK flops): no levels 25 / 1e7
// (and growing like sqrt(n)), ratio 16: 12 / 3.5e7, ratio 8: 9 / 3.8e7 (slower to factorize).
constexpr int kLevelRatio = 16;

// The strict triangle of a factor, from UMFPACK's compressed rows of L (or columns of U) whose
// last entry is the diagonal, stored as runs of consecutive column (row) indices: row i owns
// the runs first[i] .. first[i+1]-1, and run r the values offset[r] .. offset[r+1]-1 at the
// indices index[r], index[r]+1, ... The factors of the augmented matrix come in dense blocks
// (about 2 runs of 10-20 entries per row or column at 16385 nodes), so a solve reads contiguous
// stretches of the work vector and almost no indices (8 instead of 12 bytes per entry; the
// solve is memory bound). Float values were tried (measured in docs/performance.md): twice as
// fast again and the same GMRES counts, but the full-band solve then misses J^{-1} by 3-17 %.
struct RunTriangle {
  std::vector<int> first, index, offset;
  std::vector<double> value, inv_diag;  // inv_diag: 1 / diagonal (U only)

  void Build(int size, const int* ptr, const int* idx, const double* val, bool keep_diag) {
    first.resize(size + 1);
    value.resize(ptr[size] - size);  // every entry but the diagonal
    index.clear();
    offset.clear();
    inv_diag.resize(keep_diag ? size : 0);
    double* out = value.data();
    int written = 0;
    for (int i = 0; i < size; ++i) {
      first[i] = static_cast<int>(index.size());
      const int end = ptr[i + 1] - 1;  // the diagonal
      for (int p = ptr[i]; p < end; ++p) {
        if (p == ptr[i] || idx[p] != idx[p - 1] + 1) {
          index.push_back(idx[p]);
          offset.push_back(written);
        }
        out[written++] = val[p];
      }
      if (keep_diag) inv_diag[i] = 1.0 / val[end];
    }
    first[size] = static_cast<int>(index.size());
    offset.push_back(written);
  }
  void Release() {
    for (auto* v : {&first, &index, &offset}) std::vector<int>().swap(*v);
    std::vector<double>().swap(value);
    std::vector<double>().swap(inv_diag);
  }
  // z <- L^{-1} z for a unit lower triangular L stored by rows (four partial sums per row).
  void ForwardUnit(int size, double* z) const {
    for (int i = 0; i < size; ++i) {
      double s0 = 0, s1 = 0, s2 = 0, s3 = 0;
      for (int r = first[i]; r < first[i + 1]; ++r) {
        const double* v = value.data() + offset[r];
        const double* x = z + index[r];
        const int len = offset[r + 1] - offset[r];
        int t = 0;
        for (; t + 4 <= len; t += 4) {
          s0 += v[t] * x[t];
          s1 += v[t + 1] * x[t + 1];
          s2 += v[t + 2] * x[t + 2];
          s3 += v[t + 3] * x[t + 3];
        }
        for (; t < len; ++t) s0 += v[t] * x[t];
      }
      z[i] -= (s0 + s1) + (s2 + s3);
    }
  }
  // z <- U^{-1} z for an upper triangular U stored by columns: each column is subtracted once
  // its unknown is known.
  void Backward(int size, double* z) const {
    for (int j = size - 1; j >= 0; --j) {
      const double w = z[j] * inv_diag[j];
      z[j] = w;
      for (int r = first[j]; r < first[j + 1]; ++r) {
        const double* v = value.data() + offset[r];
        double* x = z + index[r];
        const int len = offset[r + 1] - offset[r];
        for (int t = 0; t < len; ++t) x[t] -= v[t] * w;
      }
    }
  }
};
}  // namespace

struct FilmAugmentedPreconditioner::Impl {
  Eigen::SparseMatrix<double> matrix;  // column-major, int indices: UMFPACK's CSC
  std::vector<Eigen::Triplet<double>> triplets;
  void* symbolic = nullptr;
  void* numeric = nullptr;
  double control[UMFPACK_CONTROL];
  double info[UMFPACK_INFO];
  int n = 0, band = -1, ratio = -1;  // pattern of the last symbolic analysis
  mutable Eigen::VectorXd rhs, sol, work;
  mutable std::vector<int> iwork;
  // P R A Q = L U as extracted from the Numeric object (umfpack_get_numeric.h): row k of P R A
  // is row perm_row[k] of A times scale[k]; column k of A Q is column perm_col[k] of A.
  RunTriangle lower, upper;
  std::vector<int> perm_row, perm_col;
  std::vector<double> scale;
  bool extracted = false;  // the factors above are valid (else Solve uses `numeric`)

  Impl() {
    umfpack_di_defaults(control);
    // The augmented matrix is structurally symmetric apart from the dense rows: the
    // symmetric strategy (AMD on A + A^T, diagonal pivots preferred) keeps the fill near
    // nnz(A); the unsymmetric default (COLAMD) filled U to ~n^2/5 at n = 1025.
    control[UMFPACK_STRATEGY] = UMFPACK_STRATEGY_SYMMETRIC;
    control[UMFPACK_IRSTEP] = 0;  // no iterative refinement: GMRES corrects the rest
  }
  ~Impl() { Free(); }
  void Free() {
    if (numeric) umfpack_di_free_numeric(&numeric);
    if (symbolic) umfpack_di_free_symbolic(&symbolic);
  }
  // Takes the factors out of `numeric` and frees it. False (keeping `numeric` for
  // umfpack_di_wsolve) if UMFPACK refuses or a row of L / column of U does not end with its
  // nonzero diagonal.
  bool ExtractFactors(int size);
};

bool FilmAugmentedPreconditioner::Impl::ExtractFactors(int size) {
  int lnz = 0, unz = 0, rows = 0, cols = 0, udiag = 0, do_recip = 0;
  if (umfpack_di_get_lunz(&lnz, &unz, &rows, &cols, &udiag, numeric) != UMFPACK_OK ||
      rows != size || cols != size || udiag != size)
    return false;
  // UMFPACK's own arrays, released once converted (they exist only during the extraction).
  std::vector<int> lp(size + 1), lj(lnz), up(size + 1), ui(unz);
  std::vector<double> lx(lnz), ux(unz), rs(size);
  perm_row.resize(size);
  perm_col.resize(size);
  if (umfpack_di_get_numeric(lp.data(), lj.data(), lx.data(), up.data(), ui.data(), ux.data(),
                             perm_row.data(), perm_col.data(), nullptr, &do_recip, rs.data(),
                             numeric) != UMFPACK_OK)
    return false;
  for (int i = 0; i < size; ++i)
    if (lp[i + 1] <= lp[i] || lj[lp[i + 1] - 1] != i || up[i + 1] <= up[i] ||
        ui[up[i + 1] - 1] != i || ux[up[i + 1] - 1] == 0.0)
      return false;
  umfpack_di_free_numeric(&numeric);
  scale.resize(size);
  for (int k = 0; k < size; ++k) {
    const double r = rs[perm_row[k]];  // R = diag(Rs) or diag(Rs)^{-1}
    scale[k] = do_recip ? r : 1.0 / r;
  }
  lower.Build(size, lp.data(), lj.data(), lx.data(), false);
  upper.Build(size, up.data(), ui.data(), ux.data(), true);
  return true;
}

FilmAugmentedPreconditioner::FilmAugmentedPreconditioner() : impl_(std::make_unique<Impl>()) {}
FilmAugmentedPreconditioner::~FilmAugmentedPreconditioner() = default;

bool FilmAugmentedPreconditioner::Factorize(const NewtonSystem& sys, int band, std::string* why) {
  Impl& d = *impl_;
  const int n = sys.n, m = n - 2, size = 2 * n - 1;
  const int hcol = m, h0col = m + n, load_row = m + n;
  const int ratio = kLevelRatio;
  // kc_q = (p_ref/h_ref) K_q and its prefix sums pk_q = sum_{d <= q} kc_d.
  const double ks = sys.p_ref / sys.h_ref;
  std::vector<double> kc(n, 0.0), pk(n + 1, 0.0);  // pk[q + 1] = sum_{d=0..q} kc_d
  if (sys.elastic)
    for (int q = 0; q < n; ++q) kc[q] = ks * sys.elastic->Coefficient(q);
  for (int q = 0; q < n; ++q) pk[q + 1] = pk[q] + kc[q];
  // sum_{j=lo..hi} kc_|c-j| for 0 <= lo <= hi < n.
  auto row_sum = [&](int c, int lo, int hi) {
    if (hi < c) return pk[c - lo + 1] - pk[c - hi];
    if (lo > c) return pk[hi - c + 1] - pk[lo - c];
    return pk[c - lo + 1] + pk[hi - c + 1] - kc[0];
  };
  auto& t = d.triplets;
  t.clear();
  t.reserve(static_cast<size_t>(n) * (4 * band + 24));
  // Reynolds rows: the full stencil pattern always (zeros on cavitated rows), so that the
  // pattern, and with it UMFPACK's symbolic analysis, does not depend on the cavitated set.
  for (int i = 1; i <= m; ++i) {
    const bool cav = sys.cavitated[i] != 0;
    const double rs = (*sys.row_scale)[i];
    const double fa = cav ? 0.0 : rs * sys.p_ref, fb = cav ? 0.0 : rs * sys.h_ref;
    double diag = cav ? 1.0 : 0.0;
    for (int c = 0; c < 4; ++c) {
      const int k = i - 2 + c;
      if (k < 0 || k >= n) continue;
      if (k == i)
        diag += fa * (*sys.a)(i, c);
      else if (k >= 1 && k <= m)
        t.emplace_back(i - 1, k - 1, fa * (*sys.a)(i, c));
      t.emplace_back(i - 1, hcol + k, fb * (*sys.b)(i, c));
    }
    t.emplace_back(i - 1, i - 1, diag);
  }
  // Film rows. Levels of stride g = ratio^l; node k belongs to the highest level whose stride
  // divides it. The top level (at most ~8 nodes, plus both ends) has exact dense rows; a node of
  // level l < top has a second difference with spacing g to its neighbours k - g and
  // min(k + g, n - 1), with the kernel combination truncated to |k - j| <= band g and the
  // dropped tail's row sum added to the diagonal (exact for a uniform pressure change).
  std::vector<int> strides{1};
  if (ratio >= 2)
    while ((n - 1) / strides.back() > 8) strides.push_back(strides.back() * ratio);
  const int top = static_cast<int>(strides.size()) - 1;
  const int top_stride = ratio >= 2 ? strides[top] : n;  // ratio < 2: only the two ends exact
  for (int k = 0; k < n; ++k) {
    const int row = hcol + k;
    if (k == 0 || k == n - 1 || k % top_stride == 0) {
      t.emplace_back(row, hcol + k, 1.0);
      t.emplace_back(row, h0col, -1.0);
      for (int j = 1; j <= m; ++j) t.emplace_back(row, j - 1, -kc[std::abs(k - j)]);
      continue;
    }
    int level = 0;
    while (level + 1 < top && k % strides[level + 1] == 0) ++level;
    if (ratio < 2) level = 0;
    const int g = strides[level];
    const int left = k - g, right = std::min(k + g, n - 1);
    const double wl = 1.0, wr = static_cast<double>(g) / (right - k), wc = -(wl + wr);
    t.emplace_back(row, hcol + left, wl);
    t.emplace_back(row, hcol + k, wc);
    t.emplace_back(row, hcol + right, wr);
    const int lo = std::max(1, k - band * g), hi = std::min(m, k + band * g);
    double in_band = 0.0;
    for (int j = lo; j <= hi; ++j) {
      const double dkj =
          wl * kc[std::abs(left - j)] + wc * kc[std::abs(k - j)] + wr * kc[std::abs(right - j)];
      in_band += dkj;
      if (j != k) t.emplace_back(row, j - 1, -dkj);
    }
    const double total =
        wl * row_sum(left, 1, m) + wc * row_sum(k, 1, m) + wr * row_sum(right, 1, m);
    const double dkk = wl * kc[std::abs(left - k)] + wc * kc[0] + wr * kc[std::abs(right - k)];
    t.emplace_back(row, k - 1, -(dkk + (total - in_band)));
  }
  const double wload = sys.dx * sys.p_ref / sys.load;
  for (int j = 0; j < m; ++j) t.emplace_back(load_row, j, wload);
  d.matrix.resize(size, size);
  d.matrix.setFromTriplets(t.begin(), t.end());
  d.matrix.makeCompressed();
  const int* cp = d.matrix.outerIndexPtr();
  const int* ri = d.matrix.innerIndexPtr();
  const double* v = d.matrix.valuePtr();
  if (!d.symbolic || d.n != n || d.band != band || d.ratio != ratio) {
    d.Free();
    if (umfpack_di_symbolic(size, size, cp, ri, v, &d.symbolic, d.control, d.info) != UMFPACK_OK) {
      d.Free();
      *why = "newton_krylov: UMFPACK symbolic analysis of the augmented preconditioner failed";
      return false;
    }
    d.n = n;
    d.band = band;
    d.ratio = ratio;
    ++symbolic_analyses_;
  }
  if (d.numeric) umfpack_di_free_numeric(&d.numeric);
  // The old factors go first: they would otherwise coexist with the new Numeric object.
  d.extracted = false;
  d.lower.Release();
  d.upper.Release();
  const int status = umfpack_di_numeric(cp, ri, v, d.symbolic, &d.numeric, d.control, d.info);
  if (status != UMFPACK_OK) {  // singular (status 1) included: the solve would give inf
    if (d.numeric) umfpack_di_free_numeric(&d.numeric);
    *why =
        "newton_krylov: UMFPACK factorization of the augmented preconditioner failed "
        "(status " +
        std::to_string(status) + ")";
    return false;
  }
  d.extracted = d.ExtractFactors(size);
  d.iwork.resize(d.extracted ? 0 : size);
  d.work.resize(size);
  return true;
}

void FilmAugmentedPreconditioner::Solve(const Eigen::VectorXd& x, Eigen::VectorXd* y) const {
  const Impl& d = *impl_;
  const int n = d.n, m = n - 2;
  d.rhs.setZero(2 * n - 1);
  d.rhs.head(m) = x.head(m);
  d.rhs[m + n] = x[m];
  d.sol.resize(2 * n - 1);
  if (d.extracted) {
    // x = Q U^{-1} L^{-1} P R b.
    const int size = 2 * n - 1;
    double* z = d.work.data();
    for (int k = 0; k < size; ++k) z[k] = d.scale[k] * d.rhs[d.perm_row[k]];
    d.lower.ForwardUnit(size, z);
    d.upper.Backward(size, z);
    for (int k = 0; k < size; ++k) d.sol[d.perm_col[k]] = z[k];
  } else {
    // After a factorization that succeeded (Factorize refuses a singular one) the solve has
    // no failure of its own left: a status other than OK is a defect, not a hard film.
    const int status = umfpack_di_wsolve(
        UMFPACK_A, d.matrix.outerIndexPtr(), d.matrix.innerIndexPtr(), d.matrix.valuePtr(),
        d.sol.data(), d.rhs.data(), d.numeric, d.control, nullptr, d.iwork.data(), d.work.data());
    if (status != UMFPACK_OK)
      throw std::runtime_error(
          "newton_krylov: UMFPACK solve with the augmented preconditioner "
          "failed (status " +
          std::to_string(status) + ")");
  }
  y->resize(m + 1);
  y->head(m) = d.sol.head(m);
  (*y)[m] = d.sol[m + n];
}

}  // namespace tehl::internal
