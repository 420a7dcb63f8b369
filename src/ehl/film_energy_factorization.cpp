// The factorization and solve of the film energy system (src/ehl/film_energy_system.hpp):
// KLU on the matrix without the recirculation zones' history, and the chord correction with
// GMRES on the whole matrix.
#include <klu.h>

#include <algorithm>
#include <cmath>
#include <utility>

#include "ehl/film_energy_system.hpp"
#include "ehl/gmres.hpp"

namespace tehl::internal {

// KLU handles: the symbolic analysis (block-triangular form, AMD per block) is kept while the
// sparsity pattern stays the same; the numeric factorization is redone every iteration.
struct FilmEnergySystem::Klu {
  klu_common common;
  klu_symbolic* symbolic = nullptr;
  klu_numeric* numeric = nullptr;
  Klu() { klu_defaults(&common); }
  ~Klu() {
    if (numeric) klu_free_numeric(&numeric, &common);
    if (symbolic) klu_free_symbolic(&symbolic, &common);
  }
};

FilmEnergySystem::FilmEnergySystem(const UniformGrid& grid,
                                   int nz,
                                   int near_cells,
                                   bool finite_peclet)
    : n_(grid.size()),
      nz_(nz),
      block_(nz + 2),
      dx_(grid.dx_m()),
      dxi_(1.0 / (nz - 1)),
      grid_(grid),
      near_cells_(near_cells),
      finite_peclet_(finite_peclet),
      source_{MovingHeatSource(grid), MovingHeatSource(grid)},
      far_{FarHistory(source_[0], near_cells), FarHistory(source_[1], near_cells)},
      far_y_(grid.size()),
      klu_(std::make_unique<Klu>()) {}

FilmEnergySystem::~FilmEnergySystem() = default;

bool FilmEnergySystem::HasFactorization() const { return klu_->numeric != nullptr; }

bool FilmEnergySystem::Factorize(bool exact) {
  // The matrix to factorize: A itself, or A without the moving-heat-source history inside a
  // recirculation zone (columns joined by reverse-flow faces) and without the conduction
  // along x from a column to the one upstream of it across a zone boundary. KLU's
  // block-triangular form turns each zone into one diagonal block; the history (a dense
  // triangle) would fill it, while without it the block is banded and cheap. Outside the
  // zones the history is lower block-triangular and costs only forward substitution, so it
  // stays; the upstream conduction, O(1/Peclet) of the convection, is left to the iteration
  // (with walls of fixed temperature there is no history and A is banded: all of it stays).
  // A face whose convection does not dominate its conduction along x (cell Peclet number
  // below kZonePeclet in some layer, as in a slow cavitated outlet) joins its columns too:
  // lagged there, the conduction would make the chord steps contract poorly.
  std::vector<int> zone(n_);
  for (int i = 0; i < n_; ++i) {
    bool joined = false;
    for (int j = 0; i > 0 && j < nz_; ++j) {
      const double dxi_j = (j == 0 || j == nz_ - 1) ? 0.5 * dxi_ : dxi_;
      joined =
          joined || fx_(i, j) < 0 || cp_ * std::abs(fx_(i, j)) < kZonePeclet * kx_face_[i] * dxi_j;
    }
    zone[i] = joined ? zone[i - 1] : i;
  }
  fact_ptr_.assign(col_ptr_.size(), 0);
  fact_idx_.clear();
  fact_val_.clear();
  fact_idx_.reserve(row_idx_.size());
  fact_val_.reserve(row_idx_.size());
  // Even the exact factorization leaves the upstream conduction out: with it every column
  // would join one diagonal block, which the surface history would fill.
  const bool lag_conduction = moving_walls_;
  int dropped = 0, lagged = 0, zone_lagged = 0;
  const int zone_band = near_cells_;
  for (int c = 0; c + 1 < static_cast<int>(col_ptr_.size()); ++c) {
    fact_ptr_[c] = static_cast<int>(fact_idx_.size());
    const int ci = c / block_;
    const bool wall_column = c % block_ >= nz_;
    for (int e = col_ptr_[c]; e < col_ptr_[c + 1]; ++e) {
      const int ri = row_idx_[e] / block_;
      if (lag_conduction && !wall_column && ri < ci && zone[ri] != zone[ci]) {
        ++lagged;
        continue;
      }
      if (wall_column && ri > ci && zone[ri] == zone[ci]) {
        if (!exact) {
          ++dropped;
          continue;
        }
        // Exact: inside a zone only the near band of the history (A holds no more; a whole
        // history would fill the zone's block: a 129-node rigid film with reverse flow
        // everywhere took 4 times as long).
        if (ri - ci > zone_band) {
          ++zone_lagged;
          continue;
        }
      }
      fact_idx_.push_back(row_idx_[e]);
      fact_val_.push_back(values_[e]);
    }
  }
  fact_ptr_.back() = static_cast<int>(fact_idx_.size());
  factorized_exact_ = dropped == 0;
  lags_couplings_ = lagged > 0 || zone_lagged > 0;

  Klu& k = *klu_;
  const int size = n_ * block_;
  if (!k.symbolic || fact_ptr_ != analyzed_ptr_ || fact_idx_ != analyzed_idx_) {
    if (k.numeric) klu_free_numeric(&k.numeric, &k.common);
    if (k.symbolic) klu_free_symbolic(&k.symbolic, &k.common);
    analyzed_ptr_.clear();
    k.symbolic = klu_analyze(size, fact_ptr_.data(), fact_idx_.data(), &k.common);
    if (!k.symbolic) return false;
    analyzed_ptr_ = fact_ptr_;
    analyzed_idx_ = fact_idx_;
  }
  // Same pattern: refactor with the previous pivot order (no pivot search), unless its pivots
  // have become poor (reciprocal pivot growth); then a fresh factorization.
  if (k.numeric &&
      klu_refactor(fact_ptr_.data(), fact_idx_.data(), fact_val_.data(), k.symbolic, k.numeric,
                   &k.common) &&
      klu_rgrowth(fact_ptr_.data(), fact_idx_.data(), fact_val_.data(), k.symbolic, k.numeric,
                  &k.common) &&
      k.common.rgrowth > 1e-8)
    return true;
  if (k.numeric) klu_free_numeric(&k.numeric, &k.common);
  k.numeric =
      klu_factor(fact_ptr_.data(), fact_idx_.data(), fact_val_.data(), k.symbolic, &k.common);
  return k.numeric != nullptr;
}

bool FilmEnergySystem::Correction(const Eigen::VectorXd& x,
                                  bool krylov,
                                  Eigen::VectorXd* delta) const {
  Klu& k = *klu_;
  if (!k.numeric) return false;
  // The whole operator: A v and, outside A, the far history (surface rows T_s - T0 - F sum G q
  // = 0, so A_whole v = A v - F/dx sum_far G s).
  const bool far = lags_far_history();
  auto apply_whole = [&](const Eigen::VectorXd& v, Eigen::VectorXd* out) {
    out->setZero(v.size());
    for (int c = 0; c + 1 < static_cast<int>(col_ptr_.size()); ++c)
      for (int e = col_ptr_[c]; e < col_ptr_[c + 1]; ++e) (*out)[row_idx_[e]] += values_[e] * v[c];
    if (far)
      for (int s = 0; s < 2; ++s) {
        far_[s].Apply(v.data() + nz_ + s, block_, far_y_.data());
        const double f = (s == 0 ? built_factor1_ : built_factor2_) / dx_;
        for (int i = 0; i < n_; ++i) (*out)[i * block_ + nz_ + s] -= f * far_y_[i];
      }
  };
  auto solve_factorized = [&](Eigen::VectorXd* v) {
    return klu_solve(k.symbolic, k.numeric, static_cast<int>(v->size()), 1, v->data(), &k.common) !=
           0;
  };
  // The residual b - A_whole x.
  Eigen::VectorXd residual = Eigen::Map<const Eigen::VectorXd>(rhs_.data(), rhs_.size());
  for (int c = 0; c + 1 < static_cast<int>(col_ptr_.size()); ++c)
    for (int e = col_ptr_[c]; e < col_ptr_[c + 1]; ++e) residual[row_idx_[e]] -= values_[e] * x[c];
  if (far)
    for (int s = 0; s < 2; ++s) {
      far_[s].Apply(x.data() + nz_ + s, block_, far_y_.data());
      const double f = (s == 0 ? built_factor1_ : built_factor2_) / dx_;
      for (int i = 0; i < n_; ++i) residual[i * block_ + nz_ + s] += f * far_y_[i];
    }
  if (!(krylov && far)) {
    // A chord step with the factorized matrix.
    *delta = std::move(residual);
    return solve_factorized(delta) && delta->allFinite();
  }
  // A Krylov step: GMRES on the whole operator, preconditioned by the factorization, to a
  // loose relative residual (the outer iteration recomputes the residual). For finite Peclet
  // numbers: the heat conducted ahead of each source (every upstream lag) stays out of the
  // factorized matrix, and lagging it in chord steps contracts slowly or not at all when the
  // solids are strongly coupled to the film (the upstream weights of a Peclet number near 1
  // sum to many times the diagonal one).
  bool ok = true;
  auto precondition = [&](const Eigen::VectorXd& v, Eigen::VectorXd* out) {
    *out = v;
    ok = solve_factorized(out) && ok;
  };
  delta->setZero(residual.size());
  const GmresResult g = Gmres(apply_whole, precondition, residual, delta, kKrylovRestart,
                              kKrylovMaxIterations, kKrylovTolerance);
  krylov_iterations_ += g.iterations;
  return ok && delta->allFinite();
}

}  // namespace tehl::internal
