// LineContactSolver::Impl: the thermal / non-Newtonian coupling (the pressure/energy alternation
// and coupled grid sequencing; Newton on the coupling map is line_contact_coupling_newton.cpp).

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include "base/number_text.hpp"
#include "ehl/film_field.hpp"
#include "ehl/fixed_point_newton.hpp"
#include "ehl/line_contact_impl.hpp"
#include "tehl/lubricant/lubricant.hpp"

namespace tehl {
namespace {
using internal::TimeDerivative;
using Clock = std::chrono::steady_clock;
// Coupled (thermal) grid sequencing stops at this many nodes [-].
constexpr int kMinThermalCoarseNodes = 65;
// Newton tolerance of the early thermal coupling iterations [-].
constexpr double kCouplingNewtonTolerance = 1e-5;
// Halvings of a temperature update whose pressure solve fails [-].
constexpr int kMaxTemperatureBackoffs = 4;
// A failed Newtonian thermal coupling names the non-Newtonian effect above this |SRR| [-]
// (the cool branch of the sliding Newtonian disc of docs/thermal.md ends near 0.055, and a
// 1 GPa disc at SRR 0.05 did not settle either).
constexpr double kSlidingHintSrr = 0.01;
// A coupling past its iteration budget goes on while it still converges: the smallest change
// of its last kProgressWindow iterations is below that of the kProgressWindow before, and at
// that rate it reaches `tolerance` by iteration `cap`. (Requiring a halving per window made
// the outcome of a coupling converging at about that rate depend on round-off: the L_T 5,
// SRR 0.5 disc of thermal_coupling_test.cpp settled in most processes and stopped 1.6x its
// tolerance from settled in others, with other FFTW plans.)
constexpr int kProgressWindow = 10;
bool StillConverging(const std::vector<double>& change, double tolerance, int cap) {
  const int n = static_cast<int>(change.size());
  if (n < 2 * kProgressWindow) return false;
  const auto at = [&](int i) { return change.begin() + i; };
  const double recent = *std::min_element(at(n - kProgressWindow), at(n));
  const double before = *std::min_element(at(n - 2 * kProgressWindow), at(n - kProgressWindow));
  if (!(recent < before)) return false;
  if (recent <= tolerance) return true;
  // Windows still needed at the rate recent / before per window.
  const double windows = std::log(tolerance / recent) / std::log(recent / before);
  return n + kProgressWindow * windows <= cap;
}
}  // namespace

LineContactSolver::Summary LineContactSolver::Impl::SolveCoupled(const ContactConditions& c,
                                                                 const TimeDerivative& td,
                                                                 const FilmState* previous,
                                                                 double dt_s,
                                                                 FilmState* s) {
  const bool steady = dt_s <= 0 && !td.active;
  const int nc = (grid_.size() - 1) / 2 + 1;
  const bool sequence = eff_.thermal && steady && nc >= kMinThermalCoarseNodes;
  // Where a coarse grid can start it, the fine Newton waits for that start: from the
  // stalled alternation it rarely converges (measured on the sliding discs).
  Summary sum = CoupleOnce(c, td, previous, dt_s, !sequence, s);
  // Sequenced too when a pressure solve inside the coupling failed after the first coupling
  // iteration (a temperature far from the film's: the Ree-Eyring disc at L_T 3, SRR 1 on 257
  // nodes, whose second pressure solve failed even with the temperature step halved 4 times).
  const bool coupling_failed = sum.termination == Termination::kCouplingNotConverged ||
                               (sum.coupling_iterations > 0 && !sum.usable());
  if (sum.usable() || !sequence || !coupling_failed) return sum;
  const auto t0 = Clock::now();
  if (!thermal_coarse_)
    thermal_coarse_ = std::make_unique<Impl>(UniformGrid(grid_.x_start_m(), grid_.x_end_m(), nc),
                                             e_prime_, lub_, eff_, opt_, s1_, s2_, solids_);
  FilmState cs;
  internal::CopyClock(*s, &cs);
  const Summary coarse = thermal_coarse_->SolveCoupled(c, td, nullptr, 0.0, &cs);
  Summary total = sum;
  total.total_iterations += coarse.total_iterations;
  total.krylov_iterations += coarse.krylov_iterations;
  total.coupling_iterations += coarse.coupling_iterations;
  total.coupling_newton_iterations += coarse.coupling_newton_iterations;
  if (coarse.usable()) {
    FilmState fine = Interpolated(thermal_coarse_->grid_, cs, c);
    const Summary again = CoupleOnce(c, td, previous, dt_s, true, &fine);
    total.total_iterations += again.total_iterations;
    total.krylov_iterations += again.krylov_iterations;
    total.coupling_iterations += again.coupling_iterations;
    total.coupling_newton_iterations += again.coupling_newton_iterations;
    if (std::getenv("TEHL_DEBUG_COUPLING"))
      std::fprintf(stderr, "thermal sequencing %d -> %d: %s\n", nc, grid_.size(),
                   again.usable() ? "settled" : again.message.c_str());
    if (again.usable()) {
      *s = fine;
      Summary done = again;
      done.total_iterations = total.total_iterations;
      done.krylov_iterations = total.krylov_iterations;
      done.coupling_iterations = total.coupling_iterations;
      done.coupling_newton_iterations = total.coupling_newton_iterations;
      done.wall_time_s = sum.wall_time_s + std::chrono::duration<double>(Clock::now() - t0).count();
      return done;
    }
  }
  total.message += coarse.usable() ? "; started from the coupled solution on " +
                                         std::to_string(nc) + " nodes, it did not settle either"
                                   : "; a retry on a coarser grid of " + std::to_string(nc) +
                                         " nodes (to start from) did not settle either";
  total.wall_time_s += std::chrono::duration<double>(Clock::now() - t0).count();
  return total;
}

LineContactSolver::Summary LineContactSolver::Impl::CoupleOnce(const ContactConditions& c,
                                                               const TimeDerivative& td,
                                                               const FilmState* previous,
                                                               double dt_s,
                                                               bool newton,
                                                               FilmState* s) {
  if (!field_) return Solve(c, td, s);
  const auto t0 = Clock::now();
  field_->Begin(c, *s);
  Summary sum;
  int total = 0, krylov = 0, stages = 0, coupling = 0;
  double change_t = -1, change_f = 0, change_p = 1, balance = -1;
  EnergyBalance energy;
  Eigen::VectorXd p_last;
  bool settled = false;
  std::string energy_failure, newton_message;
  const double newton_tolerance = opt_.tolerance;
  // Newton on the coupling (Newtonian thermal runs) takes over from the best iterate when
  // the alternation stalls: no new smallest temperature change for coupling_newton_after
  // iterations, or all iterations used.
  // Ree-Eyring thermal runs keep the alternation (with its budget extension while it still
  // converges) and take Newton on (T, w log f) only from the best iterate of an alternation
  // that did not settle.
  const bool newton_run = eff_.thermal && !eff_.non_newtonian && opt_.coupling_newton_after > 0;
  const bool newton_last = eff_.thermal && eff_.non_newtonian && opt_.coupling_newton_after > 0;
  const bool newton_possible = newton && (newton_run || newton_last);
  double best_change = std::numeric_limits<double>::infinity();
  int since_best = 0;
  Eigen::VectorXd best_x;
  FilmState best_s;
  FilmState good_s;        // the last settled pressure ...
  Eigen::MatrixXd good_t;  // ... and its temperature
  int backoffs = 0, restarts = 0;
  const FilmState start = eff_.thermal && eff_.non_newtonian ? *s : FilmState();
  std::vector<double> progress;  // per coupling iteration: change_t (thermal) or change_p
  int k = 0;
  for (; !settled; ++k) {
    // Past its budget an alternation goes on while it still converges, unless Newton on the
    // coupling takes over from its best iterate, here or after the coarse grid (Newtonian
    // thermal runs).
    if (k >= opt_.max_coupling_iterations &&
        !(!newton_run && k < opt_.max_coupling_iterations_converging &&
          StillConverging(progress,
                          eff_.thermal ? opt_.thermal_tolerance_k
                                       : opt_.coupling_pressure_tolerance,
                          opt_.max_coupling_iterations_converging)))
      break;
    // Inexact coupling: while the temperature still moves by more than 10x its tolerance,
    // the pressure need not be solved to the final tolerance.
    opt_.tolerance = change_t > 10 * opt_.thermal_tolerance_k
                         ? std::max(newton_tolerance, kCouplingNewtonTolerance)
                         : newton_tolerance;
    // After the first coupling iteration a failed pressure solve backs off along the
    // temperature update instead of falling back on load continuation: the pressure is
    // solved again from the last settled pressure at T_good + theta (T - T_good), theta =
    // 1/2, 1/4, ... (a trust region on the temperature step; docs/thermal.md, "Thermal
    // coupling"). The coupling then goes on from the backed-off temperature.
    const bool can_back_off = eff_.thermal && good_t.size() > 0;
    const int continuation_stages = opt_.max_continuation_stages;
    if (can_back_off) opt_.max_continuation_stages = 0;
    sum = Solve(c, td, s);
    total += sum.total_iterations;
    krylov += sum.krylov_iterations;
    stages += sum.continuation_stages;
    if (!sum.usable() && k == 0 && eff_.thermal && eff_.non_newtonian) {
      // A thermal Ree-Eyring solve starts from the factor of its start in full (FilmField::
      // Begin). On a rough film that factor is tied to where the asperities were: one step
      // later they have moved by about a cell and the first pressure solve can fail (the
      // seed 004 cycle with 0.2 um waviness at step 1, docs/studies.md). It is solved again
      // with the factor half-way from 1 (in log), as isothermal runs start, then with f = 1.
      for (double relaxation : {internal::FilmField::kEyringRelaxation, 0.0}) {
        if (sum.usable()) break;
        *s = start;
        field_->RestartRheology(c, start, relaxation);
        sum = Solve(c, td, s);
        total += sum.total_iterations;
        krylov += sum.krylov_iterations;
        stages += sum.continuation_stages;
        ++restarts;
      }
    }
    if (!sum.usable() && can_back_off) {
      const Eigen::MatrixXd t_target = field_->film_temperature();
      for (int b = 1; b <= kMaxTemperatureBackoffs && !sum.usable(); ++b) {
        field_->SetTemperature(good_t + std::ldexp(1.0, -b) * (t_target - good_t));
        *s = good_s;
        sum = Solve(c, td, s);
        total += sum.total_iterations;
        krylov += sum.krylov_iterations;
        ++backoffs;
      }
      opt_.max_continuation_stages = continuation_stages;
      if (!sum.usable() && continuation_stages > 0) {  // last resort: the full update with
        field_->SetTemperature(t_target);               // load continuation
        *s = good_s;
        sum = Solve(c, td, s);
        total += sum.total_iterations;
        krylov += sum.krylov_iterations;
        stages += sum.continuation_stages;
      }
    }
    opt_.max_continuation_stages = continuation_stages;
    opt_.tolerance = newton_tolerance;
    if (!sum.usable()) break;
    good_s = *s;
    good_t = field_->film_temperature();
    ++coupling;
    // Pressure change between coupling iterations, relative to p_max.
    if (p_last.size() == s->p_pa.size())
      change_p = (s->p_pa - p_last).cwiseAbs().maxCoeff() / std::max(s->MaxPressure(), 1.0);
    p_last = s->p_pa;
    const Eigen::VectorXd x_in = newton_possible ? field_->CouplingState() : Eigen::VectorXd();
    change_f =
        field_->UpdateRheology(c, *s, eff_.thermal ? 1.0 : internal::FilmField::kEyringRelaxation,
                               !eff_.thermal && opt_.eyring_anderson);
    change_t = 0.0;
    if (eff_.thermal) {
      // The energy solver checks its inputs and throws on a malformed flow field; inside a
      // coupling that can only come from a diverging iterate, which is a failed solve, not
      // bad input.
      internal::FilmField::EnergyUpdate e;
      try {
        e = field_->UpdateTemperature(c, *s, previous, dt_s, opt_.thermal_relaxation);
      } catch (const std::exception& ex) {
        e.ok = false;
        e.summary.message = ex.what();
      }
      balance = e.summary.balance.RelativeError();
      energy = e.summary.balance;
      change_t = e.max_change_k;
      if (newton_possible && e.ok && !e.limited) {
        if (change_t < best_change) {
          best_change = change_t;
          best_x = x_in;
          best_s = *s;
          since_best = 0;
        } else if (++since_best >= opt_.coupling_newton_after && newton_run) {
          break;
        }
      }
      if (!e.ok) {
        energy_failure = e.summary.message;
        break;
      }
    }
    progress.push_back(eff_.thermal ? change_t : change_p);
    if (std::getenv("TEHL_DEBUG_COUPLING"))
      std::fprintf(
          stderr, "coupling %d: newton %d dT %g df %g dp %g balance %g backoffs %d restarts %d\n",
          k, sum.total_iterations, change_t, change_f, change_p, balance, backoffs, restarts);
    // Thermal: the temperature settles. Non-Newtonian: the pressure settles (the Eyring factor
    // itself is spiky where dp/dx is large, so its own change is not the measure).
    settled = change_t < opt_.thermal_tolerance_k &&
              (!eff_.non_newtonian || change_p < opt_.coupling_pressure_tolerance);
    if (settled) {  // the pressure of the settled fields
      sum = Solve(c, td, s);
      total += sum.total_iterations;
      krylov += sum.krylov_iterations;
    }
  }
  if (!settled && newton_possible && best_x.size() > 0) {
    *s = best_s;
    field_->SetCouplingState(best_x);
    const CouplingNewton nt = NewtonCoupling(c, td, previous, dt_s, s);
    total += nt.pressure.total_iterations;
    krylov += nt.pressure.krylov_iterations;
    coupling += nt.result.map_evaluations;
    change_t = nt.result.residual;
    balance = nt.balance;
    energy = nt.energy;
    settled = nt.result.converged && nt.pressure.usable();
    sum = nt.pressure;  // the pressure solve at the returned temperature
    sum.coupling_newton_iterations = nt.result.newton_iterations;
    energy_failure.clear();
    newton_message = nt.result.message;
  }
  field_->Store(s);
  if (sum.usable() && !settled) {
    sum.termination = Termination::kCouplingNotConverged;
    sum.message =
        !energy_failure.empty()
            ? "energy equation: " + energy_failure
            : std::string(eff_.thermal ? "the pressure/temperature coupling"
                                       : "the pressure/Eyring factor coupling") +
                  " did not settle in " + std::to_string(k) + " iterations (" +
                  (eff_.thermal
                       ? "last temperature change " + internal::FormatShort(change_t) + " K, "
                       : std::string("last ")) +
                  "pressure change " + internal::FormatShort(change_p) + " p_max" +
                  (eff_.non_newtonian ? ", largest log change of the Eyring factor " +
                                            internal::FormatShort(change_f)
                                      : std::string()) +
                  ")" +
                  (newton_message.empty() ? "" : "; Newton on the coupling: " + newton_message);
    // A sliding Newtonian film: its shear heating grows with the pressure-viscosity without
    // the bound of a shear-thinning oil (the Ree-Eyring films of docs/validation.md section 6
    // settle at all 15 sliding points, the Newtonian ones at 3).
    const double srr = (c.u1_m_s - c.u2_m_s) / c.um();
    if (eff_.thermal && !eff_.non_newtonian && std::abs(srr) > kSlidingHintSrr) {
      char srr_text[32];
      std::snprintf(srr_text, sizeof srr_text, "%.3g", srr);
      sum.message += std::string("; a Newtonian film sliding at SRR ") + srr_text +
                     ": the effect non_newtonian (Ree-Eyring, docs/thermal.md) bounds its shear "
                     "stress and settles where the Newtonian film often does not";
    }
  }
  sum.total_iterations = total;
  sum.krylov_iterations = krylov;
  sum.continuation_stages = stages;
  sum.coupling_iterations = coupling;
  sum.temperature_backoffs = backoffs;
  sum.temperature_change_k = std::isfinite(change_t) ? change_t : -1.0;
  // A failed energy solve can leave a non-finite temperature and with it a non-finite
  // balance: reported as not computed (-1), never as NaN.
  sum.energy_balance_error = std::isfinite(balance) ? balance : -1.0;
  if (std::isfinite(balance)) sum.energy = energy;
  sum.wall_time_s = std::chrono::duration<double>(Clock::now() - t0).count();
  return sum;
}

}  // namespace tehl
