// Newton-Krylov linear solver: GMRES on J dz = rhs with J applied matrix-free (the elastic
// part through the FFT), right-preconditioned by the UMFPACK factorization of the augmented
// "differential deflection" system of film_augmented_preconditioner.hpp (film change as an
// unknown, second-differenced elastic kernel on a hierarchy of strides, half-band
// settings.band). The factorization is kept across Newton iterations and solves while GMRES
// converges quickly with it. Measured cost and iteration counts: docs/performance.md.
#include <algorithm>

#include "ehl/film_augmented_preconditioner.hpp"
#include "ehl/gmres.hpp"
#include "ehl/newton_system.hpp"

namespace tehl::internal {
namespace {

class NewtonKrylovSolver final : public NewtonLinearSolver {
 public:
  explicit NewtonKrylovSolver(const KrylovSettings& s) : settings_(s) {}

  bool Solve(const NewtonSystem& sys,
             const Eigen::VectorXd& rhs,
             Eigen::VectorXd* dz,
             std::string* why) override {
    // Reuse the previous factorization while it still preconditions well: GMRES may take up
    // to twice the iterations it needed right after that factorization (plus 10); beyond
    // that the Jacobian has drifted (a load step, a moving cavitation boundary) and the
    // augmented matrix is refactorized, GMRES continuing from where it stopped.
    auto apply = [&](const Eigen::VectorXd& x, Eigen::VectorXd* y) { sys.Apply(x, y); };
    auto precondition = [&](const Eigen::VectorXd& x, Eigen::VectorXd* y) { pre_.Solve(x, y); };
    dz->setZero(rhs.size());
    last_iterations_ = 0;
    GmresResult g;
    if (factored_n_ == sys.n) {
      const int limit = std::min(2 * fresh_iterations_ + 10, settings_.max_iterations);
      g = Gmres(apply, precondition, rhs, dz, settings_.restart, limit,
                Tolerance());
      last_iterations_ = g.iterations;
    }
    if (!g.converged) {
      factored_n_ = 0;
      if (!dz->allFinite()) dz->setZero();
      if (!pre_.Factorize(sys, settings_.band, why)) return false;
      factored_n_ = sys.n;
      g = Gmres(apply, precondition, rhs, dz, settings_.restart, settings_.max_iterations,
                Tolerance());
      fresh_iterations_ = g.iterations;
      last_iterations_ += g.iterations;
    }
    if (!g.converged || !dz->allFinite()) {
      *why = "newton_krylov: GMRES reached relative residual " +
             std::to_string(g.relative_residual) + " after " + std::to_string(g.iterations) +
             " iterations";
      return g.relative_residual < 1e-3 && dz->allFinite();  // still a descent direction
    }
    return true;
  }
  int last_krylov_iterations() const override { return last_iterations_; }
  void SetRelativeTolerance(double tolerance) override { forcing_ = tolerance; }
  std::string Name() const override { return "newton_krylov"; }

 private:
  double Tolerance() const { return forcing_ > 0 ? forcing_ : settings_.relative_tolerance; }
  KrylovSettings settings_;
  double forcing_ = 0;  // inexact Newton tolerance of the next solve, 0 = settings_
  FilmAugmentedPreconditioner pre_;
  int factored_n_ = 0;        // n of the current factorization, 0 = none
  int fresh_iterations_ = 0;  // GMRES iterations right after the last factorization
  int last_iterations_ = 0;
};

}  // namespace

std::unique_ptr<NewtonLinearSolver> MakeNewtonKrylovSolver(const KrylovSettings& settings) {
  return std::make_unique<NewtonKrylovSolver>(settings);
}

}  // namespace tehl::internal
