#include "tehl/gear/operating_point.hpp"

#include <cmath>

namespace tehl {

double TorqueFromPower(double power_w, double w1) { return power_w / w1; }

ToothLoad NominalToothLoad(const GearPair& pair, const OperatingPoint& op, Flank flank) {
  const LineOfAction& l = pair.line(flank);
  ToothLoad t;
  t.normal_force_n = op.pinion_torque_nm / l.pinion_base_radius_m;
  t.tangential_force_n = t.normal_force_n * std::cos(l.working_pressure_angle_rad);
  t.load_per_width_n_per_m = t.normal_force_n / pair.spec().face_width_m;
  return t;
}

}  // namespace tehl
