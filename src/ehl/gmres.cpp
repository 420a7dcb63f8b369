#include "ehl/gmres.hpp"

#include <cmath>
#include <vector>

namespace tehl::internal {

GmresResult Gmres(const LinearOperator& apply_a, const LinearOperator& apply_m_inverse,
                  const Eigen::VectorXd& b, Eigen::VectorXd* x, int restart, int max_iterations,
                  double tol) {
  GmresResult result;
  const int n = static_cast<int>(b.size());
  const double bnorm = b.norm();
  if (bnorm == 0.0) {
    x->setZero(n);
    result.converged = true;
    return result;
  }
  if (x->size() != n) x->setZero(n);
  Eigen::MatrixXd v(n, restart + 1), z(n, restart);
  Eigen::MatrixXd h = Eigen::MatrixXd::Zero(restart + 1, restart);
  Eigen::VectorXd cs(restart), sn(restart), g(restart + 1), w(n), ax(n), tmp(n);
  // A zero initial guess (the usual Newton step) needs no product for its residual.
  bool x_zero = x->isZero(0.0);
  while (result.iterations < max_iterations) {
    Eigen::VectorXd r = b;
    if (!x_zero) {
      apply_a(*x, &ax);
      r -= ax;
    }
    x_zero = false;
    double beta = r.norm();
    result.relative_residual = beta / bnorm;
    if (result.relative_residual <= tol) {
      result.converged = true;
      return result;
    }
    v.col(0) = r / beta;
    g.setZero();
    g[0] = beta;
    h.setZero();
    int k = 0;
    for (; k < restart && result.iterations < max_iterations; ++k) {
      ++result.iterations;
      apply_m_inverse(v.col(k), &tmp);
      z.col(k) = tmp;
      apply_a(tmp, &w);
      for (int i = 0; i <= k; ++i) {  // modified Gram-Schmidt
        h(i, k) = w.dot(v.col(i));
        w -= h(i, k) * v.col(i);
      }
      h(k + 1, k) = w.norm();
      if (h(k + 1, k) > 0) v.col(k + 1) = w / h(k + 1, k);
      for (int i = 0; i < k; ++i) {  // previous rotations
        const double t = cs[i] * h(i, k) + sn[i] * h(i + 1, k);
        h(i + 1, k) = -sn[i] * h(i, k) + cs[i] * h(i + 1, k);
        h(i, k) = t;
      }
      const double d = std::hypot(h(k, k), h(k + 1, k));
      cs[k] = d > 0 ? h(k, k) / d : 1.0;
      sn[k] = d > 0 ? h(k + 1, k) / d : 0.0;
      h(k, k) = d;
      h(k + 1, k) = 0.0;
      g[k + 1] = -sn[k] * g[k];
      g[k] = cs[k] * g[k];
      result.relative_residual = std::abs(g[k + 1]) / bnorm;
      if (result.relative_residual <= tol || d == 0.0) {
        ++k;
        break;
      }
    }
    // x += Z y with H y = g (upper triangular k x k).
    Eigen::VectorXd y = h.topLeftCorner(k, k).triangularView<Eigen::Upper>().solve(g.head(k));
    *x += z.leftCols(k) * y;
    if (result.relative_residual <= tol) {
      // Confirm with the true residual (rounding can make the recurrence optimistic).
      apply_a(*x, &ax);
      result.relative_residual = (b - ax).norm() / bnorm;
      if (result.relative_residual <= 10 * tol) {
        result.converged = true;
        return result;
      }
    }
  }
  return result;
}

}  // namespace tehl::internal
