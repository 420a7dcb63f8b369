// The back flanks in the torsional model (src/drive/torsional_model.cpp, docs/dynamics.md
// "Back flanks"): the coast flanks' own mesh, phase and base circles. Their phase against
// the gear core's coast offset, their force and its lever K = cos(alpha_tc) / cos(alpha_td)
// (seed 000 eq. 3.23) through an energy balance, the mode that tracks their segments
// backwards in time, and the convergence of a resonance that strikes them.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>

#include "tehl/drive/dynamic_response.hpp"
#include "tehl/drive/dynamic_sweep.hpp"
#include "tehl/gear/flank_phase.hpp"
#include "tehl/gear/potential_energy_stiffness.hpp"
#include "unit/drive/seed000_dynamics.hpp"

namespace tehl {
namespace {

// The seed 000 pair with 35/20 deg flanks (seed 000 section 7.3), potential-energy stiffness
// on each side, the back flanks on the coast side's mesh.
struct Asymmetric {
  Asymmetric()
      : pair(testing::Seed000Spec(35, 20)),
        coast(CoastSideSpec(pair.spec())),
        drive_model(PinionBlank(pair), WheelBlank(pair)),
        coast_model(PinionBlank(coast), WheelBlank(coast)),
        mesh(pair, AsPairStiffnessFn(drive_model)) {
    mesh.SetBackFlanks(std::make_shared<const TorsionalMesh>(coast, AsPairStiffnessFn(coast_model)),
                       CoastPhaseOffset(pair));
    params = testing::Seed000Dynamics().params;
    params.backlash_m = 0;
  }
  GearPair pair, coast;
  PotentialEnergyStiffness drive_model, coast_model;
  TorsionalMesh mesh;
  TorsionalParameters params;
};

TEST(BackFlanks, TheirPhaseRunsBackwardsFromTheCoastOffset) {
  const Asymmetric a;
  const TorsionalMesh& back = *a.mesh.back_flanks();
  const double pb = a.mesh.base_pitch_m(), pbc = back.base_pitch_m();
  // K of seed 000 eq. 3.23 with the transverse angles (spur: the normal ones).
  EXPECT_NEAR(a.mesh.back_ratio(), std::cos(DegToRad(20)) / std::cos(DegToRad(35)), 1e-12);
  EXPECT_NEAR(pbc / pb, a.mesh.back_ratio(), 1e-12);
  EXPECT_NEAR(back.contact_ratio(), a.pair.line(Flank::kCoast).contact_ratio, 1e-12);
  const double delta = CoastPhaseOffset(a.pair);
  for (int i = 0; i < 40; ++i) {
    const double phi = pb * (i + 0.37) / 40;
    const double q = a.mesh.BackPhase(phi);
    EXPECT_GE(q, 0.0);
    EXPECT_LT(q, pbc);
    EXPECT_NEAR(std::remainder(q / pbc + phi / pb - delta, 1.0), 0.0, 1e-12);
  }
}

TEST(BackFlanks, ForceIsTheCoastMeshClosedByKTimesTheDepthWithTheLeverK) {
  const Asymmetric a;
  const TorsionalMesh& back = *a.mesh.back_flanks();
  TorsionalParameters p = a.params;
  p.backlash_m = 20e-6;
  p.damping_ratio = 0;
  p.friction = FrictionLaw::kNone;
  const TorsionalModel m(a.mesh, p);
  const double k_ratio = a.mesh.back_ratio();
  for (int i = 0; i < 20; ++i) {
    const double phi = a.mesh.base_pitch_m() * (i + 0.5) / 20;
    const int seg = a.mesh.SegmentAt(phi);
    const double q = a.mesh.BackPhase(phi);
    for (double depth : {1e-6, 5e-6, 20e-6}) {
      const double x = -(p.backlash_m + depth);
      const double f_c = back.MeshStiffness(back.SegmentAt(q), q) * k_ratio * depth;
      EXPECT_NEAR(m.MeshForce(ContactState::kBackFlank, seg, phi, x, 0), -f_c, 1e-9 * f_c);
      // m_e x'' = F_s + K F_c without friction.
      EXPECT_NEAR(m.Acceleration(ContactState::kBackFlank, seg, phi, x, 0) * m.equivalent_mass_kg(),
                  m.static_force_n() + k_ratio * f_c, 1e-9 * k_ratio * f_c);
    }
  }
}

// Undamped, frictionless, constant stiffnesses k on the drive flanks and k_c on the back
// flanks: the force is the gradient of V = k x^2 / 2 (x > 0), K^2 k_c (x + b)^2 / 2 (x < -b),
// minus F_s x; energy is conserved through separations and back-flank strikes only when the
// back flanks close by K (-(x + b)) and push on x with the lever K.
TEST(BackFlanks, UndampedConstantMeshesConserveEnergyWithKSquared) {
  const Asymmetric a;
  const double k = 5e8, k_c = 7e8;
  TorsionalMesh mesh = TorsionalMesh::Constant(a.pair, k);
  mesh.SetBackFlanks(std::make_shared<const TorsionalMesh>(TorsionalMesh::Constant(a.coast, k_c)),
                     CoastPhaseOffset(a.pair));
  TorsionalParameters p = a.params;
  p.damping_ratio = 0;
  p.friction = FrictionLaw::kNone;
  p.pinion_speed_rad_s = RpmToRadPerS(3000.0);
  const double xs = p.pinion_torque_nm / mesh.pinion_base_radius_m() / k;
  // Started at 3 x_s the teeth leave the drive flanks with m_e v^2 / 2 = (9/2 - 3) k x_s^2
  // and fly F_s depth = 3/2 k x_s^2, 1.5 x_s deep: with b = x_s / 2 they strike the back
  // flanks every oscillation.
  p.backlash_m = 0.5 * xs;
  TorsionalModel m(mesh, p);
  const double kk = mesh.back_ratio() * mesh.back_ratio() * k_c, b = p.backlash_m;
  const auto energy = [&](double x, double v) {
    double pot = -m.static_force_n() * x;
    if (x > 0) pot += 0.5 * k * x * x;
    if (x < -b) pot += 0.5 * kk * (x + b) * (x + b);
    return 0.5 * m.equivalent_mass_kg() * v * v + pot;
  };
  std::vector<double> y = {3 * xs, 0.0};
  m.Reset(0.0, y[0], y[1]);
  const double e0 = energy(y[0], y[1]), scale = 0.5 * k * 9 * xs * xs;
  IntegratorOptions io;
  io.relative_tolerance = 1e-9;
  io.absolute_tolerance = {1e-9 * xs, 1e-9 * xs * std::sqrt(kk / m.equivalent_mass_kg())};
  DormandPrince54 dp(io);
  double worst = 0;
  long strikes = 0;
  const IntegratorSummary s =
      dp.Integrate(m, 0.0, 50 * m.mesh_period_s(), &y, [&](const DenseStep& st) {
        double z[2];
        st.Evaluate(st.t_end_s, z);
        worst = std::max(worst, std::abs(energy(z[0], z[1]) - e0) / scale);
        return true;
      });
  ASSERT_TRUE(s.usable()) << s.message;
  for (const auto& e : m.events()) strikes += e.to == ContactState::kBackFlank;
  EXPECT_GT(strikes, 20);
  EXPECT_LT(worst, 1e-6);
  std::printf("energy drift over 50 periods with %ld back-flank strikes: %.3g\n", strikes, worst);
}

TEST(BackFlanks, TheModeTracksTheirSegmentsBackwards) {
  const Asymmetric a;
  const TorsionalMesh& back = *a.mesh.back_flanks();
  TorsionalModel m(a.mesh, a.params);
  const double t0 = 0.3 * m.mesh_period_s();
  const double y[2] = {-2e-6, 1e-3};
  m.Reset(t0, y[0], y[1]);
  ASSERT_EQ(m.state(), ContactState::kBackFlank);
  double t = t0, yy[2] = {y[0], y[1]};
  int back_switches = 0;
  while (t < t0 + 3 * m.mesh_period_s()) {
    const double next = m.NextScheduledTime(t);
    ASSERT_GT(next, t);
    const double mid = 0.5 * (t + next);
    const double phi = m.phase_m(mid);
    // The tracked segment is the one holding the back phase, which moves backwards.
    EXPECT_EQ(m.back_segment(), back.SegmentAt(a.mesh.BackPhase(phi))) << "t " << mid;
    double d[2];
    m.Derivative(mid, yy, d);
    EXPECT_NEAR(d[1], m.Acceleration(m.state(), m.segment(), phi, yy[0], yy[1]),
                1e-9 * std::abs(d[1]));
    // At the step's end, on a switch of either mesh, the step's own back segment gives the
    // limit from inside the step: the force just before the end.
    const double inside = m.MeshForce(m.state(), m.segment(), m.back_segment(),
                                      m.phase_m(next - 1e-9 * (next - t)), yy[0], yy[1]);
    const double at_end =
        m.MeshForce(m.state(), m.segment(), m.back_segment(), m.phase_m(next), yy[0], yy[1]);
    EXPECT_NEAR(at_end, inside, 1e-6 * std::abs(inside)) << "t " << next;
    const int before = m.back_segment();
    m.Switch(-1, next, yy);
    back_switches += m.back_segment() != before;
    t = next;
  }
  // Every back segment is left once per period.
  EXPECT_NEAR(back_switches, 3 * static_cast<int>(back.segments().size()), 1);
}

TEST(BackFlanks, HalvingTheToleranceChangesAResonanceStrikingThemByLessThanHalfAPercent) {
  const Asymmetric a;
  TorsionalParameters p = a.params;
  TorsionalModel probe(a.mesh, p);
  p.pinion_speed_rad_s = 2 * kPi * probe.natural_frequency_hz() / a.pair.pinion().teeth;
  DynamicResponseOptions o;
  TorsionalModel m1(a.mesh, p), m2(a.mesh, p);
  const DynamicResponse r1 = SolvePeriodicResponse(m1, o);
  o.relative_tolerance *= 0.5;
  const DynamicResponse r2 = SolvePeriodicResponse(m2, o);
  ASSERT_TRUE(r1.periodic && r2.periodic) << r1.message << " / " << r2.message;
  EXPECT_GT(r1.back_flank_fraction, 0.05);  // the case does strike the back flanks
  EXPECT_NEAR(r2.peak_force_n / r1.peak_force_n, 1.0, 0.005);
  EXPECT_NEAR(r2.min_force_n / r1.min_force_n, 1.0, 0.005);
  std::printf("at %.0f rpm: DLF %.4f, min F %.1f N, back flank %.1f %% of the period\n",
              RadPerSToRpm(p.pinion_speed_rad_s), r1.dynamic_load_factor, r1.min_force_n,
              100 * r1.back_flank_fraction);
}

// Friction on the back flanks: with one inertia made huge, the change of x'' that friction
// makes isolates the torque on the other gear, T_f1 or T_f2. They must be those of the coast
// contacts, sum_j mu F_cj sgn(u1 - u2)_j rho_ij with rho_1c = T1cA_c + s_c, rho_2c = T1cT2c -
// rho_1c on the coast line of action (gear core) and u_i = w_i rho_ic, and their power on
// the gears, -T_f1 w1 + T_f2 w2 = -sum_j mu F_cj |u1 - u2|_j, dissipates.
TEST(BackFlanks, FrictionOnTheBackFlanksDissipatesAtTheCoastContacts) {
  const Asymmetric a;
  const LineOfAction& coast = a.pair.line(Flank::kCoast);
  const TorsionalMesh& back = *a.mesh.back_flanks();
  TorsionalParameters p = a.params;
  p.friction = FrictionLaw::kConstant;
  p.friction_coefficient = 0.1;
  p.damping_ratio = 0;
  const double w1 = p.pinion_speed_rad_s;
  const double w2 = w1 * a.pair.pinion().teeth / a.pair.wheel().teeth;
  const double rb1 = a.mesh.pinion_base_radius_m(), rb2 = a.mesh.wheel_base_radius_m();
  const double x = -4e-6;  // 4 um deep on the back flanks (b = 0)
  int checked = 0;
  for (int i = 0; i < 16; ++i) {
    const double phi = a.mesh.base_pitch_m() * (i + 0.5) / 16;
    const int seg = a.mesh.SegmentAt(phi);
    double torque[2];
    for (int gear = 0; gear < 2; ++gear) {
      TorsionalParameters q = p;
      (gear == 0 ? q.wheel_inertia_kg_m2 : q.pinion_inertia_kg_m2) *= 1e9;
      TorsionalParameters dry = q;
      dry.friction = FrictionLaw::kNone;
      const TorsionalModel with(a.mesh, q), without(a.mesh, dry);
      const double dxx = with.Acceleration(ContactState::kBackFlank, seg, phi, x, 0) -
                         without.Acceleration(ContactState::kBackFlank, seg, phi, x, 0);
      // dx'' = -(r_b1 T_f1 / J1 + r_b2 T_f2 / J2), the other term 1e9 times smaller.
      torque[gear] =
          gear == 0 ? -dxx * q.pinion_inertia_kg_m2 / rb1 : -dxx * q.wheel_inertia_kg_m2 / rb2;
    }
    // The coast contacts from the gear core's coast line.
    const TorsionalModel m(a.mesh, p);
    const double f_c = -m.MeshForce(ContactState::kBackFlank, seg, phi, x, 0);
    const double q = a.mesh.BackPhase(phi);
    const int bseg = back.SegmentAt(q);
    double tf1 = 0, tf2 = 0, dissipated = 0, k_sum = 0;
    for (int j = -2; j <= 3; ++j) {
      const double sc = q + j * coast.base_pitch_m;
      if (sc >= 0 && sc <= coast.length_m) k_sum += back.PairStiffness(sc);
    }
    for (int j = -2; j <= 3; ++j) {
      const double sc = q + j * coast.base_pitch_m;
      if (sc < 0 || sc > coast.length_m) continue;
      const double rho1 = coast.a_m + sc, rho2 = coast.tangent_length_m - rho1;
      const double u = w1 * rho1 - w2 * rho2;
      const double fj = f_c * back.PairStiffness(sc) / k_sum;
      tf1 += 0.1 * fj * (u > 0 ? 1 : -1) * rho1;
      tf2 += 0.1 * fj * (u > 0 ? 1 : -1) * rho2;
      dissipated += 0.1 * fj * std::abs(u);
    }
    (void)bseg;
    EXPECT_NEAR(torque[0], tf1, 1e-6 * std::abs(tf1) + 1e-9) << "phi " << phi;
    EXPECT_NEAR(torque[1], tf2, 1e-6 * std::abs(tf2) + 1e-9) << "phi " << phi;
    const double power = -torque[0] * w1 + torque[1] * w2;
    EXPECT_LT(power, 0.0) << "phi " << phi;
    EXPECT_NEAR(power, -dissipated, 1e-6 * dissipated) << "phi " << phi;
    ++checked;
  }
  EXPECT_EQ(checked, 16);
}

// At zero backlash without corner contact the mesh is a piecewise-linear spring whose two
// sides (drive and coast flanks) vary with their own phases: near its resonance that
// parametric excitation can pump energy in faster than the damping takes it out, and with
// nothing to bound the amplitude the response grows without bound. The solve stops and says
// so. With the back flanks on the drive flanks' mesh at its own phase (one k(t) on both
// sides: a linear system with a time-varying stiffness) only the narrower Mathieu zone of
// that linear system grows (here 1.00 and 1.02 n_r at zeta = 0.02).
TEST(BackFlanks, APumpedPiecewiseLinearMeshIsReportedAsGrowingWithoutBound) {
  const Asymmetric a;
  TorsionalParameters p = a.params;
  p.damping_ratio = 0.02;
  const TorsionalModel probe(a.mesh, p);
  const double nr = 60.0 * probe.natural_frequency_hz() / a.pair.pinion().teeth;
  TorsionalMesh linear(a.pair, AsPairStiffnessFn(a.drive_model));
  int diverged = 0, only_piecewise = 0;
  for (int i = 0; i <= 20; ++i) {
    p.pinion_speed_rad_s = RpmToRadPerS((0.9 + 0.02 * i) * nr);
    TorsionalModel m(a.mesh, p);
    const DynamicResponse r = SolvePeriodicResponse(m, DynamicResponseOptions{});
    if (!r.diverged) continue;
    ++diverged;
    EXPECT_FALSE(r.periodic);
    EXPECT_NE(r.message.find("grows without bound"), std::string::npos) << r.message;
    EXPECT_LT(r.periods, DynamicResponseOptions{}.max_periods);  // stopped, not run out
    TorsionalModel l(linear, p);
    const DynamicResponse rl = SolvePeriodicResponse(l, DynamicResponseOptions{});
    only_piecewise += rl.periodic;
    std::printf("%.2f n_r: %s; one k(t) on both sides: %s\n", 0.9 + 0.02 * i, r.message.c_str(),
                rl.message.c_str());
  }
  EXPECT_GT(diverged, 0);
  EXPECT_GE(only_piecewise, 3);

  // Out of periods before 1000 static deflections, still growing: named as growing too (at
  // 1.06 n_r the size passes 1000 x_s after about 40 periods; 24 periods stop short of it).
  p.pinion_speed_rad_s = RpmToRadPerS(1.06 * nr);
  DynamicResponseOptions short_run;
  short_run.max_periods = 24;
  TorsionalModel m(a.mesh, p);
  const DynamicResponse r = SolvePeriodicResponse(m, short_run);
  EXPECT_TRUE(r.diverged) << r.message;
  EXPECT_NE(r.message.find("still growing after 24 mesh periods"), std::string::npos) << r.message;
  // A bounded response that is not periodic within its periods is not growing.
  p.pinion_speed_rad_s = RpmToRadPerS(0.96 * nr);
  TorsionalModel b(a.mesh, p);
  const DynamicResponse rb = SolvePeriodicResponse(b, DynamicResponseOptions{});
  EXPECT_FALSE(rb.periodic) << rb.message;
  EXPECT_FALSE(rb.diverged) << rb.message;

  // A continuation sweep hands nothing on from a speed that grows without bound: the next
  // speed starts from the static deflection, as a static sweep's does.
  p.pinion_speed_rad_s = 0;
  const std::vector<double> speeds = {1.16 * nr, 1.18 * nr};
  const std::vector<SweepPoint> cont =
      SweepSpeeds(a.mesh, p, speeds, DynamicResponseOptions{}, 1, SweepStart::kContinuation);
  const std::vector<SweepPoint> stat = SweepSpeeds(a.mesh, p, speeds, DynamicResponseOptions{});
  ASSERT_TRUE(cont[0].diverged);
  EXPECT_EQ(cont[1].dynamic_load_factor, stat[1].dynamic_load_factor);
}

}  // namespace
}  // namespace tehl
