// DC motors in steady state (seed 001 section 3), SI units (rad/s, not the document's rpm):
//   separately excited / shunt:  E_b = K_w I_f w,  w = (E - I_a R_a)/(K_w I_f)   (3.1.1)
//                                T = K_a I_a                                      (3.1.2)
//                                shunt: the field is across the supply, I_f = E / R_f
//   permanent magnet:            E_b = K_w w,      w = (E - I_a R_a)/K_w, T = K_a I_a
//   series (flux ~ I_a):         E_b = K_w I_a w,  w = (E - I_a R_a)/(K_w I_a)
//                                (the printed (3.1.3) has K_a I_a^2 in the denominator, an
//                                error of the source, corrected as in the extraction)
//                                T = K_a I_a^2                                    (3.1.4)
// K_a defaults to the lossless value (E_b I_a = T w): K_w I_f, K_w, or K_w for series.
// A larger K_a would make T w > E_b I_a (more shaft power than the armature takes) and is
// rejected; a smaller one models the armature's own losses.
// R_a is the whole armature circuit (series: armature + series field).
// Speed control (seed 001, Fig. 3.1.3): with the rated armature current I_r and the rated
// field, the base speed w_b = (E - I_r R_a)/(K_w I_f) separates the constant-torque region
// below it (armature voltage control, T_max = K_a I_r) from the constant-power region above
// it (field weakening, E_b = E - I_r R_a kept, T_max = P_r / w, P_r = T_max w_b).
#pragma once

#include <optional>
#include <string>
#include <string_view>

namespace tehl {

enum class DcMotorType { kSeparatelyExcited, kShunt, kPermanentMagnet, kSeries };
std::string ToString(DcMotorType t);  // "separately_excited", "shunt", "permanent_magnet", "series"
std::optional<DcMotorType> DcMotorTypeFromString(std::string_view s);

struct DcMotorSpec {
  DcMotorType type = DcMotorType::kPermanentMagnet;
  double supply_voltage_v = 0;         // E, terminal voltage [V]
  double armature_resistance_ohm = 0;  // R_a, armature circuit (series: + field) [Ohm]
  double speed_constant = 0;           // K_w: [V s/(A rad)] (shunt, separate, series) or
                                       // [V s/rad] (permanent magnet)
  double torque_constant = 0;          // K_a: [N m/A] (T = K_a I_a) or [N m/A^2] (series);
                                       // 0 = the lossless value
  double field_current_a = 0;          // I_f, separately excited [A]
  double field_resistance_ohm = 0;     // R_f, shunt: I_f = E / R_f [Ohm]
  double rated_current_a = 0;          // I_r for the speed-control envelope; 0 = none [A]
  double max_speed_rad_s = 0;          // end of field weakening; 0 = no limit [rad/s]
};

// Where the speed-controlled drive runs (seed 001, Fig. 3.1.3).
enum class SpeedRegion { kConstantTorque, kConstantPower, kBeyondMaximum };
std::string ToString(SpeedRegion r);

class DcMotor {
 public:
  explicit DcMotor(const DcMotorSpec& spec);  // validates; throws InputError (keys = fields)
  const DcMotorSpec& spec() const { return spec_; }

  double FieldCurrent() const;    // I_f; 0 for permanent magnet and series [A]
  double Flux() const;            // K_w I_f or K_w (not series) [V s/rad]
  double TorqueConstant() const;  // K_a as used [N m/A] or [N m/A^2]
  double SpeedAtCurrent(double armature_current_a) const;   // (3.1.1) / corrected (3.1.3)
  double TorqueAtCurrent(double armature_current_a) const;  // (3.1.2) / (3.1.4) [N m]
  double CurrentAtSpeed(double speed_rad_s) const;          // inverse of SpeedAtCurrent [A]
  double TorqueAtSpeed(double speed_rad_s) const;           // the torque-speed line [N m]
  double NoLoadSpeed() const;                               // T = 0; +infinity for series [rad/s]
  double StallTorque() const;                               // at w = 0, I_a = E / R_a [N m]
  double InputPower(double armature_current_a) const;       // E I_a (+ E I_f for shunt) [W]

  // Speed-control envelope; all 0 without rated_current_a.
  double BaseSpeed() const;                      // w_b [rad/s]
  double RatedTorque() const;                    // K_a I_r (series K_a I_r^2) [N m]
  double TorqueLimit(double speed_rad_s) const;  // T_max(w): constant torque, then P_r / w
  SpeedRegion Region(double speed_rad_s) const;

 private:
  DcMotorSpec spec_;
};

// A load on the driven member of a train: T_L = T_0 + c |w_L|, reflected to the motor
// through the train value i = w_L / w_m and the train efficiency eta (motor drives):
// T_L,motor = T_L |i| / eta.
struct MotorLoad {
  double torque_nm = 0;     // T_0 [N m]
  double viscous_nm_s = 0;  // c [N m s/rad]
  double train_value = 1;   // i = w_L / w_m [-], nonzero
  double efficiency = 1;    // eta in (0, 1] [-]
};

struct MotorOperatingPoint {
  enum class Termination { kRunning, kStalled, kRunaway };
  Termination termination = Termination::kRunning;
  std::string message;
  double motor_speed_rad_s = 0;   // [rad/s]
  double motor_torque_nm = 0;     // developed torque [N m]
  double armature_current_a = 0;  // [A]
  double field_current_a = 0;     // [A]
  double input_power_w = 0;       // electrical [W]
  double shaft_power_w = 0;       // T_m w_m [W]
  double load_speed_rad_s = 0;    // w_L = i w_m [rad/s]
  double load_torque_nm = 0;      // T_L at w_L [N m]
  double load_power_w = 0;        // T_L |w_L| [W]
  bool within_envelope = true;    // T_m <= TorqueLimit(w_m) (true without an envelope)
  bool usable() const { return termination == Termination::kRunning; }
};

// The speed where the motor's torque-speed line meets the reflected load (bisection on the
// monotone difference). Stalled: the load exceeds the stall torque; runaway: a series motor
// without load.
MotorOperatingPoint SolveOperatingPoint(const DcMotor& motor, const MotorLoad& load);

// A speed-controlled drive at motor speed w against `load`: the armature voltage (constant-
// torque region, rated field) or the field current (constant-power region, rated voltage)
// that carries the load (not for permanent magnet above the base speed: no field to weaken).
struct ControlledPoint {
  SpeedRegion region = SpeedRegion::kConstantTorque;
  double armature_voltage_v = 0;  // [V]
  double field_current_a = 0;     // [A] (series, permanent magnet: 0)
  double armature_current_a = 0;  // [A]
  double motor_torque_nm = 0;     // [N m]
  bool feasible = true;           // I_a <= I_r and the region is reachable
  std::string message;
};
ControlledPoint SolveControlledPoint(const DcMotor& motor,
                                     const MotorLoad& load,
                                     double speed_rad_s);

}  // namespace tehl
