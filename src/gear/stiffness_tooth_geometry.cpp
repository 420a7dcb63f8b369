#include "gear/stiffness_tooth_geometry.hpp"

#include <algorithm>
#include <cmath>

#include "tehl/error.hpp"
#include "tehl/units.hpp"

namespace tehl::internal {

StiffnessToothGeometry::StiffnessToothGeometry(const ToothBlank& blank)
    : teeth_(blank.teeth),
      dedendum_coefficient_(blank.dedendum_coefficient),
      fillet_coefficient_(blank.root_fillet_coefficient) {
  TEHL_ASSERT(!blank.internal && blank.teeth > 0 && blank.module_m > 0, "unchecked blank");
  const double z = blank.teeth;
  pitch_radius_ = 0.5 * z * blank.module_m;
  root_radius_ =
      pitch_radius_ - (blank.dedendum_coefficient - blank.profile_shift) * blank.module_m;
  tip_radius_ = blank.tip_radius_m;
  auto make_side = [&](double alpha) {
    Side s;
    s.pressure_angle = alpha;
    s.base_radius = pitch_radius_ * std::cos(alpha);
    s.involute_offset =
        (0.5 * kPi + 2.0 * blank.profile_shift * std::tan(alpha)) / z + Involute(alpha);
    return s;
  };
  drive_ = make_side(blank.drive_pressure_angle_rad);
  coast_ = make_side(blank.coast_pressure_angle_rad);
}

double StiffnessToothGeometry::HalfAngle(FlankSide s, double r_m) const {
  const Side& f = side(s);
  if (r_m <= f.base_radius) return f.involute_offset;  // radial flank below the base circle
  return f.involute_offset - Involute(std::acos(f.base_radius / r_m));
}

double StiffnessToothGeometry::HalfWidthAtAxial(FlankSide s, double y_m) const {
  // Fixed point r = y / cos psi(r): psi is small and varies slowly with r, so the map is a
  // strong contraction (factor ~ r tan(psi) dpsi/dr < 1e-2 on a real tooth).
  double r = y_m / std::cos(HalfAngle(s, y_m));
  for (int i = 0; i < 50; ++i) {
    const double next = y_m / std::cos(HalfAngle(s, r));
    const bool done = std::abs(next - r) <= 1e-15 * r;
    r = next;
    if (done) break;
  }
  return r * std::sin(HalfAngle(s, r));
}

double StiffnessToothGeometry::RootFilletAngle(FlankSide s) const {
  const double alpha = side(s).pressure_angle;
  const double rho = fillet_coefficient_;
  return 2.0 *
         (0.25 * kPi + (dedendum_coefficient_ - rho) * std::tan(alpha) + rho / std::cos(alpha)) /
         teeth_;
}

}  // namespace tehl::internal
