// LineContactSolver::Impl::AdaptiveStep: a transient step under time-error control
// (Options::time_tolerance > 0; docs/theory.md, "Time-step error"). The step from t_n to
// t_n + dt is integrated in substeps whose sizes follow the local error estimate, as in
// adaptive BDF codes (Hairer & Wanner, Solving ODEs II, sections III.5 and III.7): a substep
// above the tolerance is repeated shorter, the next one is sized from the last estimate, and
// no substep is more than twice the one before (variable-step BDF2 is zero-stable for step
// ratios below 1 + sqrt(2), Grigorieff 1983). The history keeps the substeps' levels, and the
// next step starts at the size the last substep proposed.

#include <algorithm>
#include <cmath>

#include "ehl/line_contact_impl.hpp"

namespace tehl {
namespace {

// Whether the conditions jump from b to a in anything a step interpolates: by more than 1e-6
// relative (a gear cycle's left and right limits of a continuous load differ by about 2e-9,
// the load at B by 0.69).
bool Jumps(const ContactConditions& a, const ContactConditions& b) {
  auto differ = [](double x, double y) {
    return std::abs(x - y) > 1e-6 * std::max(std::abs(x), std::abs(y));
  };
  return differ(a.reduced_radius_m, b.reduced_radius_m) || differ(a.u1_m_s, b.u1_m_s) ||
         differ(a.u2_m_s, b.u2_m_s) || differ(a.load_n_per_m, b.load_n_per_m) ||
         differ(a.temperature_k, b.temperature_k);
}

// Substep sizes relative to the step: the first after a start or a jump, the smallest.
constexpr double kFirstFraction = 1.0 / 256;
constexpr double kSmallestFraction = 1.0 / 4096;
// Growth and shrink limits of the next substep, and the safety factor on the estimate's
// prediction (the usual 0.9).
constexpr double kMaxGrowth = 2.0, kMinShrink = 0.2, kSafety = 0.9;
// Retries of a substep whose solve did not converge (each a quarter of the size before).
constexpr int kMaxFailures = 4;

}  // namespace

LineContactSolver::Summary LineContactSolver::Impl::AdaptiveStep(const ContactConditions& c_new,
                                                                 double dt,
                                                                 FilmState* s,
                                                                 const ContactConditions* c_start) {
  const double tolerance = opt_.time_tolerance;
  const History start_hist = hist_;
  const FilmState start_state = *s;
  const ContactConditions c_old = c_start ? *c_start : hist_.c_prev;
  // Conditions that jump at t_n make the solution's time derivative jump there: levels
  // before t_n would spoil both BDF2 and the estimate, so the integration starts afresh from
  // t_n (BDF1 first), as ODE integrators restart at a discontinuity, with a short substep.
  const bool jump = c_start && Jumps(*c_start, hist_.c_prev);
  if (jump) hist_.levels = std::min(hist_.levels, 1);
  const int estimated_from = opt_.time_scheme == TimeScheme::kBdf2 ? 3 : 2;  // levels
  double h = hist_.levels < estimated_from || !(hist_.h_next > 0) ? kFirstFraction * dt
                                                                  : std::min(hist_.h_next, dt);
  const double h_min = kSmallestFraction * dt;
  Summary sum;
  int total = 0, krylov = 0, substeps = 0, failures = 0;
  double t = 0, worst = -1;
  for (;;) {
    const double rest = dt - t;
    const bool last = h > 0.9 * rest;
    if (last)
      h = rest;
    else if (h > 0.5 * rest)
      h = 0.5 * rest;
    const History before = hist_;
    const FilmState state_before = *s;
    TimeError e;
    sum = OneStep(Interpolate(c_old, c_new, last ? 1.0 : (t + h) / dt), h, s, &e);
    total += sum.total_iterations;
    krylov += sum.krylov_iterations;
    if (!sum.usable()) {
      hist_ = before;
      *s = state_before;
      if (++failures > kMaxFailures || h <= h_min) break;
      h = std::max(0.25 * h, h_min);
      continue;
    }
    if (e.value > tolerance && h > h_min) {
      hist_ = before;
      *s = state_before;
      h = std::max(h * std::max(kMinShrink, kSafety * std::pow(tolerance / e.value, 1 / e.order)),
                   h_min);
      continue;
    }
    t += h;
    ++substeps;
    worst = std::max(worst, e.value);
    const double grow = e.value > 0
                            ? std::clamp(kSafety * std::pow(tolerance / e.value, 1 / e.order),
                                         kMinShrink, kMaxGrowth)
                            : kMaxGrowth;
    h *= grow;
    if (last) break;
  }
  sum.substeps = std::max(substeps, 1);
  sum.time_error = sum.usable() ? worst : -1;
  if (sum.usable()) {
    hist_.h_next = h;
  } else {
    // A failed step leaves the state and the history of its start, as a failed step of the
    // ladder leaves the history.
    hist_ = start_hist;
    *s = start_state;
  }
  sum.total_iterations = total;
  sum.krylov_iterations = krylov;
  return sum;
}

}  // namespace tehl
