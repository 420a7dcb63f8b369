// The seed 004 mesh cycle (35/105 teeth, m = 2 mm, 10 kW at 1000 rpm, SAE 40 / SAE 90,
// isothermal) at reduced resolution (257 nodes, 40 steps): every step converges, the central
// film at the pitch point lies between the Pan-Hamrock and Moes values of VALIDATION.md
// section 5, and the film follows seed 004's trends (VALIDATION.md section 7: 1 thinnest at
// engagement, 4 load, 5 speed, 6 oil).
#include <gtest/gtest.h>

#include <algorithm>

#include "regression/mesh_cycle_runs.hpp"

namespace tehl {
namespace {
using testing::Reduced;
using testing::RunReduced;

double PitchCentralFilm(const MeshCycleResult& r) { return r.steps[r.PitchStep()].h_c_m; }

double MeanMinFilm(const MeshCycleResult& r) {
  double sum = 0;
  for (const auto& s : r.steps) sum += s.h_min_m;
  return sum / r.steps.size();
}

void ExpectComplete(const MeshCycleResult& r) {
  ASSERT_TRUE(r.converged()) << r.steps.back().summary.message;
  EXPECT_EQ(r.Restarts(), 0) << "a time step was restarted from the steady film";
  EXPECT_EQ(r.planned_steps, 40);
  ASSERT_EQ(r.steps.size(), 41u);
  EXPECT_DOUBLE_EQ(r.steps.front().s_m, 0.0);
  EXPECT_NEAR(r.steps.back().s_m, r.length_m, 1e-12);
  // VALIDATION.md section 5: g_alpha = 16.950 - 6.486 = 10.464 mm.
  EXPECT_NEAR(r.length_m, 10.464e-3, 2e-6);
}

TEST(MeshCycleSeed004, Sae40CompletesWithPitchFilmBetweenPanHamrockAndMoes) {
  const MeshCycleResult r = RunReduced("seed004_sae40");
  ExpectComplete(r);
  // The pitch point C is 11.971 - 6.486 = 5.485 mm from A (VALIDATION.md section 5); the
  // nearest step is within half a step (single-contact segment B-D: 1.344 mm / steps there).
  const MeshCycleStep& c = r.steps[r.PitchStep()];
  EXPECT_NEAR(c.s_m, 5.485e-3, 0.2e-3);
  // VALIDATION.md section 5, SAE 40 at C: R = 8.978 mm, um = 1.254 m/s, w = 116.14 kN/m
  // (single contact, share 1) -> the C_RT, C_UT, C_WT references.
  EXPECT_NEAR(r.r0_m, 8.978e-3, 0.002e-3);
  EXPECT_NEAR(r.u0_m_s, 1.254, 0.001);
  EXPECT_NEAR(r.w0_n_per_m, 116.14e3, 0.05e3);
  // Central film between Pan-Hamrock (0.73 um) and Moes (0.88 um), VALIDATION.md section 5.
  EXPECT_GT(PitchCentralFilm(r), 0.73e-6);
  EXPECT_LT(PitchCentralFilm(r), 0.88e-6);
}

TEST(MeshCycleSeed004, FilmIsThinnestNearEngagement) {
  // Seed 004 trend 1 (VALIDATION.md section 7): the minimum film is smallest at the start of
  // engagement, where R and um are smallest (C_RT, C_UT < 1 on A-B).
  const MeshCycleResult r = RunReduced("seed004_sae40");
  ASSERT_TRUE(r.converged());
  EXPECT_EQ(r.Restarts(), 0) << "a time step was restarted from the steady film";
  const auto thinnest = std::min_element(
      r.steps.begin(), r.steps.end(),
      [](const MeshCycleStep& a, const MeshCycleStep& b) { return a.h_min_m < b.h_min_m; });
  EXPECT_LT(thinnest->s_m, 0.1 * r.length_m) << "thinnest film at s = " << thinnest->s_m;
  EXPECT_LT(r.steps.front().h_min_m, r.steps[r.PitchStep()].h_min_m);
  EXPECT_LT(r.steps.front().h_min_m, r.steps.back().h_min_m);
}

TEST(MeshCycleSeed004, Sae90GivesThickerFilmThanSae40) {
  // Seed 004 trend 6; SAE 90 at C between Pan-Hamrock 1.05 um and Moes 1.25 um
  // (VALIDATION.md section 5).
  const MeshCycleResult r40 = RunReduced("seed004_sae40");
  const MeshCycleResult r90 = RunReduced("seed004_sae90");
  ExpectComplete(r90);
  EXPECT_GT(PitchCentralFilm(r90), 1.05e-6);
  EXPECT_LT(PitchCentralFilm(r90), 1.25e-6);
  EXPECT_GT(PitchCentralFilm(r90), PitchCentralFilm(r40));
  EXPECT_GT(MeanMinFilm(r90), MeanMinFilm(r40));
  for (size_t k = 0; k < r40.steps.size(); ++k)
    EXPECT_GT(r90.steps[k].h_min_m, r40.steps[k].h_min_m) << "step " << k;
}

TEST(MeshCycleSeed004, HigherSpeedThickensTheFilm) {
  // Seed 004 trend 5, at the same torque T1 = 95.49 N m: 1500 rpm needs P = T1 w1 = 15 kW.
  const MeshCycleResult slow = RunReduced("seed004_sae40");
  const MeshCycleResult fast = RunReduced(
      "seed004_sae40", Reduced({{"pinion_speed_rpm", "1500.0"}, {"power_w", "15000.0"}}));
  ASSERT_TRUE(fast.converged());
  EXPECT_EQ(fast.Restarts(), 0) << "a time step was restarted from the steady film";
  EXPECT_NEAR(fast.w0_n_per_m, slow.w0_n_per_m, 1e-6 * slow.w0_n_per_m);  // same load
  EXPECT_GT(PitchCentralFilm(fast), PitchCentralFilm(slow));
  EXPECT_GT(MeanMinFilm(fast), MeanMinFilm(slow));
}

TEST(MeshCycleSeed004, HigherLoadThinsTheFilm) {
  // Seed 004 trend 4, at 1000 rpm: 20 kW doubles the load.
  const MeshCycleResult light = RunReduced("seed004_sae40");
  const MeshCycleResult heavy = RunReduced("seed004_sae40", Reduced({{"power_w", "20000.0"}}));
  ASSERT_TRUE(heavy.converged());
  EXPECT_EQ(heavy.Restarts(), 0) << "a time step was restarted from the steady film";
  EXPECT_NEAR(heavy.w0_n_per_m, 2 * light.w0_n_per_m, 1e-6 * light.w0_n_per_m);
  EXPECT_LT(PitchCentralFilm(heavy), PitchCentralFilm(light));
  EXPECT_LT(MeanMinFilm(heavy), MeanMinFilm(light));
  EXPECT_GT(heavy.steps[heavy.PitchStep()].p_max_pa, light.steps[light.PitchStep()].p_max_pa);
}

}  // namespace
}  // namespace tehl
