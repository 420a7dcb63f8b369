// Newton linear solver that reuses one dense LU factorization across Newton iterations and
// time steps: GMRES on J dz = rhs with the exact J applied matrix-free (elastic part through
// the FFT), right-preconditioned by the LU of an earlier Jacobian. When GMRES needs more than
// `max_iterations` (the Jacobian has drifted: new cavitation rows, a load step), the current
// Jacobian is factorized and solved directly. Along a mesh cycle most steps then cost a few
// O(n^2) triangular solves instead of an O(n^3) factorization per Newton iteration.
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
    if (factored_ && lu_.rows() == sys.unknowns()) {
      auto apply = [&](const Eigen::VectorXd& x, Eigen::VectorXd* y) { sys.Apply(x, y); };
      auto precondition = [&](const Eigen::VectorXd& x, Eigen::VectorXd* y) {
        *y = lu_.solve(x);
      };
      dz->setZero(rhs.size());
      const GmresResult g = Gmres(apply, precondition, rhs, dz, settings_.restart,
                                  settings_.max_iterations, Tolerance());
      last_iterations_ = g.iterations;
      if (g.converged && dz->allFinite()) return true;
    }
    lu_.compute(sys.Dense());
    factored_ = true;
    ++factorizations_;
    *dz = lu_.solve(rhs);
    if (!dz->allFinite()) {
      *why = "reused_lu: singular Jacobian";
      factored_ = false;
      return false;
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
  Eigen::PartialPivLU<Eigen::MatrixXd> lu_;
  bool factored_ = false;
  int factorizations_ = 0;
  int last_iterations_ = 0;
};

}  // namespace

std::unique_ptr<NewtonLinearSolver> MakeReusedLuSolver(const KrylovSettings& settings) {
  return std::make_unique<ReusedLuSolver>(settings);
}

}  // namespace tehl::internal
