// Potential-energy tooth-pair stiffness (include/tehl/gear/potential_energy_stiffness.hpp).
#include "tehl/gear/potential_energy_stiffness.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>

#include "tehl/error.hpp"
#include "tehl/units.hpp"

namespace tehl {
namespace {

ToothBlank Steel(int z, double m, double x, double drive_deg = 20.0, double coast_deg = 20.0) {
  ToothBlank b;
  b.teeth = z;
  b.module_m = m;
  b.drive_pressure_angle_rad = DegToRad(drive_deg);
  b.coast_pressure_angle_rad = DegToRad(coast_deg);
  b.profile_shift = x;
  b.tip_radius_m = (0.5 * z + 1.0 + x) * m;
  b.face_width_m = 0.02;
  b.youngs_modulus_pa = 206e9;
  b.poisson_ratio = 0.3;
  return b;
}

double Inv(double a) { return std::tan(a) - a; }

// Composite Simpson rule with n (even) intervals: the reference quadrature of these tests,
// independent of the Gauss-Legendre rule of the model.
double Simpson(const std::function<double(double)>& f, double a, double b, int n = 20000) {
  const double h = (b - a) / n;
  double s = f(a) + f(b);
  for (int i = 1; i < n; ++i) s += (i % 2 ? 4.0 : 2.0) * f(a + i * h);
  return s * h / 3.0;
}

// Sainsot, Velex & Duverger (2004), Table 1 (published constants), X* = A/theta^2 + B h^2
// + C h/theta + D/theta + E h + F.
double SainsotFit(const double c[6], double h, double theta) {
  return c[0] / (theta * theta) + c[1] * h * h + c[2] * h / theta + c[3] / theta + c[4] * h + c[5];
}

TEST(PotentialEnergyStiffness, HertzTermOfASteelPair) {
  // Yang & Sun (1985): k_h = pi E L / (4 (1 - nu^2)); L = 20 mm, E = 206 GPa, nu = 0.3:
  // pi * 206e9 * 0.02 / (4 * 0.91) = 3.5559e9 N/m.
  const ToothBlank g = Steel(30, 0.002, 0.0);
  const PotentialEnergyStiffness pe(g, g);
  EXPECT_NEAR(pe.HertzStiffness(), 3.5559e9, 0.00005e9);
}

TEST(PotentialEnergyStiffness, HertzTermOfTwoMaterialsUsesTheReducedModulus) {
  // k_h = pi E' L / 4 with 2/E' = (1 - nu1^2)/E1 + (1 - nu2^2)/E2 (VALIDATION.md section 1).
  // Steel 206 GPa / 0.3 with aluminium bronze 117 GPa / 0.34:
  // 2/E' = 0.91/206e9 + 0.8844/117e9 -> E' = 166.994 GPa, k_h = 2.62314e9 N/m (L = 20 mm).
  const ToothBlank steel = Steel(35, 0.002, 0.0);
  ToothBlank bronze = Steel(105, 0.002, 0.0);
  bronze.youngs_modulus_pa = 117e9;
  bronze.poisson_ratio = 0.34;
  const PotentialEnergyStiffness pe(steel, bronze);
  EXPECT_NEAR(pe.HertzStiffness(), 2.62314e9, 0.00001e9);
}

// Tian (2004), symmetric tooth clamped at its base circle, parameter alpha in
// [-a1, a2] (a2: half angle of the tooth at the base circle, a1: load angle at the contact),
// plane stress:
//   1/k_b = int 3 {1 + cos a1 [(a2 - a) sin a - cos a]}^2 (a2 - a) cos a
//               / (2 E L [sin a + (a2 - a) cos a]^3) da
//   1/k_s = int 1.2 (1 + nu) (a2 - a) cos a cos^2 a1 / (E L [sin a + (a2 - a) cos a]) da
//   1/k_a = int (a2 - a) cos a sin^2 a1 / (2 E L [sin a + (a2 - a) cos a]) da
struct Reference {
  double bending, shear, axial;
};

Reference TianBaseCircle(const ToothBlank& g, double r) {
  const double alpha0 = g.drive_pressure_angle_rad, z = g.teeth, e = g.youngs_modulus_pa;
  const double nu = g.poisson_ratio, l = g.face_width_m;
  const double r_b = 0.5 * z * g.module_m * std::cos(alpha0);
  const double a2 = (0.5 * kPi + 2.0 * g.profile_shift * std::tan(alpha0)) / z + Inv(alpha0);
  const double a1 = std::tan(std::acos(r_b / r)) - a2;
  auto d = [&](double a) { return std::sin(a) + (a2 - a) * std::cos(a); };
  Reference ref;
  ref.bending = Simpson(
      [&](double a) {
        const double num = 1.0 + std::cos(a1) * ((a2 - a) * std::sin(a) - std::cos(a));
        return 3.0 * num * num * (a2 - a) * std::cos(a) / (2.0 * e * l * std::pow(d(a), 3));
      },
      -a1, a2);
  ref.shear = Simpson(
      [&](double a) {
        return 1.2 * (1.0 + nu) * (a2 - a) * std::cos(a) * std::cos(a1) * std::cos(a1) /
               (e * l * d(a));
      },
      -a1, a2);
  ref.axial = Simpson(
      [&](double a) {
        return (a2 - a) * std::cos(a) * std::sin(a1) * std::sin(a1) / (2.0 * e * l * d(a));
      },
      -a1, a2);
  return ref;
}

TEST(PotentialEnergyStiffness, ReproducesTianClampedAtTheBaseCircle) {
  // z = 30 (r_f < r_b), with and without shift, several contact radii.
  PotentialEnergyStiffness::Options classic;
  classic.start_at_root_circle = false;
  for (double x : {0.0, 0.25}) {
    const ToothBlank g = Steel(30, 0.003, x);
    const PotentialEnergyStiffness pe(g, g, classic);
    const double r_b = 0.5 * 30 * 0.003 * std::cos(DegToRad(20.0));
    for (double f : {0.1, 0.4, 0.7, 1.0}) {
      const double r = r_b + f * (g.tip_radius_m - r_b);
      const auto c = pe.PinionCompliance(r);
      const Reference ref = TianBaseCircle(g, r);
      EXPECT_NEAR(c.bending, ref.bending, 1e-7 * ref.bending) << "x = " << x << ", r = " << r;
      EXPECT_NEAR(c.shear, ref.shear, 1e-7 * ref.shear) << "x = " << x << ", r = " << r;
      EXPECT_NEAR(c.axial, ref.axial, 1e-7 * ref.axial) << "x = " << x << ", r = " << r;
    }
  }
}

TEST(PotentialEnergyStiffness, RootCircleStartAddsTheRadialPieceBelowTheBaseCircle) {
  // Default: the beam starts at r_f; between r_f and r_b the flank is the radial line at the
  // base half angle a2, so a section at axial coordinate y has half width h = y tan a2, and
  // the moment arm of the load is (y_P - y) cos a1 - h_P sin a1 = r_b - y cos a1 (derived from
  // the involute point y_P = r_b [cos a1 + (a1 + a2) sin a1], h_P = r_b [(a1 + a2) cos a1 -
  // sin a1]). Extra compliance = int over y in [r_f cos a2, r_b cos a2] of
  // (r_b - y cos a1)^2 / (E 2/3 h^3 L), 1.2 cos^2 a1 / (G 2 h L), sin^2 a1 / (E 2 h L).
  const ToothBlank g = Steel(30, 0.003, 0.0);
  const PotentialEnergyStiffness pe(g, g);
  const double alpha0 = DegToRad(20.0), e = 206e9, l = 0.02, gs = e / 2.6;
  const double r_b = 0.045 * std::cos(alpha0), r_f = 0.045 - 1.25 * 0.003;
  const double a2 = 0.5 * kPi / 30 + Inv(alpha0);
  const double r = 0.5 * (r_b + g.tip_radius_m);
  const double a1 = std::tan(std::acos(r_b / r)) - a2;
  const Reference base = TianBaseCircle(g, r);
  const double y0 = r_f * std::cos(a2), y1 = r_b * std::cos(a2);
  auto h = [&](double y) { return y * std::tan(a2); };
  const double bending = Simpson(
      [&](double y) {
        const double arm = r_b - y * std::cos(a1);
        return arm * arm / (e * 2.0 / 3.0 * std::pow(h(y), 3) * l);
      },
      y0, y1);
  const double shear = Simpson(
      [&](double y) { return 1.2 * std::cos(a1) * std::cos(a1) / (gs * 2.0 * h(y) * l); }, y0, y1);
  const double axial =
      Simpson([&](double y) { return std::sin(a1) * std::sin(a1) / (e * 2.0 * h(y) * l); }, y0, y1);
  const auto c = pe.PinionCompliance(r);
  EXPECT_NEAR(c.bending, base.bending + bending, 1e-7 * c.bending);
  EXPECT_NEAR(c.shear, base.shear + shear, 1e-7 * c.shear);
  EXPECT_NEAR(c.axial, base.axial + axial, 1e-7 * c.axial);
}

TEST(PotentialEnergyStiffness, FoundationTermOfSainsot) {
  // Sainsot et al. (2004): 1/k_f = cos^2 a1/(E L) [L* (u/S)^2 + M* (u/S) + P* (1 + Q* tan^2 a1)]
  // with u = r_b / cos a1 - r_f (the load line crosses the tooth axis at r_b / cos a1),
  // S = 2 r_f theta_f, theta_f = [pi/2 + 2 (h_fP - rho_fP) tan a0 + 2 rho_fP / cos a0] / z
  // (junction of the rack-tip fillet with the root circle) and h = r_f / r_int.
  ToothBlank g = Steel(40, 0.0025, 0.1);
  g.bore_radius_m = 0.015;
  const PotentialEnergyStiffness pe(g, g);
  const double alpha0 = DegToRad(20.0), z = 40, m = 0.0025;
  const double r_b = 0.5 * z * m * std::cos(alpha0), r_f = (0.5 * z - 1.25 + 0.1) * m;
  const double a2 = (0.5 * kPi + 2.0 * 0.1 * std::tan(alpha0)) / z + Inv(alpha0);
  const double theta_f =
      (0.5 * kPi + 2.0 * (1.25 - 0.38) * std::tan(alpha0) + 2.0 * 0.38 / std::cos(alpha0)) / z;
  const double h = r_f / 0.015;
  const double l_c[6] = {-5.574e-5, -1.9986e-3, -2.3015e-4, 4.7702e-3, 0.0271, 6.8045};
  const double m_c[6] = {60.111e-5, 28.100e-3, -83.431e-4, -9.9256e-3, 0.1624, 0.9086};
  const double p_c[6] = {-50.952e-5, 185.50e-3, 0.0538e-4, 53.300e-3, 0.2895, 0.9236};
  const double q_c[6] = {-6.2042e-5, 9.0889e-3, -4.0964e-4, 7.8297e-3, -0.1472, 0.6904};
  for (double r : {r_b * 1.01, 0.5 * z * m, g.tip_radius_m}) {
    const double a1 = std::tan(std::acos(r_b / r)) - a2;
    const double u = r_b / std::cos(a1) - r_f, s = 2.0 * r_f * theta_f;
    const double expected =
        std::cos(a1) * std::cos(a1) / (206e9 * 0.02) *
        (SainsotFit(l_c, h, theta_f) * (u / s) * (u / s) + SainsotFit(m_c, h, theta_f) * u / s +
         SainsotFit(p_c, h, theta_f) *
             (1.0 + SainsotFit(q_c, h, theta_f) * std::tan(a1) * std::tan(a1)));
    EXPECT_NEAR(pe.PinionCompliance(r).foundation, expected, 1e-12 * expected) << "r = " << r;
  }
}

TEST(PotentialEnergyStiffness, PlaneStrainScalesTheYoungsModulus) {
  // E_e = E/(1 - nu^2) in bending, axial and foundation; shear (G) unchanged.
  const ToothBlank g = Steel(30, 0.003, 0.0);
  PotentialEnergyStiffness::Options strain;
  strain.plane_strain = true;
  const PotentialEnergyStiffness stress_model(g, g), strain_model(g, g, strain);
  const double r = 0.046;
  const auto a = stress_model.PinionCompliance(r), b = strain_model.PinionCompliance(r);
  EXPECT_NEAR(b.bending / a.bending, 0.91, 1e-12);
  EXPECT_NEAR(b.axial / a.axial, 0.91, 1e-12);
  EXPECT_NEAR(b.foundation / a.foundation, 0.91, 1e-12);
  EXPECT_NEAR(b.shear / a.shear, 1.0, 1e-12);
}

TEST(PotentialEnergyStiffness, EqualAsymmetricAnglesGiveTheSymmetricToothExactly) {
  // One code path for both kinds of teeth: a 25/25 "asymmetric" blank is the symmetric one,
  // bit for bit (and Tian's symmetric integrals are checked above).
  ToothBlank symmetric = Steel(30, 0.003, 0.1, 25.0, 25.0);
  ToothBlank asymmetric = Steel(30, 0.003, 0.1, 20.0, 30.0);
  asymmetric.drive_pressure_angle_rad = DegToRad(25.0);
  asymmetric.coast_pressure_angle_rad = DegToRad(25.0);
  const PotentialEnergyStiffness a(symmetric, symmetric), b(asymmetric, asymmetric);
  for (double r : {0.0440, 0.0455, 0.0470, 0.0483}) {
    EXPECT_EQ(a.PairStiffness(r, r), b.PairStiffness(r, r)) << "r = " << r;
  }
}

TEST(PotentialEnergyStiffness, SymmetricUnderSwappingIdenticalGears) {
  const ToothBlank g = Steel(40, 0.002, 0.2);
  const PotentialEnergyStiffness pe(g, g);
  const double lo = pe.LowestContactRadius(1), hi = g.tip_radius_m;
  for (int i = 0; i <= 10; ++i) {
    const double r1 = lo + (hi - lo) * i / 10.0, r2 = hi - (hi - lo) * i / 13.0;
    const double k12 = pe.PairStiffness(r1, r2), k21 = pe.PairStiffness(r2, r1);
    EXPECT_TRUE(std::isfinite(k12));
    EXPECT_GT(k12, 0.0);
    EXPECT_NEAR(k12, k21, 1e-14 * k12) << "r1 = " << r1 << ", r2 = " << r2;
  }
}

TEST(PotentialEnergyStiffness, ToothSofterTowardsTheTip) {
  // Derivative-free check: the single-tooth stiffness falls as the contact moves towards the
  // tip, for symmetric, shifted and asymmetric teeth. Range: from where the load line is
  // normal to the tooth axis (a1 = tan alpha - a2 = 0, r = r_b sqrt(1 + a2^2), a2 the half
  // base angle of the drive flank) to the tip. There every moment arm r_b - y cos a1 and the
  // beam length grow with r. Just above the base circle (a1 < 0) the load line tilts towards
  // the tip and the arm grows again as the contact goes down, a real (small) effect where
  // gears do not touch: the mate's tip stops above it (FZG-C pinion: a1 = 0 at 34.08 mm, start
  // of active profile 34.10 mm).
  struct Case {
    int z;
    double x, drive, coast;
  };
  for (const Case& t : {Case{16, 0.18, 20, 20}, Case{35, 0, 20, 20}, Case{105, 0, 20, 20},
                        Case{36, 0, 35, 20}, Case{24, -0.2, 25, 20}, Case{40, 0.3, 20, 30}}) {
    const ToothBlank g = Steel(t.z, 0.002, t.x, t.drive, t.coast);
    const PotentialEnergyStiffness pe(g, g);
    const double alpha = DegToRad(t.drive);
    const double a2 = (0.5 * kPi + 2.0 * t.x * std::tan(alpha)) / t.z + Inv(alpha);
    const double r_b = 0.5 * t.z * 0.002 * std::cos(alpha);
    const double lo = std::max(pe.LowestContactRadius(1), r_b * std::sqrt(1.0 + a2 * a2));
    const double hi = g.tip_radius_m;
    double previous = 1.0 / pe.PinionCompliance(lo).Total();
    for (int i = 1; i <= 40; ++i) {
      const double r = lo + (hi - lo) * i / 40.0;
      const double k = 1.0 / pe.PinionCompliance(r).Total();
      EXPECT_LT(k, previous) << "z = " << t.z << ", drive " << t.drive << ", r = " << r;
      EXPECT_GT(k, 0.0);
      previous = k;
    }
  }
}

TEST(PotentialEnergyStiffness, ThirtyFiveDegreeDriveFlankIsStifferThanTwenty) {
  // Seed 000 pair (36 teeth, P = 8, m = 3.175 mm, same tip radius) with a 35 deg drive /
  // 20 deg coast flank against the symmetric 20 deg tooth. Physics: the 35 deg drive flank
  // has a smaller base circle (r_p cos 35 deg < r_p cos 20 deg) and widens faster towards
  // the root, so at the same radius the asymmetric tooth is thicker below the pitch circle
  // (same thickness at the pitch circle for x = 0) and the load line is steeper, turning
  // bending into compression: both lower the compliance. Seed 000 section 6 finds the
  // asymmetric tooth ~6.6 % less stressed in FE for the same load, consistent with this.
  const ToothBlank sym = Steel(36, 0.003175, 0.0);
  const ToothBlank asym = Steel(36, 0.003175, 0.0, 35.0, 20.0);
  const PotentialEnergyStiffness k20(sym, sym), k35(asym, asym);
  const double lo = std::max(k20.LowestContactRadius(1), k35.LowestContactRadius(1));
  const double hi = sym.tip_radius_m;
  for (int i = 0; i <= 10; ++i) {
    const double r = lo + (hi - lo) * i / 10.0;
    EXPECT_GT(k35.PairStiffness(r, r), k20.PairStiffness(r, r)) << "r = " << r;
  }
}

TEST(PotentialEnergyStiffness, QuadratureIsConverged) {
  // 24 Gauss points per smooth piece (the default) against 96.
  const ToothBlank p = Steel(17, 0.003, 0.3, 30.0, 20.0), w = Steel(60, 0.003, -0.1);
  PotentialEnergyStiffness::Options fine;
  fine.quadrature_points = 96;
  const PotentialEnergyStiffness a(p, w), b(p, w, fine);
  for (double f : {0.0, 0.3, 0.6, 1.0}) {
    const double r1 = a.LowestContactRadius(1) + f * (p.tip_radius_m - a.LowestContactRadius(1));
    const double r2 = w.tip_radius_m - f * (w.tip_radius_m - a.LowestContactRadius(2));
    EXPECT_NEAR(a.PairStiffness(r1, r2), b.PairStiffness(r1, r2), 1e-9 * b.PairStiffness(r1, r2));
  }
}

TEST(PotentialEnergyStiffness, RejectsRingGearsAndPointedTeeth) {
  const ToothBlank g = Steel(30, 0.002, 0.0);
  ToothBlank ring = Steel(60, 0.002, 0.0);
  ring.internal = true;
  try {
    PotentialEnergyStiffness(g, ring);
    ADD_FAILURE() << "expected InputError";
  } catch (const InputError& e) {
    ASSERT_EQ(e.problems().size(), 1u);
    EXPECT_EQ(e.problems()[0].key, "gear.mesh_stiffness");
  }
  // 12 teeth, x = 1, r_a = (z/2 + 1 + x) m: psi(r_a) = (pi/2 + 2 tan 20)/12 + inv 20 deg
  // - inv 45.19 deg = 0.1916 + 0.0149 - 0.2180 < 0, the flanks cross below the tip.
  const ToothBlank pointed = Steel(12, 0.002, 1.0);
  EXPECT_THROW(PotentialEnergyStiffness(pointed, g), InputError);
  ToothBlank bad = g;
  bad.poisson_ratio = 0.6;
  try {
    PotentialEnergyStiffness(g, bad);
    ADD_FAILURE() << "expected InputError";
  } catch (const InputError& e) {
    ASSERT_EQ(e.problems().size(), 1u);
    EXPECT_EQ(e.problems()[0].key, "gear.wheel.poisson_ratio");
    EXPECT_EQ(e.problems()[0].value, "0.6");
  }
}

}  // namespace
}  // namespace tehl
