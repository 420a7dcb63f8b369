// Speed and load of a gear pair, and the nominal tooth load (VALIDATION.md section 5).
#pragma once

#include "tehl/gear/gear_pair.hpp"

namespace tehl {

struct OperatingPoint {
  double pinion_speed_rad_s = 0;  // w1 [rad/s], > 0
  double pinion_torque_nm = 0;    // T1 [N m], > 0
};

// T1 = P / w1 [N m] from the transmitted power [W] and the pinion speed [rad/s].
double TorqueFromPower(double power_w, double pinion_speed_rad_s);

// Nominal (static) load of the mesh, carried by one pair in single contact.
struct ToothLoad {
  double normal_force_n = 0;          // F_bt = T1 / r_b1, along the line of action [N]
  double tangential_force_n = 0;      // F_t = T1 / r_w1 on the working pitch circle [N]
  double load_per_width_n_per_m = 0;  // w = F_bt / b [N/m]
};
// The drive flank's base radius unless `flank` says otherwise.
ToothLoad NominalToothLoad(const GearPair& pair,
                           const OperatingPoint& op,
                           Flank flank = Flank::kDrive);

}  // namespace tehl
