// Adaptive explicit Runge-Kutta integration of piecewise-smooth (hybrid) ODE systems, with
// error control, dense output and event location (docs/dynamics.md "Integrator").
//
// Method: Dormand & Prince (1980) 5(4) pair, "A family of embedded Runge-Kutta formulae",
// J. Comput. Appl. Math. 6:19-26, with its FSAL property, the 4th-order continuous extension
// of Hairer, Norsett & Wanner, "Solving Ordinary Differential Equations I", 2nd ed.,
// section II.6 (dense output of DOPRI5), and the PI step-size controller of section IV.2
// (Gustafsson), h_new = h fac, fac = safety err^-(1/5 - 0.75 beta) err_prev^beta, clamped to
// [min_factor, max_factor].
//
// Hybrid systems: the right-hand side is smooth within a "mode" and may jump when the mode
// changes. Modes change
//  - at scheduled times the system knows in advance (for the gear mesh: the single/double
//    contact switches and the pitch point); a step never crosses one: it ends exactly there
//    and the system switches before the next step;
//  - when a guard g_i(t, y) of the current mode crosses zero from >= 0 to < 0 (state events,
//    for the mesh: loss and regain of contact). Guards are checked at the step end and at
//    `guard_samples` interior points of the dense output; a crossing is located on the
//    dense output by the Illinois variant of regula falsi to `event_time_tolerance` of the
//    step, the step is cut there, the system switches, and integration restarts.
// Thread-safety: an integrator object holds the step-size memory of one run; use one per
// thread.
#pragma once

#include <functional>
#include <limits>
#include <string>
#include <vector>

namespace tehl {

// y' = f(t, y) with modes. Contract for implementers: Derivative and Guard are evaluated in
// the current mode (for t anywhere in the closed interval of the current step); only
// Switch changes the mode.
class HybridOdeSystem {
 public:
  virtual ~HybridOdeSystem() = default;
  virtual int Dimension() const = 0;
  virtual void Derivative(double t, const double* y, double* dydt) const = 0;
  // Guards of the current mode: the mode is valid while every guard is >= 0.
  virtual int GuardCount() const { return 0; }
  virtual double Guard(int /*i*/, double /*t*/, const double* /*y*/) const { return 1.0; }
  // First scheduled switch strictly after t [s]; +infinity when none.
  virtual double NextScheduledTime(double /*t*/) const {
    return std::numeric_limits<double>::infinity();
  }
  // Applies a mode change at t: guard `guard` crossed zero (guard >= 0), or the scheduled
  // time t was reached (guard = -1). May adjust y (e.g. put it exactly on the guard surface).
  virtual void Switch(int /*guard*/, double /*t*/, double* /*y*/) {}
};

// One accepted step and its continuous extension, valid on [t0_s, t_end_s]; t_end_s is
// t0_s + h_s, or earlier when the step was cut at a state event.
struct DenseStep {
  double t0_s = 0;                   // step start [s]
  double h_s = 0;                    // full step the coefficients were built for [s]
  double t_end_s = 0;                // end of validity [s]
  std::vector<double> coefficients;  // 5 blocks of Dimension() values (Hairer's rcont1..5)
  int dimension() const { return static_cast<int>(coefficients.size() / 5); }
  // y(t) for t in [t0_s, t_end_s] (4th-order accurate) into y[0..dimension).
  void Evaluate(double t, double* y) const;
  double Component(double t, int i) const;
};

struct IntegratorOptions {
  double relative_tolerance = 1e-8;        // rtol [-], > 0
  std::vector<double> absolute_tolerance;  // atol per component [units of y]; empty = rtol
  double initial_step_s = 0;               // first step [s]; 0 = automatic (Hairer's hinit)
  double max_step_s = std::numeric_limits<double>::infinity();  // [s], > 0
  long max_steps = 50'000'000;                // accepted + rejected steps per call [-]
  double safety = 0.9;                        // step-size safety factor, in (0, 1) [-]
  double min_factor = 0.2;                    // smallest step-size ratio, in (0, 1) [-]
  double max_factor = 10.0;                   // largest step-size ratio, > 1 [-]
  double pi_beta = 0.04;                      // beta of the PI controller, in [0, 0.2) [-]
  double event_time_tolerance = 1e-12;        // event location, relative to the step [-]
  int guard_samples = 3;                      // interior dense-output points checked [-], >= 0
  std::vector<std::string> Validate() const;  // every violated rule; empty = valid
};

enum class IntegratorTermination {
  kReachedEnd,
  kInvalidOptions,
  kMaxSteps,
  kStepTooSmall,
  kNonFinite,
  kEventChattering,  // repeated state events without progress in time
  kStoppedByObserver,
};
std::string ToString(IntegratorTermination t);

struct IntegratorSummary {
  IntegratorTermination termination = IntegratorTermination::kInvalidOptions;
  std::string message = "Integrate() was not called.";
  long accepted_steps = 0;      // [-]
  long rejected_steps = 0;      // [-]
  long evaluations = 0;         // right-hand side evaluations [-]
  long state_events = 0;        // located guard crossings [-]
  long scheduled_switches = 0;  // [-]
  bool usable() const { return termination == IntegratorTermination::kReachedEnd; }
  void Add(const IntegratorSummary& other);  // sums the counters, keeps this termination
};

// Called after every accepted (possibly cut) step, in the mode that held during it, before
// the switch that ends it. Return false to stop the integration.
using StepObserver = std::function<bool(const DenseStep&)>;

class DormandPrince54 {
 public:
  explicit DormandPrince54(IntegratorOptions options) : options_(std::move(options)) {}
  const IntegratorOptions& options() const { return options_; }

  // Integrates from t0 to t1 > t0; y holds y(t0) on entry and y(t1) on return. The step size
  // is remembered between calls (continue a run with another call).
  IntegratorSummary Integrate(HybridOdeSystem& system,
                              double t0_s,
                              double t1_s,
                              std::vector<double>* y,
                              const StepObserver& observer = {});

 private:
  IntegratorOptions options_;
  double step_s_ = 0;         // proposal for the next step [s]; 0 = not yet known
  double error_prev_ = 1e-4;  // PI memory
};

}  // namespace tehl
