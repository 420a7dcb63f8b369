// Dynamic load factor against speed for the seed 000 pair: main resonance where the mesh
// frequency meets the natural frequency, super-harmonic peaks below it, tooth separation
// with light damping, and contact-loss times against an independent bisection reference.
#include "tehl/drive/dynamic_sweep.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "tehl/drive/dynamic_response.hpp"
#include "unit/drive/seed000_dynamics.hpp"

namespace tehl {
namespace {

using testing::ResonanceRpm;

std::vector<double> Speeds(double from, double to, double step) {
  std::vector<double> v;
  for (double n = from; n <= to + 1e-9; n += step) v.push_back(n);
  return v;
}

// Index of the largest DLF among points with speed in [lo, hi].
size_t PeakIn(const std::vector<SweepPoint>& s, double lo, double hi) {
  size_t best = s.size();
  for (size_t i = 0; i < s.size(); ++i)
    if (s[i].pinion_speed_rpm >= lo && s[i].pinion_speed_rpm <= hi &&
        (best == s.size() || s[i].dynamic_load_factor > s[best].dynamic_load_factor))
      best = i;
  return best;
}

TEST(DynamicSweep, MainPeakWhereTheMeshFrequencyMeetsTheNaturalFrequency) {
  // The largest DLF of the sweep lies within one sweep step of n = 60 f_n / z1 (f_n from the
  // period-mean stiffness). Zero backlash makes the force law linear (the back flank takes
  // over at x = 0), so the softening of contact loss (the peak bends to lower speeds, with
  // a jump, when the teeth separate; docs/dynamics.md) does not shift it.
  testing::Seed000Dynamics d;
  d.params.damping_ratio = 0.05;
  d.params.backlash_m = 0.0;
  const double nr = ResonanceRpm(d);
  const double step = 0.02 * nr;
  const std::vector<SweepPoint> s =
      SweepSpeeds(*d.mesh, d.params, Speeds(0.6 * nr, 1.4 * nr, step), DynamicResponseOptions{});
  const size_t peak = PeakIn(s, 0, 1e9);
  for (const auto& p : s)
    std::printf("%8.1f rpm  DLF %.4f  pair %.4f  sep %.3f  periodic %d (%d)\n", p.pinion_speed_rpm,
                p.dynamic_load_factor, p.pair_load_factor, p.separated_fraction, p.periodic,
                p.periods);
  std::printf("resonance %.1f rpm, peak at %.1f rpm\n", nr, s[peak].pinion_speed_rpm);
  EXPECT_LE(std::abs(s[peak].pinion_speed_rpm - nr), step * (1 + 1e-9));  // grid rounding
  EXPECT_GT(s[peak].dynamic_load_factor, 1.2);
}

TEST(DynamicSweep, SuperHarmonicPeaksAtHalfAndAThirdOfTheResonanceSpeed) {
  // The mesh stiffness is a rectangular-ish wave (seed 000 Fig. 4.19): its harmonics 2 f_m
  // and 3 f_m meet f_n at n_r / 2 and n_r / 3, where the DLF has local maxima above the
  // speeds 10 % away on either side. Zero backlash, as above.
  testing::Seed000Dynamics d;
  d.params.damping_ratio = 0.05;
  d.params.backlash_m = 0.0;
  const double nr = ResonanceRpm(d);
  for (int h : {2, 3}) {
    const double n0 = nr / h, step = 0.02 * n0;
    const std::vector<SweepPoint> s =
        SweepSpeeds(*d.mesh, d.params, Speeds(0.8 * n0, 1.2 * n0, step), DynamicResponseOptions{});
    const size_t peak = PeakIn(s, 0.9 * n0, 1.1 * n0);
    for (const auto& p : s)
      std::printf("h%d %8.1f rpm  DLF %.4f\n", h, p.pinion_speed_rpm, p.dynamic_load_factor);
    ASSERT_LT(peak, s.size());
    EXPECT_NEAR(s[peak].pinion_speed_rpm, n0, 0.05 * n0) << "harmonic " << h;
    EXPECT_GT(s[peak].dynamic_load_factor, s.front().dynamic_load_factor) << "harmonic " << h;
    EXPECT_GT(s[peak].dynamic_load_factor, s.back().dynamic_load_factor) << "harmonic " << h;
  }
}

TEST(DynamicSweep, LightDampingSeparatesTheTeethNearResonance) {
  // zeta = 0.02 at the resonance speed: the mesh force is 0 for part of the period (seed 000
  // ch. 6: "at high speed there are intervals where the teeth separate, giving F = 0").
  testing::Seed000Dynamics d;
  d.params.damping_ratio = 0.02;
  d.params.pinion_speed_rad_s = RpmToRadPerS(ResonanceRpm(d));
  TorsionalModel m(*d.mesh, d.params);
  const DynamicResponse r = SolvePeriodicResponse(m, DynamicResponseOptions{});
  std::printf("%s; sep %.3f back %.3f min %.3g peak %.3g\n", r.message.c_str(),
              r.separated_fraction, r.back_flank_fraction, r.min_force_n, r.peak_force_n);
  EXPECT_GT(r.separated_fraction, 0.01);
  EXPECT_FALSE(r.contact_loss_times_s.empty());
  // The teeth part (50 um of backlash) but never strike the back flanks: the smallest contact
  // force is 0, not the damper's pull at the instant of parting (x = 0, x' < 0).
  ASSERT_EQ(r.back_flank_fraction, 0.0);
  EXPECT_EQ(r.min_force_n, 0.0);
  int zero = 0;
  for (const DynamicSample& s : r.samples)
    zero += s.state == ContactState::kSeparated && s.force_n == 0;
  EXPECT_GT(zero, 0);
}

// x(T) in drive-flank contact from (t0, y0) by classical RK4 with n steps, in one segment.
double DriveFlankX(
    const TorsionalModel& m, int seg, long period, double t0, const double* y0, double t1, int n) {
  double x = y0[0], v = y0[1];
  const double h = (t1 - t0) / n;
  auto acc = [&](double t, double xx, double vv) {
    return m.Acceleration(ContactState::kDriveFlank, seg, m.PhaseAt(period, t), xx, vv);
  };
  for (int i = 0; i < n; ++i) {
    const double t = t0 + i * h;
    const double k1x = v, k1v = acc(t, x, v);
    const double k2x = v + 0.5 * h * k1v, k2v = acc(t + 0.5 * h, x + 0.5 * h * k1x, k2x);
    const double k3x = v + 0.5 * h * k2v, k3v = acc(t + 0.5 * h, x + 0.5 * h * k2x, k3x);
    const double k4x = v + h * k3v, k4v = acc(t + h, x + h * k3x, k4x);
    x += h / 6 * (k1x + 2 * k2x + 2 * k3x + k4x);
    v += h / 6 * (k1v + 2 * k2v + 2 * k3v + k4v);
  }
  return x;
}

TEST(DynamicSweep, ContactLossTimesMatchABisectionReference) {
  // For each contact loss of the periodic response: from the start of the step in which it
  // happened (state and mode known), integrate the drive-flank equations with fine fixed-step
  // RK4 and bisect on the end time for x = 0. The located times agree to 1e-7 of a period.
  testing::Seed000Dynamics d;
  d.params.damping_ratio = 0.02;
  d.params.friction = FrictionLaw::kBuckingham;
  d.params.pinion_speed_rad_s = RpmToRadPerS(ResonanceRpm(d));
  TorsionalModel m(*d.mesh, d.params);
  const DynamicResponse r = SolvePeriodicResponse(m, DynamicResponseOptions{});
  ASSERT_FALSE(r.contact_loss_times_s.empty()) << r.message;
  const long period = std::lround(r.period_start_s / r.mesh_period_s);
  for (double tl : r.contact_loss_times_s) {
    const double te = r.period_start_s + tl;
    const auto it = std::find_if(r.steps.begin(), r.steps.end(), [&](const auto& st) {
      return st.state == ContactState::kDriveFlank && std::abs(st.dense.t_end_s - te) < 1e-15;
    });
    ASSERT_NE(it, r.steps.end());
    const double t0 = it->dense.t0_s;
    double y0[2];
    it->dense.Evaluate(t0, y0);
    ASSERT_GT(y0[0], 0.0);
    double lo = t0, hi = t0 + 2 * (te - t0);
    const double seg_end =
        (period * d.mesh->base_pitch_m() + d.mesh->segments()[it->segment].end_m) /
        m.contact_speed_m_s();
    hi = std::min(hi, seg_end);
    ASSERT_LT(DriveFlankX(m, it->segment, period, t0, y0, hi, 4000), 0.0);
    for (int i = 0; i < 60; ++i) {
      const double mid = 0.5 * (lo + hi);
      (DriveFlankX(m, it->segment, period, t0, y0, mid, 4000) > 0 ? lo : hi) = mid;
    }
    EXPECT_NEAR(te, 0.5 * (lo + hi), 1e-7 * r.mesh_period_s);
  }
}

}  // namespace
}  // namespace tehl
