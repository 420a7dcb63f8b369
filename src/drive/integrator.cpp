#include "tehl/drive/integrator.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace tehl {
namespace {

// Dormand-Prince 5(4) tableau (Dormand & Prince 1980; Hairer et al. Table II.5.2).
constexpr double c2 = 1.0 / 5, c3 = 3.0 / 10, c4 = 4.0 / 5, c5 = 8.0 / 9;
constexpr double a21 = 1.0 / 5;
constexpr double a31 = 3.0 / 40, a32 = 9.0 / 40;
constexpr double a41 = 44.0 / 45, a42 = -56.0 / 15, a43 = 32.0 / 9;
constexpr double a51 = 19372.0 / 6561, a52 = -25360.0 / 2187, a53 = 64448.0 / 6561,
                 a54 = -212.0 / 729;
constexpr double a61 = 9017.0 / 3168, a62 = -355.0 / 33, a63 = 46732.0 / 5247, a64 = 49.0 / 176,
                 a65 = -5103.0 / 18656;
constexpr double a71 = 35.0 / 384, a73 = 500.0 / 1113, a74 = 125.0 / 192, a75 = -2187.0 / 6784,
                 a76 = 11.0 / 84;
// Error coefficients: 5th-order minus embedded 4th-order weights.
constexpr double e1 = 71.0 / 57600, e3 = -71.0 / 16695, e4 = 71.0 / 1920, e5 = -17253.0 / 339200,
                 e6 = 22.0 / 525, e7 = -1.0 / 40;
// Dense output (Hairer et al., DOPRI5 continuous extension).
constexpr double d1 = -12715105075.0 / 11282082432.0, d3 = 87487479700.0 / 32700410799.0,
                 d4 = -10690763975.0 / 1880347072.0, d5 = 701980252875.0 / 199316789632.0,
                 d6 = -1453857185.0 / 822651844.0, d7 = 69997945.0 / 29380423.0;

bool AllFinite(const std::vector<double>& v) {
  return std::all_of(v.begin(), v.end(), [](double x) { return std::isfinite(x); });
}

}  // namespace

void DenseStep::Evaluate(double t, double* y) const {
  const int n = dimension();
  const double s = (t - t0_s) / h_s, s1 = 1.0 - s;
  const double* r = coefficients.data();
  for (int i = 0; i < n; ++i)
    y[i] = r[i] + s * (r[n + i] + s1 * (r[2 * n + i] + s * (r[3 * n + i] + s1 * r[4 * n + i])));
}

double DenseStep::Component(double t, int i) const {
  const int n = dimension();
  const double s = (t - t0_s) / h_s, s1 = 1.0 - s;
  const double* r = coefficients.data();
  return r[i] + s * (r[n + i] + s1 * (r[2 * n + i] + s * (r[3 * n + i] + s1 * r[4 * n + i])));
}

std::vector<std::string> IntegratorOptions::Validate() const {
  std::vector<std::string> bad;
  auto rule = [&](bool ok, const char* field, double value, const char* constraint) {
    if (ok) return;
    std::ostringstream m;
    m << "IntegratorOptions::" << field << " = " << value << " violates " << constraint;
    bad.push_back(m.str());
  };
  rule(relative_tolerance > 0 && relative_tolerance < 1, "relative_tolerance", relative_tolerance,
       "in (0, 1)");
  for (double a : absolute_tolerance) rule(a > 0, "absolute_tolerance", a, "> 0");
  rule(initial_step_s >= 0, "initial_step_s", initial_step_s, ">= 0");
  rule(max_step_s > 0, "max_step_s", max_step_s, "> 0");
  rule(max_steps >= 1, "max_steps", static_cast<double>(max_steps), ">= 1");
  rule(safety > 0 && safety < 1, "safety", safety, "in (0, 1)");
  rule(min_factor > 0 && min_factor < 1, "min_factor", min_factor, "in (0, 1)");
  rule(max_factor > 1, "max_factor", max_factor, "> 1");
  rule(pi_beta >= 0 && pi_beta < 0.2, "pi_beta", pi_beta, "in [0, 0.2)");
  rule(event_time_tolerance > 0 && event_time_tolerance < 1e-2, "event_time_tolerance",
       event_time_tolerance, "in (0, 0.01)");
  rule(guard_samples >= 0, "guard_samples", guard_samples, ">= 0");
  return bad;
}

