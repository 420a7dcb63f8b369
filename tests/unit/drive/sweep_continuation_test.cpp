// Speed sweeps by continuation (src/drive/dynamic_sweep.cpp, docs/dynamics.md "Speed
// sweeps"): a periodic state restarts itself, continuation agrees with the static start where
// the response is unique, and around a jump the upward and downward sweeps follow two
// branches that both are periodic responses of the same speed.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "tehl/drive/dynamic_response.hpp"
#include "tehl/drive/dynamic_sweep.hpp"
#include "unit/drive/seed000_dynamics.hpp"

namespace tehl {
namespace {

using testing::ResonanceRpm;

std::vector<double> Speeds(double from, double to, int n) {
  std::vector<double> v;
  for (int i = 0; i < n; ++i) v.push_back(from + (to - from) * i / (n - 1));
  return v;
}

DynamicResponse Solve(const testing::Seed000Dynamics& d, double rpm, std::vector<double> start) {
  TorsionalParameters p = d.params;
  p.pinion_speed_rad_s = RpmToRadPerS(rpm);
  TorsionalModel m(*d.mesh, p);
  DynamicResponseOptions o;
  o.initial_state = std::move(start);
  return SolvePeriodicResponse(m, o);
}

TEST(SweepContinuation, APeriodicStateRestartsItself) {
  // Below the resonance, on the drive flanks: the periodic state at the end of a response is
  // on the orbit, and a response started there is periodic at once (the test needs two
  // periods) with the same load factor.
  testing::Seed000Dynamics d;
  const double rpm = 0.6 * ResonanceRpm(d);
  const DynamicResponse a = Solve(d, rpm, {});
  ASSERT_TRUE(a.periodic) << a.message;
  ASSERT_EQ(a.separated_fraction, 0.0);
  const DynamicResponse b = Solve(d, rpm, {a.end_x_m, a.end_v_m_s});
  ASSERT_TRUE(b.periodic) << b.message;
  EXPECT_EQ(b.periods, DynamicResponseOptions{}.min_periods);
  EXPECT_LT(b.periods, a.periods);
  // The first response stopped within about 1e-6 x_s of the orbit (its periodicity test);
  // the peak force moves by that order.
  EXPECT_NEAR(b.dynamic_load_factor / a.dynamic_load_factor, 1.0, 1e-5);
}

TEST(SweepContinuation, RefusesAStartThatIsNotAState) {
  testing::Seed000Dynamics d;
  const DynamicResponse r = Solve(d, 1000.0, {1e-6});
  EXPECT_FALSE(r.periodic);
  EXPECT_NE(r.message.find("initial_state"), std::string::npos) << r.message;
}

TEST(SweepContinuation, AgreesWithTheStaticStartWhereTheResponseIsUnique) {
  // Zero backlash and moderate damping: the drive and back flanks take over from each other
  // at x = 0 and the response is unique at every speed.
  testing::Seed000Dynamics d;
  d.params.backlash_m = 0;
  const double nr = ResonanceRpm(d);
  const std::vector<double> speeds = Speeds(0.6 * nr, 1.4 * nr, 21);
  const DynamicResponseOptions o;
  const std::vector<SweepPoint> a = SweepSpeeds(*d.mesh, d.params, speeds, o);
  const std::vector<SweepPoint> b =
      SweepSpeeds(*d.mesh, d.params, speeds, o, 1, SweepStart::kContinuation);
  ASSERT_EQ(a.size(), b.size());
  for (size_t i = 0; i < a.size(); ++i) {
    ASSERT_TRUE(a[i].periodic && b[i].periodic) << a[i].pinion_speed_rpm;
    EXPECT_NEAR(b[i].dynamic_load_factor / a[i].dynamic_load_factor, 1.0, 1e-4)
        << a[i].pinion_speed_rpm << " rpm";
  }
}

TEST(SweepContinuation, UpAndDownFollowTwoBranchesThroughTheJump) {
  // Light damping with backlash: the teeth separate near the resonance, a softening spring,
  // so the peak bends to lower speeds and ends in a jump (near 0.815 n_r for this pair);
  // below it the downward sweep, coming from above the jump, stays on the upper branch and
  // the upward sweep on the lower one. Both are periodic responses (the state repeats) of
  // the same speed.
  testing::Seed000Dynamics d;
  d.params.damping_ratio = 0.02;
  const double nr = ResonanceRpm(d);
  std::vector<double> speeds = {0.76 * nr, 0.78 * nr, 0.80 * nr, 0.86 * nr};
  const DynamicResponseOptions o;
  const std::vector<SweepPoint> up =
      SweepSpeeds(*d.mesh, d.params, speeds, o, 1, SweepStart::kContinuation);
  std::reverse(speeds.begin(), speeds.end());
  std::vector<SweepPoint> down =
      SweepSpeeds(*d.mesh, d.params, speeds, o, 1, SweepStart::kContinuation);
  std::reverse(down.begin(), down.end());
  for (size_t i = 0; i < up.size(); ++i)
    std::printf(
        "%8.1f rpm  up %.4f (%d, %d periods, separated %.3f)  down %.4f (%d, %d periods, "
        "separated %.3f)\n",
        up[i].pinion_speed_rpm, up[i].dynamic_load_factor, up[i].periodic, up[i].periods,
        up[i].separated_fraction, down[i].dynamic_load_factor, down[i].periodic, down[i].periods,
        down[i].separated_fraction);
  for (size_t i = 0; i + 1 < up.size(); ++i) {
    ASSERT_TRUE(up[i].periodic && down[i].periodic) << up[i].pinion_speed_rpm << " rpm";
    EXPECT_GT(down[i].dynamic_load_factor, 1.5 * up[i].dynamic_load_factor)
        << up[i].pinion_speed_rpm << " rpm";
    EXPECT_GT(down[i].separated_fraction, up[i].separated_fraction);
  }
  // Above the jump there is one branch, met by both.
  EXPECT_NEAR(up.back().dynamic_load_factor / down.back().dynamic_load_factor, 1.0, 1e-4);
}

}  // namespace
}  // namespace tehl
