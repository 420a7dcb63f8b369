// Restarted GMRES(m) with right preconditioning (Saad & Schultz 1986; Saad, Iterative
// Methods for Sparse Linear Systems, 2nd ed., Alg. 9.5), Givens rotations, modified
// Gram-Schmidt. Matrix-free: the operator and the preconditioner are callables.
#pragma once

#include <functional>

#include <Eigen/Core>

namespace tehl::internal {

struct GmresResult {
  bool converged = false;
  int iterations = 0;            // inner iterations over all restarts [-]
  double relative_residual = 0;  // ||b - A x|| / ||b|| [-]
};

using LinearOperator = std::function<void(const Eigen::VectorXd&, Eigen::VectorXd*)>;

// Solves A x = b; x holds the initial guess on entry (zero is fine).
GmresResult Gmres(const LinearOperator& apply_a, const LinearOperator& apply_m_inverse,
                  const Eigen::VectorXd& b, Eigen::VectorXd* x, int restart, int max_iterations,
                  double relative_tolerance);

}  // namespace tehl::internal