std::string ToString(IntegratorTermination t) {
  switch (t) {
    case IntegratorTermination::kReachedEnd:
      return "reached_end";
    case IntegratorTermination::kInvalidOptions:
      return "invalid_options";
    case IntegratorTermination::kMaxSteps:
      return "max_steps";
    case IntegratorTermination::kStepTooSmall:
      return "step_too_small";
    case IntegratorTermination::kNonFinite:
      return "non_finite";
    case IntegratorTermination::kEventChattering:
      return "event_chattering";
    case IntegratorTermination::kStoppedByObserver:
      return "stopped_by_observer";
  }
  return "unknown";
}

void IntegratorSummary::Add(const IntegratorSummary& o) {
  accepted_steps += o.accepted_steps;
  rejected_steps += o.rejected_steps;
  evaluations += o.evaluations;
  state_events += o.state_events;
  scheduled_switches += o.scheduled_switches;
}

IntegratorSummary DormandPrince54::Integrate(HybridOdeSystem& sys,
                                             double t0,
                                             double t1,
                                             std::vector<double>* y_io,
                                             const StepObserver& observer) {
  IntegratorSummary sum;
  const IntegratorOptions& o = options_;
  const int n = sys.Dimension();
  std::vector<double>& y = *y_io;
  if (const auto bad = o.Validate();
      !bad.empty() || static_cast<int>(y.size()) != n || !(t1 > t0) ||
      (!o.absolute_tolerance.empty() && static_cast<int>(o.absolute_tolerance.size()) != n)) {
    sum.termination = IntegratorTermination::kInvalidOptions;
    sum.message = bad.empty() ? "state size, tolerance size or interval is inconsistent" : bad[0];
    return sum;
  }
  auto atol = [&](int i) {
    return o.absolute_tolerance.empty() ? o.relative_tolerance : o.absolute_tolerance[i];
  };
  std::vector<double> k1(n), k2(n), k3(n), k4(n), k5(n), k6(n), k7(n), yt(n), yn(n), err(n);
  auto eval = [&](double t, const std::vector<double>& state, std::vector<double>& f) {
    sys.Derivative(t, state.data(), f.data());
    ++sum.evaluations;
  };
  auto norm = [&](const std::vector<double>& v, const std::vector<double>& ref) {
    double s = 0;
    for (int i = 0; i < n; ++i) {
      const double sc = atol(i) + o.relative_tolerance * std::abs(ref[i]);
      s += (v[i] / sc) * (v[i] / sc);
    }
    return std::sqrt(s / n);
  };

  double t = t0;
  bool fsal = false;  // k1 holds f(t, y) in the current mode
  double h = step_s_;
  const double span = t1 - t0;
  int zero_length_events = 0;
  DenseStep dense;
  dense.coefficients.assign(5 * n, 0.0);
  std::vector<double> yg(n);

  while (t < t1) {
    if (sum.accepted_steps + sum.rejected_steps >= o.max_steps) {
      sum.termination = IntegratorTermination::kMaxSteps;
      sum.message = "more than max_steps steps";
      return sum;
    }
    if (!fsal) {
      eval(t, y, k1);
      fsal = true;
    }
    if (h <= 0) {  // Hairer's starting step (hinit), or the user's
      if (o.initial_step_s > 0) {
        h = o.initial_step_s;
      } else {
        const double dn0 = norm(y, y), dn1 = norm(k1, y);
        double h0 = (dn0 < 1e-5 || dn1 < 1e-5) ? 1e-6 * span : 0.01 * dn0 / dn1;
        h0 = std::min(h0, span);
        for (int i = 0; i < n; ++i) yt[i] = y[i] + h0 * k1[i];
        eval(t + h0, yt, k2);
        for (int i = 0; i < n; ++i) err[i] = (k2[i] - k1[i]) / h0;
        const double dn2 = norm(err, y);
        const double dm = std::max(dn1, dn2);
        const double h1 = dm <= 1e-15 ? std::max(1e-6 * span, h0 * 1e-3) : std::pow(0.01 / dm, 0.2);
        h = std::min(100 * h0, h1);
      }
    }
    h = std::min(h, o.max_step_s);
    // End the step exactly at the next scheduled switch or at t1.
    double t_sched = sys.NextScheduledTime(t);
    if (std::abs(t_sched - t1) <= 1e-12 * span) t_sched = t1;  // the same instant, rounded
    double t_stop = std::min(t_sched, t1);
    bool hits_stop = false;
    if (t + h * (1.0 + 1e-6) >= t_stop) {  // no sliver of a step left before the stop
      h = t_stop - t;
      hits_stop = true;
    }
    if (h <= std::abs(t) * 1e-15 || h <= 0) {
      if (hits_stop) {  // already there (rounding): switch without a step
        t = t_stop;
        if (t_sched <= t1 && t_stop == t_sched) {
          sys.Switch(-1, t, y.data());
          ++sum.scheduled_switches;
          fsal = false;
          h = step_s_ > 0 ? step_s_ : 0;
          continue;
        }
        break;
      }
      sum.termination = IntegratorTermination::kStepTooSmall;
      sum.message = "step size underflow at t = " + std::to_string(t);
      return sum;
    }

    for (int i = 0; i < n; ++i) yt[i] = y[i] + h * a21 * k1[i];
    eval(t + c2 * h, yt, k2);
    for (int i = 0; i < n; ++i) yt[i] = y[i] + h * (a31 * k1[i] + a32 * k2[i]);
    eval(t + c3 * h, yt, k3);
    for (int i = 0; i < n; ++i) yt[i] = y[i] + h * (a41 * k1[i] + a42 * k2[i] + a43 * k3[i]);
    eval(t + c4 * h, yt, k4);
    for (int i = 0; i < n; ++i)
      yt[i] = y[i] + h * (a51 * k1[i] + a52 * k2[i] + a53 * k3[i] + a54 * k4[i]);
    eval(t + c5 * h, yt, k5);
    for (int i = 0; i < n; ++i)
      yt[i] = y[i] + h * (a61 * k1[i] + a62 * k2[i] + a63 * k3[i] + a64 * k4[i] + a65 * k5[i]);
    eval(t + h, yt, k6);
    for (int i = 0; i < n; ++i)
      yn[i] = y[i] + h * (a71 * k1[i] + a73 * k3[i] + a74 * k4[i] + a75 * k5[i] + a76 * k6[i]);
    eval(t + h, yn, k7);
    for (int i = 0; i < n; ++i)
      err[i] = h * (e1 * k1[i] + e3 * k3[i] + e4 * k4[i] + e5 * k5[i] + e6 * k6[i] + e7 * k7[i]);
    double e = 0;
    for (int i = 0; i < n; ++i) {
      const double sc = atol(i) + o.relative_tolerance * std::max(std::abs(y[i]), std::abs(yn[i]));
      e += (err[i] / sc) * (err[i] / sc);
    }
    e = std::sqrt(e / n);
    if (!std::isfinite(e) || !AllFinite(yn)) {
      if (h < 1e-14 * span) {
        sum.termination = IntegratorTermination::kNonFinite;
        sum.message = "non-finite state at t = " + std::to_string(t);
        return sum;
      }
      h *= 0.1;
      ++sum.rejected_steps;
      continue;
    }
    const double expo = 0.2 - 0.75 * o.pi_beta;
    if (e > 1.0) {  // reject: shrink, never grow
      ++sum.rejected_steps;
      h *= std::max(o.min_factor, o.safety * std::pow(e, -expo));
      continue;
    }
    // Accepted. Step-size proposal (PI controller).
    const double e_safe = std::max(e, 1e-10);
    double fac = o.safety * std::pow(e_safe, -expo) * std::pow(error_prev_, o.pi_beta);
    fac = std::clamp(fac, o.min_factor, o.max_factor);
    error_prev_ = std::max(e, 1e-4);
    const double h_next = h * fac;
    ++sum.accepted_steps;

    // Dense output of this step.
    double* r = dense.coefficients.data();
    for (int i = 0; i < n; ++i) {
      const double dy = yn[i] - y[i];
      const double bspl = h * k1[i] - dy;
      r[i] = y[i];
      r[n + i] = dy;
      r[2 * n + i] = bspl;
      r[3 * n + i] = dy - h * k7[i] - bspl;
      r[4 * n + i] =
          h * (d1 * k1[i] + d3 * k3[i] + d4 * k4[i] + d5 * k5[i] + d6 * k6[i] + d7 * k7[i]);
    }
    dense.t0_s = t;
    dense.h_s = h;
    dense.t_end_s = t + h;

    // State events: the first guard that goes from >= 0 to < 0 in this step.
    const int ng = sys.GuardCount();
    int hit = -1;
    double t_event = 0;
    if (ng > 0) {
      const int m = o.guard_samples + 1;  // sample intervals
      double prev_theta = 0;
      std::vector<double> g_prev(ng);
      for (int i = 0; i < ng; ++i) g_prev[i] = std::max(0.0, sys.Guard(i, t, y.data()));
      for (int j = 1; j <= m && hit < 0; ++j) {
        const double theta = static_cast<double>(j) / m;
        const double tj = t + theta * h;
        if (j == m)
          yg = yn;
        else
          dense.Evaluate(tj, yg.data());
        double best = 2.0;
        for (int i = 0; i < ng; ++i) {
          const double gj = sys.Guard(i, tj, yg.data());
          if (gj < 0 && g_prev[i] >= 0) {
            // Illinois regula falsi on [prev_theta, theta] for guard i.
            double ta = prev_theta, tb = theta, ga = g_prev[i], gb = gj;
            int side = 0;
            for (int it = 0; it < 200 && (tb - ta) > o.event_time_tolerance; ++it) {
              double tc = (ga - gb) != 0 ? tb - gb * (tb - ta) / (gb - ga) : 0.5 * (ta + tb);
              if (!(tc > ta && tc < tb)) tc = 0.5 * (ta + tb);
              dense.Evaluate(t + tc * h, yg.data());
              const double gc = sys.Guard(i, t + tc * h, yg.data());
              if (gc >= 0) {
                ta = tc;
                ga = gc;
                if (side == +1) gb *= 0.5;
                side = +1;
              } else {
                tb = tc;
                gb = gc;
                if (side == -1) ga *= 0.5;
                side = -1;
              }
            }
            const double root = tb;  // first point where the guard is negative (to tolerance)
            if (root < best) {
              best = root;
              hit = i;
            }
          }
          g_prev[i] = gj;
        }
        if (hit >= 0) t_event = t + best * h;
        prev_theta = theta;
      }
    }
    if (hit >= 0) {
      dense.t_end_s = t_event;
      dense.Evaluate(t_event, y.data());
      const bool progress = t_event - t > 10.0 * o.event_time_tolerance * h;
      zero_length_events = progress ? 0 : zero_length_events + 1;
      if (zero_length_events > 8) {
        sum.termination = IntegratorTermination::kEventChattering;
        sum.message = "state events without progress at t = " + std::to_string(t);
        return sum;
      }
      t = t_event;
      if (observer && !observer(dense)) {
        sum.termination = IntegratorTermination::kStoppedByObserver;
        sum.message = "stopped by the observer";
        return sum;
      }
      sys.Switch(hit, t, y.data());
      ++sum.state_events;
      fsal = false;
      h = std::max(h_next, 1e-3 * h);
      step_s_ = h;
      continue;
    }

    zero_length_events = 0;
    t = hits_stop ? t_stop : t + h;
    dense.t_end_s = t;
    y = yn;
    k1 = k7;  // FSAL
    if (observer && !observer(dense)) {
      sum.termination = IntegratorTermination::kStoppedByObserver;
      sum.message = "stopped by the observer";
      return sum;
    }
    // A step cut short to land on a stop should not shrink the next one.
    h = hits_stop ? std::max(h_next, step_s_) : h_next;
    step_s_ = h;
    if (hits_stop && t_stop == t_sched) {
      sys.Switch(-1, t, y.data());
      ++sum.scheduled_switches;
      fsal = false;
    }
    if (hits_stop && t_stop == t1) break;
  }
  sum.termination = IntegratorTermination::kReachedEnd;
  sum.message = "reached the end time";
  return sum;
}

}  // namespace tehl
