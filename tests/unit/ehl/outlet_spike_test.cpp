// The outlet spike finder on piecewise-linear profiles, whose half-prominence width is known
// exactly (linear interpolation between nodes is exact when the kinks sit on nodes).
#include "tehl/ehl/outlet_spike.hpp"

#include <gtest/gtest.h>

#include <vector>

namespace tehl {
namespace {

// Piecewise linear through (node, value) knots, zero outside the first and last knot.
Eigen::VectorXd Profile(int n, const std::vector<std::pair<int, double>>& knots) {
  Eigen::VectorXd p = Eigen::VectorXd::Zero(n);
  for (size_t k = 0; k + 1 < knots.size(); ++k) {
    const auto [i0, v0] = knots[k];
    const auto [i1, v1] = knots[k + 1];
    for (int i = i0; i <= i1; ++i) p[i] = v0 + (v1 - v0) * (i - i0) / double(i1 - i0);
  }
  return p;
}

// Hump 0 -> 2 P0 -> shelf P0, a spike rising over w cells to P0 + A and falling over w' cells
// to 0. Half level P0 + A/2: crossed w/2 before the peak and w' A / (2 (P0 + A)) after it.
TEST(OutletSpike, HalfProminenceWidthOfATriangularSpikeIsExact) {
  const double p0 = 0.6e9, a = 0.4e9;
  for (int w : {2, 5, 12}) {
    for (int w2 : {1, 3, 8}) {
      const int peak = 300;
      const Eigen::VectorXd p = Profile(
          400,
          {{20, 0.0}, {150, 2 * p0}, {220, p0}, {peak - w, p0}, {peak, p0 + a}, {peak + w2, 0.0}});
      const OutletSpike s = FindOutletSpike(p, -1e-3, 1e-5);
      ASSERT_TRUE(s.found) << w << " " << w2;
      EXPECT_EQ(s.node, peak);
      EXPECT_DOUBLE_EQ(s.x_m, -1e-3 + peak * 1e-5);
      EXPECT_DOUBLE_EQ(s.pressure_pa, p0 + a);
      EXPECT_DOUBLE_EQ(s.prominence_pa, a);
      EXPECT_NEAR(s.width_cells, 0.5 * w + w2 * a / (2 * (p0 + a)), 1e-12) << w << " " << w2;
      EXPECT_EQ(s.resolved(), s.width_cells >= kSpikeResolvedCells);
    }
  }
}

// Round-off pressures past the outlet (1e-4 Pa against p_max 1 GPa, with a micro-peak, as a
// linear solve can leave them on cavitated nodes) do not hide the spike before them: the
// same spike and width as without them.
TEST(OutletSpike, RoundOffPressuresPastTheOutletDoNotHideTheSpike) {
  const double p0 = 0.6e9, a = 0.4e9;
  Eigen::VectorXd p =
      Profile(400, {{20, 0.0}, {150, 2 * p0}, {220, p0}, {295, p0}, {300, p0 + a}, {303, 0.0}});
  const OutletSpike clean = FindOutletSpike(p, -1e-3, 1e-5);
  ASSERT_TRUE(clean.found);
  p[304] = 1.006e-4;
  p[305] = 1.018e-4;
  p[306] = 3.5e-5;
  const OutletSpike s = FindOutletSpike(p, -1e-3, 1e-5);
  ASSERT_TRUE(s.found);
  EXPECT_EQ(s.node, clean.node);
  EXPECT_DOUBLE_EQ(s.width_cells, clean.width_cells);
}

TEST(OutletSpike, AHumpWithoutADipOrATinyRippleIsNoSpike) {
  // A Hertz-like hump: rises and falls once.
  const Eigen::VectorXd hump = Profile(200, {{10, 0.0}, {100, 1e9}, {180, 0.0}});
  EXPECT_FALSE(FindOutletSpike(hump, 0.0, 1e-5).found);
  EXPECT_TRUE(FindOutletSpike(hump, 0.0, 1e-5).resolved());
  // A ripple of 1 % of p_max before the outlet: below the 2 % prominence asked.
  const Eigen::VectorXd ripple =
      Profile(200, {{10, 0.0}, {100, 1e9}, {150, 0.5e9}, {152, 0.51e9}, {180, 0.0}});
  EXPECT_FALSE(FindOutletSpike(ripple, 0.0, 1e-5).found);
  EXPECT_TRUE(FindOutletSpike(ripple, 0.0, 1e-5, 0.005).found);
  // Nothing to find in a film without pressure.
  EXPECT_FALSE(FindOutletSpike(Eigen::VectorXd::Zero(50), 0.0, 1e-5).found);
}

}  // namespace
}  // namespace tehl
