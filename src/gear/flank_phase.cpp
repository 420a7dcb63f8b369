#include "tehl/gear/flank_phase.hpp"

#include <cmath>

#include "tehl/gear/involute.hpp"

namespace tehl {

GearPairSpec CoastSideSpec(const GearPairSpec& spec) {
  GearPairSpec s = spec;
  s.drive_pressure_angle_rad = spec.coast_pressure_angle_rad;
  s.coast_pressure_angle_rad = spec.drive_pressure_angle_rad;
  return s;
}

double CoastPhaseOffset(const GearPair& pair) {
  const GearGeometry& g = pair.pinion();
  const LineOfAction& d = pair.line(Flank::kDrive);
  const LineOfAction& c = pair.line(Flank::kCoast);
  const double theta_b = g.reference_thickness_m / g.pitch_radius_m +
                         Involute(g.drive.pressure_angle_rad) +
                         Involute(g.coast.pressure_angle_rad);
  const double delta = g.teeth *
                           (theta_b + d.working_pressure_angle_rad + c.working_pressure_angle_rad) /
                           (2.0 * kPi) -
                       d.a_m / d.base_pitch_m - c.a_m / c.base_pitch_m;
  return delta - std::floor(delta);
}

}  // namespace tehl
