// LineContactSolver::Impl: grid sequencing, the starting film of a fine grid interpolated
// from the solution on a coarser one.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "base/number_text.hpp"
#include "ehl/line_contact_impl.hpp"
#include "tehl/ehl/hertz_edge.hpp"
#include "tehl/ehl/surface_roughness.hpp"
#include "tehl/units.hpp"

namespace tehl {
using internal::TimeDerivative;

FilmState LineContactSolver::Impl::SequencedGuess(const ContactConditions& c,
                                                  const TimeDerivative& td,
                                                  const FilmState& clock) {
  const int n = grid_.size();
  const int nc = (n - 1) / 2 + 1;
  if (td.active || nc < opt_.coarse_grid_nodes) return InitialGuess(c, &clock);
  if (!coarse_) {
    Options o = opt_;
    o.linear_solver = LinearSolverKind::kAuto;
    // A coarse grid is solved once per cold solve, from scratch: the reused dense LU pays off
    // only over many warm solves (a mesh cycle). Measured (M = 20, L = 10, medians of 5): the
    // 513-node level by Newton-Krylov instead of the dense LU took a 1025-node cold solve from
    // 58 to 39 ms (UMFPACK preconditioner); with the two-level preconditioner the 257-node
    // level as well, 513 ... 4097-node cold solves 10.8 -> 8.0, 18.1 -> 16.3, 35.8 -> 33.0,
    // 69 -> 67 ms. Only the bottom level (129 nodes) keeps the dense LU.
    o.dense_max_nodes = std::min(o.dense_max_nodes, 129);
    // Its deflection is evaluated a few hundred times per cold solve: FFTW_MEASURE planning
    // of its size cost more than that (docs/performance.md, "One-off cost").
    o.fft_plan_effort = FftPlanEffort::kEstimate;
    // The coarse guess is isothermal and Newtonian: the fine grid couples the fields.
    FilmEffects coarse_effects = eff_;
    coarse_effects.thermal = false;
    coarse_effects.non_newtonian = false;
    coarse_effects.finite_peclet = false;
    coarse_ = std::make_unique<Impl>(UniformGrid(grid_.x_start_m(), grid_.x_end_m(), nc), e_prime_,
                                     lub_, coarse_effects, o, s1_, s2_, solids_);
  }
  FilmState cs;
  internal::CopyClock(clock, &cs);
  const Summary sum = coarse_->Solve(c, TimeDerivative{}, &cs);
  if (!sum.usable()) return InitialGuess(c, &clock);
  return Interpolated(coarse_->grid_, cs, c);
}

FilmState LineContactSolver::Impl::Interpolated(const UniformGrid& g,
                                                const FilmState& cs,
                                                const ContactConditions& c) {
  const int n = grid_.size();
  FilmState s;
  internal::CopyClock(cs, &s);
  s.p_pa.setZero(n);
  const bool thermal = cs.temperature.t_k.rows() == g.size();
  if (thermal) s.temperature.t_k.resize(n, cs.temperature.t_k.cols());
  for (int i = 0; i < n; ++i) {
    const double t = (grid_.x(i) - g.x_start_m()) / g.dx_m();
    const int k = std::clamp(static_cast<int>(t), 0, g.size() - 2);
    const double f = std::clamp(t - k, 0.0, 1.0);
    if (i > 0 && i < n - 1) s.p_pa[i] = (1 - f) * cs.p_pa[k] + f * cs.p_pa[k + 1];
    if (thermal)
      s.temperature.t_k.row(i) =
          (1 - f) * cs.temperature.t_k.row(k) + f * cs.temperature.t_k.row(k + 1);
  }
  if (thermal) {
    const Eigen::Index nz = s.temperature.t_k.cols();
    s.temperature.t1_k = s.temperature.t_k.col(0);
    s.temperature.t2_k = s.temperature.t_k.col(nz - 1);
    s.temperature.q1_w_m2.setZero(n);
    s.temperature.q2_w_m2.setZero(n);
  }
  s.h0_m = cs.h0_m;
  Film(c, &s);
  return s;
}

}  // namespace tehl
