// Grid convergence of the steady isothermal EHL line contact at M = 20, L = 10 (VALIDATION.md
// section 3, p_H = 0.80 GPa). The discretization is second order in dx inside the film
// (central Poiseuille term, second-order upwind Couette term, exact-cell elastic kernel), so
// the observed order of h_c, log2((h_{n/2} - h_n)/(h_n - h_{2n})), should approach 2. h_min
// sits next to the outlet constriction, where the cavitation boundary falls between nodes, so
// its order is asserted >= 1.5. The Richardson estimate of the error of the default grid
// (513 nodes), |h_1025 - h_513| / (2^q - 1) with q the observed order, must be <= 1 %.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <vector>

#include "tehl/ehl/hertz_edge.hpp"
#include "verification/ehl_moes_point.hpp"

namespace tehl {
namespace {

using testing::MoesPoint;
using testing::MoesSolver;

struct Level {
  int n;
  double hc, hmin;  // Moes-scaled H_c, H_min
  int iterations;
  double seconds;
};

std::vector<Level> Solve(const std::vector<int>& sizes,
                         const LineContactSolver::Options& options = {}) {
  const MoesPoint mp{20, 10};
  std::vector<Level> levels;
  for (int n : sizes) {
    MoesSolver ms(mp, n, options);
    FilmState st;
    const LineContactSolver::Summary sum = ms.solver.SolveSteady(mp.Conditions(), &st);
    EXPECT_TRUE(sum.usable()) << "n = " << n << ": " << sum.BriefReport();
    levels.push_back({n, ms.Hc(st), ms.Hmin(st), sum.iterations, sum.wall_time_s});
  }
  return levels;
}

// Observed order from three successive levels k-2, k-1, k (NaN for k < 2).
double Order(const std::vector<Level>& l, size_t k, double Level::*h) {
  if (k < 2) return std::nan("");
  return std::log2(std::abs((l[k - 1].*h - l[k - 2].*h) / (l[k].*h - l[k - 1].*h)));
}

// A table in the layout of deal.II's ConvergenceTable (value, then its observed order).
void Print(const std::vector<Level>& l) {
  std::printf("%6s %12s %6s %12s %6s %5s %8s\n", "n", "H_c", "order", "H_min", "order", "its",
              "time[s]");
  for (size_t k = 0; k < l.size(); ++k) {
    const double qc = Order(l, k, &Level::hc), qm = Order(l, k, &Level::hmin);
    std::printf("%6d %12.6f %6s %12.6f %6s %5d %8.2f\n", l[k].n, l[k].hc,
                std::isnan(qc) ? "-" : (std::to_string(qc).substr(0, 4)).c_str(), l[k].hmin,
                std::isnan(qm) ? "-" : (std::to_string(qm).substr(0, 4)).c_str(),
                l[k].iterations, l[k].seconds);
  }
}

void CheckOrders(const std::vector<Level>& l) {
  for (size_t k = 2; k < l.size(); ++k) {
    EXPECT_GE(Order(l, k, &Level::hc), 1.8) << "h_c, n = " << l[k].n;
    EXPECT_GE(Order(l, k, &Level::hmin), 1.5) << "h_min, n = " << l[k].n;
  }
}

// Richardson error estimate of level k from levels k-1, k, k+1 (order from the same three).
double RichardsonError(const std::vector<Level>& l, size_t k, double Level::*h) {
  const double q = Order(l, k + 1, h);
  return std::abs(l[k + 1].*h - l[k].*h) / (std::pow(2.0, q) - 1.0) / (l[k].*h);
}

#ifndef TEHL_SLOW_TESTS
TEST(GridConvergenceVerification, SecondOrderFrom129To1025Nodes) {
  const std::vector<Level> l = Solve({129, 257, 513, 1025});
  ASSERT_EQ(l.size(), 4u);
  Print(l);
  CheckOrders(l);
  // Levels 257, 513, 1025 (indices 1..3): the error estimate of 513 (index 2).
  const double ec = RichardsonError(l, 2, &Level::hc), em = RichardsonError(l, 2, &Level::hmin);
  std::printf("Richardson error estimate at n = 513: h_c %.3g %%, h_min %.3g %%\n", 100 * ec,
              100 * em);
  EXPECT_LE(ec, 0.01);
  EXPECT_LE(em, 0.01);
}

#else  // the slow binary (ctest label slow)
TEST(GridConvergenceVerification, SecondOrderFrom257To4097Nodes) {
  // Dense LU up to 4097 nodes: the discrete solution does not depend on the linear solver
  // (ehl_linear_solvers_test), and Newton-Krylov stalls on 4097 nodes at this point
  // (GMRES relative residual 0.37 after 400 iterations; docs/validation.md).
  LineContactSolver::Options o;
  o.dense_max_nodes = 4097;
  const std::vector<Level> l = Solve({257, 513, 1025, 2049, 4097}, o);
  ASSERT_EQ(l.size(), 5u);
  Print(l);
  CheckOrders(l);
  const double ec = RichardsonError(l, 1, &Level::hc), em = RichardsonError(l, 1, &Level::hmin);
  std::printf("Richardson error estimate at n = 513: h_c %.3g %%, h_min %.3g %%\n", 100 * ec,
              100 * em);
  EXPECT_LE(ec, 0.01);
  EXPECT_LE(em, 0.01);
}
#endif

// The Hertzian-edge estimate of the central film's grid deficit (include/tehl/ehl/
// hertz_edge.hpp) against the grid-converged films of docs/validation.md: M = 500, L = 2
// (H_c 1.1659, section 3.1) on 1025 and 4097 nodes, and M = 20, L = 10 (H_c 4.3450, section
// 4) on 257 and 513 nodes. Those converged films are this solver's own, Richardson-extrapolated
// from its finest grids (16385 nodes for M = 500, 4097 for M = 20; observed order 2.0). The
// estimate's
// constant was fitted on the M = 20, L = 10 series, so the M = 500 points are the independent
// check. The estimate, from the computed film alone, bounds the true deficit and is within the
// factor of 3 docs/validation.md states (measured 2.8, 2.2, 1.04, 1.02).
TEST(GridConvergenceVerification, HertzEdgeEstimateBoundsTheFilmDeficit) {
  struct Point {
    MoesPoint mp;
    double converged_hc;
    int n;
  };
  for (const Point& pt : {Point{{500, 2}, 1.1659, 1025}, Point{{500, 2}, 1.1659, 4097},
                          Point{{20, 10}, 4.3450, 257}, Point{{20, 10}, 4.3450, 513}}) {
    MoesSolver ms(pt.mp, pt.n);
    FilmState st;
    const LineContactSolver::Summary sum = ms.solver.SolveSteady(pt.mp.Conditions(), &st);
    ASSERT_TRUE(sum.usable()) << sum.BriefReport();
    const HertzEdge e = EstimateHertzEdge(pt.mp.radius_m, pt.mp.Hertz().half_width_m,
                                          st.CentralFilm(ms.grid), ms.grid.dx_m());
    const double deficit = 1.0 - ms.Hc(st) / pt.converged_hc;
    std::printf(
        "M = %g, L = %g, n = %d: edge %.2f cells, estimated deficit %.3g %%, true %.3g %%\n",
        pt.mp.M, pt.mp.L, pt.n, e.width_cells, 100 * e.film_deficit, 100 * deficit);
    EXPECT_LE(deficit, e.film_deficit);
    EXPECT_GE(deficit, e.film_deficit / 3);
  }
}

}  // namespace
}  // namespace tehl
