// ISO 6336-1:2006 method B, single stiffness c' and mesh stiffness c_gamma_alpha
// (VALIDATION.md section 5):
//   q' = C1 + C2/zn1 + C3/zn2 + C4 x1 + C5 x1/zn1 + C6 x2 + C7 x2/zn2 + C8 x1^2 + C9 x2^2
//        [mm um / N], C1..C9 = 0.04723, 0.15551, 0.25791, -0.00635, -0.11654, -0.00193,
//        -0.24188, 0.00529, 0.00182 (x2, not x1, in the C7 and C9 terms);
//   c'_th = 1/q';  c' = c'_th C_M C_R C_B cos(beta) (E / E_st);
//   C_M = 0.8, C_R = 1 (solid disc gears);
//   C_B = 0.5 (C_B1 + C_B2), C_B,i = [1 + 0.5 (1.2 - h_fP,i/m)] [1 - 0.02 (20 deg - alpha_n,i)]
//        (= 0.975 for h_fP = 1.25 m and alpha_n = 20 deg);
//   E / E_st: material factor for pairs other than steel/steel, E = 2 E1 E2 / (E1 + E2),
//        E_st = 206 GPa (1 for steel/steel);
//   c_gamma_alpha = c' (0.75 eps_alpha + 0.25);
//   zn = z / (cos^2(beta_b) cos(beta)), sin(beta_b) = sin(beta) cos(alpha_n) (virtual spur
//        gear); for an internal wheel zn2 -> infinity (the ring is treated as a rack).
// Range of the q' fit stated by the standard: -0.5 <= x1 + x2 <= 2.0 (enforced for external
// pairs). For asymmetric teeth alpha_n is the drive-flank angle.
#include <cmath>
#include <string>

#include "gear/stiffness_blank_check.hpp"
#include "tehl/error.hpp"
#include "tehl/gear/mesh_stiffness.hpp"
#include "tehl/units.hpp"

