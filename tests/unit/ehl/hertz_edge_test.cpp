// The Hertzian edge of a film (include/tehl/ehl/hertz_edge.hpp): the dry gap outside a Hertz
// line contact (Johnson, Contact Mechanics, 1985, section 5.6) against the numerical dry
// contact, and the edge width against that gap.
#include "tehl/ehl/hertz_edge.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "tehl/ehl/dry_contact.hpp"
#include "tehl/units.hpp"

namespace tehl {
namespace {

constexpr double kEPrime = 226.4e9;  // steel-steel E' (VALIDATION.md section 1) [Pa]
constexpr double kRadius = 0.01;     // [m]
constexpr double kLoad = 1.0e5;      // [N/m]

// Johnson's gap against the DC-FFT dry contact (Polonsky-Keer) on 4097 points over
// [-3b, 3b]: outside the contact the numerical gap, less its value at the edge node (the
// discrete contact ends within a cell of b), follows the formula to 1 % of the gap at 2b
// from xi = 1.2 on.
TEST(HertzEdge, JohnsonsGapMatchesTheDryContact) {
  const double b = LineContactHertz(kLoad, kRadius, kEPrime).half_width_m;
  const int n = 4097;
  const double dx = 6 * b / (n - 1);
  DryContactSolver solver(n, -3 * b, dx, kEPrime);
  DryContactProblem problem;
  problem.reduced_radius_m = kRadius;
  problem.load_n_per_m = kLoad;
  DryContactSolution sol;
  ASSERT_TRUE(solver.Solve({}, problem, &sol).usable());
  const double scale = HertzGap(kRadius, b, 2.0);
  int checked = 0;
  for (int i = 0; i < n; ++i) {
    const double xi = (-3 * b + i * dx) / b;
    if (std::abs(xi) < 1.2) continue;
    EXPECT_NEAR(sol.gap_m[i], HertzGap(kRadius, b, xi), 0.01 * scale) << "xi = " << xi;
    ++checked;
  }
  EXPECT_GT(checked, 2000);
  EXPECT_EQ(HertzGap(kRadius, b, 0.5), 0.0);
}

// The width delta is where Johnson's gap reaches h_c: g(1 + delta / b) = h_c up to the next
// term of the expansion in eps = delta / b (relative 0.4 eps, from the series of
// xi sqrt(xi^2 - 1) - acosh(xi) at xi = 1 + eps), over films from 1e-5 to 1e-2 of b^2 / R.
TEST(HertzEdge, WidthIsWhereTheDryGapReachesTheFilm) {
  const double b = LineContactHertz(kLoad, kRadius, kEPrime).half_width_m;
  for (double f : {1e-5, 1e-4, 1e-3, 1e-2}) {
    const double h_c = f * b * b / kRadius;
    const HertzEdge e = EstimateHertzEdge(kRadius, b, h_c, b / 100);
    const double eps = e.width_m / b;
    EXPECT_NEAR(HertzGap(kRadius, b, 1 + eps) / h_c, 1.0, 0.4 * eps) << "eps = " << eps;
    EXPECT_NEAR(HertzGap(kRadius, b, -1 - eps) / h_c, 1.0, 0.4 * eps);
    EXPECT_DOUBLE_EQ(e.width_cells, 100 * eps);
    EXPECT_DOUBLE_EQ(e.film_deficit, kEdgeDeficitConstant / (e.width_cells * e.width_cells));
    EXPECT_EQ(e.resolved(), e.width_cells >= kEdgeResolvedCells);
  }
  // Moes' groups: R h_c / b^2 = pi H_c / (8 M); M = 500, H_c = 1.1659 (docs/validation.md
  // section 3.1) gives eps = (3 pi H_c / (16 sqrt(2) M))^(2/3) = 0.0098073.
  const double h_c = kPi * 1.1659 / (8 * 500) * b * b / kRadius;
  EXPECT_NEAR(EstimateHertzEdge(kRadius, b, h_c, b).width_m / b, 0.0098073, 1e-7);
}

TEST(HertzEdge, NoEdgeWithoutAFilmOrAContact) {
  EXPECT_EQ(EstimateHertzEdge(0.01, 1e-4, 0.0, 1e-6).width_m, 0.0);
  EXPECT_EQ(EstimateHertzEdge(0.01, 0.0, 1e-6, 1e-6).width_cells, 0.0);
  EXPECT_FALSE(EstimateHertzEdge(0.01, 1e-4, -1e-6, 1e-6).resolved());
}

// The grid that spans an edge: (n - 1) delta / span >= kEdgeResolvedCells, n = 2^k + 1.
TEST(HertzEdge, NodesSpanningAnEdgeAreTheFewestPowerOfTwoPlusOne) {
  // span / delta = 60: 600 cells are needed, 1024 is the first power of two above.
  EXPECT_EQ(NodesSpanningEdge(6e-3, 1e-4, 17, 1 << 20), 1025);
  EXPECT_EQ(NodesSpanningEdge(6e-3, 1e-4, 2049, 1 << 20), 2049);  // never below the minimum
  EXPECT_EQ(NodesSpanningEdge(6e-3, 1e-4, 17, 513), 513);         // nor above the cap
  // Exactly 10 cells at 513 nodes: 512 delta / span = 10 with span = 512.
  EXPECT_EQ(NodesSpanningEdge(512.0, kEdgeResolvedCells, 17, 1 << 20), 513);
  EXPECT_EQ(NodesSpanningEdge(512.0, 0.99 * kEdgeResolvedCells, 17, 1 << 20), 1025);
  // No edge (a rigid film, a zero width): the minimum.
  EXPECT_EQ(NodesSpanningEdge(6e-3, 0.0, 257, 1 << 20), 257);
}

}  // namespace
}  // namespace tehl
