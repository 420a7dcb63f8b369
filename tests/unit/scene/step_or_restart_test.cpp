// StepOrRestart (src/scene/step_restart.hpp), the fallback of [numerics] failed_step =
// "steady_restart": when the steady solve from the state before a failed step fails too, the
// steady film is solved cold (grid sequencing from the coarse grid), which does not depend on
// that state. Isothermal reference-oil disc (VALIDATION.md section 3: eta0 = 0.04 Pa s,
// Z = 0.68, E' = 226.4 GPa, R = 10 mm) on 257 nodes.
#include <gtest/gtest.h>

#include <cmath>

#include "scene/step_restart.hpp"
#include "support/test_lubricants.hpp"
#include "tehl/ehl/grid.hpp"

namespace tehl {
namespace {

constexpr double kEPrime = 226.4e9;  // [Pa]
constexpr double kRadius = 0.01;     // [m]
constexpr double kLoad = 1.0e5;      // [N/m]: p_H = 0.63 GPa
constexpr double kPi = 3.14159265358979323846;

struct Disc {
  Lubricant oil = testing::ReferenceOil();
  UniformGrid grid =
      UniformGrid::AroundHertz(std::sqrt(8.0 * kLoad * kRadius / (kPi * kEPrime)), 257);
  ContactConditions Conditions(double load_n_per_m) const {
    return {kRadius, 1.0, 1.0, load_n_per_m, oil.reference_temperature_k()};
  }
  LineContactSolver Solver(int max_iterations) const {
    LineContactSolver::Options o;
    o.max_iterations = max_iterations;
    o.max_continuation_stages = 0;
    return LineContactSolver(grid, kEPrime, oil, FilmEffects{}, o);
  }
};

// A pressure that no film under these conditions is near: p_H-sized teeth on every other node.
// The budget of Newton iterations is what a warm step from the true film needs (asserted
// below), so the step and the steady solve from this state fail on it.
TEST(StepOrRestart, AFailedSteadySolveFromTheStateBeforeTheStepIsRetriedCold) {
  const Disc d;
  const int budget = 12;
  LineContactSolver solver = d.Solver(budget);
  const ContactConditions c0 = d.Conditions(kLoad), c1 = d.Conditions(1.02 * kLoad);
  FilmState s;
  ASSERT_TRUE(solver.SolveSteady(c0, &s).usable());
  const double dt = 1e-5;  // [s]
  {
    LineContactSolver warm = d.Solver(budget);
    FilmState t = s;
    warm.BeginTransient(c0, t);
    ASSERT_TRUE(warm.Step(c1, dt, &t).usable()) << "the budget must suffice for a warm step";
  }
  solver.BeginTransient(c0, s);
  FilmState bad = s;
  const double p_max = s.MaxPressure();
  for (int i = 1; i + 1 < bad.p_pa.size(); ++i) bad.p_pa[i] = (i % 2) ? p_max : 0.0;
  bad.h0_m = -10 * bad.h0_m;
  const internal::MarchedStep step = internal::StepOrRestart(solver, c1, dt, &bad, true);
  ASSERT_TRUE(step.summary.usable()) << step.summary.message;
  EXPECT_FALSE(step.restart_reason.empty());
  // The restarted film is the steady film at c1: a separate cold solve (tolerance 1e-8 on the
  // scaled residual of both).
  LineContactSolver fresh = d.Solver(100);
  FilmState ref;
  ASSERT_TRUE(fresh.SolveSteady(c1, &ref).usable());
  EXPECT_NEAR(bad.CentralFilm(d.grid) / ref.CentralFilm(d.grid), 1.0, 1e-6);
  EXPECT_NEAR(bad.MaxPressure() / ref.MaxPressure(), 1.0, 1e-6);
  EXPECT_NEAR(bad.time_s, s.time_s + dt, 1e-15);
}

}  // namespace
}  // namespace tehl
