// The seed 004 isothermal cycle (257 nodes) with `[numerics] time_tolerance`: after the load
// jumps at B and D the film is a squeeze transient that 40 equal steps do not resolve. The
// error-controlled run takes substeps there (from the load after the jump) and follows a run
// of 16 times as many steps; the uncontrolled one does not (docs/theory.md, "Time-step error").
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

TEST(MeshCycleTimeTolerance, SubstepsAfterTheLoadJumpsFollowTheFineStepFilm) {
  const MeshCycleResult plain = testing::RunReduced("seed004_sae40");
  const MeshCycleResult controlled =
      testing::RunReduced("seed004_sae40", testing::Reduced({{"time_tolerance", "1e-4"}}));
  const MeshCycleResult fine =
      testing::RunReduced("seed004_sae40", testing::Reduced({{"steps", "640"}}));
  ASSERT_TRUE(plain.converged() && controlled.converged() && fine.converged());
  const double e_plain = LargestFilmDifference(plain, fine);
  const double e_controlled = LargestFilmDifference(controlled, fine);
  std::printf(
      "largest |h / h(640 steps) - 1| over the 40 steps: %.4f (no control, %d substeps), "
      "%.4f (time_tolerance 1e-4, %d substeps)\n",
      e_plain, Substeps(plain), e_controlled, Substeps(controlled));
  EXPECT_GT(Substeps(controlled), Substeps(plain));
  EXPECT_LT(e_controlled, 0.25 * e_plain);
}

}  // namespace
}  // namespace tehl