namespace tehl {
namespace {

constexpr double kC[9] = {0.04723,  0.15551,  0.25791, -0.00635, -0.11654,
                          -0.00193, -0.24188, 0.00529, 0.00182};
constexpr double kMeshFactorCM = 0.8;      // C_M, ISO 6336-1 method B
constexpr double kBlankFactorCR = 1.0;     // C_R, solid disc gears
constexpr double kSteelModulusPa = 206e9;  // E_st

double BasicRackFactor(const ToothBlank& b) {
  return (1.0 + 0.5 * (1.2 - b.dedendum_coefficient)) *
         (1.0 - 0.02 * (20.0 - RadToDeg(b.drive_pressure_angle_rad)));
}

void CheckIsoBlank(const ToothBlank& b, const std::string& which, ProblemList& problems) {
  using internal::FormatValue;
  const std::string member = "gear." + which + ".";
  auto add = [&](const std::string& key, const std::string& value, const std::string& rule,
                 const std::string& allowed) {
    problems.Add(InputProblem{"", 0, key, value, rule, allowed});
  };
  if (b.teeth < 3) add(member + "teeth", std::to_string(b.teeth), "too few teeth", "z >= 3");
  if (!std::isfinite(b.profile_shift) || std::abs(b.profile_shift) > 1.5) {
    add(member + "profile_shift", FormatValue(b.profile_shift), "out of range [-]",
        "-1.5 <= x <= 1.5");
  }
  if (!std::isfinite(b.dedendum_coefficient) || b.dedendum_coefficient <= 0) {
    add("gear.dedendum_coefficient", FormatValue(b.dedendum_coefficient), "must be > 0 [-]",
        "h_fP / m > 0");
  }
  const double a = b.drive_pressure_angle_rad;
  if (!std::isfinite(a) || a <= 0 || a > DegToRad(45.0)) {
    add("gear.pressure_angle_deg", FormatValue(RadToDeg(a)), "out of range [deg]",
        "0 < alpha <= 45 deg");
  }
  if (!std::isfinite(b.youngs_modulus_pa) || b.youngs_modulus_pa <= 0) {
    add(member + "youngs_modulus_pa", FormatValue(b.youngs_modulus_pa), "must be > 0 [Pa]",
        "a positive modulus");
  }
}

}  // namespace

IsoStiffness IsoMethodB(const ToothBlank& pinion,
                        const ToothBlank& wheel,
                        double eps_alpha,
                        double helix_angle_rad) {
  using internal::FormatValue;
  using internal::MethodRangeProblem;
  ProblemList problems;
  CheckIsoBlank(pinion, "pinion", problems);
  CheckIsoBlank(wheel, "wheel", problems);
  if (!std::isfinite(eps_alpha) || eps_alpha < 1.0) {
    problems.Add(MethodRangeProblem(FormatValue(eps_alpha), "iso: transverse contact ratio < 1",
                                    "eps_alpha >= 1"));
  }
  if (!std::isfinite(helix_angle_rad) || helix_angle_rad < 0 || helix_angle_rad > DegToRad(45.0)) {
    problems.Add(InputProblem{"", 0, "gear.helix_angle_deg", FormatValue(RadToDeg(helix_angle_rad)),
                              "out of range [deg]", "0 <= beta <= 45 deg"});
  }
  if (pinion.internal) {
    problems.Add(MethodRangeProblem("true", "iso: the pinion cannot be a ring gear",
                                    "internal = false for the pinion"));
  }
  const double x1 = pinion.profile_shift, x2 = wheel.profile_shift;
  if (!wheel.internal && std::isfinite(x1 + x2) && (x1 + x2 < -0.5 || x1 + x2 > 2.0)) {
    problems.Add(MethodRangeProblem(FormatValue(x1 + x2),
                                    "iso: x1 + x2 outside the range of the q' fit",
                                    "-0.5 <= x1 + x2 <= 2.0"));
  }
  problems.ThrowIfAny();

  const double beta = helix_angle_rad;
  auto virtual_teeth = [&](const ToothBlank& b) {
    const double sin_beta_b = std::sin(beta) * std::cos(b.drive_pressure_angle_rad);
    const double cos2_beta_b = 1.0 - sin_beta_b * sin_beta_b;
    return b.teeth / (cos2_beta_b * std::cos(beta));
  };
  // ISO 6336-1 numbers the smaller gear 1 whichever drives: an external pair whose driver
  // has more teeth enters the fit with the two members swapped (a ring is always gear 2).
  const bool swap = !wheel.internal && wheel.teeth < pinion.teeth;
  const ToothBlank& gear1 = swap ? wheel : pinion;
  const ToothBlank& gear2 = swap ? pinion : wheel;
  const double xs1 = gear1.profile_shift, xs2 = gear2.profile_shift;
  const double inv_zn1 = 1.0 / virtual_teeth(gear1);
  const double inv_zn2 = gear2.internal ? 0.0 : 1.0 / virtual_teeth(gear2);

  IsoStiffness out;
  out.q_prime_mm_um_per_n = kC[0] + kC[1] * inv_zn1 + kC[2] * inv_zn2 + kC[3] * xs1 +
                            kC[4] * xs1 * inv_zn1 + kC[5] * xs2 + kC[6] * xs2 * inv_zn2 +
                            kC[7] * xs1 * xs1 + kC[8] * xs2 * xs2;
  out.c_prime_th_n_per_mm_um = 1.0 / out.q_prime_mm_um_per_n;
  const double c_b = 0.5 * (BasicRackFactor(pinion) + BasicRackFactor(wheel));
  const double e1 = pinion.youngs_modulus_pa, e2 = wheel.youngs_modulus_pa;
  const double material = (2.0 * e1 * e2 / (e1 + e2)) / kSteelModulusPa;
  out.c_prime_n_per_mm_um =
      out.c_prime_th_n_per_mm_um * kMeshFactorCM * kBlankFactorCR * c_b * std::cos(beta) * material;
  out.c_gamma_alpha_n_per_mm_um = out.c_prime_n_per_mm_um * (0.75 * eps_alpha + 0.25);
  return out;
}

}  // namespace tehl
