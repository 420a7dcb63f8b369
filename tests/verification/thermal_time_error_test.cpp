// The local time error estimate of thermal transient steps (Summary::time_error: the larger of
// the estimates for rho h and for the film temperature; docs/theory.md, "Time-step error").
// The energy equation's transient term is BDF1, so in a thermal run the estimate falls as
// dt^2 once the temperature's error dominates (BDF1's local truncation error is O(dt^2), e.g.
// Hairer & Wanner, Solving ODEs II, section III.5), while the isothermal film's BDF2 estimate
// falls as dt^3.
// Case: the steel disc of thermal_disc_case.hpp in pure rolling at L_T = 1 (SAE 40, p_H =
// 0.8 GPa; T_max - T0 about 17 K), 129 nodes, under the load w0 (1 + 0.3 sin(pi t/T)),
// T = 8 b/um.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>
#include <vector>

#include "verification/thermal_disc_case.hpp"

namespace tehl {
namespace {

using testing::Sae40;
using testing::ThermalDisc;

constexpr int kNodes = 129;

ThermalDisc Disc() {
  ThermalDisc d;
  d.um_m_s = testing::SpeedForLoading(Sae40(), 1.0);
  return d;
}

// The geometric mean of the estimates over the middle half of the period for `steps` equal
// steps from the steady film.
double MeanEstimate(bool thermal, int steps) {
  const ThermalDisc d = Disc();
  FilmEffects e;
  e.transient = true;
  e.thermal = thermal;
  LineContactSolver solver(UniformGrid::AroundHertz(d.half_width_m(), kNodes), d.e_prime_pa,
                           Sae40(), e, LineContactSolver::Options{});
  const ContactConditions c0 = d.Conditions(Sae40());
  FilmState st;
  const LineContactSolver::Summary s0 = solver.SolveSteady(c0, &st);
  EXPECT_TRUE(s0.usable()) << s0.BriefReport();
  solver.BeginTransient(c0, st);
  const double period = 8.0 * d.half_width_m() / d.um_m_s, dt = period / steps;
  double sum = 0;
  int count = 0;
  for (int k = 1; k <= steps; ++k) {
    ContactConditions c = c0;
    c.load_n_per_m *= 1.0 + 0.3 * std::sin(std::numbers::pi * k * dt / period);
    const LineContactSolver::Summary step = solver.Step(c, dt, &st);
    EXPECT_TRUE(step.usable()) << "step " << k << ": " << step.BriefReport();
    EXPECT_EQ(step.substeps, 1);
    if (k >= steps / 4 && k <= 3 * steps / 4) {
      EXPECT_GT(step.time_error, 0.0) << k;
      sum += std::log(step.time_error);
      ++count;
    }
  }
  return std::exp(sum / count);
}

TEST(ThermalTimeErrorEstimate, FallsAsTheSquareOfTheStep) {
  std::vector<double> thermal, isothermal;
  for (int steps : {16, 32, 64}) {
    thermal.push_back(MeanEstimate(true, steps));
    isothermal.push_back(MeanEstimate(false, steps));
  }
  const double q1 = std::log2(thermal[0] / thermal[1]), q2 = std::log2(thermal[1] / thermal[2]);
  std::printf(
      "time_error, geometric mean over T/4 .. 3T/4, thermal: %.3e (16 steps) %.3e (32) "
      "%.3e (64), orders %.3f %.3f; isothermal: %.3e %.3e %.3e, orders %.3f %.3f\n",
      thermal[0], thermal[1], thermal[2], q1, q2, isothermal[0], isothermal[1], isothermal[2],
      std::log2(isothermal[0] / isothermal[1]), std::log2(isothermal[1] / isothermal[2]));
  EXPECT_NEAR(q1, 2.0, 0.25);
  EXPECT_NEAR(q2, 2.0, 0.25);
  // The temperature's estimate is the larger: above the film's own on the finest steps.
  EXPECT_GT(thermal[2], isothermal[2]);
}

}  // namespace
}  // namespace tehl
