// The summary values of a film (FilmState::MinFilm, CentralFilm, MaxPressure): exact on the
// shapes they interpolate, never below zero between positive nodes, and defined on an empty
// state (a first solve that failed leaves one).
#include <gtest/gtest.h>

#include <cmath>

#include "tehl/ehl/grid.hpp"
#include "tehl/ehl/line_contact_solver.hpp"

namespace tehl {
namespace {

TEST(FilmState, MinFilmIsExactForAParabolaWhoseVertexLiesBetweenNodes) {
  // h(x) = h0 + k (x - x0)^2 sampled on unit spacing, x0 = 10.3: the parabola through the
  // three nodes around the vertex is h itself, so its minimum is h0 (by construction).
  const double h0 = 0.5e-6, k = 2e-9, x0 = 10.3;
  FilmState s;
  s.h_m.resize(21);
  for (int i = 0; i < 21; ++i) s.h_m[i] = h0 + k * (i - x0) * (i - x0);
  EXPECT_NEAR(s.MinFilm(), h0, 1e-15);
}

TEST(FilmState, MinFilmDoesNotDipBelowZeroBetweenPositiveNodes) {
  // A film 0.5 nm thin at one node between a 1 um and a 2 nm neighbour (a sharp asperity):
  // the parabola through them has its vertex at 0.5e-9 - (2e-9 - 1e-6)^2 / (8 (1e-6 - 1e-9 +
  // 2e-9)) = -1.2e-7 m; the smallest node, 0.5 nm, is returned instead.
  FilmState s;
  s.h_m.resize(5);
  s.h_m << 2e-6, 1e-6, 0.5e-9, 2e-9, 1e-6;
  EXPECT_EQ(s.MinFilm(), 0.5e-9);
}

TEST(FilmState, EmptyStateHasZeroSummaries) {
  const FilmState s;
  EXPECT_EQ(s.MinFilm(), 0.0);
  EXPECT_EQ(s.MaxPressure(), 0.0);
  EXPECT_EQ(s.CentralFilm(UniformGrid(-1e-3, 1e-3, 65)), 0.0);
}

// A longer inlet at the same spacing: -4.5 .. 1.5 on 513 nodes (dx = 6/512) from -9 needs
// 10.5 / dx = 896 cells, 897 nodes (odd, and x = 0 stays a node); from -9.01 one cell more
// rounds up to 898 cells, 899 nodes.
TEST(UniformGrid, NodesFromStartKeepTheSpacingAndAnOddCount) {
  const UniformGrid g(-4.5, 1.5, 513);
  EXPECT_EQ(g.NodesFromStart(-9.0), 897);
  EXPECT_EQ(g.NodesFromStart(-9.01), 899);
  EXPECT_EQ(g.NodesFromStart(-4.5), 513);
}

}  // namespace
}  // namespace tehl
