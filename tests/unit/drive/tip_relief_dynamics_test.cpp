// Tip relief in the torsional model (torsional_mesh.hpp, docs/gear.md "Tip relief"): the
// static balance against the gear layer, the quasi-static limit, and the classic result that
// a long relief sized for the load makes the mesh force constant at any speed.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "tehl/drive/dynamic_response.hpp"
#include "tehl/drive/torsional_model.hpp"
#include "tehl/units.hpp"
#include "unit/drive/seed000_dynamics.hpp"

namespace tehl {
namespace {

TEST(TipReliefDynamics, StaticApproachBalancesTheForceAndMatchesTheGearLayer) {
  testing::Seed000Dynamics d;
  const PairStiffnessFn k = AsPairStiffnessFn(*d.model);
  const PathOfContact path(d.pair, d.params.pinion_speed_rad_s);
  const double force = d.params.pinion_torque_nm / d.mesh->pinion_base_radius_m();
  const double x0 = force / d.mesh->MeshStiffness(0, 0.0);  // double contact, no relief
  TipRelief r;
  r.wheel_amount_m = r.pinion_amount_m = 1.5 * x0;
  r.wheel_length_m = r.pinion_length_m = 0.6 * path.s_b_m();
  const TorsionalMesh mesh(d.pair, k, 33, r);
  int compared = 0;
  for (int i = 1; i < 40; ++i) {
    const double s = path.length_m() * i / 40;
    const double x = mesh.StaticApproachAt(s, false, force);
    int seg = mesh.SegmentAt(std::fmod(s, mesh.base_pitch_m()));
    const double phase = std::fmod(s, mesh.base_pitch_m());
    EXPECT_NEAR(mesh.ElasticForce(seg, phase, x), force, 1e-9 * force) << "s = " << s;
    // The gear layer with the exact pair stiffness; the mesh interpolates it (Chebyshev).
    const RelievedShare g = RelievedLoadShare(path, s, k, r, force);
    EXPECT_NEAR(mesh.ShareAt(s, false, x), g.share, 2e-3) << "s = " << s;
    EXPECT_NEAR(x, g.approach_m, 2e-3 * g.approach_m) << "s = " << s;
    ++compared;
  }
  EXPECT_EQ(compared, 39);
}

TEST(TipReliefDynamics, AtVeryLowSpeedTheDynamicLoadIsTheRelievedStaticLoad) {
  // 1 rpm, quasi-static: the tracked pair's dynamic load is its relieved static load to 1 %
  // away from the first 1 % of the period after each stiffness jump (the transient there
  // decays, see torsional_model_test.cpp), and the relief has unloaded the pair near A.
  testing::Seed000Dynamics d;
  d.params.pinion_speed_rad_s = RpmToRadPerS(1.0);
  const PathOfContact path(d.pair, 1.0);
  const double force = d.params.pinion_torque_nm / d.mesh->pinion_base_radius_m();
  TipRelief r;
  r.wheel_amount_m = r.pinion_amount_m = 1.5 * force / d.mesh->MeshStiffness(0, 0.0);
  r.wheel_length_m = r.pinion_length_m = 0.6 * path.s_b_m();
  const TorsionalMesh mesh(d.pair, AsPairStiffnessFn(*d.model), 33, r);
  TorsionalModel m(mesh, d.params);
  const DynamicResponse resp = SolvePeriodicResponse(m, DynamicResponseOptions{});
  ASSERT_TRUE(resp.periodic) << resp.message;
  const auto loads = TrackedPairLoad(resp, d.pair.spec().face_width_m, 401);
  ASSERT_FALSE(loads.empty());
  EXPECT_LT(loads.front().share, d.mesh->ShareAt(0.0, false) - 0.2);  // relieved at A
  int compared = 0;
  for (const PairLoadPoint& p : loads) {
    const double phase = std::fmod(p.s_m, mesh.base_pitch_m());
    const MeshSegment& seg = mesh.segments()[mesh.SegmentAt(phase)];
    if (phase - seg.begin_m < 0.01 * mesh.base_pitch_m() || p.static_n_per_m <= 0) continue;
    EXPECT_NEAR(p.dynamic_n_per_m, p.static_n_per_m, 0.01 * p.static_n_per_m) << "s " << p.s_m;
    ++compared;
  }
  EXPECT_GT(compared, 250);
}

TEST(TipReliefDynamics, ALongReliefSizedForTheLoadMakesTheMeshForceConstant) {
  // Equal pair stiffness k and a linear relief C = F/k on both tips over the whole
  // double-contact length L = g - p_b: in double contact the gaps sum to C, so the approach
  // (F/k + C)/2 = F/k is the single-contact one, and x = F/k is an equilibrium at every
  // phase: the static transmission error is flat. Where that equilibrium is stable the mesh
  // force stays F; without relief the stiffness step excites the mesh (DLF 1.4-3.7 here).
  // The stiffness of the relieved mesh about x = F/k still alternates between 2k and k, so
  // at light damping the Mathieu zones (mesh frequency 2 w_n / n) can destabilize it: at
  // zeta = 0.02 and the principal zone (n = 1) it is.
  testing::Seed000Dynamics d;
  const double k = 2e8;
  const PairStiffnessFn constant = [k](double, double) { return k; };
  const PathOfContact path(d.pair, 1.0);
  const double force = d.params.pinion_torque_nm / d.mesh->pinion_base_radius_m();
  TipRelief r;
  r.wheel_amount_m = r.pinion_amount_m = force / k;
  r.wheel_length_m = r.pinion_length_m = path.length_m() - path.base_pitch_m();
  const TorsionalMesh relieved(d.pair, constant, 33, r), plain(d.pair, constant, 33);
  for (int i = 0; i <= 40; ++i) {
    const double s = path.length_m() * i / 40;
    EXPECT_NEAR(relieved.StaticApproachAt(s, false, force), force / k, 1e-12 * force / k);
  }
  // Speeds as ratios of the mesh frequency z1 n to the natural frequency of the mean stiffness.
  auto at = [&](double ratio, double zeta, const TorsionalMesh& mesh) {
    TorsionalParameters p = d.params;
    p.damping_ratio = zeta;
    const TorsionalModel probe(plain, p);
    p.pinion_speed_rad_s *= ratio * probe.natural_frequency_hz() / probe.mesh_frequency_hz();
    TorsionalModel model(mesh, p);
    return SolvePeriodicResponse(model, DynamicResponseOptions{});
  };
  for (double ratio : {0.5, 0.85, 1.0, 2.0}) {
    const DynamicResponse rw = at(ratio, 0.1, relieved);
    ASSERT_TRUE(rw.periodic) << rw.message;
    EXPECT_NEAR(rw.dynamic_load_factor, 1.0, 1e-3) << "ratio " << ratio;
    EXPECT_NEAR(rw.min_force_n / rw.static_force_n, 1.0, 1e-3) << "ratio " << ratio;
    EXPECT_GT(at(ratio, 0.1, plain).dynamic_load_factor, 1.2) << "ratio " << ratio;
  }
  EXPECT_GT(at(2.0, 0.02, relieved).dynamic_load_factor, 1.2);
}

TEST(TipReliefDynamics, BackFlanksCarryTheirReliefAsTheDriveFlanks) {
  // A relief is cut on both flanks of a tooth: closing the back flanks by d = -(x + b) meets
  // the same gaps as closing the drive flanks by d, so the back-flank force is the drive-flank
  // force with the sign turned (on a mesh without back flanks of its own, as here, the back
  // flanks use the drive flanks' mesh, as k(t) does).
  // Without relief both are k(t) d, unchanged.
  testing::Seed000Dynamics d;
  const PairStiffnessFn k = AsPairStiffnessFn(*d.model);
  const PathOfContact path(d.pair, d.params.pinion_speed_rad_s);
  const double force = d.params.pinion_torque_nm / d.mesh->pinion_base_radius_m();
  const double x0 = force / d.mesh->MeshStiffness(0, 0.0);
  TipRelief r;
  r.wheel_amount_m = r.pinion_amount_m = 1.5 * x0;
  r.wheel_length_m = r.pinion_length_m = 0.6 * path.s_b_m();
  const TorsionalMesh relieved(d.pair, k, 33, r);
  const TorsionalModel with(relieved, d.params), without(*d.mesh, d.params);
  const double b = d.params.backlash_m;
  int below_plain = 0;
  for (int i = 0; i < 20; ++i) {
    const double phase = relieved.base_pitch_m() * (i + 0.5) / 20;
    const int seg = relieved.SegmentAt(phase);
    for (double depth : {0.25 * x0, x0, 3 * x0}) {
      const double back = with.MeshForce(ContactState::kBackFlank, seg, phase, -(depth + b), 0);
      const double drive = with.MeshForce(ContactState::kDriveFlank, seg, phase, depth, 0);
      // -(x + b) recovers the depth to round-off.
      EXPECT_NEAR(back, -drive, 1e-9 * std::abs(drive)) << "phase " << phase << " depth " << depth;
      const double plain = without.MeshForce(ContactState::kBackFlank, seg, phase, -(depth + b), 0);
      EXPECT_NEAR(plain, -d.mesh->MeshStiffness(seg, phase) * depth, 1e-12 * std::abs(plain));
      EXPECT_LE(-back, -plain * (1 + 1e-12));  // a gap only takes force away
      if (-back < -plain * (1 - 1e-6)) ++below_plain;
    }
  }
  EXPECT_GT(below_plain, 0);  // the relieved tips do unload the back flanks somewhere
}

}  // namespace
}  // namespace tehl
