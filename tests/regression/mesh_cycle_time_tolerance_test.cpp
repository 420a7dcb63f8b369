// The seed 004 isothermal cycle (513 nodes) with `[numerics] time_tolerance`: after the load
// jumps at B and D the film is a squeeze transient that 150 equal steps do not resolve. Under
// control each step takes substeps sized by the time error (restarting at the jumps), so the
// film along the path no longer depends on the number of steps: runs of 150 and 600 steps agree,
// where without control they do not (docs/theory.md, "Time-step error").
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numeric>
#include <vector>

#include "regression/mesh_cycle_runs.hpp"

namespace tehl {
namespace {

// The largest relative difference of h_min and of h_c between `run` and `ref` at run's steps
// (ref linear in s between its steps).
double LargestFilmDifference(const MeshCycleResult& run, const MeshCycleResult& ref) {
  std::vector<double> s, h_min, h_c;
  for (const MeshCycleStep& k : ref.steps) {
    s.push_back(k.s_m);
    h_min.push_back(k.h_min_m);
    h_c.push_back(k.h_c_m);
  }
  auto at = [&](const std::vector<double>& v, double x) {
    const size_t j =
        std::clamp<size_t>(std::upper_bound(s.begin(), s.end(), x) - s.begin(), 1, s.size() - 1);
    const double f = (x - s[j - 1]) / (s[j] - s[j - 1]);
    return (1 - f) * v[j - 1] + f * v[j];
  };
  double worst = 0;
  for (const MeshCycleStep& k : run.steps) {
    EXPECT_TRUE(k.summary.usable()) << k.s_m;
    worst = std::max({worst, std::abs(k.h_min_m / at(h_min, k.s_m) - 1),
                      std::abs(k.h_c_m / at(h_c, k.s_m) - 1)});
  }
  return worst;
}

int Substeps(const MeshCycleResult& r) {
  return std::accumulate(r.steps.begin(), r.steps.end(), 0,
                         [](int n, const MeshCycleStep& k) { return n + k.summary.substeps; });
}

TEST(MeshCycleTimeTolerance, ControlledFilmsDoNotDependOnTheStepCount) {
  // 513 nodes: on 257 the film between B and D swings by up to 10 % over a few steps, between
  // which a comparison at the coarse run's points interpolates.
  const auto run = [](const char* steps, const char* tolerance) {
    return testing::RunReduced("seed004_sae40", testing::Reduced({{"grid_points", "513"},
                                                                  {"steps", steps},
                                                                  {"time_tolerance", tolerance}}));
  };
  const MeshCycleResult plain = run("150", "0"), plain_fine = run("600", "0");
  const MeshCycleResult controlled = run("150", "1e-5"), controlled_fine = run("600", "1e-5");
  ASSERT_TRUE(plain.converged() && plain_fine.converged() && controlled.converged() &&
              controlled_fine.converged());
  const double e_plain = LargestFilmDifference(plain, plain_fine);
  const double e_controlled = LargestFilmDifference(controlled, controlled_fine);
  std::printf(
      "largest |h(150 steps) / h(600 steps) - 1|: %.4f without control (%d, %d substeps), "
      "%.4f at time_tolerance 1e-5 (%d, %d substeps)\n",
      e_plain, Substeps(plain), Substeps(plain_fine), e_controlled, Substeps(controlled),
      Substeps(controlled_fine));
  EXPECT_GT(Substeps(controlled), Substeps(plain));
  EXPECT_LT(e_controlled, 0.1 * e_plain);
}

}  // namespace
}  // namespace tehl
