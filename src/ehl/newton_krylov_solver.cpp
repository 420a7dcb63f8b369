// Newton-Krylov linear solver: GMRES on J dz = rhs with J applied matrix-free (the elastic
// part through the FFT), right-preconditioned by the augmented "differential deflection"
// system (film change as an unknown, second-differenced elastic kernel of half-band
// settings.band). Two preconditioners:
//  - two-level (settings.coarse_pressures > 0, the default): the one-level augmented system as
//    a bordered band LU (banded_film_preconditioner.hpp, LAPACK) after a Galerkin coarse-space
//    correction of coarse_pressures to 2 coarse_pressures piecewise-linear pressures (one per
//    16 cells in between; coarse_correction.hpp):
//      y = C x;  y += M^{-1} (x - J y).
//    Linear cost and memory in n; falls back to the hierarchy below if a factorization fails.
//  - hierarchy of strides (coarse_pressures = 0): the UMFPACK factorization of
//    film_augmented_preconditioner.hpp, whose fill grows faster than n.
// The factorization is kept across Newton iterations and solves while GMRES converges quickly
// with it. Measured cost and iteration counts: docs/performance.md.
#include <algorithm>
#include <string>
#include <vector>

#include "ehl/banded_film_preconditioner.hpp"
#include "ehl/coarse_correction.hpp"
#include "ehl/film_augmented_preconditioner.hpp"
#include "ehl/gmres.hpp"
#include "ehl/newton_system.hpp"
#include "ehl/newton_system_file.hpp"

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
    MaybeWriteNewtonSystem(sys, rhs);  // TEHL_WRITE_NEWTON_SYSTEMS (newton_system_file.hpp)
    auto apply = [&](const Eigen::VectorXd& x, Eigen::VectorXd* y) { sys.Apply(x, y); };
    auto precondition = [&](const Eigen::VectorXd& x, Eigen::VectorXd* y) {
      if (!two_level_) {
        pre_.Solve(x, y);
        return;
      }
      ApplyTwoLevel(sys, coarse_, banded_, x, y, &scratch_);
    };
    dz->setZero(rhs.size());
    last_iterations_ = 0;
    GmresResult g;
    if (factored_n_ == sys.n) RefreshOutlet(sys);
    if (factored_n_ == sys.n) {
      const int limit = std::min(2 * fresh_iterations_ + 10, settings_.max_iterations);
      g = Gmres(apply, precondition, rhs, dz, settings_.restart, limit,
                Tolerance());
      last_iterations_ = g.iterations;
    }
    if (!g.converged) {
      factored_n_ = 0;
      if (!dz->allFinite()) dz->setZero();
      if (!Factorize(sys, why)) return false;
      factored_n_ = sys.n;
      band_cavitated_ = sys.cavitated;
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
  // Between Newton iterations the Jacobian drifts most at the outlet: the pressure spike and
  // the cavitation boundary (rows that switch between Reynolds and p = 0). A kept band
  // factorization is brought up to date there (settings.outlet_refresh): the rows from n /
  // outlet_refresh nodes before the outlet, or before the first row whose cavitation changed,
  // are factorized again (BandedFilmPreconditioner::Refresh); the coarse level stays as it
  // was. Measured on a load ramp at 4097 nodes: docs/performance.md.
  void RefreshOutlet(const NewtonSystem& sys) {
    if (!two_level_ || settings_.outlet_refresh <= 0 || !banded_.paired()) return;
    const int n = sys.n;
    int first = n, last_fluid = 1;
    for (int i = 1; i < n - 1; ++i) {
      if (first == n && sys.cavitated[i] != band_cavitated_[i]) first = i;
      if (!sys.cavitated[i]) last_fluid = i;
    }
    const int from = std::max(1, std::min(first, last_fluid) - n / settings_.outlet_refresh);
    std::string why;
    if (!banded_.Refresh(sys, from, &why)) {
      factored_n_ = 0;  // factorize afresh
      return;
    }
    std::copy(sys.cavitated.begin() + from, sys.cavitated.end(), band_cavitated_.begin() + from);
  }
  bool Factorize(const NewtonSystem& sys, std::string* why) {
    two_level_ = false;
    if (settings_.coarse_pressures > 0) {
      // One coarse pressure per 16 cells, between c and 2c (c = coarse_pressures): on fine
      // grids the band (8 nodes) and the coarse spacing then leave fewer scales to GMRES
      // (docs/performance.md: 13.7 -> 11.8 GMRES iterations per Newton iteration at 4097
      // nodes, 18.5 -> 14.5 at 16385), while up to 2049 nodes nothing changes. One per 8
      // cells (2c from 2049 nodes) made 2049 nodes so much faster than 4097 that the cold
      // time grew by 2.51 on that doubling, against the target of 2.3.
      // Wide hats in the inlet (settings.inlet_hats), where the elastic coupling is weak, let
      // a lattice of half the stride carry as many coarse pressures as the uniform hats, twice
      // as dense in the Hertz zone: docs/performance.md. Only where the uniform stride is at
      // least the band's 8 nodes (2049 nodes and up at c = 128): below, band and coarse
      // spacing leave no scale between them, and the merge only costs (measured at 1025).
      int stride = CoarseStride(sys.n, settings_.coarse_pressures), until = 0;
      const int half = stride / 2;
      if (settings_.inlet_hats > 1 && stride >= 8 &&
          ElasticZoneStart(sys) > settings_.inlet_hats * half) {
        stride = half;  // at least one wide hat; otherwise the uniform hats as before
        until = ElasticZoneStart(sys);
      }
      std::string banded_why;
      two_level_ = coarse_.Build(sys, stride, until, settings_.inlet_hats) &&
                   banded_.Factorize(sys, settings_.band, &banded_why);
    }
    return two_level_ || pre_.Factorize(sys, settings_.band, why);
  }
  KrylovSettings settings_;
  double forcing_ = 0;  // inexact Newton tolerance of the next solve, 0 = settings_
  FilmAugmentedPreconditioner pre_;  // hierarchy of strides (UMFPACK)
  BandedFilmPreconditioner banded_;  // two-level: fine band LU ...
  CoarseCorrection coarse_;          // ... and the coarse space
  bool two_level_ = false;           // the current factorization is the two-level one
  TwoLevelScratch scratch_;
  int factored_n_ = 0;        // n of the current factorization, 0 = none
  std::vector<char> band_cavitated_;  // the cavitated rows the band factorization holds
  int fresh_iterations_ = 0;  // GMRES iterations right after the last factorization
  int last_iterations_ = 0;
};

}  // namespace

std::unique_ptr<NewtonLinearSolver> MakeNewtonKrylovSolver(const KrylovSettings& settings) {
  return std::make_unique<NewtonKrylovSolver>(settings);
}

}  // namespace tehl::internal
