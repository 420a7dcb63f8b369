#include "ehl/coarse_correction.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "ehl/banded_film_preconditioner.hpp"
#include "ehl/newton_system.hpp"
#include "tehl/ehl/elastic_deflection.hpp"

namespace tehl::internal {

void ApplyTwoLevel(const NewtonSystem& sys,
                   const CoarseCorrection& coarse,
                   const BandedFilmPreconditioner& fine,
                   const Eigen::VectorXd& x,
                   Eigen::VectorXd* y,
                   TwoLevelScratch* w) {
  w->x = x;  // x and y may alias
  coarse.Apply(w->x, &w->coarse_y);
  sys.Apply(w->coarse_y, &w->fine_rhs);
  w->fine_rhs = w->x - w->fine_rhs;
  fine.Solve(w->fine_rhs, y);
  *y += w->coarse_y;
  // Exactly x_i on cavitated rows: the sum above leaves round-off there (~1e-27 Pa).
  for (int i = 1; i + 1 < sys.n; ++i)
    if (sys.cavitated[i]) (*y)[i - 1] = w->x[i - 1];
}

int CoarseStride(int n, int coarse_pressures) {
  const int c = coarse_pressures;
  const int target = std::clamp((n - 1) / 16, c, 2 * c);
  return std::max(2, (n - 1) / (target + 1));
}

int ElasticZoneStart(const NewtonSystem& sys) {
  if (!sys.elastic) return 0;
  std::vector<double> ratio(sys.n, 0.0);
  double top = 0;
  for (int i = 1; i + 1 < sys.n; ++i) {
    if (sys.cavitated[i]) continue;
    double sa = 0, sb = 0;
    for (int q = 0; q < 4; ++q) {
      sa += std::abs((*sys.a)(i, q));
      sb += std::abs((*sys.b)(i, q));
    }
    ratio[i] = sa > 0 ? sb / sa : std::numeric_limits<double>::infinity();
    if (std::isfinite(ratio[i])) top = std::max(top, ratio[i]);
  }
  for (int i = 1; i + 1 < sys.n; ++i)
    if (ratio[i] > 1e-6 * top) return i;
  return 0;
}

double CoarseCorrection::HatWeight(int node, int c) const {
  const int d = std::abs(node - (c + 1) * stride_);
  return d < stride_ ? hat_[d] : 0.0;  // 1 - d/G from the table (Build fills it first)
}

bool CoarseCorrection::Build(const NewtonSystem& sys,
                             int stride,
                             int wide_until,
                             int wide_multiple) {
  const int n = sys.n;
  merged_ = false;
  if (stride < 2) return false;
  const int nc = (n - 1) / stride - 1;  // hats centred at G .. nc G, each inside the grid
  if (nc < 2) return false;
  n_ = n;
  stride_ = stride;
  nc_ = nc;
  hat_.resize(stride);
  for (int t = 0; t < stride; ++t) hat_[t] = 1.0 - static_cast<double>(t) / stride;
  const int g = stride;
  // kh[d] = sum_t (1 - |t|/G) K_|d - t|: the deflection (per unit p_ref, scaled to H) a
  // distance d from the centre of a unit hat.
  // The triangle (1 - |t|/G) is (1/G) times a box of G ones convolved with itself, so kh is
  // two running box sums of the even extension K'(j) = K_|j| (zero for |j| >= n): O(n) with
  // prefix sums, kept in long double so that their differences keep double precision.
  std::vector<double> kh(n, 0.0);
  if (sys.elastic) {
    const int lo = -(g - 1), hi = n + g - 2;  // j = d - t ranges over lo .. hi
    std::vector<long double> pk(hi - lo + 2, 0.0L);  // pk[i] = sum of K'(j), lo <= j < lo + i
    for (int j = lo; j <= hi; ++j) {
      const int q = std::abs(j);
      pk[j - lo + 1] = pk[j - lo] + (q < n ? sys.elastic->Coefficient(q) : 0.0);
    }
    // box(j) = sum_{a=0}^{G-1} K'(j - a) for j = 0 .. hi; pb its prefix sums.
    std::vector<long double> pb(hi + 2, 0.0L);
    for (int j = 0; j <= hi; ++j) pb[j + 1] = pb[j] + (pk[j - lo + 1] - pk[j - g + 1 - lo]);
    // kh[d] = (1/G) sum_{j=d}^{d+G-1} box(j).
    for (int d = 0; d < n; ++d) kh[d] = static_cast<double>((pb[d + g] - pb[d]) / g);
  }
  // Test functions W: hat l at row i (row index i - 1), both hats that cover node i.
  e_.setZero(nc + 1, nc + 1);
  // Elastic part, E_BK(l, c) = sum_i hat_l(i) sum_q bb(i, q) kh(|i - 2 + q - N_c|) with
  // bb = rs p_ref b (zero on cavitated rows): with T_l(k) = sum over (i, q) with i - 2 + q = k of
  // hat_l(i) bb(i, q) (k in N_l - G - 1 .. N_l + G), E_BK(l, c) = sum_k T_l(k) kh(|k - N_c|).
  const int len = 2 * g + 2;
  // E_BK(l, c) reads kh at |k - N_c| = |(l - c - 1) G - 1 + t|, t = k - k0 = 0 .. len - 1:
  // with kh extended to negative arguments (khs[j - j_min] = kh(|j|), j from -nc G - 1 to
  // nc G), each entry is one dot product of contiguous vectors (vectorized; the element-wise
  // loop with |.| inside was most of a factorization's time at 4097 nodes).
  const int j_min = -nc * g - 1, j_max = nc * g;
  std::vector<double> khs(sys.elastic ? j_max - j_min + 1 : 0);
  for (size_t q = 0; q < khs.size(); ++q) khs[q] = kh[std::abs(static_cast<int>(q) + j_min)];
  Eigen::VectorXd tl(len);
  for (int l = 0; l < nc; ++l) {
    const int nl = (l + 1) * g, k0 = nl - g - 1;
    tl.setZero();
    for (int i = nl - g + 1; i <= nl + g - 1; ++i) {
      if (sys.cavitated[i]) continue;
      const double w = HatWeight(i, l) * (*sys.row_scale)[i] * sys.p_ref;
      for (int q = 0; q < 4; ++q) {
        const int k = i - 2 + q;
        if (k >= 0 && k < n) tl[k - k0] += w * (*sys.b)(i, q);
      }
    }
    if (sys.elastic)
      for (int c = 0; c < nc; ++c) {
        const int off = k0 - (c + 1) * g;  // k - N_c at t = 0
        e_(l, c) = tl.dot(Eigen::Map<const Eigen::VectorXd>(khs.data() + (off - j_min), len));
      }
    // Local part: the Reynolds stencil (nodes i-2 .. i+1, or the identity of a cavitated row)
    // on the hats it reaches from the support of hat l: l-2 .. l+1.
    for (int c = std::max(l - 2, 0); c <= std::min(l + 1, nc - 1); ++c) {
      double acc = 0;
      for (int i = nl - g + 1; i <= nl + g - 1; ++i) {
        double v;
        if (sys.cavitated[i]) {
          v = HatWeight(i, c);
        } else {
          double s = 0;
          for (int q = 0; q < 4; ++q) s += (*sys.a)(i, q) * HatWeight(i - 2 + q, c);
          v = (*sys.row_scale)[i] * sys.p_ref * s;
        }
        acc += HatWeight(i, l) * v;
      }
      e_(l, c) += acc;
    }
    // Column of H0 (h changes by h_ref everywhere).
    double acc = 0;
    for (int i = nl - g + 1; i <= nl + g - 1; ++i) {
      if (sys.cavitated[i]) continue;
      double s = 0;
      for (int q = 0; q < 4; ++q)
        if (i - 2 + q >= 0 && i - 2 + q < n) s += (*sys.b)(i, q);
      acc += HatWeight(i, l) * (*sys.row_scale)[i] * sys.h_ref * s;
    }
    e_(l, nc) = acc;
  }
  // Load row: dx times the sum of a hat (G); it does not depend on H0.
  for (int c = 0; c < nc; ++c) e_(nc, c) = sys.dx * sys.p_ref * g / sys.load;
  merged_ = MergeInlet(wide_until, wide_multiple);
  lu_.compute(e_);
  if (!(lu_.rcond() > 1e-14)) return false;
  rc_.resize(e_.rows());
  return true;
}

bool CoarseCorrection::MergeInlet(int wide_until, int wide_multiple) {
  const int m = wide_multiple;
  if (m < 2) return false;
  // Centres as lattice indices j (node j G), 1 .. nc: every m-th below wide_until, then all.
  std::vector<int> centre;
  for (int j = m; j <= nc_ && j * stride_ < wide_until; j += m) centre.push_back(j);
  if (centre.empty()) return false;
  for (int j = centre.back() + 1; j <= nc_; ++j) centre.push_back(j);
  const int k_count = static_cast<int>(centre.size());
  // Column k of P: hat k at the lattice nodes between its neighbours (index 0 is node 0,
  // index nc + 1 the last lattice node, neither an unknown).
  std::vector<Eigen::Triplet<double>> t;
  for (int k = 0; k < k_count; ++k) {
    const int a = k ? centre[k - 1] : 0, c = centre[k];
    const int b = k + 1 < k_count ? centre[k + 1] : nc_ + 1;
    for (int j = a + 1; j < b; ++j) {
      const double w =
          j <= c ? static_cast<double>(j - a) / (c - a) : static_cast<double>(b - j) / (b - c);
      t.emplace_back(j - 1, k, w);
    }
  }
  t.emplace_back(nc_, k_count, 1.0);  // H0 (and the load row) unchanged
  merge_.resize(nc_ + 1, k_count + 1);
  merge_.setFromTriplets(t.begin(), t.end());
  const Eigen::MatrixXd ep = e_ * merge_;  // E_G P
  e_ = merge_.transpose() * ep;
  return true;
}

void CoarseCorrection::Apply(const Eigen::VectorXd& x, Eigen::VectorXd* y) const {
  const int m = n_ - 2, g = stride_;
  Eigen::VectorXd& rc = merged_ ? rf_ : rc_;  // the uniform restriction W_G^T x
  rc.resize(nc_ + 1);
  for (int c = 0; c < nc_; ++c) {
    const int centre = (c + 1) * g;
    double s = x[centre - 1];
    for (int t = 1; t < g; ++t) s += hat_[t] * (x[centre - t - 1] + x[centre + t - 1]);
    rc[c] = s;
  }
  rc[nc_] = x[m];
  if (merged_) rc_ = merge_.transpose() * rf_;
  if (merged_) sf_ = merge_ * lu_.solve(rc_);
  const Eigen::VectorXd& sc = merged_ ? sf_ : (sf_ = lu_.solve(rc_));
  y->setZero(m + 1);
  for (int c = 0; c < nc_; ++c) {
    const int centre = (c + 1) * g;
    (*y)[centre - 1] += sc[c];
    for (int t = 1; t < g; ++t) {
      const double w = hat_[t] * sc[c];
      (*y)[centre - t - 1] += w;
      (*y)[centre + t - 1] += w;
    }
  }
  (*y)[m] = sc[nc_];
}

}  // namespace tehl::internal
