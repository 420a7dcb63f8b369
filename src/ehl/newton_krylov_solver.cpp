// Newton-Krylov linear solver: GMRES on J dz = rhs with J applied matrix-free (the elastic
// part through the FFT), right-preconditioned by a sparse LU (UMFPACK) of
//   M = A + B K_band  (+ the h0 column and the load row),
// where K_band keeps the elastic influence coefficients with |k - j| <= band.
#include <Eigen/Sparse>
#include <Eigen/UmfPackSupport>
#include <cmath>
#include <vector>

#include "ehl/gmres.hpp"
#include "ehl/newton_system.hpp"
#include "tehl/ehl/elastic_deflection.hpp"

namespace tehl::internal {
namespace {

class NewtonKrylovSolver final : public NewtonLinearSolver {
 public:
  explicit NewtonKrylovSolver(const KrylovSettings& s) : settings_(s) {}

  bool Solve(const NewtonSystem& sys, const Eigen::VectorXd& rhs, Eigen::VectorXd* dz,
             std::string* why) override {
    BuildPreconditioner(sys);
    lu_.compute(m_);
    if (lu_.info() != Eigen::Success) {
      *why = "newton_krylov: sparse LU of the preconditioner failed";
      return false;
    }
    auto apply = [&](const Eigen::VectorXd& x, Eigen::VectorXd* y) { sys.Apply(x, y); };
    auto precondition = [&](const Eigen::VectorXd& x, Eigen::VectorXd* y) { *y = lu_.solve(x); };
    dz->setZero(rhs.size());
    const GmresResult g = Gmres(apply, precondition, rhs, dz, settings_.restart,
                                settings_.max_iterations, settings_.relative_tolerance);
    last_iterations_ = g.iterations;
    if (!g.converged || !dz->allFinite()) {
      *why = "newton_krylov: GMRES reached relative residual " +
             std::to_string(g.relative_residual) + " after " + std::to_string(g.iterations) +
             " iterations";
      return g.relative_residual < 1e-3 && dz->allFinite();  // still a descent direction
    }
    return true;
  }
  int last_krylov_iterations() const override { return last_iterations_; }
  std::string Name() const override { return "newton_krylov"; }

 private:
  void BuildPreconditioner(const NewtonSystem& sys) {
    const int n = sys.n, m = n - 2, band = settings_.band;
    std::vector<Eigen::Triplet<double>> t;
    t.reserve(static_cast<size_t>(m) * (2 * band + 8) + 2 * m);
    std::vector<double> kcoef(band + 4, 0.0);
    if (sys.elastic)
      for (int k = 0; k < band + 4 && k < n; ++k) kcoef[k] = sys.elastic->Coefficient(k);
    std::vector<double> row(2 * band + 8);
    for (int i = 1; i <= m; ++i) {
      if (sys.cavitated[i]) {
        t.emplace_back(i - 1, i - 1, 1.0);
        continue;
      }
      // Columns i-2-band .. i+1+band in a local buffer.
      const int lo = i - 2 - band;
      std::fill(row.begin(), row.end(), 0.0);
      double bsum = 0.0;
      for (int c = 0; c < 4; ++c) {
        const int k = i - 2 + c;
        if (k < 0 || k >= n) continue;
        const double bk = (*sys.b)(i, c);
        bsum += bk;
        row[k - lo] += (*sys.a)(i, c);
        if (sys.elastic && bk != 0.0)
          for (int j = k - band; j <= k + band; ++j) row[j - lo] += bk * kcoef[std::abs(k - j)];
      }
      const double f = (*sys.row_scale)[i] * sys.p_ref;
      for (int j = std::max(lo, 1); j <= std::min(i + 1 + band, m); ++j)
        if (row[j - lo] != 0.0) t.emplace_back(i - 1, j - 1, f * row[j - lo]);
      t.emplace_back(i - 1, m, (*sys.row_scale)[i] * sys.h_ref * bsum);
    }
    for (int j = 0; j < m; ++j) t.emplace_back(m, j, sys.dx * sys.p_ref / sys.load);
    m_.resize(m + 1, m + 1);
    m_.setFromTriplets(t.begin(), t.end());
    m_.makeCompressed();
  }

  KrylovSettings settings_;
  Eigen::SparseMatrix<double> m_;
  Eigen::UmfPackLU<Eigen::SparseMatrix<double>> lu_;
  int last_iterations_ = 0;
};

}  // namespace

std::unique_ptr<NewtonLinearSolver> MakeNewtonKrylovSolver(const KrylovSettings& settings) {
  return std::make_unique<NewtonKrylovSolver>(settings);
}

}  // namespace tehl::internal
