// LineContactSolver::Impl: the scaled complementarity residual, the pressure Newton (watchdog
// line search), continuation in load and grid sequencing.

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>
#include <memory>
#include <string>
#include <utility>

#include "base/number_text.hpp"
#include "ehl/line_contact_impl.hpp"
#include "tehl/ehl/hertz_edge.hpp"
#include "tehl/ehl/surface_roughness.hpp"
#include "tehl/units.hpp"

namespace tehl {
namespace {
using internal::FluidLaws;
using internal::NewtonSystem;
using internal::TimeDerivative;
using Clock = std::chrono::steady_clock;
}  // namespace

void LineContactSolver::Impl::UpdateRowWeights(const Scales& sc) {
  const int n = grid_.size();
  row_weight_.setZero(n);
  SystemFor(sc, 1.0).Diagonals(&diagonal_);
  double largest = 0.0;
  for (int i = 1; i < n - 1; ++i) {
    row_weight_[i] = std::abs(diagonal_[i]) * sc.p_ref;
    largest = std::max(largest, row_weight_[i]);
  }
  for (int i = 1; i < n - 1; ++i)
    row_weight_[i] = -1.0 / std::max(row_weight_[i], 1e-300 + 1e-14 * largest);
}

NewtonSystem LineContactSolver::Impl::SystemFor(const Scales& sc, double load) const {
  NewtonSystem ns;
  ns.n = grid_.size();
  ns.dx = grid_.dx_m();
  ns.p_ref = sc.p_ref;
  ns.h_ref = sc.h_ref;
  ns.row_scale = &row_weight_;
  ns.load = load;
  ns.a = &sys_.dr_dp();
  ns.b = &sys_.dr_dh();
  ns.elastic = elastic_ ? &*elastic_ : nullptr;
  return ns;
}

bool LineContactSolver::Impl::Residual(const ContactConditions& c,
                                       const FluidLaws& fluid,
                                       const Scales& sc,
                                       const TimeDerivative& td,
                                       FilmState* s,
                                       Eigen::VectorXd* f,
                                       bool linearize,
                                       bool refresh_weights) {
  Film(c, s);
  if (!s->h_m.allFinite() || s->h_m.minCoeff() <= 0.0) return false;
  sys_.Evaluate(fluid, c.um(), s->p_pa, s->h_m, td, linearize);
  if (linearize && refresh_weights) UpdateRowWeights(sc);
  return ComplementarityResidual(c, sc, *s, f);
}

bool LineContactSolver::Impl::ComplementarityResidual(const ContactConditions& c,
                                                      const Scales& sc,
                                                      const FilmState& s,
                                                      Eigen::VectorXd* f) {
  const int n = grid_.size(), m = n - 2;
  f->resize(m + 1);
  cavitated_.assign(n, 0);
  for (int i = 1; i <= m; ++i) {
    const double pi = s.p_pa[i] / sc.p_ref;
    const double ri = row_weight_[i] * sys_.residual()[i];
    // std::min(pi, NaN) is pi: a Reynolds residual that is not finite (a viscosity that
    // overflowed at a cold, highly loaded node of a thermal film) must not hide behind it.
    if (!std::isfinite(ri)) return false;
    cavitated_[i] = pi <= ri;
    (*f)[i - 1] = std::min(pi, ri);
  }
  (*f)[m] = (grid_.dx_m() * s.p_pa.sum() - c.load_n_per_m) / c.load_n_per_m;
  return f->allFinite();
}

LineContactSolver::Summary LineContactSolver::Impl::Newton(const ContactConditions& c,
                                                           double pressure_scale,
                                                           const TimeDerivative& td,
                                                           FilmState* s) {
  Summary sum;
  sum.linear_solver = linear_->Name();
  const FluidLaws fluid = Fluid(c, pressure_scale);
  const Scales sc = ScalesFor(c);
  const int n = grid_.size(), m = n - 2;
  Eigen::VectorXd f, f_trial, dz;
  if (!Residual(c, fluid, sc, td, s, &f, true)) {
    // A non-positive film from the guess: lift h0 until the film is positive.
    const double lift = std::max(0.0, -s->h_m.minCoeff()) + sc.h_ref;
    s->h0_m += lift;
    if (!Residual(c, fluid, sc, td, s, &f, true)) {
      sum.termination = Termination::kInvalidInput;
      sum.message = "the initial guess gives a non-positive or non-finite film";
      return sum;
    }
  }
  NewtonSystem ns = SystemFor(sc, c.load_n_per_m);
  FilmState trial = *s;
  double norm = f.lpNorm<Eigen::Infinity>();
  sum.residual = norm;
  // Watchdog globalization (Chamberlain, Powell, Lemarechal & Pedersen 1982): a full Newton
  // step may raise ||F|| for a few iterations while the pressure spike and the cavitation
  // boundary move. Up to kWatchdog full steps are taken from a checkpoint; if ||F|| has not
  // fallen below the checkpoint's by then, the iteration returns there and backtracks.
  constexpr int kWatchdog = 3;
  int watchdog = 0;
  bool watchdog_allowed = true;
  FilmState checkpoint;
  Eigen::VectorXd f_check, dz_check;
  double phi_check = 0.0;
  auto try_step = [&](double lambda, const Eigen::VectorXd& dir, const FilmState& from) {
    // Projected step: p >= 0 holds at the solution, so negative pressures from a step
    // that moves the cavitation boundary are set to zero at once (without this the
    // boundary creeps one node per damped iteration on fine grids).
    trial.p_pa = from.p_pa;
    trial.p_pa.segment(1, m) += lambda * sc.p_ref * dir.head(m);
    trial.p_pa = trial.p_pa.cwiseMax(0.0);
    trial.h0_m = from.h0_m + lambda * sc.h_ref * dir[m];
    trial.travel1_m = from.travel1_m;
    trial.travel2_m = from.travel2_m;
    // Linearized at once, with the row weights of the current iterate (the line search
    // compares norms under one scaling): the accepted trial is the last state evaluated, so
    // the next iteration needs only its row weights, not a second evaluation of the film
    // and the lubricant laws (about 9 FFT convolutions' worth of time, docs/performance.md).
    return Residual(c, fluid, sc, td, &trial, &f_trial, true, false);
  };
  // Inexact Newton (Eisenstat & Walker 1996, choice 2): the linear solve's relative tolerance
  // follows the residual's decrease; never tighter than needed to reach the tolerance.
  // The forcing term is capped at 1e-3: measured at M = 20, L = 10 (513 ... 16385 nodes), a cap
  // of 0.1 let inexact steps upset the cavitation set (16385 nodes, warm: 23 Newton iterations
  // instead of 5); 1e-3 keeps the Newton counts and saves 15-30 % of the GMRES iterations.
  constexpr double kEtaMax = 1e-3, kExactBelow = 1e-3, kFinalFraction = 1e-2;
  double eta = kEtaMax, norm2_prev = -1.0;
  for (int it = 0; it < opt_.max_iterations; ++it) {
    if (norm < opt_.tolerance) break;
    if (opt_.inexact_newton) {
      const double norm2 = f.norm();
      if (norm2_prev > 0) {
        const double ew = 0.9 * std::pow(norm2 / norm2_prev, 2.0);
        const double safeguard = 0.9 * eta * eta;
        eta = std::min(kEtaMax, safeguard > 0.1 ? std::max(ew, safeguard) : ew);
      }
      eta = std::max(eta, 1e-10);
      norm2_prev = norm2;
      // Near the solution the linear residual is asked to fall below a hundredth of the Newton
      // tolerance in absolute terms (relative tolerance 0.01 tol / ||F||_2, never looser than
      // eta nor tighter than the solver's own 1e-10). The step then lands as close to the root
      // as an exact step would at this tolerance: a plain forcing term there left a residual
      // of its own size, which moved p by 1e-8-3e-8 of p_max against dense LU (257 and 1025
      // nodes); solving every step near the root to 1e-10 cost twice the GMRES iterations.
      double rel = eta;
      if (norm < kExactBelow) rel = std::min(eta, kFinalFraction * opt_.tolerance / norm2);
      linear_->SetRelativeTolerance(std::max(rel, 1e-10));
    }
    ns.cavitated = cavitated_;
    std::string why;
    if (!linear_->Solve(ns, -f, &dz, &why)) {
      sum.termination = Termination::kLinearSolverFailed;
      sum.message = why;
      return Finish(c, s, sum);
    }
    sum.krylov_iterations += linear_->last_krylov_iterations();
    double phi0 = f.norm();
    double lambda = 1.0;
    bool accepted = false;
    const bool full_ok = try_step(1.0, dz, *s);
    const double phi_full = full_ok ? f_trial.norm() : 0.0;
    if (full_ok && phi_full <= (1.0 - 1e-4) * phi0) {
      accepted = true;
    } else if (full_ok && watchdog_allowed && watchdog < kWatchdog) {
      if (watchdog == 0) {
        checkpoint = *s;
        f_check = f;
        dz_check = dz;
        phi_check = phi0;
      }
      ++watchdog;
      accepted = true;
    } else {
      if (watchdog > 0) {  // back to the checkpoint, then backtrack along its direction
        *s = checkpoint;
        Residual(c, fluid, sc, td, s, &f, true);
        dz = dz_check;
        phi0 = phi_check;
        watchdog = 0;
        watchdog_allowed = false;
      }
      for (lambda = 0.5; lambda >= opt_.min_step_fraction; lambda *= 0.5) {
        if (try_step(lambda, dz, *s) && f_trial.norm() <= (1.0 - 1e-4 * lambda) * phi0) {
          accepted = true;
          break;
        }
      }
    }
    if (!accepted) {
      sum.iterations = it;
      sum.termination = Termination::kLineSearchFailed;
      sum.message = "line search found no decrease of the residual (step " +
                    internal::FormatReal(lambda) + ") at residual " + internal::FormatReal(norm);
      Residual(c, fluid, sc, td, s, &f, false);
      return Finish(c, s, sum);
    }
    std::swap(s->p_pa, trial.p_pa);
    std::swap(s->h_m, trial.h_m);
    s->h0_m = trial.h0_m;
    UpdateRowWeights(sc);  // the trial's evaluation left its derivatives in sys_
    ComplementarityResidual(c, sc, *s, &f);
    norm = f.lpNorm<Eigen::Infinity>();
    if (watchdog > 0 && f.norm() <= (1.0 - 1e-4) * phi_check) {
      watchdog = 0;  // the full steps paid off
      watchdog_allowed = true;
    } else if (watchdog == 0 && lambda < 1.0) {
      watchdog_allowed = true;  // a damped step was taken: full steps may be tried again
    }
    IterationRecord rec;
    rec.residual = norm;
    rec.step = lambda;
    rec.krylov_iterations = linear_->last_krylov_iterations();
    rec.cavitated_nodes = static_cast<int>(std::count(cavitated_.begin(), cavitated_.end(), 1));
    sum.history.push_back(rec);
    sum.iterations = it + 1;
  }
  sum.residual = norm;
  if (norm < opt_.tolerance) {
    sum.termination = Termination::kConverged;
    sum.message = "converged";
  } else {
    sum.termination = Termination::kMaxIterations;
    sum.message = "no convergence in " + std::to_string(opt_.max_iterations) +
                  " Newton iterations (residual " + internal::FormatReal(norm) + ")";
  }
  return Finish(c, s, sum);
}

LineContactSolver::Summary LineContactSolver::Impl::Finish(const ContactConditions& c,
                                                           FilmState* s,
                                                           Summary sum) {
  // The reported pressure is the complementarity solution: p >= 0 exactly.
  s->p_pa = s->p_pa.cwiseMax(0.0);
  Film(c, s);
  sum.total_iterations = sum.iterations;
  sum.load_error = std::abs(grid_.dx_m() * s->p_pa.sum() - c.load_n_per_m) / c.load_n_per_m;
  return sum;
}

bool LineContactSolver::Impl::ValidConditions(const ContactConditions& c, Summary* sum) const {
  using internal::FormatShort;
  std::string bad;
  if (!(c.reduced_radius_m > 0) || !std::isfinite(c.reduced_radius_m))
    bad += " R = " + FormatShort(c.reduced_radius_m) + " m, not finite and > 0;";
  if (!(c.load_n_per_m > 0) || !std::isfinite(c.load_n_per_m))
    bad += " w = " + FormatShort(c.load_n_per_m) + " N/m, not finite and > 0;";
  if (!(c.um() > 0) || !std::isfinite(c.um()))
    bad += " entrainment speed um = " + FormatShort(c.um()) +
           " m/s, not finite and > 0 (the inlet is at x_start);";
  if (!(c.temperature_k >= kMinAbsoluteTemperatureK) || !(c.temperature_k <= kMaxTemperatureK))
    bad += " T = " + FormatShort(c.temperature_k) + " K, not a temperature from " +
           FormatShort(kMinAbsoluteTemperatureK) + " to " + FormatShort(kMaxTemperatureK) +
           " K (below: degrees Celsius?);";
  if (bad.empty()) return true;
  sum->termination = Termination::kInvalidInput;
  sum->message = "invalid contact conditions:" + bad;
  return false;
}

LineContactSolver::Summary LineContactSolver::Impl::Solve(const ContactConditions& c,
                                                          const TimeDerivative& td,
                                                          FilmState* s) {
  const auto t0 = Clock::now();
  Summary sum;
  if (!ValidConditions(c, &sum)) return sum;
  if (!s->valid() || s->p_pa.size() != grid_.size()) *s = SequencedGuess(c, td, *s);
  const FilmState start = *s;
  sum = Newton(c, 1.0, td, s);
  int total = sum.total_iterations, krylov = sum.krylov_iterations, stages = 0;
  if (!sum.usable() && opt_.max_continuation_stages > 0 && !td.active) {
    // Continuation: theta scales the load and the pressure-viscosity coefficient.
    const std::string first_failure = sum.message;
    *s = InitialGuess(ContactConditions{c.reduced_radius_m, c.u1_m_s, c.u2_m_s,
                                        0.05 * c.load_n_per_m, c.temperature_k},
                      &start);
    double theta = 0.05, growth = 2.0;
    ContactConditions c_good = c;  // the conditions *s solves once a stage has converged
    bool have_good = false;
    double theta_good = 0.0;  // the load fraction *s solves
    Summary stage;
    while (stages < opt_.max_continuation_stages) {
      ContactConditions ci = c;
      ci.load_n_per_m = theta * c.load_n_per_m;
      FilmState trial = *s;
      // Each stage raises the load: start it from the last stage's film scaled to the new
      // Hertz zone, so its outlet does not have to creep there one cell per iteration.
      if (have_good) PredictHertzSimilar(c_good, ci, &trial);
      stage = Newton(ci, theta, td, &trial);
      ++stages;
      total += stage.total_iterations;
      krylov += stage.krylov_iterations;
      if (stage.usable()) {
        *s = trial;
        c_good = ci;
        have_good = true;
        theta_good = theta;
        if (theta >= 1.0) break;
        theta = std::min(1.0, theta * growth);
      } else {
        growth = std::sqrt(growth);
        theta = theta / std::sqrt(growth);
        if (growth < 1.01) break;
      }
    }
    sum = stage;
    if (sum.usable() && theta_good < 1.0) {
      // The stages ran out below the full load: the film solves a fraction of it only.
      sum.termination = Termination::kMaxIterations;
      sum.message = "no convergence directly (" + first_failure +
                    "); continuation in load and pressure-viscosity coefficient reached " +
                    internal::FormatReal(theta_good) + " of the load in " + std::to_string(stages) +
                    " stages" + EdgeHint(c);
    } else if (!sum.usable()) {
      sum.message = "no convergence directly (" + first_failure +
                    ") nor by continuation in "
                    "load and pressure-viscosity coefficient (" +
                    stage.message + ")" + EdgeHint(c);
      if (have_good)
        sum.message += "; the film left is that of the last stage that converged, at " +
                       internal::FormatReal(theta_good) + " of the load";
      if (!s->valid()) *s = start;
    }
  }
  if (!sum.usable()) sum.message += RoughnessHint(c, *s);
  sum.total_iterations = total;
  sum.krylov_iterations = krylov;
  sum.continuation_stages = stages;
  if (s->valid())  // against the full load, whatever stage the state comes from
    sum.load_error = std::abs(grid_.dx_m() * s->p_pa.sum() - c.load_n_per_m) / c.load_n_per_m;
  sum.wall_time_s = std::chrono::duration<double>(Clock::now() - t0).count();
  return sum;
}

double LineContactSolver::Impl::ResidualNorm(const ContactConditions& c, const FilmState& st) {
  if (field_) field_->Begin(c, st);
  FilmState s = st;
  Eigen::VectorXd f;
  if (!Residual(c, Fluid(c), ScalesFor(c), TimeDerivative{}, &s, &f, true))
    return std::numeric_limits<double>::infinity();
  return f.lpNorm<Eigen::Infinity>();
}

}  // namespace tehl
