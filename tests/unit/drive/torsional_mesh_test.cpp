// TorsionalMesh: the period of the mesh stiffness against the gear core it is built from
// (pair stiffness, mesh stiffness, load share), its segments, and the period mean.
#include "tehl/drive/torsional_mesh.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "tehl/gear/load_sharing.hpp"
#include "tehl/gear/mesh_cycle.hpp"
#include "tehl/gear/path_of_contact.hpp"
#include "tehl/gear/potential_energy_stiffness.hpp"
#include "unit/drive/seed000_dynamics.hpp"

namespace tehl {
namespace {

TEST(TorsionalMesh, InterpolatedPairStiffnessMatchesTheGearCore) {
  // The Chebyshev interpolant reproduces k(s) of both methods between its nodes, for the
  // symmetric seed 000 pair (Kuang-Yang) and the 35/20 asymmetric one (potential energy).
  testing::Seed000Dynamics d;
  const PathOfContact path(d.pair, 1.0);
  const PairStiffnessFn k = AsPairStiffnessFn(*d.model);
  for (int i = 0; i <= 97; ++i) {
    const double s = path.length_m() * i / 97.0;
    const ContactPoint c = path.At(s);
    EXPECT_NEAR(d.mesh->PairStiffness(s) / k(c.r1_m, c.r2_m), 1.0, 1e-6) << "s = " << s;
  }
  const GearPair asym(testing::Seed000Spec(35.0, 20.0));
  const PotentialEnergyStiffness pe(PinionBlank(asym), WheelBlank(asym));
  const TorsionalMesh m(asym, AsPairStiffnessFn(pe));
  const PathOfContact pa(asym, 1.0);
  for (int i = 0; i <= 37; ++i) {
    const double s = pa.length_m() * i / 37.0;
    const ContactPoint c = pa.At(s);
    EXPECT_NEAR(m.PairStiffness(s) / pe.PairStiffness(c.r1_m, c.r2_m), 1.0, 1e-5) << "s = " << s;
  }
}

TEST(TorsionalMesh, SegmentsCutAtTheContactSwitchesAndThePitchPoint) {
  // For 1 < eps_alpha < 2: double contact on [0, s_B), single on [s_B, p_b) with s_B =
  // g_alpha - p_b (DESIGN.md section 2, B = E - p_b); the pitch point cuts one of them.
  testing::Seed000Dynamics d;
  const TorsionalMesh& m = *d.mesh;
  const double pb = m.base_pitch_m(), sb = m.length_m() - pb;
  const double sc = std::fmod(m.pitch_point_m(), pb);
  ASSERT_EQ(m.segments().size(), 3u);
  EXPECT_EQ(m.segments().front().begin_m, 0.0);
  EXPECT_EQ(m.segments().back().end_m, pb);
  std::vector<double> cuts = {m.segments()[0].end_m, m.segments()[1].end_m};
  EXPECT_NEAR(std::min(cuts[0], cuts[1]), std::min(sb, sc), 1e-15);
  EXPECT_NEAR(std::max(cuts[0], cuts[1]), std::max(sb, sc), 1e-15);
  for (const MeshSegment& seg : m.segments()) {
    const double mid = 0.5 * (seg.begin_m + seg.end_m);
    EXPECT_EQ(seg.pairs.size(), mid < sb ? 2u : 1u) << "segment at " << mid;
  }
  EXPECT_NEAR(m.contact_ratio(), 1.6924, 1e-4);  // seed 000 extraction section 7.3
}

TEST(TorsionalMesh, MeshStiffnessAndSharesMatchTheGearCore) {
  // k_mesh(phi) = MeshStiffnessAt (parallel sum, load_sharing.hpp); the share of the pair at
  // s = StiffnessLoadShare; shares of the pairs in contact add up to 1.
  testing::Seed000Dynamics d;
  const TorsionalMesh& m = *d.mesh;
  const PathOfContact path(d.pair, 1.0);
  const PairStiffnessFn k = AsPairStiffnessFn(*d.model);
  for (int i = 0; i < 40; ++i) {
    const double phase = m.base_pitch_m() * (i + 0.5) / 40.0;
    const int seg = m.SegmentAt(phase);
    EXPECT_NEAR(m.MeshStiffness(seg, phase) / MeshStiffnessAt(path, phase, k), 1.0, 1e-6);
    double sum = 0;
    for (size_t j = 0; j < m.segments()[seg].pairs.size(); ++j)
      sum += m.PairShare(seg, static_cast<int>(j), phase);
    EXPECT_NEAR(sum, 1.0, 1e-12);
  }
  for (int i = 1; i < 50; ++i) {
    const double s = m.length_m() * i / 50.0;
    EXPECT_NEAR(m.ShareAt(s, false), StiffnessLoadShare(path, s, k), 1e-6) << "s = " << s;
  }
}

TEST(TorsionalMesh, PeriodMeanEqualsTheSampledMeanOfTheGearCore) {
  // SummarizeMeshStiffness samples k_mesh at 4000 points of a period; the mesh integrates
  // k(s) over the path (Simpson). Both are the period mean.
  testing::Seed000Dynamics d;
  const PathOfContact path(d.pair, 1.0);
  const MeshStiffnessSummary ref = SummarizeMeshStiffness(path, AsPairStiffnessFn(*d.model), 4000);
  EXPECT_NEAR(d.mesh->mean_stiffness_n_per_m() / ref.mean_n_per_m, 1.0, 1e-3);
  EXPECT_NEAR(d.mesh->min_stiffness_n_per_m() / ref.min_n_per_m, 1.0, 1e-3);
  EXPECT_NEAR(d.mesh->max_stiffness_n_per_m() / ref.max_n_per_m, 1.0, 1e-3);
}

TEST(TorsionalMesh, ConstantStiffnessIsConstantAndSharedEqually) {
  testing::Seed000Dynamics d;
  const TorsionalMesh m = TorsionalMesh::Constant(d.pair, 5e8);
  EXPECT_EQ(m.mean_stiffness_n_per_m(), 5e8);
  EXPECT_EQ(m.MeshStiffness(0, 0.0), 5e8);
  EXPECT_EQ(m.PairShare(0, 0, 0.0), 0.5);  // double contact at phase 0
}

}  // namespace
}  // namespace tehl
