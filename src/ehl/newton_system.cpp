#include "ehl/newton_system.hpp"

#include <algorithm>

#include <Eigen/LU>

#include "tehl/ehl/elastic_deflection.hpp"

namespace tehl::internal {
namespace {

// y[i - 1] = rs[i] sum_c (A(i, c) p[i - 2 + c] + B(i, c) h[i - 2 + c]), i = 2 .. m: branch-free
// so that it vectorizes across rows; cloned for x86-64-v3 (AVX2 + FMA).
__attribute__((target_clones("arch=x86-64-v3", "default"))) void StencilRows(int m,
                                                                             const double* a,
                                                                             Eigen::Index lda,
                                                                             const double* b,
                                                                             Eigen::Index ldb,
                                                                             const double* pv,
                                                                             const double* hv,
                                                                             const double* rs,
                                                                             double* y) {
  const double *a_0 = a, *a_1 = a + lda, *a_2 = a + 2 * lda, *a_3 = a + 3 * lda;
  const double *b_0 = b, *b_1 = b + ldb, *b_2 = b + 2 * ldb, *b_3 = b + 3 * ldb;
  for (int i = 2; i <= m; ++i) {
    double s = 0.0;
    s += a_0[i] * pv[i - 2] + b_0[i] * hv[i - 2];
    s += a_1[i] * pv[i - 1] + b_1[i] * hv[i - 1];
    s += a_2[i] * pv[i] + b_2[i] * hv[i];
    s += a_3[i] * pv[i + 1] + b_3[i] * hv[i + 1];
    y[i - 1] = rs[i] * s;
  }
}

}  // namespace

void NewtonSystem::Apply(const Eigen::VectorXd& x, Eigen::VectorXd* y) const {
  const int m = n - 2;
  // Scratch vectors kept between calls: GMRES applies J once or twice per iteration.
  pv_.resize(n);
  hv_.resize(n);
  pv_[0] = 0.0;
  pv_[n - 1] = 0.0;
  pv_.segment(1, m) = p_ref * x.head(m);
  if (elastic) {
    elastic->Apply(pv_.data(), hv_.data());
    hv_.array() += h_ref * x[m];
  } else {
    hv_.setConstant(h_ref * x[m]);
  }
  y->resize(m + 1);
  const double* pv = pv_.data();
  const double* hv = hv_.data();
  const double* rs = row_scale->data();
  // Columns c = 0 .. 3 of A and B (n x 4, column-major) hold node k = i - 2 + c.
  const Eigen::Index lda = a->rows(), ldb = b->rows();
  const double* a0 = a->data();
  const double* b0 = b->data();
  double* yd = y->data();
  // Row i = 1 has no node i - 2; every other row sums its four terms in the same order.
  {
    double s = 0.0;
    for (int c = 1; c < 4; ++c) s += a0[1 + c * lda] * pv[c - 1] + b0[1 + c * ldb] * hv[c - 1];
    yd[0] = rs[1] * s;
  }
  StencilRows(m, a0, lda, b0, ldb, pv, hv, rs, yd);
  for (int i = 1; i <= m; ++i)
    if (cavitated[i]) yd[i - 1] = x[i - 1];
  (*y)[m] = dx * pv_.sum() / load;
}

Eigen::MatrixXd NewtonSystem::Dense() const {
  const int m = n - 2;
  Eigen::MatrixXd j = Eigen::MatrixXd::Zero(m + 1, m + 1);
  Eigen::VectorXd kcoef;
  if (elastic) {
    kcoef.resize(n);
    for (int k = 0; k < n; ++k) kcoef[k] = elastic->Coefficient(k);
  }
  // Each row's elastic part is summed in a contiguous buffer (column c - 1 holds unknown c)
  // and written to the column-major matrix once: four strided passes per row cost more than
  // the arithmetic.
  Eigen::RowVectorXd acc(m);
  for (int i = 1; i <= m; ++i) {
    const int row = i - 1;
    if (cavitated[i]) {
      j(row, row) = 1.0;
      continue;
    }
    double bsum = 0.0;
    const double rs = (*row_scale)[i];
    bool any = false;
    if (elastic) acc.setZero();
    for (int c = 0; c < 4; ++c) {
      const int k = i - 2 + c;
      if (k < 0 || k >= n) continue;
      const double bk = (*b)(i, c);
      bsum += bk;
      if (elastic && bk != 0.0) {
        // acc[col - 1] += f K(|k - col|), col = 1..m, split at col = k to drop the abs.
        const double f = rs * p_ref * bk;
        const int split = std::clamp(k, 1, m + 1);
        for (int col = 1; col < split; ++col) acc[col - 1] += f * kcoef[k - col];
        for (int col = split; col <= m; ++col) acc[col - 1] += f * kcoef[col - k];
        any = true;
      }
    }
    if (any) j.row(row).head(m) = acc;
    for (int c = 0; c < 4; ++c) {
      const int k = i - 2 + c;
      if (k >= 1 && k <= m) j(row, k - 1) += rs * p_ref * (*a)(i, c);
    }
    j(row, m) = rs * h_ref * bsum;
  }
  j.row(m).head(m).setConstant(dx * p_ref / load);
  return j;
}

void NewtonSystem::Diagonals(Eigen::VectorXd* d) const {
  d->setZero(n);
  // Node k = i - 2 + c is |k - i| = |c - 2| cells from i: only K_0, K_1 and K_2 enter.
  const double k0 = elastic ? elastic->Coefficient(0) : 0.0;
  const double k1 = elastic && n > 1 ? elastic->Coefficient(1) : 0.0;
  const double k2 = elastic && n > 2 ? elastic->Coefficient(2) : 0.0;
  const double kc[4] = {k2, k1, k0, k1};
  for (int i = 1; i + 1 < n; ++i) {
    double s = (*a)(i, 2);
    for (int c = (i >= 2 ? 0 : 1); c < 4; ++c) s += (*b)(i, c) * kc[c];
    (*d)[i] = s;
  }
}

namespace {

class DenseLuSolver final : public NewtonLinearSolver {
 public:
  bool Solve(const NewtonSystem& system, const Eigen::VectorXd& rhs, Eigen::VectorXd* dz,
             std::string* why) override {
    const Eigen::PartialPivLU<Eigen::MatrixXd> lu(system.Dense());
    *dz = lu.solve(rhs);
    if (!dz->allFinite()) {
      *why = "dense LU: singular Jacobian";
      return false;
    }
    return true;
  }
  std::string Name() const override { return "dense"; }
};

}  // namespace

std::unique_ptr<NewtonLinearSolver> MakeDenseLuSolver() {
  return std::make_unique<DenseLuSolver>();
}

}  // namespace tehl::internal
