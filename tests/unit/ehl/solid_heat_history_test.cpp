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
                                  MovingHeatSource(g).History(reach, {FluxSpan{&q, kInf}});
    EXPECT_LT((split - whole).cwiseAbs().maxCoeff(), 1e-12 * whole.cwiseAbs().maxCoeff()) << reach;
  }
}

TEST(SolidHeatHistory, FluxStoppedOneStepAgoDecaysAsOneDimensionalConduction) {
  // Reference in the file comment: H_i = 2 q0 [sqrt(x_i - x_0) - sqrt(r)].
  const UniformGrid g = TestGrid(193);
  const double q0 = 2.5e7;
  const Eigen::VectorXd q = Eigen::VectorXd::Constant(g.size(), q0);
  for (double r : {0.2 * g.dx_m(), 5.5 * g.dx_m()}) {
    const Eigen::VectorXd h = MovingHeatSource(g).History(r, {FluxSpan{&q, kInf}});
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
  const Eigen::VectorXd h = MovingHeatSource(g).History(reach, spans);
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
    internal::RememberLevels(g, t, 3 * dx, dx, &next);
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
    internal::RememberLevels(g, t, 1e-3 * dx, 1e-3 * dx, &next);
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
  internal::ForgetLevels(&t);
  EXPECT_TRUE(t.earlier.empty());
  EXPECT_TRUE(std::isinf(t.travel1_m));
}

}  // namespace
}  // namespace tehl
