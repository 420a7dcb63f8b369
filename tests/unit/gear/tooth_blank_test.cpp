// The ToothBlank of each gear for the stiffness methods, and the stiffness integration:
// parallel sum over the pairs in contact, stiffness load sharing with a real method.
#include "tehl/gear/tooth_blank.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "tehl/gear/mesh_cycle.hpp"
#include "unit/gear/reference_pairs.hpp"

namespace tehl {
namespace {

TEST(ToothBlank, CarriesTheGearAsBuilt) {
  const GearPair pair(testing::FzgCSpec());
  const ToothBlank p = PinionBlank(pair), w = WheelBlank(pair);
  EXPECT_EQ(p.teeth, 16);
  EXPECT_EQ(w.teeth, 24);
  EXPECT_DOUBLE_EQ(p.module_m, 4.5e-3);
  EXPECT_DOUBLE_EQ(p.profile_shift, 0.1817);
  EXPECT_DOUBLE_EQ(w.profile_shift, 0.1715);
  EXPECT_DOUBLE_EQ(p.tip_radius_m, 41.318e-3);
  EXPECT_DOUBLE_EQ(w.tip_radius_m, 59.272e-3);
  EXPECT_DOUBLE_EQ(p.face_width_m, 14e-3);
  EXPECT_DOUBLE_EQ(p.youngs_modulus_pa, 206e9);
  EXPECT_DOUBLE_EQ(p.drive_pressure_angle_rad, p.coast_pressure_angle_rad);
  EXPECT_FALSE(w.internal);
}

TEST(ToothBlank, IsoMethodBOfTheBlanksMatchesValidation) {
  // VALIDATION.md section 5 (computed): FZG C c' = 12.31, c_gamma_alpha = 16.57 N/(mm um);
  // 62/62, x = 0: 14.47 and 23.04.
  const GearPair fzg(testing::FzgCSpec());
  const IsoStiffness a =
      IsoMethodB(PinionBlank(fzg), WheelBlank(fzg), fzg.line(Flank::kDrive).contact_ratio);
  EXPECT_NEAR(a.c_prime_n_per_mm_um, 12.31, 0.005);
  EXPECT_NEAR(a.c_gamma_alpha_n_per_mm_um, 16.57, 0.005);
  GearPairSpec s = testing::Seed004Spec();
  s.pinion.teeth = s.wheel.teeth = 62;
  s.pinion.material = s.wheel.material = GearMaterial{};
  const GearPair p62(s);
  const IsoStiffness b =
      IsoMethodB(PinionBlank(p62), WheelBlank(p62), p62.line(Flank::kDrive).contact_ratio);
  EXPECT_NEAR(b.c_prime_n_per_mm_um, 14.47, 0.005);
  EXPECT_NEAR(b.c_gamma_alpha_n_per_mm_um, 23.04, 0.005);
}

TEST(ToothBlank, PotentialEnergyMeshStiffnessCrossChecksIso) {
  // The 62/62 steel pair: the period mean of the parallel sum of potential-energy pair
  // stiffnesses against ISO 6336-1 c_gamma_alpha = 23.04 N/(mm um) (VALIDATION.md section 5,
  // a cross-check, not an exact law: within 10%). Stiffness load sharing sums to 1.
  GearPairSpec s = testing::Seed004Spec();
  s.pinion.teeth = s.wheel.teeth = 62;
  s.face_width_m = 0.02;
  s.pinion.material = s.wheel.material = GearMaterial{};
  const GearPair pair(s);
  const auto model =
      MakePairStiffnessModel("potential_energy", PinionBlank(pair), WheelBlank(pair));
  const PairStiffnessFn k = AsPairStiffnessFn(*model);
  const PathOfContact path(pair, 100.0);
  const MeshStiffnessSummary m = SummarizeMeshStiffness(path, k);
  const double per_width = m.mean_n_per_m * 1e-6 / 20.0;  // N/(mm um)
  EXPECT_NEAR(per_width, 23.04, 0.1 * 23.04);
  EXPECT_GT(m.max_n_per_m, m.min_n_per_m);
  for (int i = 0; i <= 20; ++i) {
    const double q = path.length_m() * i / 20;
    double sum = 0;
    for (double o : path.SimultaneousContacts(q)) sum += StiffnessLoadShare(path, o, k);
    EXPECT_NEAR(sum, 1.0, 1e-12);
  }
}

}  // namespace
}  // namespace tehl
