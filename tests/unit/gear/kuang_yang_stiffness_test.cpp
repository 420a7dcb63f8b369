// Kuang & Yang (1992) tooth stiffness fit, seed 000 eqs. 4.3-4.5.
#include "tehl/gear/kuang_yang_stiffness.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "tehl/error.hpp"
#include "tehl/units.hpp"

namespace tehl {
namespace {

ToothBlank Steel(int z, double m, double x) {
  ToothBlank b;
  b.teeth = z;
  b.module_m = m;
  b.drive_pressure_angle_rad = b.coast_pressure_angle_rad = DegToRad(20.0);
  b.profile_shift = x;
  b.tip_radius_m = (0.5 * z + 1.0 + x) * m;
  b.face_width_m = 0.0254;
  b.youngs_modulus_pa = 206e9;
  b.poisson_ratio = 0.3;
  return b;
}

// Every problem of the InputError thrown by f() has key "gear.mesh_stiffness" and one of them
// names `value`.
template <typename F>
void ExpectRangeError(F f, const std::string& value) {
  try {
    f();
    ADD_FAILURE() << "expected InputError for " << value;
  } catch (const InputError& e) {
    bool named = false;
    for (const InputProblem& p : e.problems()) {
      EXPECT_EQ(p.key, "gear.mesh_stiffness") << p.ToString();
      named = named || p.value == value;
    }
    EXPECT_TRUE(named) << e.what();
  }
}

TEST(KuangYangStiffness, SeedPairAtThePitchPoint) {
  // Seed 000 section 7.3 (computed there from eqs. 4.3-4.5): 36 teeth, P = 8 (m = 3.175 mm),
  // x = 0: A0 = 31.353 N/(um mm) = single-tooth stiffness at the pitch point; the pair there
  // is 15.68 N/(um mm).
  const ToothBlank g = Steel(36, 0.003175, 0.0);
  const double r_p = 0.5 * 36 * 0.003175;
  EXPECT_NEAR(KuangYangStiffness::SingleToothPerWidth(g, r_p), 31.353, 5e-4);
  const KuangYangStiffness k(g, g);
  const double b_mm = 25.4;
  EXPECT_NEAR(k.PairStiffness(r_p, r_p) / (b_mm * 1e6), 15.68, 0.005);
}

TEST(KuangYangStiffness, TipValueWithTheCorrectedA2) {
  // At the tip (r - r_p = m, x = 0) K = A0 + A2. Corrected A2 (header):
  // 2.637 - 1.222*36 + 0.02217*36^2 - 0.0001179*36^3 = 2.637 - 43.992 + 28.73232 - 5.50074
  // = -18.12342, so K_tip = 31.35332 - 18.12342 = 13.2299 N/(um mm). (With the printed
  // 0.0221 the seed 000 section 7.3 gets 13.14.)
  const ToothBlank g = Steel(36, 0.003175, 0.0);
  EXPECT_NEAR(KuangYangStiffness::SingleToothPerWidth(g, g.tip_radius_m), 13.2299, 5e-4);
}

TEST(KuangYangStiffness, SofterTowardsTheTipOverTheWholeRange) {
  // Derivative-free check: a tooth loaded nearer its tip deflects more, so K(r) must fall
  // from the base circle to the tip for every z and x of the validity range. (The A3 printed
  // in the thesis breaks this, e.g. z = 36, x = 0.55.)
  for (int z : {13, 20, 36, 60, 99}) {
    for (double x : {-0.55, -0.3, 0.0, 0.3, 0.55}) {
      const ToothBlank g = Steel(z, 0.002, x);
      const double r_b = 0.5 * z * 0.002 * std::cos(DegToRad(20.0));
      double previous = KuangYangStiffness::SingleToothPerWidth(g, r_b);
      for (int i = 1; i <= 20; ++i) {
        const double r = r_b + (g.tip_radius_m - r_b) * i / 20.0;
        const double k = KuangYangStiffness::SingleToothPerWidth(g, r);
        EXPECT_LT(k, previous) << "z = " << z << ", x = " << x << ", r = " << r;
        EXPECT_GT(k, 0.0) << "z = " << z << ", x = " << x << ", r = " << r;
        previous = k;
      }
    }
  }
}

TEST(KuangYangStiffness, PairIsTheTwoTeethInSeries) {
  // Seed 000 eq. 4.5: K = K1 K2 / (K1 + K2), times the common face width.
  const ToothBlank p = Steel(20, 0.002, 0.2);
  ToothBlank w = Steel(50, 0.002, -0.1);
  w.face_width_m = 0.030;  // the common width is the pinion's 25.4 mm
  const KuangYangStiffness k(p, w);
  const double r1 = 0.0205, r2 = 0.0495;
  const double k1 = KuangYangStiffness::SingleToothPerWidth(p, r1);
  const double k2 = KuangYangStiffness::SingleToothPerWidth(w, r2);
  EXPECT_NEAR(k.PairStiffness(r1, r2), k1 * k2 / (k1 + k2) * 25.4e6,
              1e-6 * k.PairStiffness(r1, r2));
}

TEST(KuangYangStiffness, RejectsBlanksOutsideTheFit) {
  const ToothBlank ok = Steel(30, 0.002, 0.0);
  ExpectRangeError([&] { KuangYangStiffness(Steel(10, 0.002, 0.0), ok); }, "10");
  ExpectRangeError([&] { KuangYangStiffness(ok, Steel(30, 0.002, 0.8)); }, "0.8");
  ToothBlank bronze = ok;
  bronze.youngs_modulus_pa = 117e9;
  ExpectRangeError([&] { KuangYangStiffness(ok, bronze); }, "1.17e+11");
  ToothBlank asymmetric = ok;
  asymmetric.drive_pressure_angle_rad = DegToRad(35.0);
  ExpectRangeError([&] { KuangYangStiffness(asymmetric, ok); }, "20");
  // The fit has no pressure angle and no addendum: another tooth form than the 20 deg
  // full-depth tooth is outside it (at 18 deg, h_aP = 1.25 it lies 21 % above the potential
  // energy of the same teeth).
  ToothBlank eighteen = ok;
  eighteen.drive_pressure_angle_rad = eighteen.coast_pressure_angle_rad = DegToRad(18.0);
  ExpectRangeError([&] { KuangYangStiffness(eighteen, ok); }, "18");
  ToothBlank long_addendum = ok;
  long_addendum.addendum_coefficient = 1.25;
  ExpectRangeError([&] { KuangYangStiffness(ok, long_addendum); }, "1.25");
}

TEST(KuangYangStiffness, FactoryRejectsTenTeethAndLargeShift) {
  const ToothBlank ok = Steel(30, 0.002, 0.0);
  ExpectRangeError([&] { MakePairStiffnessModel("kuang_yang", Steel(10, 0.002, 0.0), ok); }, "10");
  ExpectRangeError([&] { MakePairStiffnessModel("kuang_yang", ok, Steel(30, 0.002, 0.8)); }, "0.8");
  EXPECT_EQ(MakePairStiffnessModel("kuang_yang", ok, ok)->Name(), "kuang_yang");
}

}  // namespace
}  // namespace tehl
