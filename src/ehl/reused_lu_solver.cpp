// Newton linear solver that reuses one dense LU factorization across Newton iterations and
// time steps: GMRES on J dz = rhs with the exact J applied matrix-free (elastic part through
// the FFT), right-preconditioned by the LU of an earlier Jacobian. When GMRES needs more than
// `max_iterations` (the Jacobian has drifted: new cavitation rows, a load step), the current
// Jacobian is factorized and solved directly. Along a mesh cycle most steps then cost a few
// O(n^2) triangular solves instead of an O(n^3) factorization per Newton iteration.
// As a preconditioner the factors are applied in single precision: the triangular solves are
// memory bound (an n x n factor, 2 MB at 513 nodes, leaves the cache), and GMRES corrects
// the rounding; the direct solve after a factorization stays in double precision.
#include <cmath>
#include <limits>

#include <Eigen/LU>

#include "ehl/gmres.hpp"
#include "ehl/newton_system.hpp"

namespace tehl::internal {
namespace {

class ReusedLuSolver final : public NewtonLinearSolver {
 public:
  explicit ReusedLuSolver(const KrylovSettings& s) : settings_(s) {}

  bool Solve(const NewtonSystem& sys, const Eigen::VectorXd& rhs, Eigen::VectorXd* dz,
             std::string* why) override {
    last_iterations_ = 0;
    if (factored_ && size_ == sys.unknowns()) {
      auto apply = [&](const Eigen::VectorXd& x, Eigen::VectorXd* y) { sys.Apply(x, y); };
      auto precondition = [&](const Eigen::VectorXd& x, Eigen::VectorXd* y) {
        if (!single_) {
          *y = lu_.solve(x);
          return;
        }
        work_ = (permutation_ * x).cast<float>();
        factor_.triangularView<Eigen::UnitLower>().solveInPlace(work_);
        factor_.triangularView<Eigen::Upper>().solveInPlace(work_);
        *y = work_.cast<double>();
      };
      dz->setZero(rhs.size());
      const GmresResult g = Gmres(apply, precondition, rhs, dz, settings_.restart,
                                  settings_.max_iterations, Tolerance());
      last_iterations_ = g.iterations;
      if (g.converged && dz->allFinite()) return true;
    }
    lu_.compute(sys.Dense());
    size_ = sys.unknowns();
    factored_ = true;
    ++factorizations_;
    *dz = lu_.solve(rhs);
    if (!dz->allFinite()) {
      *why = "reused_lu: singular Jacobian";
      factored_ = false;
      return false;
    }
    // Kept in single precision unless a factor entry would overflow a float; entries below
    // the smallest normal float are dropped rather than kept as slow subnormals. The double
    // factors are then released: they served the direct solve above.
    const double largest = lu_.matrixLU().cwiseAbs().maxCoeff();
    single_ = std::isfinite(largest) && largest < 1e37;
    if (single_) {
      permutation_ = lu_.permutationP();
      factor_ = lu_.matrixLU().cast<float>().unaryExpr(
          [](float v) { return std::abs(v) < std::numeric_limits<float>::min() ? 0.0f : v; });
      lu_ = Eigen::PartialPivLU<Eigen::MatrixXd>();
    }
    return true;
  }
  int last_krylov_iterations() const override { return last_iterations_; }
  void SetRelativeTolerance(double tolerance) override { forcing_ = tolerance; }
  std::string Name() const override { return "reused_lu"; }

 private:
  double Tolerance() const { return forcing_ > 0 ? forcing_ : settings_.relative_tolerance; }
  KrylovSettings settings_;
  double forcing_ = 0;  // inexact Newton tolerance of the next solve, 0 = settings_
  Eigen::PartialPivLU<Eigen::MatrixXd> lu_;  // kept only when !single_
  Eigen::PermutationMatrix<Eigen::Dynamic, Eigen::Dynamic, int> permutation_;  // P of P J = L U
  Eigen::MatrixXf factor_;  // L and U in single precision, for preconditioning
  Eigen::VectorXf work_;
  int size_ = 0;            // unknowns of the factorized Jacobian [-]
  bool single_ = false;
  bool factored_ = false;
  int factorizations_ = 0;
  int last_iterations_ = 0;
};

}  // namespace

std::unique_ptr<NewtonLinearSolver> MakeReusedLuSolver(const KrylovSettings& settings) {
  return std::make_unique<ReusedLuSolver>(settings);
}

}  // namespace tehl::internal
