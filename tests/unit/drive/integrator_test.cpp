// DormandPrince54: accuracy against analytic solutions, the order of its dense output, exact
// landing on scheduled switches, event location against closed-form event times, and the
// rejection of invalid options.
#include "tehl/drive/integrator.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace tehl {
namespace {

// y'' = -w^2 y: y = cos(w t), y' = -w sin(w t).
class Oscillator : public HybridOdeSystem {
 public:
  explicit Oscillator(double w) : w_(w) {}
  int Dimension() const override { return 2; }
  void Derivative(double, const double* y, double* f) const override {
    f[0] = y[1];
    f[1] = -w_ * w_ * y[0];
  }

 private:
  double w_;
};

TEST(DormandPrince54, HarmonicOscillatorErrorFollowsTheTolerance) {
  // Exact solution cos(w t); the global error must shrink with the tolerance.
  double previous = 1;
  for (double tol : {1e-6, 1e-8, 1e-10}) {
    Oscillator osc(2.0 * M_PI);
    IntegratorOptions o;
    o.relative_tolerance = tol;
    o.absolute_tolerance = {tol, tol};
    DormandPrince54 dp(o);
    std::vector<double> y = {1.0, 0.0};
    const IntegratorSummary s = dp.Integrate(osc, 0.0, 10.0, &y);
    ASSERT_TRUE(s.usable()) << s.message;
    const double err = std::abs(y[0] - 1.0);
    EXPECT_LT(err, 2000 * tol) << "tol " << tol;
    EXPECT_LT(err, previous) << "tol " << tol;
    previous = err;
  }
}

// y' = y, one step of size h from y = 1: the dense output at the midpoint is a 4th-order
// interpolant, so its local error is O(h^5): halving h divides it by about 32.
double MidpointDenseError(double h) {
  class Growth : public HybridOdeSystem {
   public:
    int Dimension() const override { return 1; }
    void Derivative(double, const double* y, double* f) const override { f[0] = y[0]; }
  } sys;
  IntegratorOptions o;
  o.relative_tolerance = 1e-2;  // accept the step as given
  o.initial_step_s = h;
  DormandPrince54 dp(o);
  std::vector<double> y = {1.0};
  double mid = 0;
  dp.Integrate(sys, 0.0, h, &y, [&](const DenseStep& d) {
    mid = d.Component(0.5 * h, 0);
    return true;
  });
  return std::abs(mid - std::exp(0.5 * h));
}

TEST(DormandPrince54, DenseOutputIsFourthOrder) {
  const double e1 = MidpointDenseError(0.2), e2 = MidpointDenseError(0.1);
  EXPECT_NEAR(std::log2(e1 / e2), 5.0, 0.5) << e1 << " " << e2;
}

// y' = 1 before t = 0.3 and y' = -2 after (a scheduled switch): y(1) = 0.3 - 1.4 = -1.1.
class Kink : public HybridOdeSystem {
 public:
  int Dimension() const override { return 1; }
  void Derivative(double, const double*, double* f) const override { f[0] = after_ ? -2.0 : 1.0; }
  double NextScheduledTime(double) const override {
    return after_ ? std::numeric_limits<double>::infinity() : 0.3;
  }
  void Switch(int guard, double t, double*) override {
    EXPECT_EQ(guard, -1);
    EXPECT_EQ(t, 0.3);
    after_ = true;
  }

 private:
  bool after_ = false;
};

TEST(DormandPrince54, LandsExactlyOnScheduledSwitches) {
  Kink k;
  DormandPrince54 dp(IntegratorOptions{});
  std::vector<double> y = {0.0};
  bool seen = false;
  const IntegratorSummary s = dp.Integrate(k, 0.0, 1.0, &y, [&](const DenseStep& d) {
    seen = seen || d.t_end_s == 0.3;
    return true;
  });
  ASSERT_TRUE(s.usable()) << s.message;
  EXPECT_TRUE(seen);
  EXPECT_EQ(s.scheduled_switches, 1);
  EXPECT_NEAR(y[0], -1.1, 1e-13);
}

// A ball dropped from height 1 under g = 9.81 bounces with restitution e = 0.8. Closed form:
// first impact at t1 = sqrt(2/g), impact speed v0 = g t1; each flight then lasts
// 2 e^k v0 / g, so impact n is at t1 + sum_{k=1}^{n-1} 2 e^k v0 / g.
class Ball : public HybridOdeSystem {
 public:
  int Dimension() const override { return 2; }
  void Derivative(double, const double* y, double* f) const override {
    f[0] = y[1];
    f[1] = -9.81;
  }
  int GuardCount() const override { return 1; }
  double Guard(int, double, const double* y) const override { return y[0]; }
  void Switch(int guard, double t, double* y) override {
    EXPECT_EQ(guard, 0);
    impacts.push_back(t);
    y[0] = 0.0;
    y[1] = -0.8 * y[1];
  }
  std::vector<double> impacts;
};

TEST(DormandPrince54, LocatesStateEventsAtTheClosedFormTimes) {
  Ball ball;
  IntegratorOptions o;
  o.relative_tolerance = 1e-10;
  o.absolute_tolerance = {1e-12, 1e-12};
  DormandPrince54 dp(o);
  std::vector<double> y = {1.0, 0.0};
  const IntegratorSummary s = dp.Integrate(ball, 0.0, 3.0, &y);
  ASSERT_TRUE(s.usable()) << s.message;
  ASSERT_GE(ball.impacts.size(), 4u);
  const double g = 9.81, t1 = std::sqrt(2.0 / g), v0 = g * t1;
  double expected = t1;
  for (size_t n = 0; n < 4; ++n) {
    EXPECT_NEAR(ball.impacts[n], expected, 1e-9) << "impact " << n;
    expected += 2.0 * std::pow(0.8, n + 1) * v0 / g;
  }
  EXPECT_EQ(s.state_events, static_cast<long>(ball.impacts.size()));
}

TEST(IntegratorOptions, RejectsEachInvalidSetting) {
  auto rejected = [](IntegratorOptions o) { return !o.Validate().empty(); };
  IntegratorOptions o;
  EXPECT_TRUE(o.Validate().empty());
  o = {};
  o.relative_tolerance = 0;
  EXPECT_TRUE(rejected(o));
  o = {};
  o.absolute_tolerance = {-1.0};
  EXPECT_TRUE(rejected(o));
  o = {};
  o.safety = 1.5;
  EXPECT_TRUE(rejected(o));
  o = {};
  o.max_factor = 0.5;
  EXPECT_TRUE(rejected(o));
  o = {};
  o.pi_beta = 0.3;
  EXPECT_TRUE(rejected(o));
  o = {};
  o.guard_samples = -1;
  EXPECT_TRUE(rejected(o));
  // Integrate reports invalid options in its summary instead of throwing.
  o = {};
  o.relative_tolerance = -1;
  Oscillator osc(1.0);
  DormandPrince54 dp(o);
  std::vector<double> y = {1.0, 0.0};
  const IntegratorSummary s = dp.Integrate(osc, 0.0, 1.0, &y);
  EXPECT_EQ(s.termination, IntegratorTermination::kInvalidOptions);
  EXPECT_NE(s.message.find("relative_tolerance"), std::string::npos);
}

}  // namespace
}  // namespace tehl
