// Tests of the dry line-contact solver (VALIDATION.md section 2, rows "dry contact" and
// "load balance").
#include "tehl/ehl/dry_contact.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "tehl/ehl/surface_roughness.hpp"
#include "tehl/error.hpp"
#include "tehl/units.hpp"

namespace tehl {
namespace {

constexpr double kEPrime = 226.4e9;  // steel-steel E' (VALIDATION.md section 1) [Pa]

struct HertzCase {
  double r_m, w_n_per_m;
  double left, right;  // grid ends in units of b
  int n;
};

double HertzPressure(const HertzScales& hz, double x) {
  const double b = hz.half_width_m;
  return std::abs(x) < b ? hz.max_pressure_pa * std::sqrt(1 - x * x / (b * b)) : 0.0;
}

// Hertz line contact (VALIDATION.md section 1): b = sqrt(8 w R/(pi E')), p_H = sqrt(w E'/(2 pi R)),
// p(x) = p_H sqrt(1 - x^2/b^2). VALIDATION.md section 2: pressure within 1% of p_H, half-width
// within 1% of b, load balance to 1e-6. Grids: 2049 points on [-1.5b, 1.5b] (dx = b/683) for
// R = 10 mm, w = 300 kN/m; 2049 points on [-2b, 1.2b] (not symmetric) for R = 25 mm, w = 1 MN/m.
TEST(DryContactVerification, SmoothCylindersGiveHertzPressureAndHalfWidth) {
  for (const HertzCase& c :
       {HertzCase{0.01, 3e5, -1.5, 1.5, 2049}, HertzCase{0.025, 1e6, -2.0, 1.2, 2049}}) {
    const HertzScales hz = LineContactHertz(c.w_n_per_m, c.r_m, kEPrime);
    const double b = hz.half_width_m;
    const double dx = (c.right - c.left) * b / (c.n - 1);
    DryContactSolver solver(c.n, c.left * b, dx, kEPrime);
    DryContactProblem problem;
    problem.reduced_radius_m = c.r_m;
    problem.load_n_per_m = c.w_n_per_m;
    DryContactSolution solution;
    const DryContactSolver::Summary s = solver.Solve({}, problem, &solution);
    ASSERT_EQ(s.termination, DryContactSolver::Termination::kConverged) << s.BriefReport();
    EXPECT_TRUE(s.usable());
    double worst = 0;
    for (int i = 0; i < c.n; ++i) {
      worst = std::max(worst, std::abs(solution.pressure_pa[i] - HertzPressure(hz, solver.X(i))));
    }
    EXPECT_LT(worst, 0.01 * hz.max_pressure_pa) << "R = " << c.r_m;
    EXPECT_NEAR(s.contact_half_width_m, b, 0.01 * b);
    EXPECT_NEAR(0.5 * (s.contact_begin_m + s.contact_end_m), 0.0, 0.01 * b);  // centred
    EXPECT_NEAR(s.max_pressure_pa, hz.max_pressure_pa, 0.01 * hz.max_pressure_pa);
    EXPECT_LT(s.load_balance_error, 1e-6);
  }
}

TEST(DryContactVerification, LoadBalanceAndContactConditionsHold) {
  // VALIDATION.md section 2: integral p dx = w to 1e-6, computed here independently of the
  // summary. The contact conditions p >= 0, gap >= 0, p gap = 0 hold to 1e-9 of the Hertz
  // approach scale b^2/(2R); the gap is also recomputed with the direct O(n^2) sum.
  const double r = 0.01, w = 3e5;
  const HertzScales hz = LineContactHertz(w, r, kEPrime);
  const double b = hz.half_width_m, scale = b * b / (2 * r);
  const int n = 1025;
  DryContactSolver solver(n, -1.5 * b, 3 * b / (n - 1), kEPrime);
  DryContactProblem problem;
  problem.reduced_radius_m = r;
  problem.load_n_per_m = w;
  DryContactSolution sol;
  const auto s = solver.Solve({}, problem, &sol);
  ASSERT_TRUE(s.usable()) << s.BriefReport();
  double load = 0;
  for (double p : sol.pressure_pa) load += p * solver.dx_m();
  EXPECT_NEAR(load, w, 1e-6 * w);
  std::vector<double> v(n);
  solver.deflection().ApplyDirect(sol.pressure_pa.data(), v.data());
  for (int i = 0; i < n; ++i) {
    const double x = solver.X(i);
    const double gap = sol.approach_m + x * x / (2 * r) + v[i];
    EXPECT_NEAR(gap, sol.gap_m[i], 1e-9 * scale) << i;
    EXPECT_GE(sol.pressure_pa[i], 0.0);
    EXPECT_GE(gap, -1e-9 * scale) << i;
    if (sol.pressure_pa[i] > 0) {
      EXPECT_LT(std::abs(gap), 1e-9 * scale) << i;
    }
  }
}

TEST(DryContactVerification, ShortWavinessAddsTheWestergaardRipple) {
  // A surface z = D sin(k x + phi) pressed flat needs the pressure ripple p* sin(k x + phi) with
  // p* = pi E* D / lambda = pi E' D / (2 lambda) (Westergaard, J. Appl. Mech. 6 (1939) A49;
  // derivation: int cos(k x') ln|x - x'| dx' = -pi cos(k x)/k, so the kernel of
  // elastic_deflection.hpp maps p* cos(kx) to v = 4 p* cos(kx)/(E' k), and v must cancel D).
  // Elasticity is linear, so with lambda = b/8 and p* = 0.1 p_H (full contact in the centre) the
  // pressure over |x| < b/2 is Hertz + ripple; the superposition is not exact because the ripple
  // shifts the contact edges, hence 1% of p*. Also checks the sign: a positive height (into the
  // gap) raises the pressure.
  const double r = 0.01, w = 3e5, travel = 1.1e-5, phase = 0.3;
  const HertzScales hz = LineContactHertz(w, r, kEPrime);
  const double b = hz.half_width_m, lambda = b / 8, p_star = 0.1 * hz.max_pressure_pa;
  const double amplitude = p_star * 2 * lambda / (kPi * kEPrime);
  const SinusoidalWaviness wavy(amplitude, lambda, phase);
  const int n = 2049;
  DryContactSolver solver(n, -1.5 * b, 3 * b / (n - 1), kEPrime);
  DryContactProblem problem;
  problem.reduced_radius_m = r;
  problem.load_n_per_m = w;
  std::vector<double> x(n);
  for (int i = 0; i < n; ++i) x[i] = solver.X(i);
  problem.surface_height_m.resize(n);
  SampleHeights(wavy, x.data(), n, travel, problem.surface_height_m.data());
  DryContactSolution sol;
  const auto s = solver.Solve({}, problem, &sol);
  ASSERT_TRUE(s.usable()) << s.BriefReport();
  EXPECT_LT(s.load_balance_error, 1e-6);
  for (int i = 0; i < n; ++i) {
    if (std::abs(x[i]) >= 0.5 * b) continue;
    const double expected =
        HertzPressure(hz, x[i]) + p_star * std::sin(2 * kPi * (x[i] - travel) / lambda + phase);
    EXPECT_NEAR(sol.pressure_pa[i], expected, 0.01 * p_star) << "x/b = " << x[i] / b;
  }
}

TEST(DryContact, UniformHeightOnlyShiftsTheApproach) {
  // Sign convention (surface_roughness.hpp): gap = h0 + x^2/(2R) + v - s. A uniform s = c
  // leaves the pressure unchanged and raises h0 by c.
  const double r = 0.01, w = 3e5, c = 2e-7;
  const double b = LineContactHertz(w, r, kEPrime).half_width_m;
  const int n = 513;
  DryContactSolver solver(n, -1.5 * b, 3 * b / (n - 1), kEPrime);
  DryContactProblem smooth{r, w, {}};
  DryContactProblem lifted{r, w, std::vector<double>(n, c)};
  DryContactSolution a, bsol;
  ASSERT_TRUE(solver.Solve({}, smooth, &a).usable());
  ASSERT_TRUE(solver.Solve({}, lifted, &bsol).usable());
  EXPECT_NEAR(bsol.approach_m - a.approach_m, c, 1e-9 * c);
  const double p_h = LineContactHertz(w, r, kEPrime).max_pressure_pa;
  for (int i = 0; i < n; ++i) EXPECT_NEAR(bsol.pressure_pa[i], a.pressure_pa[i], 1e-6 * p_h);
}

TEST(DryContact, ReportsContactReachingTheGridEnd) {
  // Grid [-0.5 b, 0.5 b]: the contact cannot fit.
  const double r = 0.01, w = 3e5;
  const double b = LineContactHertz(w, r, kEPrime).half_width_m;
  DryContactSolver solver(129, -0.5 * b, b / 128, kEPrime);
  DryContactSolution sol;
  const auto s = solver.Solve({}, DryContactProblem{r, w, {}}, &sol);
  EXPECT_EQ(s.termination, DryContactSolver::Termination::kContactAtGridEdge);
  EXPECT_FALSE(s.usable());
  EXPECT_NE(s.message.find("widen"), std::string::npos);
}

TEST(DryContact, ReportsMaxIterationsWithoutThrowing) {
  const double b = LineContactHertz(3e5, 0.01, kEPrime).half_width_m;
  DryContactSolver solver(257, -1.5 * b, 3 * b / 256, kEPrime);
  DryContactSolver::Options options;
  options.max_iterations = 2;
  DryContactSolution sol;
  const auto s = solver.Solve(options, DryContactProblem{0.01, 3e5, {}}, &sol);
  EXPECT_EQ(s.termination, DryContactSolver::Termination::kMaxIterations);
  EXPECT_EQ(s.iterations, 2);
  EXPECT_FALSE(s.usable());
  EXPECT_LT(s.load_balance_error, 1e-6);  // the load is enforced at every iteration
}

TEST(DryContactSolverOptions, RejectsNonPositiveToleranceAndIterations) {
  DryContactSolver::Options o;
  EXPECT_TRUE(o.Validate().empty());
  o.tolerance = 0;
  o.max_iterations = 0;
  const auto bad = o.Validate();
  ASSERT_EQ(bad.size(), 2u);
  EXPECT_EQ(bad[0], "DryContactSolver::Options::tolerance = 0 violates > 0");
  EXPECT_EQ(bad[1], "DryContactSolver::Options::max_iterations = 0 violates >= 1");
  DryContactSolver solver(16, 0.0, 1e-6, kEPrime);
  DryContactSolution sol;
  EXPECT_THROW(solver.Solve(o, DryContactProblem{0.01, 3e5, {}}, &sol), InputError);
}

TEST(DryContact, RejectsBadProblemNamingEachKey) {
  DryContactSolver solver(16, 0.0, 1e-6, kEPrime);
  DryContactSolution sol;
  try {
    solver.Solve({}, DryContactProblem{-0.01, 0.0, std::vector<double>(5, 0.0)}, &sol);
    FAIL() << "no InputError";
  } catch (const InputError& e) {
    ASSERT_EQ(e.problems().size(), 3u);
    EXPECT_EQ(e.problems()[0].key, "DryContactProblem::reduced_radius_m");
    EXPECT_EQ(e.problems()[1].key, "DryContactProblem::load_n_per_m");
    EXPECT_EQ(e.problems()[2].key, "DryContactProblem::surface_height_m");
  }
  EXPECT_THROW(DryContactSolver(2, 0.0, 1e-6, kEPrime), InputError);
}

}  // namespace
}  // namespace tehl
