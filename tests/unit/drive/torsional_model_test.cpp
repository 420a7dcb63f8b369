// TorsionalModel: friction law in SI, frequencies, the static limit (with and without
// friction), energy conservation, tolerance independence and event location.
#include "tehl/drive/torsional_model.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "tehl/drive/dynamic_response.hpp"
#include "unit/drive/seed000_dynamics.hpp"

namespace tehl {
namespace {

TEST(BuckinghamFriction, SiFormMatchesTheInchValuesOfSeed000) {
  // Seed 000 eq. 4.10 with V in in/s; extraction section 7.3 evaluates it: f(0) = 0.0500,
  // f(1) = 0.0461, f(10) = 0.0206, f(50) = 0.0142, f(100) = 0.0200, f(200) = 0.0283.
  const double in_s = 0.0254;  // m/s per in/s
  EXPECT_NEAR(BuckinghamFriction(0.0), 0.0500, 5e-5);
  EXPECT_NEAR(BuckinghamFriction(1 * in_s), 0.0461, 5e-5);
  EXPECT_NEAR(BuckinghamFriction(10 * in_s), 0.0206, 5e-5);
  EXPECT_NEAR(BuckinghamFriction(50 * in_s), 0.0142, 5e-5);
  EXPECT_NEAR(BuckinghamFriction(100 * in_s), 0.0200, 5e-5);
  EXPECT_NEAR(BuckinghamFriction(-200 * in_s), 0.0283, 5e-5);  // |V|
}

TEST(TorsionalModel, MeshFrequencyOfTheSeed000PairAt1000Rpm) {
  // 36 teeth x 1000/60 rev/s = 600 Hz (seed 000 extraction section 7.3).
  testing::Seed000Dynamics d;
  d.params.pinion_speed_rad_s = RpmToRadPerS(1000.0);
  const TorsionalModel m(*d.mesh, d.params);
  EXPECT_NEAR(m.mesh_frequency_hz(), 600.0, 1e-9);
  EXPECT_NEAR(1.0 / m.mesh_period_s(), 600.0, 1e-9);
  // Equivalent mass of x = r_b1 th1 - r_b2 th2 for equal gears: J / (2 r_b^2).
  const double rb = d.mesh->pinion_base_radius_m();
  EXPECT_NEAR(m.equivalent_mass_kg(), d.params.pinion_inertia_kg_m2 / (2 * rb * rb), 1e-12);
  // The two-inertia system's non-zero eigenvalue (theta1, theta2 coupled by k on the line of
  // action, a rigid-body mode at 0): w^2 = k (r_b1^2 / J1 + r_b2^2 / J2).
  const double rb2 = d.mesh->wheel_base_radius_m();
  const double w2 = d.mesh->mean_stiffness_n_per_m() * (rb * rb / d.params.pinion_inertia_kg_m2 +
                                                        rb2 * rb2 / d.params.wheel_inertia_kg_m2);
  EXPECT_NEAR(m.natural_frequency_hz(), std::sqrt(w2) / (2 * M_PI), 1e-9 * std::sqrt(w2));
}

TEST(TorsionalModel, FlanksInContactPushAndNeverPull) {
  // A contact force is compressive: k x + c x' on the drive flanks (x > 0) when that is
  // positive, and 0 while the flanks part faster than the teeth spring back (c x' < -k x);
  // on the back flanks the mirror image. Seed 000 eqs. 4.37-4.42 give k x + c x' with the
  // contact state set by x alone, which would let the damper pull the flanks together.
  testing::Seed000Dynamics d;
  d.params.damping_ratio = 0.1;
  const TorsionalModel m(*d.mesh, d.params);
  const double c = m.damping_n_s_per_m(), k = d.mesh->MeshStiffness(0, 0.0);
  const double x = 1e-6, v_pull = -2.0 * k * x / c;
  EXPECT_GT(m.MeshForce(ContactState::kDriveFlank, 0, 0.0, x, 0.0), 0.0);
  EXPECT_EQ(m.MeshForce(ContactState::kDriveFlank, 0, 0.0, x, v_pull), 0.0);
  const double xb = -(d.params.backlash_m + x);
  EXPECT_LT(m.MeshForce(ContactState::kBackFlank, 0, 0.0, xb, 0.0), 0.0);
  EXPECT_EQ(m.MeshForce(ContactState::kBackFlank, 0, 0.0, xb, -v_pull), 0.0);
  // Closing flanks: the damper adds to the spring.
  EXPECT_NEAR(m.MeshForce(ContactState::kDriveFlank, 0, 0.0, x, 1e-3), k * x + c * 1e-3,
              1e-9 * (k * x + c * 1e-3));
}

TEST(TorsionalParameters, RejectsEachInvalidValue) {
  testing::Seed000Dynamics d;
  EXPECT_TRUE(d.params.Validate().empty());
  auto bad = [&](auto edit) {
    TorsionalParameters p = d.params;
    edit(p);
    return !p.Validate().empty();
  };
  EXPECT_TRUE(bad([](TorsionalParameters& p) { p.pinion_inertia_kg_m2 = 0; }));
  EXPECT_TRUE(bad([](TorsionalParameters& p) { p.wheel_inertia_kg_m2 = -1; }));
  EXPECT_TRUE(bad([](TorsionalParameters& p) { p.pinion_torque_nm = 0; }));
  EXPECT_TRUE(bad([](TorsionalParameters& p) { p.damping_ratio = 1.0; }));
  EXPECT_TRUE(bad([](TorsionalParameters& p) { p.backlash_m = -1e-6; }));
  EXPECT_TRUE(bad([](TorsionalParameters& p) { p.friction_coefficient = 1.2; }));
}

// Phases at least 1 % of the base pitch after every segment start: the free vibration
// started by a stiffness jump decays within exp(-zeta w_n t); at 1 rpm the 1 % window lasts
// 17 ms, 80 undamped periods of the mesh mode, e^(-0.05 * 2 pi * 80) = 1e-11.
std::vector<double> QuietPhases(const TorsionalMesh& mesh) {
  std::vector<double> out;
  for (int i = 0; i < 400; ++i) {
    const double phase = mesh.base_pitch_m() * (i + 0.5) / 400;
    const MeshSegment& seg = mesh.segments()[mesh.SegmentAt(phase)];
    if (phase - seg.begin_m > 0.01 * mesh.base_pitch_m()) out.push_back(phase);
  }
  return out;
}

TEST(TorsionalModel, AtVeryLowSpeedTheDynamicLoadIsTheStaticLoadSharing) {
  // Without friction the quasi-static mesh force is T_m / r_b1, and the tracked pair's load
  // is its stiffness share of it (load_sharing.hpp, kStiffness): within 1 %.
  testing::Seed000Dynamics d;
  d.params.pinion_speed_rad_s = RpmToRadPerS(1.0);
  TorsionalModel m(*d.mesh, d.params);
  const DynamicResponse r = SolvePeriodicResponse(m, DynamicResponseOptions{});
  ASSERT_TRUE(r.periodic) << r.message;
  for (double phase : QuietPhases(*d.mesh))
    EXPECT_NEAR(r.ForceAt(phase, false) / r.static_force_n, 1.0, 0.01) << "phase " << phase;
  int compared = 0;
  for (const PairLoadPoint& p : TrackedPairLoad(r, d.pair.spec().face_width_m, 401)) {
    const double phase = std::fmod(p.s_m, d.mesh->base_pitch_m());
    const MeshSegment& seg = d.mesh->segments()[d.mesh->SegmentAt(phase)];
    if (phase - seg.begin_m < 0.01 * d.mesh->base_pitch_m()) continue;
    EXPECT_NEAR(p.dynamic_n_per_m, p.static_n_per_m, 0.01 * p.static_n_per_m) << "s " << p.s_m;
    ++compared;
  }
  EXPECT_GT(compared, 300);
}

TEST(TorsionalModel, AtVeryLowSpeedFrictionShiftsTheForceAsTheStaticBalanceSays) {
  // Quasi-static balance with friction (x'' = 0 in the equation of the header, T_f linear in
  // F): F = [r_b1 T_m / J1 + r_b2 T_L / J2] / [1/m_e + sum_j mu share_j sgn_j (r_b1 rho1_j / J1
  // + r_b2 rho2_j / J2)], derived here by hand from seed 000 eqs. 4.1-4.2. Constant mu = 0.1.
  testing::Seed000Dynamics d;
  d.params.pinion_speed_rad_s = RpmToRadPerS(1.0);
  d.params.friction = FrictionLaw::kConstant;
  d.params.friction_coefficient = 0.1;
  TorsionalModel m(*d.mesh, d.params);
  const DynamicResponse r = SolvePeriodicResponse(m, DynamicResponseOptions{});
  ASSERT_TRUE(r.periodic) << r.message;
  const TorsionalMesh& mesh = *d.mesh;
  const double rb1 = mesh.pinion_base_radius_m(), rb2 = mesh.wheel_base_radius_m();
  const double j1 = d.params.pinion_inertia_kg_m2, j2 = d.params.wheel_inertia_kg_m2;
  const double tm = d.params.pinion_torque_nm, tl = tm * rb2 / rb1;
  double max_shift = 0;
  for (double phase : QuietPhases(mesh)) {
    const int seg = mesh.SegmentAt(phase);
    const MeshSegment& sg = mesh.segments()[seg];
    double den = 1.0 / m.equivalent_mass_kg();
    for (size_t j = 0; j < sg.pairs.size(); ++j) {
      const double s = phase + sg.pairs[j] * mesh.base_pitch_m();
      const double sgn = s > mesh.pitch_point_m() ? 1.0 : -1.0;
      den += 0.1 * mesh.PairShare(seg, static_cast<int>(j), phase) * sgn *
             (rb1 * mesh.Rho1(s) / j1 + rb2 * mesh.Rho2(s) / j2);
    }
    const double f_ref = (rb1 * tm / j1 + rb2 * tl / j2) / den;
    EXPECT_NEAR(r.ForceAt(phase, false) / f_ref, 1.0, 0.01) << "phase " << phase;
    max_shift = std::max(max_shift, std::abs(f_ref / r.static_force_n - 1.0));
  }
  EXPECT_GT(max_shift, 0.02);  // friction does change the force: the test can fail
}

// Energy of the undamped frictionless model, m_e x'' = F_s - F(x):
// E = m_e v^2 / 2 + V(x), V = k x^2 / 2 - F_s x (x > 0), -F_s x (-b <= x <= 0),
// k (x + b)^2 / 2 - F_s x (x < -b).
double Energy(const TorsionalModel& m, double k, double x, double v) {
  const double b = m.parameters().backlash_m, fs = m.static_force_n();
  double pot = -fs * x;
  if (x > 0) pot += 0.5 * k * x * x;
  if (x < -b) pot += 0.5 * k * (x + b) * (x + b);
  return 0.5 * m.equivalent_mass_kg() * v * v + pot;
}

// Largest |E - E0| / (k (3 x_s)^2 / 2) over n_periods of the undamped frictionless model with
// constant stiffness, started at 3 static deflections, at integrator tolerance rtol.
double EnergyDrift(double rtol, int n_periods, long* events) {
  testing::Seed000Dynamics d;
  const double k = 5e8;
  const TorsionalMesh mesh = TorsionalMesh::Constant(d.pair, k);
  d.params.damping_ratio = 0.0;
  d.params.pinion_speed_rad_s = RpmToRadPerS(3000.0);
  TorsionalModel m(mesh, d.params);
  const double xs = m.static_force_n() / k;
  std::vector<double> y = {3 * xs, 0.0};
  m.Reset(0.0, y[0], y[1]);
  const double e0 = Energy(m, k, y[0], y[1]), scale = 0.5 * k * 9 * xs * xs;
  IntegratorOptions io;
  io.relative_tolerance = rtol;
  io.absolute_tolerance = {rtol * xs, rtol * xs * std::sqrt(k / m.equivalent_mass_kg())};
  DormandPrince54 dp(io);
  double worst = 0;
  const IntegratorSummary s =
      dp.Integrate(m, 0.0, n_periods * m.mesh_period_s(), &y, [&](const DenseStep& st) {
        double z[2];
        st.Evaluate(st.t_end_s, z);
        worst = std::max(worst, std::abs(Energy(m, k, z[0], z[1]) - e0) / scale);
        return true;
      });
  EXPECT_TRUE(s.usable()) << s.message;
  *events = s.state_events;
  return worst;
}

TEST(TorsionalModel, UndampedConstantStiffnessConservesEnergyThroughSeparations) {
  // Started at 3 static deflections the tooth leaves the drive flank once per oscillation
  // (amplitude 2 x_s about x_s) and comes back: energy is conserved to 1e-6 of its scale
  // over 100 mesh periods, and the drift falls with the tolerance (it is the integrator's
  // truncation error, not a jump at the located contact loss and regain).
  long events = 0;
  const double coarse = EnergyDrift(1e-8, 100, &events);
  const double fine = EnergyDrift(1e-9, 100, &events);
  EXPECT_GT(events, 100);  // it did separate, many times
  EXPECT_LT(fine, 1e-6);
  EXPECT_LT(fine, 0.5 * coarse);
  std::printf("energy drift over 100 periods: %.3g (rtol 1e-8), %.3g (rtol 1e-9)\n", coarse, fine);
}

TEST(TorsionalModel, HalvingTheToleranceChangesThePeakLoadByLessThanHalfAPercent) {
  testing::Seed000Dynamics d;
  d.params.pinion_speed_rad_s = RpmToRadPerS(5000.0);
  DynamicResponseOptions o;
  TorsionalModel m1(*d.mesh, d.params);
  const DynamicResponse r1 = SolvePeriodicResponse(m1, o);
  o.relative_tolerance *= 0.5;
  TorsionalModel m2(*d.mesh, d.params);
  const DynamicResponse r2 = SolvePeriodicResponse(m2, o);
  ASSERT_TRUE(r1.periodic && r2.periodic) << r1.message << " / " << r2.message;
  EXPECT_NEAR(r2.peak_force_n / r1.peak_force_n, 1.0, 0.005);
  EXPECT_GT(r1.dynamic_load_factor, 1.05);  // a dynamic case, not the static limit
}

}  // namespace
}  // namespace tehl
