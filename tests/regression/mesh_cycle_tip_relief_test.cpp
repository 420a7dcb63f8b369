// The seed 004 cycle with tip relief (cases/seed004_sae40_tip_relief.toml) against the same
// cycle without it, at reduced resolution: the load step at B shrinks to the share left at E,
// and the squeeze transient that the step sets off in the single-contact films goes with it.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "regression/mesh_cycle_runs.hpp"

namespace tehl {
namespace {

using testing::Reduced;
using testing::RunReduced;

// Spread (max - min) / mean of h_c over the films in single contact (B..D), whose load is
// constant and whose R and um change by under 3 % there: a steady film would vary little.
double SingleContactSpread(const MeshCycleResult& r) {
  double lo = 1e9, hi = 0, sum = 0;
  int n = 0;
  for (const MeshCycleStep& st : r.steps)
    if (st.zone == "B-D" && st.s_m > r.s_b_m && st.s_m < r.s_d_m) {
      lo = std::min(lo, st.h_c_m);
      hi = std::max(hi, st.h_c_m);
      sum += st.h_c_m;
      ++n;
    }
  return n > 0 ? (hi - lo) / (sum / n) : 0.0;
}

// The static load just before B (the last step of A-B) over the load just after.
double StepAtB(const MeshCycleResult& r) {
  double before = 0, after = 0;
  for (const MeshCycleStep& st : r.steps) {
    if (st.zone == "A-B") before = st.static_load_n_per_m;
    if (st.zone == "B-D" && after == 0) after = st.static_load_n_per_m;
  }
  return after > 0 ? 1 - before / after : 1.0;
}

TEST(MeshCycleTipRelief, ReliefRemovesTheSqueezeTransientAfterB) {
  // Isothermal Newtonian films on 257 nodes and 60 steps for both runs.
  const MeshCycleResult relieved = RunReduced(
      "seed004_sae40_tip_relief", Reduced({{"steps", "60"}, {"non_newtonian", "false"}}));
  const MeshCycleResult plain = RunReduced("seed004_sae40", Reduced({{"steps", "60"}}));
  ASSERT_TRUE(relieved.converged());
  EXPECT_EQ(relieved.Restarts(), 0) << "a time step was restarted from the steady film";
  ASSERT_TRUE(plain.converged());
  EXPECT_EQ(plain.Restarts(), 0) << "a time step was restarted from the steady film";
  // docs/gear.md "Tip relief": without relief the share steps from 0.591 to 1 at B; with
  // 13 um over 2.3 mm from 0.965 (the last A-B step lies a little before B).
  EXPECT_GT(StepAtB(plain), 0.35);
  EXPECT_LT(StepAtB(relieved), 0.06);
  const double with = SingleContactSpread(relieved), without = SingleContactSpread(plain);
  EXPECT_LT(with, 0.04) << "h_c spread over B..D with relief";
  EXPECT_GT(without, 2 * with) << "h_c spread over B..D without relief";
}

TEST(MeshCycleTipRelief, AReliefThatLiftsThePairOffIsSolvedOnTheLoadedPart) {
  // 20 um on both tips exceeds the 14.1 / 14.2 um the other pairs close on their own at A and
  // E (docs/gear.md "Tip relief"): the films run from A' to E', where the pair carries 1 % of
  // F_bt (kMinFilmShare), and every step converges.
  const MeshCycleResult r =
      RunReduced("seed004_sae40_tip_relief",
                 Reduced({{"tip_relief_m", "20e-6"}, {"steps", "40"}, {"non_newtonian", "false"}}));
  ASSERT_TRUE(r.converged());
  EXPECT_EQ(r.Restarts(), 0) << "a time step was restarted from the steady film";
  EXPECT_GT(r.begin_m, 0.0);
  EXPECT_LT(r.begin_m, r.s_b_m);
  EXPECT_LT(r.end_m, r.length_m);
  EXPECT_GT(r.end_m, r.s_d_m);
  EXPECT_EQ(r.steps.front().s_m, r.begin_m);
  EXPECT_EQ(r.steps.back().s_m, r.end_m);
  const double nominal = r.w0_n_per_m;  // single contact at C: the whole F_bt / b
  EXPECT_NEAR(r.steps.front().static_load_n_per_m / nominal, 0.01, 1e-4);
  EXPECT_NEAR(r.steps.back().static_load_n_per_m / nominal, 0.01, 1e-4);
  for (const MeshCycleStep& st : r.steps) EXPECT_GT(st.h_min_m, 0.0);
}

}  // namespace
}  // namespace tehl
