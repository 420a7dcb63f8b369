// The solids' heat history of transient steps (include/tehl/ehl/surface_temperature.hpp:
// MovingHeatSource::Recent and History; src/ehl/solid_heat_history.hpp).
//
// References (Carslaw & Jaeger 1959, section 2.9; Duhamel's superposition): a surface point of
// a half-space moving at u (high Peclet number) sees 1-D conduction; a flux q acting on it from
// time 0 to t_h and then switched off leaves at t_h + t the rise
//   theta = 2 q [sqrt(t_h + t) - sqrt(t)] / sqrt(pi rho c k).
// Along the grid a point at x_i has been in the contact for (x_i - x_0)/u, so a steady flux q0
// stopped one step of travel r = u dt ago gives F H_i with H_i = 2 q0 [sqrt(x_i - x_0) -
// sqrt(r)], F = 1/sqrt(pi rho c k u) (for x_i - x_0 > r).
#include "ehl/solid_heat_history.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include "tehl/ehl/film_energy.hpp"
#include "tehl/ehl/surface_temperature.hpp"
#include "tehl/error.hpp"

namespace tehl {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

UniformGrid TestGrid(int n = 97) { return UniformGrid(-4.5e-4, 1.5e-4, n); }

Eigen::VectorXd RandomFlux(int n, unsigned seed) {
  std::mt19937 gen(seed);
  std::uniform_real_distribution<double> u(-1e7, 3e7);
  Eigen::VectorXd q(n);
  for (int k = 0; k < n; ++k) q[k] = u(gen);
  return q;
}

// sum_k G_ik q_k with the weights of `s` [W/m^2 m^(1/2)].
Eigen::VectorXd Apply(const MovingHeatSource& s, const Eigen::VectorXd& q) {
  Eigen::VectorXd y = Eigen::VectorXd::Zero(q.size());
  for (int i = 0; i < s.size(); ++i)
    for (int k = 0; k < s.size(); ++k) y[i] += s.Weight(i, k) * q[k];
  return y;
}

TEST(SolidHeatHistory, RecentWithInfiniteReachIsTheWholeKernel) {
  const UniformGrid g = TestGrid();
  const MovingHeatSource whole(g), recent = MovingHeatSource::Recent(g, kInf);
  for (int i = 0; i < g.size(); ++i)
    for (int k = 0; k < g.size(); ++k) EXPECT_EQ(recent.Weight(i, k), whole.Weight(i, k));
  EXPECT_THROW(MovingHeatSource::Recent(g, 0.0), InputError);
}

TEST(SolidHeatHistory, RecentPlusASteadyHistoryIsTheSteadyIntegral) {
  // A flux that has always acted: the step's lags and the history's together are the whole
  // integral, for reaches inside a cell, across cells and beyond the grid.
  const UniformGrid g = TestGrid();
  const Eigen::VectorXd q = RandomFlux(g.size(), 7);
  const Eigen::VectorXd whole = Apply(MovingHeatSource(g), q);
  for (double reach : {0.3 * g.dx_m(), 2.7 * g.dx_m(), 40.0 * g.dx_m(), 1.0}) {
    const Eigen::VectorXd split = Apply(MovingHeatSource::Recent(g, reach), q) +
                                  MovingHeatSource(g).History(reach, 1.0, {FluxSpan{&q, kInf}});
    EXPECT_LT((split - whole).cwiseAbs().maxCoeff(), 1e-12 * whole.cwiseAbs().maxCoeff()) << reach;
  }
}

TEST(SolidHeatHistory, FluxStoppedOneStepAgoDecaysAsOneDimensionalConduction) {
  // Reference in the file comment: H_i = 2 q0 [sqrt(x_i - x_0) - sqrt(r)].
  const UniformGrid g = TestGrid(193);
  const double q0 = 2.5e7;
  const Eigen::VectorXd q = Eigen::VectorXd::Constant(g.size(), q0);
  for (double r : {0.2 * g.dx_m(), 5.5 * g.dx_m()}) {
    const Eigen::VectorXd h = MovingHeatSource(g).History(r, 1.0, {FluxSpan{&q, kInf}});
    for (int i = 0; i < g.size(); ++i) {
      const double d = g.x(i) - g.x(0);
      const double expected = d > r ? 2 * q0 * (std::sqrt(d) - std::sqrt(r)) : 0.0;
      EXPECT_NEAR(h[i], expected, 1e-12 * 2 * q0 * std::sqrt(d) + 1e-300) << i;
    }
  }
}

TEST(SolidHeatHistory, SpansMatchAQuadratureOfDuhamelsIntegral) {
  // Three earlier levels of different fluxes and travels (the last unbounded), against a
  // 16-point Gauss-Legendre rule on 8 pieces of every part of a cell between two span edges
  // (a smooth integrand there, lags >= the reach > 0): an independent evaluation.
  const UniformGrid g = TestGrid(49);
  const double dx = g.dx_m(), reach = 1.3 * dx;
  const std::vector<Eigen::VectorXd> q = {RandomFlux(g.size(), 1), RandomFlux(g.size(), 2),
                                          RandomFlux(g.size(), 3)};
  const std::vector<double> travel = {2.2 * dx, 0.4 * dx, kInf};
  std::vector<FluxSpan> spans;
  for (int j = 0; j < 3; ++j) spans.push_back(FluxSpan{&q[j], travel[j]});
  const Eigen::VectorXd h = MovingHeatSource(g).History(reach, 1.0, spans);
  // Gauss-Legendre, 16 points on [-1, 1] (weights from the recurrence of the Legendre
  // polynomials, Newton on their roots).
  std::vector<double> gx(16), gw(16);
  for (int m = 0; m < 16; ++m) {
    double z = std::cos(M_PI * (m + 0.75) / 16.5), dp = 0;
    for (int it = 0; it < 50; ++it) {
      double p0 = 1, p1 = z;
      for (int k = 2; k <= 16; ++k) {
        const double p2 = ((2 * k - 1) * z * p1 - (k - 1) * p0) / k;
        p0 = p1;
        p1 = p2;
      }
      dp = 16 * (z * p1 - p0) / (z * z - 1);
      z -= p1 / dp;
    }
    gx[m] = z;
    gw[m] = 2 / ((1 - z * z) * dp * dp);
  }
  // Lag edges: the reach, then the end of each bounded span.
  const std::vector<double> edges = {reach, reach + travel[0], reach + travel[0] + travel[1], kInf};
  for (int i = 1; i < g.size(); ++i) {
    double sum = 0;
    for (int k = 0; k <= i; ++k) {
      const double a = std::max(g.x(0), g.x(k) - 0.5 * dx), b = std::min(g.x(i), g.x(k) + 0.5 * dx);
      // The cell's lags [x_i - b, x_i - a], cut at the edges: a smooth integrand on each part.
      for (int j = 0; j < 3; ++j) {
        const double lo = std::max(g.x(i) - b, edges[j]), hi = std::min(g.x(i) - a, edges[j + 1]);
        for (int piece = 0; lo < hi && piece < 8; ++piece) {
          const double p0 = lo + (hi - lo) * piece / 8, p1 = lo + (hi - lo) * (piece + 1) / 8;
          for (int m = 0; m < 16; ++m) {
            const double lag = 0.5 * (p0 + p1) + 0.5 * (p1 - p0) * gx[m];
            sum += 0.5 * (p1 - p0) * gw[m] * q[j][k] / std::sqrt(lag);
          }
        }
      }
    }
    EXPECT_NEAR(h[i], sum, 1e-10 * 3e7 * 2 * std::sqrt(g.x(i) - g.x(0))) << i;
  }
}

TEST(SolidHeatHistory, SpeedsThatChangeAreIntegratedInTime) {
  // Duhamel's integral is one in time: theta = (1/sqrt(pi rho c k)) integral q(t') dt' /
  // sqrt(t - t'), the flux being that of the place the surface point passed at t'. A step at
  // u = 1 m/s after a level of 1.2 m/s (3.4 dx of travel) after a steady level at 0.8 m/s:
  // follow each node's point back in time, cutting its path where it crosses a cell face or
  // changes level; on each piece the flux is constant and integral dtau / sqrt(tau) =
  // 2 (sqrt(tau_b) - sqrt(tau_a)). H must equal sqrt(u) times that sum (T - T0 = F(u) H).
  const UniformGrid g = TestGrid(41);
  const double dx = g.dx_m(), u = 1.0, dt = 0.7 * dx / u;
  const Eigen::VectorXd qa = RandomFlux(g.size(), 11), qb = RandomFlux(g.size(), 12);
  const double ua = 1.2, la = 3.4 * dx, ub = 0.8;
  const Eigen::VectorXd h =
      MovingHeatSource(g).History(u * dt, u, {FluxSpan{&qa, la, ua}, FluxSpan{&qb, kInf, ub}});
  auto cell = [&](double x) {  // the node whose cell holds x
    return std::clamp(static_cast<int>(std::floor((x - g.x(0)) / dx + 0.5)), 0, g.size() - 1);
  };
  for (int i = 1; i < g.size(); ++i) {
    double sum = 0;
    // Levels in time: [dt, dt + la/ua] at ua, then [dt + la/ua, inf) at ub.
    struct Leg {
      double t0, t1, x0, speed;
      const Eigen::VectorXd* q;
    };
    const std::vector<Leg> legs = {{dt, dt + la / ua, g.x(i) - u * dt, ua, &qa},
                                   {dt + la / ua, kInf, g.x(i) - u * dt - la, ub, &qb}};
    for (const Leg& leg : legs) {
      double tau = leg.t0, x = leg.x0;
      while (tau < leg.t1 && x > g.x(0)) {
        // Back to the next cell face below x (faces at x_k - dx/2), or the inlet end.
        const int k = cell(x - 1e-12 * dx);
        const double face = std::max(g.x(0), g.x(k) - 0.5 * dx);
        const double t_next = std::min(leg.t1, tau + (x - face) / leg.speed);
        sum += (*leg.q)[k] * 2 * (std::sqrt(t_next) - std::sqrt(tau));
        x -= (t_next - tau) * leg.speed;
        tau = t_next;
      }
    }
    EXPECT_NEAR(h[i], std::sqrt(u) * sum, 1e-9 * 3e7 * std::sqrt(g.x(i) - g.x(0))) << i;
  }
  // The same spans at the step's speed are the lag integral of the first tests: with all
  // speeds equal H does not depend on them.
  const Eigen::VectorXd same =
      MovingHeatSource(g).History(u * dt, u, {FluxSpan{&qa, la, u}, FluxSpan{&qb, kInf, u}});
  const Eigen::VectorXd unknown =
      MovingHeatSource(g).History(u * dt, u, {FluxSpan{&qa, la}, FluxSpan{&qb, kInf}});
  EXPECT_EQ(same, unknown);
}

TEST(SolidHeatHistory, AChainOfStepsAfterAStoppedFluxMatchesTheClosedForm) {
  // A uniform flux q0 steady at u0 = 1.2 m/s, then steps without flux at changing speeds and
  // time steps, kept by RememberLevels. A point at d = x_i - x_0 was heated for t_h = (d -
  // travel since the stop)/u0 and has cooled for t (the steps' total time): reference in the
  // file comment, theta = 2 q0 [sqrt(t_h + t) - sqrt(t)] / sqrt(pi rho c k), i.e. H_i =
  // 2 q0 sqrt(u) [sqrt(t_h + t) - sqrt(t)] at the last step's speed u (T - T0 = F(u) H).
  const UniformGrid g = TestGrid(97);
  const double q0 = 1e7, u0 = 1.2;
  FilmTemperature t;
  t.q1_w_m2 = t.q2_w_m2 = Eigen::VectorXd::Constant(g.size(), q0);
  internal::ForgetLevels(u0, u0, &t);
  const Eigen::VectorXd zero = Eigen::VectorXd::Zero(g.size());
  double travel = 0, time = 0;
  for (auto [dt, u] : {std::pair{7e-6, 1.1}, std::pair{13e-6, 1.0}, std::pair{20e-6, 0.9}}) {
    FilmTemperature next;
    next.q1_w_m2 = next.q2_w_m2 = zero;
    internal::RememberLevels(g, t, dt, u, u, &next);
    t = next;
    travel += u * dt;
    time += dt;
  }
  const double dt = 1e-5, u = 1.0;
  travel += u * dt;
  time += dt;
  const internal::StepHistory h = internal::HistoryOfStep(g, t, dt, u, 0.5 * u);
  ASSERT_TRUE(h.active);
  for (int i = 0; i < g.size(); ++i) {
    const double heated = std::max(0.0, (g.x(i) - g.x(0) - travel) / u0);
    const double expected = 2 * q0 * std::sqrt(u) * (std::sqrt(heated + time) - std::sqrt(time));
    EXPECT_NEAR(h.history1[i], expected, 1e-12 * 2 * q0 * std::sqrt(g.x(g.size() - 1) - g.x(0)))
        << i;
  }
}

TEST(SolidHeatHistory, LevelsAreKeptForOneTransitOfTheGridAndMergedWithinTheCap) {
  const UniformGrid g = TestGrid(33);
  const double length = g.x(g.size() - 1) - g.x(0), dx = g.dx_m();
  FilmTemperature steady;
  steady.q1_w_m2 = Eigen::VectorXd::Constant(g.size(), 1e7);
  steady.q2_w_m2 = Eigen::VectorXd::Constant(g.size(), 2e7);
  // Steps of 3 dx on surface 1, dx on surface 2: a level stays while either surface still
  // sees it on the grid.
  FilmTemperature t = steady;
  for (int step = 0; step < 40; ++step) {
    FilmTemperature next;
    next.q1_w_m2 = Eigen::VectorXd::Constant(g.size(), step);
    next.q2_w_m2 = Eigen::VectorXd::Constant(g.size(), -step);
    internal::RememberLevels(g, t, 1.0, 3 * dx, dx, &next);
    t = next;
  }
  EXPECT_EQ(t.travel1_m, 3 * dx);
  EXPECT_EQ(t.travel2_m, dx);
  // The level after t starts at a lag of at least t's own dx, earlier[j] at (j + 2) dx: 31
  // levels start on the grid (length 32 dx), with their own fluxes; the steady level has
  // left it.
  ASSERT_EQ(t.earlier.size(), 31u);
  EXPECT_EQ(t.earlier.front().q1_w_m2[0], 38);
  EXPECT_EQ(t.earlier.back().q1_w_m2[0], 8);
  EXPECT_LT(t.earlier.size() * dx, length + dx);
  // Far more short steps than the cap: merged, the travel and the flux integral kept, and
  // the steady level last.
  t = steady;
  const int steps = kMaxSolidFluxLevels + 100;
  double flux_travel = 0;  // sum of q1 dt u over the levels after the steady one
  for (int step = 0; step < steps; ++step) {
    FilmTemperature next;
    next.q1_w_m2 = Eigen::VectorXd::Constant(g.size(), 1e6 * (step + 1));
    next.q2_w_m2 = next.q1_w_m2;
    internal::RememberLevels(g, t, 1e-3, dx, dx, &next);
    if (step + 1 < steps) flux_travel += 1e6 * (step + 1) * 1e-3 * dx;
    t = next;
  }
  ASSERT_EQ(static_cast<int>(t.earlier.size()), kMaxSolidFluxLevels);
  EXPECT_TRUE(std::isinf(t.earlier.back().travel1_m));
  EXPECT_EQ(t.earlier.back().q1_w_m2[0], 1e7);
  double travel = 0, integral = 0;
  for (size_t j = 0; j + 1 < t.earlier.size(); ++j) {
    travel += t.earlier[j].travel1_m;
    integral += t.earlier[j].q1_w_m2[0] * t.earlier[j].travel1_m;
  }
  EXPECT_NEAR(travel, (steps - 1) * 1e-3 * dx, 1e-12 * steps * dx);
  EXPECT_NEAR(integral, flux_travel, 1e-12 * flux_travel);
  // The newest levels stay unmerged.
  EXPECT_EQ(t.earlier.front().travel1_m, 1e-3 * dx);
  // A steady solve forgets.
  internal::ForgetLevels(1.0, 1.0, &t);
  EXPECT_TRUE(t.earlier.empty());
  EXPECT_TRUE(std::isinf(t.travel1_m));
}

}  // namespace
}  // namespace tehl
