#include "gear/stiffness_blank_check.hpp"

#include <cmath>
#include <cstdio>

#include "tehl/units.hpp"

namespace tehl::internal {

std::string FormatValue(double v) {
  char buf[32];
  std::snprintf(buf, sizeof(buf), "%.6g", v);
  return buf;
}

InputProblem MethodRangeProblem(const std::string& value,
                                const std::string& rule,
                                const std::string& allowed) {
  return InputProblem{"", 0, "gear.mesh_stiffness", value, rule, allowed};
}

std::vector<InputProblem> CheckToothBlank(const ToothBlank& b, const std::string& which) {
  std::vector<InputProblem> out;
  const std::string member = "gear." + which + ".";
  auto add = [&](const std::string& key, const std::string& value, const std::string& rule,
                 const std::string& allowed) {
    out.push_back(InputProblem{"", 0, key, value, rule, allowed});
  };
  auto finite = [](double v) { return std::isfinite(v); };

  if (b.teeth < 3) {
    add(member + "teeth", std::to_string(b.teeth), "too few teeth", "an integer >= 3");
  }
  if (!finite(b.module_m) || b.module_m <= 0) {
    add("gear.module_m", FormatValue(b.module_m), "must be > 0 [m]", "a positive length");
  }
  const double max_angle = DegToRad(45.0);
  for (const auto& [name, angle] :
       {std::pair<const char*, double>{"pressure_angle_deg", b.drive_pressure_angle_rad},
        {"coast_pressure_angle_deg", b.coast_pressure_angle_rad}}) {
    if (!finite(angle) || angle <= 0 || angle > max_angle) {
      add(std::string("gear.") + name, FormatValue(RadToDeg(angle)),
          "pressure angle out of range [deg]", "0 < angle <= 45 deg");
    }
  }
  if (!finite(b.profile_shift) || std::abs(b.profile_shift) > 1.5) {
    add(member + "profile_shift", FormatValue(b.profile_shift), "out of range [-]",
        "-1.5 <= x <= 1.5");
  }
  if (!finite(b.dedendum_coefficient) || b.dedendum_coefficient <= 0) {
    add("gear.dedendum_coefficient", FormatValue(b.dedendum_coefficient), "must be > 0 [-]",
        "h_fP / m > 0");
  }
  if (!finite(b.root_fillet_coefficient) || b.root_fillet_coefficient < 0 ||
      b.root_fillet_coefficient >= b.dedendum_coefficient) {
    add("gear.root_fillet_coefficient", FormatValue(b.root_fillet_coefficient), "out of range [-]",
        "0 <= rho_fP / m < h_fP / m");
  }
  const double root_radius =
      0.5 * b.teeth * b.module_m - (b.dedendum_coefficient - b.profile_shift) * b.module_m;
  if (out.empty() && root_radius <= 0) {
    add(member + "teeth", std::to_string(b.teeth), "root radius would be <= 0", "z/2 > h_fP/m - x");
  }
  if (!finite(b.tip_radius_m) || b.tip_radius_m <= root_radius) {
    add(member + "tip_radius_m", FormatValue(b.tip_radius_m), "must exceed the root radius [m]",
        "r_a > r_f = " + FormatValue(root_radius) + " m");
  }
  if (!finite(b.face_width_m) || b.face_width_m <= 0) {
    add("gear.face_width_m", FormatValue(b.face_width_m), "must be > 0 [m]", "a positive length");
  }
  if (!finite(b.youngs_modulus_pa) || b.youngs_modulus_pa <= 0) {
    add(member + "youngs_modulus_pa", FormatValue(b.youngs_modulus_pa), "must be > 0 [Pa]",
        "a positive modulus");
  }
  if (!finite(b.poisson_ratio) || b.poisson_ratio < 0 || b.poisson_ratio >= 0.5) {
    add(member + "poisson_ratio", FormatValue(b.poisson_ratio), "out of range [-]",
        "0 <= nu < 0.5");
  }
  if (!finite(b.bore_radius_m) || b.bore_radius_m < 0 ||
      (root_radius > 0 && b.bore_radius_m >= root_radius)) {
    add(member + "bore_radius_m", FormatValue(b.bore_radius_m), "out of range [m]",
        "0 (not given) or 0 < r_int < r_f");
  }
  return out;
}

}  // namespace tehl::internal
