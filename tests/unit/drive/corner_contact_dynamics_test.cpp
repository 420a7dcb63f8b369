// Corner contact in the torsional model (docs/dynamics.md, "Corner contact"): with the pairs
// meshing beyond A and E where the approach closes their separation, the mesh force follows
// the static force at low speed at every phase, where the stepped stiffness of [A, E] alone
// sends a spike of k_after / k_before through the mesh at each step, at any speed.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "tehl/drive/dynamic_response.hpp"
#include "tehl/drive/torsional_model.hpp"
#include "unit/drive/seed000_dynamics.hpp"

namespace tehl {
namespace {

TorsionalMesh CornerMesh(const testing::Seed000Dynamics& d) {
  return TorsionalMesh(d.pair, AsPairStiffnessFn(*d.model), 33, {}, 0.05 * d.pair.spec().module_m);
}

TEST(CornerContactDynamics, AtVeryLowSpeedTheMeshForceIsTheStaticForceAtEveryPhase) {
  // Quasi-static (1 rpm, no friction): m_e x'' = F_s - F with F continuous in time, so F = F_s
  // at every phase, the instants where pairs enter and leave included (analysis; the
  // integrator's tolerance 1e-8). Without corner contact the force steps with the stiffness
  // where a pair enters at A: F = k_double x_single = (k_double / k_single) F_s.
  testing::Seed000Dynamics d;
  d.params.friction = FrictionLaw::kNone;
  d.params.pinion_speed_rad_s = RpmToRadPerS(1.0);
  const TorsionalMesh corner = CornerMesh(d);
  ASSERT_TRUE(corner.corner_contact());
  TorsionalModel with(corner, d.params);
  const DynamicResponse r = SolvePeriodicResponse(with, DynamicResponseOptions{});
  ASSERT_TRUE(r.periodic) << r.message;
  EXPECT_NEAR(r.peak_force_n / r.static_force_n, 1.0, 2e-3);
  EXPECT_NEAR(r.min_force_n / r.static_force_n, 1.0, 2e-3);
  for (int i = 0; i < 200; ++i) {
    // And the approach is the static one under F_s of the pairs at that phase.
    const double phase = corner.base_pitch_m() * (i + 0.5) / 200;
    const DynamicSample s = r.SampleAt(phase, false);
    EXPECT_NEAR(s.x_m / corner.StaticApproachAt(phase, false, r.static_force_n), 1.0, 2e-3)
        << "phase " << phase;
  }

  TorsionalModel without(*d.mesh, d.params);
  const DynamicResponse step = SolvePeriodicResponse(without, DynamicResponseOptions{});
  const MeshSegment& last = d.mesh->segments().back();
  const double k_before =
      d.mesh->MeshStiffness(static_cast<int>(d.mesh->segments().size()) - 1, last.end_m);
  const double k_after = d.mesh->MeshStiffness(0, 0.0);
  ASSERT_GT(k_after, 1.2 * k_before);
  EXPECT_NEAR(step.peak_force_n / step.static_force_n, k_after / k_before,
              0.01 * k_after / k_before);
}

TEST(CornerContactDynamics, TheEnteringPairCarriesLoadBeforeA) {
  // Under the static force the approach x_s exceeds the separation of the entering pair's
  // corner close to A: that pair carries k (x_s - e) > 0 before s = 0 and all of k x_s at A,
  // and the pairs' loads add up to F_s (CommonApproach, tip_relief.hpp).
  testing::Seed000Dynamics d;
  const TorsionalMesh mesh = CornerMesh(d);
  const double pb = mesh.base_pitch_m(), fs = 1000.0;
  // The next pair at s = -0.05 e_A: separation about 0.05^2 of the 0.16 mm at e_A (quadratic).
  const double phase = pb - 0.05 * mesh.corner_before_m();
  const int seg = mesh.SegmentAt(phase);
  const MeshSegment& m = mesh.segments()[seg];
  const double x = mesh.StaticApproachAt(phase, false, fs);
  EXPECT_NEAR(mesh.ElasticForce(seg, phase, x), fs, 1e-9 * fs);
  double shares = 0;
  for (size_t i = 0; i < m.pairs.size(); ++i) {
    const double s = phase + m.pairs[i] * pb;
    const double share = mesh.PairShare(seg, static_cast<int>(i), phase, x);
    shares += share;
    if (s > mesh.length_m()) {
      EXPECT_TRUE(m.corner[i]);
    }
    if (s < 0) {
      EXPECT_TRUE(m.corner[i]);
      EXPECT_LT(mesh.GapAt(s), x);
      EXPECT_GT(share, 0.0) << "the entering pair at s = " << s;
      EXPECT_EQ(mesh.PairShare(seg, static_cast<int>(i), phase), 0.0);  // not in the nominal sum
    }
  }
  EXPECT_NEAR(shares, 1.0, 1e-12);
}

}  // namespace
}  // namespace tehl
