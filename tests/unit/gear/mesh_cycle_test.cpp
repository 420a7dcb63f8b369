// The mesh cycle table: nominal load, load per unit width along the path, mesh stiffness,
// and the Hertz scales it gives (VALIDATION.md section 5).
#include "tehl/gear/mesh_cycle.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "tehl/error.hpp"
#include "tehl/units.hpp"
#include "unit/gear/reference_pairs.hpp"

namespace tehl {
namespace {

TEST(NominalToothLoad, Seed004At10kWAnd1000Rpm) {
  // VALIDATION.md section 5: T1 = 95.49 N m, F_bt = 2903.5 N, w = 116.14 kN/m.
  const GearPair pair(testing::Seed004Spec());
  OperatingPoint op;
  op.pinion_speed_rad_s = RpmToRadPerS(1000);
  op.pinion_torque_nm = TorqueFromPower(10e3, op.pinion_speed_rad_s);
  EXPECT_NEAR(op.pinion_torque_nm, 95.49, 0.005);
  const ToothLoad load = NominalToothLoad(pair, op);
  EXPECT_NEAR(load.normal_force_n, 2903.5, 0.05);
  EXPECT_NEAR(load.load_per_width_n_per_m, 116.14e3, 5);
  // Tangential force on the pitch circle: T1 / r1 (standard pair, r_w = r).
  EXPECT_NEAR(load.tangential_force_n, op.pinion_torque_nm / 0.035, 1e-9);
}

TEST(NominalToothLoad, Seed004HertzScalesAtThePitchPoint) {
  // VALIDATION.md section 5: p_H ~ 522 MPa, b ~ 142 um (E = 117 GPa, nu = 0.34, R = 8.978 mm).
  const GearPair pair(testing::Seed004Spec());
  OperatingPoint op{RpmToRadPerS(1000), TorqueFromPower(10e3, RpmToRadPerS(1000))};
  const PathOfContact path(pair, op.pinion_speed_rad_s);
  const double w = NominalToothLoad(pair, op).load_per_width_n_per_m;
  const HertzScales h = LineContactHertz(w, path.At(path.s_c_m()).reduced_radius_m,
                                         ReducedModulus(117e9, 0.34, 117e9, 0.34));
  EXPECT_NEAR(h.max_pressure_pa, 522e6, 0.5e6);
  EXPECT_NEAR(h.half_width_m, 142e-6, 0.5e-6);
}

TEST(NominalToothLoad, FzgCHertzAtThePitchPoint) {
  // VALIDATION.md section 5: T1 = 200 N m, steel-steel: p_H at C = 1347.3 MPa, b = 199.5 um.
  // C lies in the single-contact zone (AB = 6.14 < AC = 9.68 < AD = 13.28 mm), full load.
  const GearPair pair(testing::FzgCSpec());
  const OperatingPoint op{RpmToRadPerS(1450), 200.0};
  const PathOfContact path(pair, op.pinion_speed_rad_s);
  const ContactPoint c = path.At(path.s_c_m());
  const double w =
      LinearLoadShare(path, path.s_c_m()) * NominalToothLoad(pair, op).load_per_width_n_per_m;
  const HertzScales h =
      LineContactHertz(w, c.reduced_radius_m, ReducedModulus(206e9, 0.3, 206e9, 0.3));
  EXPECT_NEAR(h.max_pressure_pa, 1347.3e6, 0.05e6);
  EXPECT_NEAR(h.half_width_m, 199.5e-6, 0.05e-6);
}

TEST(MeshCycle, LinearLoadAlongThePathWithExactSwitchPoints) {
  const GearPair pair(testing::Seed004Spec());
  const OperatingPoint op{RpmToRadPerS(1000), TorqueFromPower(10e3, RpmToRadPerS(1000))};
  const PathOfContact path(pair, op.pinion_speed_rad_s);
  const ToothLoad load = NominalToothLoad(pair, op);
  MeshCycleOptions o;
  o.points = 101;
  const auto rows = MeshCycle(path, load, o);
  ASSERT_EQ(rows.size(), 105u);  // 101 + both sides of B and D
  EXPECT_NEAR(rows.front().contact.s_m, 0.0, 0);
  EXPECT_NEAR(rows.back().contact.s_m, path.length_m(), 1e-15);
  EXPECT_NEAR(rows.front().load_n_per_m, load.load_per_width_n_per_m / 3, 1e-9);
  double jump = 0;  // the largest step of w between neighbouring rows: the switch at B or D
  for (size_t i = 1; i < rows.size(); ++i) {
    EXPECT_GT(rows[i].contact.s_m, rows[i - 1].contact.s_m);
    jump = std::max(jump, std::abs(rows[i].load_n_per_m - rows[i - 1].load_n_per_m));
    EXPECT_NEAR(rows[i].load_n_per_m, rows[i].share * load.load_per_width_n_per_m, 1e-9);
    EXPECT_EQ(rows[i].pair_stiffness_n_per_m, 0.0);
  }
  EXPECT_NEAR(jump, load.load_per_width_n_per_m / 3, 1e-3);
}

TEST(MeshCycle, StiffnessSharingNeedsAStiffness) {
  const GearPair pair(testing::Seed004Spec());
  const PathOfContact path(pair, 100.0);
  MeshCycleOptions o;
  o.load_sharing = LoadSharing::kStiffness;
  EXPECT_THROW(MeshCycle(path, ToothLoad{}, o), InputError);
  o.points = 1;
  EXPECT_EQ(o.Validate().size(), 1u);
}

TEST(SummarizeMeshStiffness, ConstantPairStiffnessGivesEpsilonTimesK) {
  // With k constant the mesh stiffness is k in single and 2k in double contact; double
  // contact lasts (eps - 1) of the mesh period, so the period mean is k eps_alpha.
  const GearPair pair(testing::FzgCSpec());
  const PathOfContact path(pair, 100.0);
  const double k = 2.5e8;
  const MeshStiffnessSummary m = SummarizeMeshStiffness(
      path, [k](double, double) { return k; }, 20000);
  EXPECT_NEAR(m.mean_n_per_m / k, pair.line(Flank::kDrive).contact_ratio, 1e-4);
  EXPECT_DOUBLE_EQ(m.min_n_per_m, k);
  EXPECT_DOUBLE_EQ(m.max_n_per_m, 2 * k);
  EXPECT_DOUBLE_EQ(m.single_pair_max_n_per_m, k);
}

}  // namespace
}  // namespace tehl
