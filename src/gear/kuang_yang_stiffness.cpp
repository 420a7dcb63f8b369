#include "tehl/gear/kuang_yang_stiffness.hpp"

#include <algorithm>
#include <cmath>

#include "gear/stiffness_blank_check.hpp"
#include "tehl/units.hpp"

namespace tehl {
namespace {

constexpr double kSteelModulusPa = 206e9;  // steel reference of the fit (VALIDATION.md 1)
constexpr double kSteelTolerance = 0.10;   // "steel": E within 10 % of 206 GPa

struct Coefficients {
  double a0, a1, a2, a3;  // [N/(um mm)]
};

// Seed 000 eqs. 4.4a-d, with the corrected A2 and A3 (see the header).
Coefficients FitCoefficients(int teeth) {
  const double z = teeth, z2 = z * z, z3 = z2 * z;
  return {3.867 + 1.612 * z - 0.02916 * z2 + 0.0001553 * z3,
          17.060 + 0.72896 * z - 0.01728 * z2 + 0.00009993 * z3,
          2.637 - 1.222 * z + 0.02217 * z2 - 0.0001179 * z3,
          -6.330 - 1.033 * z + 0.02068 * z2 - 0.0001130 * z3};
}

}  // namespace

std::vector<InputProblem> KuangYangStiffness::Validate(const ToothBlank& b,
                                                       const std::string& which) {
  using internal::FormatValue;
  using internal::MethodRangeProblem;
  std::vector<InputProblem> out = internal::CheckToothBlank(b, which);
  const std::string who = "kuang_yang (" + which + "): ";
  if (b.internal) {
    out.push_back(MethodRangeProblem("\"kuang_yang\"", who + "fitted for external gears only",
                                     "\"iso\" for a ring gear, or an external pair"));
  }
  if (!(b.teeth > 12 && b.teeth < 100)) {
    out.push_back(MethodRangeProblem(std::to_string(b.teeth),
                                     who + "number of teeth outside the fit", "12 < z < 100"));
  }
  if (!(std::abs(b.profile_shift) < 0.6)) {
    out.push_back(MethodRangeProblem(FormatValue(b.profile_shift),
                                     who + "profile shift outside the fit", "-0.6 < x < 0.6"));
  }
  if (!(std::abs(b.youngs_modulus_pa / kSteelModulusPa - 1.0) <= kSteelTolerance)) {
    out.push_back(MethodRangeProblem(FormatValue(b.youngs_modulus_pa),
                                     who + "the fit is for steel gears: E [Pa]",
                                     "185e9 <= E <= 227e9 (steel)"));
  }
  // The fit depends on z and x only: it is of one tooth form, the standard 20 deg full-depth
  // tooth (h_aP = 1) of its use in seed 000; another pressure angle or addendum changes the
  // tooth it describes (at 18 deg with h_aP = 1.25 it is 21 % above the potential energy).
  if (std::abs(RadToDeg(b.drive_pressure_angle_rad) - 20.0) > 0.5) {
    out.push_back(MethodRangeProblem(FormatValue(RadToDeg(b.drive_pressure_angle_rad)),
                                     who + "the fit is of 20 deg teeth: pressure angle [deg]",
                                     "20 deg (the fit has no pressure angle), or "
                                     "\"potential_energy\""));
  }
  if (std::abs(b.addendum_coefficient - 1.0) > 0.05) {
    out.push_back(MethodRangeProblem(FormatValue(b.addendum_coefficient),
                                     who + "the fit is of full-depth teeth: addendum h_aP/m",
                                     "h_aP/m = 1 (the fit has no addendum), or "
                                     "\"potential_energy\""));
  }
  if (b.drive_pressure_angle_rad != b.coast_pressure_angle_rad) {
    out.push_back(MethodRangeProblem(FormatValue(RadToDeg(b.coast_pressure_angle_rad)),
                                     who + "asymmetric teeth (coast angle != drive angle)",
                                     "symmetric teeth, or \"potential_energy\""));
  }
  return out;
}

KuangYangStiffness::KuangYangStiffness(const ToothBlank& pinion, const ToothBlank& wheel)
    : pinion_(pinion), wheel_(wheel) {
  ProblemList problems;
  problems.Append(Validate(pinion, "pinion"));
  problems.Append(Validate(wheel, "wheel"));
  problems.ThrowIfAny();
  face_width_m_ = std::min(pinion.face_width_m, wheel.face_width_m);
}

double KuangYangStiffness::SingleToothPerWidth(const ToothBlank& b, double r_m) {
  const Coefficients c = FitCoefficients(b.teeth);
  const double x = b.profile_shift;
  const double pitch_radius = 0.5 * b.teeth * b.module_m;
  const double u = (r_m - pitch_radius) / ((1.0 + x) * b.module_m);
  return (c.a0 + c.a1 * x) + (c.a2 + c.a3 * x) * u;
}

double KuangYangStiffness::PairStiffness(double r1_m, double r2_m) const {
  const double k1 = SingleToothPerWidth(pinion_, r1_m);
  const double k2 = SingleToothPerWidth(wheel_, r2_m);
  TEHL_ASSERT(k1 > 0 && k2 > 0, "contact radius outside the tooth");
  // [N/(um mm)] * b [mm] = N/um = 1e6 N/m; b [mm] = 1e3 b [m].
  return k1 * k2 / (k1 + k2) * face_width_m_ * 1e9;
}

}  // namespace tehl
