// LineContactSolver::Impl: time stepping (BDF1/BDF2 history, substeps, the extrapolated start
// temperature, saved and restored history).

#include <algorithm>
#include <chrono>
#include <cmath>
#include <optional>

#include "ehl/line_contact_impl.hpp"
#include "tehl/units.hpp"

namespace tehl {
namespace {
using internal::TimeDerivative;
using Clock = std::chrono::steady_clock;
}  // namespace

Eigen::VectorXd LineContactSolver::Impl::RhoH(const ContactConditions& c, FilmState s) {
  Film(c, &s);
  TimeDerivative none;
  sys_.Evaluate(Fluid(c), c.um(), s.p_pa, s.h_m, none, false);
  return sys_.rho_h();
}

void LineContactSolver::Impl::BeginTransient(const ContactConditions& c, const FilmState& s) {
  if (field_) field_->Begin(c, s);
  hist_ = History{};
  hist_.levels = 1;
  hist_.q1 = RhoH(c, s);
  hist_.c_prev = c;
}

TimeDerivative LineContactSolver::Impl::Derivative(double dt) const {
  TimeDerivative td;
  if (!eff_.transient || hist_.levels == 0) return td;
  td.active = true;
  td.q1 = hist_.q1;
  if (hist_.levels >= 2 && opt_.time_scheme == TimeScheme::kBdf2) {
    // Variable-step BDF2 (omega = dt_n / dt_{n-1}).
    const double w = dt / hist_.dt_prev;
    td.a0 = (1 + 2 * w) / ((1 + w) * dt);
    td.a1 = -(1 + w) / dt;
    td.a2 = w * w / ((1 + w) * dt);
    td.q2 = hist_.q2;
  } else {
    td.a0 = 1.0 / dt;
    td.a1 = -1.0 / dt;
    td.a2 = 0.0;
    td.q2 = hist_.q1;
  }
  return td;
}

LineContactSolver::Summary LineContactSolver::Impl::OneStep(const ContactConditions& c,
                                                            double dt,
                                                            FilmState* s,
                                                            TimeError* time_error) {
  *time_error = TimeError{};
  FilmState next = *s;
  next.time_s = s->time_s + dt;
  next.travel1_m = s->travel1_m + 0.5 * dt * (hist_.c_prev.u1_m_s + c.u1_m_s);
  next.travel2_m = s->travel2_m + 0.5 * dt * (hist_.c_prev.u2_m_s + c.u2_m_s);
  const TimeDerivative td = Derivative(dt);
  PredictHertzSimilar(hist_.c_prev, c, &next);
  ExtrapolateTemperature(dt, *s, &next);
  Summary sum = SolveCoupled(c, td, s, eff_.transient ? dt : 0.0, &next);
  if (sum.usable()) {
    Eigen::VectorXd q = RhoH(c, next);
    time_error->value = LocalTimeError(dt, q, next.p_pa);
    time_error->order = opt_.time_scheme == TimeScheme::kBdf2 ? 3.0 : 2.0;
    if (eff_.thermal) {
      const double e = TemperatureTimeError(dt, s->temperature.t_k, c, next);
      if (e > time_error->value) *time_error = TimeError{e, 2.0};
      hist_.t_prev = s->temperature.t_k;
    }
    *s = next;
    hist_.q3 = std::move(hist_.q2);
    hist_.q2 = std::move(hist_.q1);
    hist_.q1 = std::move(q);
    hist_.levels = std::min(hist_.levels + 1, 3);
    hist_.dt_prev2 = hist_.dt_prev;
    hist_.dt_prev = dt;
    hist_.c_prev = c;
  }
  return sum;
}

double LineContactSolver::Impl::TemperatureTimeError(double dt,
                                                     const Eigen::MatrixXd& t_n,
                                                     const ContactConditions& c,
                                                     const FilmState& next) const {
  const Eigen::MatrixXd& t = next.temperature.t_k;
  const Eigen::MatrixXd& t_prev = hist_.t_prev;
  const double h1 = hist_.dt_prev;
  if (!eff_.transient || hist_.levels < 2 || !(h1 > 0) || t_prev.size() == 0 ||
      t_prev.rows() != t.rows() || t_prev.cols() != t.cols() || t_n.rows() != t.rows() ||
      t_n.cols() != t.cols())
    return -1;
  // The energy equation's transient term is BDF1: 1/3 of T - (linear extrapolation) for
  // equal steps, as for rho h with BDF1 (LocalTimeError).
  const double scale = dt / (2 * dt + h1);
  const double rise = std::max(t.maxCoeff() - c.temperature_k, 1.0);
  double sum = 0;
  int count = 0;
  for (int i = 1; i + 1 < t.rows(); ++i) {
    if (!(next.p_pa[i] > 0)) continue;
    for (int j = 0; j < t.cols(); ++j) {
      const double predicted = t_n(i, j) + (dt / h1) * (t_n(i, j) - t_prev(i, j));
      sum += std::pow(t(i, j) - predicted, 2);
      ++count;
    }
  }
  return count ? scale * std::sqrt(sum / count) / rise : -1;
}

double LineContactSolver::Impl::LocalTimeError(double dt,
                                               const Eigen::VectorXd& q,
                                               const Eigen::VectorXd& p) const {
  if (!eff_.transient) return -1;
  const bool bdf2 = opt_.time_scheme == TimeScheme::kBdf2;
  const double h1 = hist_.dt_prev, h2 = hist_.dt_prev2;
  Eigen::VectorXd predicted;
  double scale = 0;  // local error = -scale (q - predicted)
  if (bdf2 && hist_.levels >= 3 && h1 > 0 && h2 > 0) {
    // The quadratic through (t_n - h1 - h2, q3), (t_n - h1, q2), (t_n, q1) misses x(t_n + dt)
    // by x''' dt (dt + h1) (dt + h1 + h2) / 6, variable-step BDF2 (a0 = (1 + 2 w) / ((1 + w)
    // dt), w = dt / h1) by -x''' dt (dt + h1) / (6 a0): the local error is their ratio times
    // q - predicted, 2/11 of it for equal steps.
    const double l0 = (dt + h1) * (dt + h1 + h2) / (h1 * (h1 + h2));
    const double l1 = -dt * (dt + h1 + h2) / (h1 * h2);
    const double l2 = dt * (dt + h1) / ((h1 + h2) * h2);
    predicted = l0 * hist_.q1 + l1 * hist_.q2 + l2 * hist_.q3;
    const double w = dt / h1;
    const double inv_a0 = (1 + w) * dt / (1 + 2 * w);
    scale = inv_a0 / (dt + h1 + h2 + inv_a0);
  } else if (!bdf2 && hist_.levels >= 2 && h1 > 0) {
    // Linear extrapolation misses by x'' dt (dt + h1) / 2, BDF1 by -x'' dt^2 / 2: 1/3 of
    // q - predicted for equal steps.
    predicted = hist_.q1 + (dt / h1) * (hist_.q1 - hist_.q2);
    scale = dt / (2 * dt + h1);
  } else {
    return -1;
  }
  // Root mean square over the loaded nodes (p > 0) of the relative error: the largest one
  // sits where the outlet's cavitation boundary crosses a node, which is not smooth in time.
  double sum = 0;
  int count = 0;
  for (int i = 1; i + 1 < q.size(); ++i)
    if (p[i] > 0 && q[i] > 0) {
      sum += std::pow((q[i] - predicted[i]) / q[i], 2);
      ++count;
    }
  return count ? scale * std::sqrt(sum / count) : -1;
}

bool LineContactSolver::Impl::PredictHertzSimilar(const ContactConditions& c_old,
                                                   const ContactConditions& c,
                                                   FilmState* s) const {
  if (!opt_.predict_hertz_similar || !eff_.elastic || !s->valid() ||
      s->p_pa.size() != grid_.size())
    return false;
  if (!(c_old.load_n_per_m > 0) || !(c_old.reduced_radius_m > 0)) return false;
  const HertzScales h_old =
      LineContactHertz(c_old.load_n_per_m, c_old.reduced_radius_m, e_prime_);
  const HertzScales h_new = LineContactHertz(c.load_n_per_m, c.reduced_radius_m, e_prime_);
  const double sx = h_new.half_width_m / h_old.half_width_m;
  // The outlet sits near x = b: Newton moves a cavitation boundary by about one cell per
  // iteration, so a shift of more than a cell is worth predicting.
  if (std::abs(sx - 1.0) * h_old.half_width_m < grid_.dx_m()) return false;
  const double sp = (c.load_n_per_m / c_old.load_n_per_m) / sx;
  const int n = grid_.size();
  const double hc = s->CentralFilm(grid_) * EstimateCentralFilm(c) / EstimateCentralFilm(c_old);
  Eigen::VectorXd p = Eigen::VectorXd::Zero(n);
  for (int i = 1; i < n - 1; ++i) {
    const double t = (grid_.x(i) / sx - grid_.x_start_m()) / grid_.dx_m();
    if (t < 0 || t > n - 1) continue;
    const int k = std::min(static_cast<int>(t), n - 2);
    const double f = t - k;
    p[i] = sp * ((1 - f) * s->p_pa[k] + f * s->p_pa[k + 1]);
  }
  s->p_pa = p;
  s->h0_m = 0.0;
  Film(c, s);
  s->h0_m = hc - s->CentralFilm(grid_);
  Film(c, s);
  return true;
}

void LineContactSolver::Impl::ExtrapolateTemperature(double dt,
                                                     const FilmState& s,
                                                     FilmState* next) const {
  const Eigen::MatrixXd& t_n = s.temperature.t_k;
  if (!eff_.thermal || hist_.dt_prev <= 0 || hist_.t_prev.size() == 0 ||
      hist_.t_prev.rows() != t_n.rows() || hist_.t_prev.cols() != t_n.cols())
    return;
  const double t0 = hist_.c_prev.temperature_k;
  FilmTemperature& t = next->temperature;
  t.t_k = (t_n + (dt / hist_.dt_prev) * (t_n - hist_.t_prev)).cwiseMax(0.8 * t0);
  t.t1_k = t.t_k.col(0);
  t.t2_k = t.t_k.col(t.t_k.cols() - 1);
}

LineContactSolver::Summary LineContactSolver::Impl::Step(const ContactConditions& c_new,
                                                         double dt,
                                                         FilmState* s,
                                                         const ContactConditions* c_start) {
  const auto t0 = Clock::now();
  Summary sum;
  if (!(dt > 0) || !std::isfinite(dt)) {
    sum.message = "time step must be > 0";
    return sum;
  }
  if (hist_.levels == 0) BeginTransient(c_new, *s);
  if (eff_.transient && opt_.time_tolerance > 0) {
    sum = AdaptiveStep(c_new, dt, s, c_start);
  } else {
    sum = SubstepLadder(c_new, dt, s, c_start);
  }
  sum.wall_time_s = std::chrono::duration<double>(Clock::now() - t0).count();
  return sum;
}

ContactConditions LineContactSolver::Impl::Interpolate(const ContactConditions& a,
                                                       const ContactConditions& b,
                                                       double f) {
  ContactConditions c = b;
  c.reduced_radius_m = a.reduced_radius_m + f * (b.reduced_radius_m - a.reduced_radius_m);
  c.u1_m_s = a.u1_m_s + f * (b.u1_m_s - a.u1_m_s);
  c.u2_m_s = a.u2_m_s + f * (b.u2_m_s - a.u2_m_s);
  c.load_n_per_m = a.load_n_per_m + f * (b.load_n_per_m - a.load_n_per_m);
  c.temperature_k = a.temperature_k + f * (b.temperature_k - a.temperature_k);
  return c;
}

LineContactSolver::Summary LineContactSolver::Impl::SubstepLadder(
    const ContactConditions& c_new, double dt, FilmState* s, const ContactConditions* c_start) {
  Summary sum;
  const History saved_hist = hist_;
  const FilmState saved_state = *s;
  int total = 0, krylov = 0;
  for (int parts : {1, 2, 4}) {
    hist_ = saved_hist;
    *s = saved_state;
    const ContactConditions c_old = c_start ? *c_start : hist_.c_prev;
    bool ok = true;
    double error = -1;
    for (int k = 1; k <= parts && ok; ++k) {
      TimeError e;
      sum = OneStep(Interpolate(c_old, c_new, static_cast<double>(k) / parts), dt / parts, s, &e);
      error = std::max(error, e.value);
      total += sum.total_iterations;
      krylov += sum.krylov_iterations;
      ok = sum.usable();
    }
    sum.substeps = parts;
    sum.time_error = ok ? error : -1;
    if (!ok) continue;
    // The next step is dt long, while the history's last interval is a substep dt / parts.
    // Variable-step BDF2 is zero-stable only for step ratios below 1 + sqrt(2) (Grigorieff
    // 1983), and 4 substeps leave a ratio of 4 (a ladder up to 16 substeps, tried: after the
    // load jump at B of a 8193-node cycle h_min then swung 26 -> 24 -> 11 -> 23 nm over three
    // steps, against 20 -> 34 -> 37 -> 36 nm with this history). So the history keeps the
    // whole-step levels t_n - dt and t_n (and the one before): the next step is the uniform
    // BDF2 step, still second order.
    if (parts > 1 && saved_hist.levels >= 1) {
      hist_.q3 = saved_hist.q2;
      hist_.q2 = saved_hist.q1;
      hist_.dt_prev2 = saved_hist.dt_prev;
      hist_.dt_prev = dt;
      hist_.levels = std::min(saved_hist.levels + 1, 3);
      if (eff_.thermal) hist_.t_prev = saved_state.temperature.t_k;
    }
    break;
  }
  // On failure the state keeps the best iterate of the last attempt (finite by construction).
  if (!sum.usable()) hist_ = saved_hist;
  sum.total_iterations = total;
  sum.krylov_iterations = krylov;
  return sum;
}

LineContactSolver::TransientHistory LineContactSolver::Impl::SaveTransient() const {
  return TransientHistory{hist_.levels,   hist_.q1,     hist_.q2,     hist_.q3,    hist_.dt_prev,
                          hist_.dt_prev2, hist_.h_next, hist_.c_prev, hist_.t_prev};
}

void LineContactSolver::Impl::RestoreTransient(const TransientHistory& h) {
  hist_.levels = h.levels;
  hist_.q1 = h.q1;
  hist_.q2 = h.q2;
  hist_.q3 = h.q3;
  hist_.dt_prev = h.dt_prev_s;
  hist_.dt_prev2 = h.dt_prev2_s;
  hist_.h_next = h.next_substep_s;
  // A history without its third level (or one of another size) estimates no error.
  if (hist_.levels >= 3 && hist_.q3.size() != hist_.q1.size()) hist_.levels = 2;
  hist_.c_prev = h.c_prev;
  hist_.t_prev = h.t_prev_k;
}

}  // namespace tehl
