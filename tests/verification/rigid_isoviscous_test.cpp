// Rigid, isoviscous, incompressible, steady line contact: Martin (1916) with the Reynolds
// exit condition (VALIDATION.md section 2): w = 4.896 eta0 um R / h0, and the film ruptures
// at X_c = x/sqrt(2 R h0) = 0.4751, where p = dp/dx = 0. The same X_c marks the pressure
// maximum at -0.4751 (dp/dx = 0 where h = h(X_c)).
#include <gtest/gtest.h>

#include <cmath>

#include "support/test_lubricants.hpp"
#include "tehl/ehl/inlet_truncation.hpp"
#include "tehl/ehl/line_contact_solver.hpp"

namespace tehl {
namespace {

struct MartinCase {
  double eta0 = 0.04, um = 1.0, radius = 0.01, h0 = 1e-6;
  double load() const { return 4.896 * eta0 * um * radius / h0; }  // VALIDATION.md section 2
  double scale() const { return std::sqrt(2.0 * radius * h0); }
};

struct MartinRun {
  FilmState state;
  LineContactSolver::Summary summary;
  Eigen::VectorXd flow;
};

MartinRun RunMartin(const MartinCase& mc, int n, LinearSolverKind kind) {
  const Lubricant oil = testing::IsoviscousOil(mc.eta0);
  // The Martin integral converges slowly at the inlet: the grid starts at X = -60
  // (VALIDATION.md: 4.894 at X = -60, 4.896 in the limit).
  const UniformGrid grid(-60.0 * mc.scale(), 2.0 * mc.scale(), n);
  FilmEffects eff;
  eff.elastic = eff.piezoviscous = eff.compressible = eff.transient = false;
  LineContactSolver::Options opt;
  opt.linear_solver = kind;
  LineContactSolver solver(grid, 226.4e9, oil, eff, opt);
  ContactConditions c{mc.radius, mc.um, mc.um, mc.load(), testing::kReferenceT0};
  MartinRun run;
  run.summary = solver.SolveSteady(c, &run.state);
  run.flow = solver.MassFlow(c, run.state);
  return run;
}

TEST(RigidIsoviscousVerification, FilmMatchesMartinAndRupturesAtReynoldsExit) {
  const MartinCase mc;
  const MartinRun run = RunMartin(mc, 20001, LinearSolverKind::kNewtonKrylov);
  ASSERT_TRUE(run.summary.usable()) << run.summary.BriefReport();
  // h0 from the load: Martin's limit 4.896 within 0.5%; the cut at X = -60 gives 4.894.
  EXPECT_NEAR(run.state.h0_m / mc.h0, 4.894 / 4.896, 0.005);
  // h = h0 + x^2/(2R): the smallest node value is h0 up to the nearest node's offset.
  const UniformGrid grid(-60.0 * mc.scale(), 2.0 * mc.scale(), 20001);
  const double half_cell = 0.5 * grid.dx_m() / mc.scale();
  EXPECT_GE(run.state.MinFilm() / run.state.h0_m, 1.0);
  EXPECT_LE(run.state.MinFilm() / run.state.h0_m, 1.0 + half_cell * half_cell);
  // Rupture: the full-film flux q = rho um h(X_c) fixes X_c = sqrt(q/(rho um h0) - 1).
  const double q = run.flow[grid.NearestNode(-mc.scale())];
  const double xc = std::sqrt(q / (870.0 * mc.um * run.state.h0_m) - 1.0);
  EXPECT_NEAR(xc, 0.4751, 0.005 * 0.4751);
  // The first cavitated node downstream of the pressure peak lies within one cell of X_c.
  int i = grid.NearestNode(0.0);
  while (i < grid.size() - 1 && run.state.p_pa[i] > 0.0) ++i;
  EXPECT_NEAR(grid.x(i) / mc.scale(), 0.4751, 2.0 * grid.dx_m() / mc.scale());
}

TEST(RigidIsoviscousVerification, LoadBalanceAndMassFlowHold) {
  const MartinCase mc;
  const MartinRun run = RunMartin(mc, 4001, LinearSolverKind::kAuto);
  ASSERT_TRUE(run.summary.usable()) << run.summary.BriefReport();
  EXPECT_LT(run.summary.load_error, 1e-6);  // VALIDATION.md section 2: 1e-6 relative
  // Steady mass flow constant along x where the film is full (p > 0), VALIDATION.md 1e-3.
  const UniformGrid grid(-60.0 * mc.scale(), 2.0 * mc.scale(), 4001);
  double qmin = 1e300, qmax = -1e300;
  for (int i = 1; i < grid.size() - 1; ++i) {
    if (run.state.p_pa[i] <= 0.0 || run.state.p_pa[i + 1] <= 0.0) continue;
    qmin = std::min(qmin, run.flow[i]);
    qmax = std::max(qmax, run.flow[i]);
  }
  EXPECT_LT((qmax - qmin) / qmax, 1e-3);
}

// The same film with its inlet cut at X0 = -4.7 and -3 (an inlet at R/2 of a film thick against
// R): h0 at the same load is Martin's times RigidInletFilmRatio(X0), the exact solution of the
// truncated problem (inlet_truncation.hpp), to the grid's accuracy.
TEST(RigidIsoviscousVerification, ATruncatedInletThinsTheFilmAsTheClosedFormSays) {
  const MartinCase mc;
  const Lubricant oil = testing::IsoviscousOil(mc.eta0);
  FilmEffects eff;
  eff.elastic = eff.piezoviscous = eff.compressible = eff.transient = false;
  for (double x0 : {-4.7, -3.0}) {
    const UniformGrid grid(x0 * mc.scale(), 2.0 * mc.scale(), 4001);
    LineContactSolver solver(grid, 226.4e9, oil, eff, {});
    FilmState s;
    const ContactConditions c{mc.radius, mc.um, mc.um, mc.load(), testing::kReferenceT0};
    ASSERT_TRUE(solver.SolveSteady(c, &s).usable()) << x0;
    EXPECT_NEAR(s.h0_m / mc.h0, RigidInletFilmRatio(x0), 2e-3) << x0;
  }
}

}  // namespace
}  // namespace tehl
