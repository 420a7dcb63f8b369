// DC motor laws of seed 001 section 3 (dc_motor.hpp) and the operating point with a load.
#include "tehl/drive/dc_motor.hpp"

#include <cmath>
#include <cstdio>
#include <limits>

#include "tehl/error.hpp"

namespace tehl {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

bool Series(const DcMotorSpec& s) { return s.type == DcMotorType::kSeries; }

}  // namespace

std::string ToString(DcMotorType t) {
  switch (t) {
    case DcMotorType::kSeparatelyExcited:
      return "separately_excited";
    case DcMotorType::kShunt:
      return "shunt";
    case DcMotorType::kPermanentMagnet:
      return "permanent_magnet";
    case DcMotorType::kSeries:
      return "series";
  }
  return "?";
}

std::optional<DcMotorType> DcMotorTypeFromString(std::string_view s) {
  for (DcMotorType t : {DcMotorType::kSeparatelyExcited, DcMotorType::kShunt,
                        DcMotorType::kPermanentMagnet, DcMotorType::kSeries})
    if (ToString(t) == s) return t;
  return std::nullopt;
}

std::string ToString(SpeedRegion r) {
  switch (r) {
    case SpeedRegion::kConstantTorque:
      return "constant torque (armature voltage control)";
    case SpeedRegion::kConstantPower:
      return "constant power (field weakening)";
    case SpeedRegion::kBeyondMaximum:
      return "beyond the maximum speed";
  }
  return "?";
}

DcMotor::DcMotor(const DcMotorSpec& spec) : spec_(spec) {
  ProblemList p;
  auto rule = [&](bool ok, const char* key, double v, const char* what, const char* allowed) {
    if (ok) return;
    char buf[48];
    std::snprintf(buf, sizeof buf, "%g", v);
    p.Add({"", 0, key, buf, what, allowed});
  };
  auto positive = [](double x) { return std::isfinite(x) && x > 0; };
  auto non_negative = [](double x) { return std::isfinite(x) && x >= 0; };
  rule(positive(spec.supply_voltage_v), "supply_voltage_v", spec.supply_voltage_v, "must be > 0",
       "a terminal voltage > 0 [V]");
  rule(positive(spec.armature_resistance_ohm), "armature_resistance_ohm",
       spec.armature_resistance_ohm, "must be > 0", "a resistance > 0 [Ohm]");
  rule(positive(spec.speed_constant), "speed_constant", spec.speed_constant, "must be > 0",
       "K_w > 0 [V s/(A rad)], permanent magnet [V s/rad]");
  rule(non_negative(spec.torque_constant), "torque_constant", spec.torque_constant, "must be >= 0",
       "K_a >= 0 (0 = lossless K_a)");
  rule(non_negative(spec.rated_current_a), "rated_current_a", spec.rated_current_a, "must be >= 0",
       "I_r >= 0 [A] (0 = no speed-control envelope)");
  rule(non_negative(spec.max_speed_rad_s), "max_speed_rad_s", spec.max_speed_rad_s, "must be >= 0",
       "a speed >= 0 [rad/s] (0 = no limit)");
  if (spec.type == DcMotorType::kSeparatelyExcited)
    rule(positive(spec.field_current_a), "field_current_a", spec.field_current_a,
         "a separately excited motor needs its field current", "I_f > 0 [A]");
  if (spec.type == DcMotorType::kShunt)
    rule(positive(spec.field_resistance_ohm), "field_resistance_ohm", spec.field_resistance_ohm,
         "a shunt motor needs its field resistance (I_f = E / R_f)", "R_f > 0 [Ohm]");
  p.ThrowIfAny();
  // Energy: the developed power T w may not exceed the power E_b I_a the armature takes
  // from the supply, so K_a I_a w <= K_w I_f w I_a (3.1.1-3.1.2): K_a <= K_w I_f (permanent
  // magnet K_w; series, T = K_a I_a^2 and E_b = K_w I_a w: K_a <= K_w).
  if (spec.torque_constant > Flux() * (1 + 1e-12)) {
    char buf[160];
    std::snprintf(buf, sizeof buf, "%.6g", Flux());
    const std::string lossless = buf;
    const std::string unit = Series(spec) ? " N m/A^2" : " N m/A";
    const std::string law = Series(spec)                                 ? "K_w"
                            : spec.type == DcMotorType::kPermanentMagnet ? "K_w"
                            : spec.type == DcMotorType::kShunt           ? "K_w E / R_f"
                                                                         : "K_w I_f";
    std::snprintf(buf, sizeof buf, "%g", spec.torque_constant);
    p.Add({"", 0, "torque_constant", buf,
           "exceeds the lossless " + law + " = " + lossless + unit +
               ": the shaft would give more power than the armature takes (T w > E_b I_a)",
           "0 < K_a <= " + lossless + unit + " (0 = the lossless value)"});
  }
  if (spec.rated_current_a > 0 && BaseSpeed() <= 0)
    p.Add({"", 0, "rated_current_a", std::to_string(spec.rated_current_a),
           "I_r R_a reaches the supply voltage: no base speed", "I_r < E / R_a [A]"});
  p.ThrowIfAny();
}

double DcMotor::FieldCurrent() const {
  switch (spec_.type) {
    case DcMotorType::kSeparatelyExcited:
      return spec_.field_current_a;
    case DcMotorType::kShunt:
      return spec_.supply_voltage_v / spec_.field_resistance_ohm;
    default:
      return 0.0;
  }
}

double DcMotor::Flux() const {
  if (spec_.type == DcMotorType::kPermanentMagnet || Series(spec_)) return spec_.speed_constant;
  return spec_.speed_constant * FieldCurrent();
}

double DcMotor::TorqueConstant() const {
  return spec_.torque_constant > 0 ? spec_.torque_constant : Flux();
}

double DcMotor::SpeedAtCurrent(double ia) const {
  const double e_b = spec_.supply_voltage_v - ia * spec_.armature_resistance_ohm;
  if (Series(spec_)) return ia > 0 ? e_b / (spec_.speed_constant * ia) : kInf;
  return e_b / Flux();
}

double DcMotor::TorqueAtCurrent(double ia) const {
  return Series(spec_) ? TorqueConstant() * ia * ia : TorqueConstant() * ia;
}

double DcMotor::CurrentAtSpeed(double w) const {
  // Series: E = I_a (K_w w + R_a); otherwise E = K_w I_f w + I_a R_a.
  if (Series(spec_))
    return spec_.supply_voltage_v / (spec_.speed_constant * w + spec_.armature_resistance_ohm);
  return (spec_.supply_voltage_v - Flux() * w) / spec_.armature_resistance_ohm;
}

double DcMotor::TorqueAtSpeed(double w) const { return TorqueAtCurrent(CurrentAtSpeed(w)); }

double DcMotor::NoLoadSpeed() const {
  return Series(spec_) ? kInf : spec_.supply_voltage_v / Flux();
}

double DcMotor::StallTorque() const {
  return TorqueAtCurrent(spec_.supply_voltage_v / spec_.armature_resistance_ohm);
}

double DcMotor::InputPower(double ia) const {
  const double line = spec_.type == DcMotorType::kShunt ? ia + FieldCurrent() : ia;
  return spec_.supply_voltage_v * line;
}

double DcMotor::BaseSpeed() const {
  return spec_.rated_current_a > 0 ? SpeedAtCurrent(spec_.rated_current_a) : 0.0;
}

double DcMotor::RatedTorque() const {
  return spec_.rated_current_a > 0 ? TorqueAtCurrent(spec_.rated_current_a) : 0.0;
}

SpeedRegion DcMotor::Region(double w) const {
  const double a = std::abs(w);
  if (spec_.max_speed_rad_s > 0 && a > spec_.max_speed_rad_s) return SpeedRegion::kBeyondMaximum;
  return a <= BaseSpeed() ? SpeedRegion::kConstantTorque : SpeedRegion::kConstantPower;
}

double DcMotor::TorqueLimit(double w) const {
  if (spec_.rated_current_a <= 0) return kInf;
  switch (Region(w)) {
    case SpeedRegion::kConstantTorque:
      return RatedTorque();
    case SpeedRegion::kConstantPower:
      // No field to weaken in a permanent-magnet motor: nothing above the base speed.
      if (spec_.type == DcMotorType::kPermanentMagnet) return 0.0;
      return RatedTorque() * BaseSpeed() / std::abs(w);
    case SpeedRegion::kBeyondMaximum:
      return 0.0;
  }
  return 0.0;
}

MotorOperatingPoint SolveOperatingPoint(const DcMotor& motor, const MotorLoad& load) {
  if (!(load.efficiency > 0 && load.efficiency <= 1) || load.train_value == 0 ||
      !std::isfinite(load.train_value) || !(load.torque_nm >= 0) || !(load.viscous_nm_s >= 0))
    throw InputError(InputProblem{"", 0, "load", "",
                                  "needs T_0 >= 0, c >= 0, a nonzero train value and "
                                  "0 < efficiency <= 1",
                                  "a valid MotorLoad"});
  const double i = std::abs(load.train_value);
  // Load torque seen at the motor shaft at motor speed w (w >= 0).
  auto reflected = [&](double w) {
    return (load.torque_nm + load.viscous_nm_s * i * w) * i / load.efficiency;
  };
  MotorOperatingPoint op;
  auto fill = [&](double w) {
    op.motor_speed_rad_s = w;
    op.armature_current_a =
        w == 0 ? motor.spec().supply_voltage_v / motor.spec().armature_resistance_ohm
               : motor.CurrentAtSpeed(w);
    op.motor_torque_nm = motor.TorqueAtCurrent(op.armature_current_a);
    op.field_current_a = motor.FieldCurrent();
    op.input_power_w = motor.InputPower(op.armature_current_a);
    op.shaft_power_w = op.motor_torque_nm * w;
    op.load_speed_rad_s = load.train_value * w;
    op.load_torque_nm = load.torque_nm + load.viscous_nm_s * std::abs(op.load_speed_rad_s);
    op.load_power_w = op.load_torque_nm * std::abs(op.load_speed_rad_s);
    op.within_envelope = op.motor_torque_nm <= motor.TorqueLimit(w) * (1 + 1e-12);
  };
  auto f = [&](double w) { return motor.TorqueAtSpeed(w) - reflected(w); };
  if (f(0.0) <= 0) {
    fill(0.0);
    op.termination = MotorOperatingPoint::Termination::kStalled;
    op.message = "stalled: the reflected load torque exceeds the stall torque";
    return op;
  }
  double hi = motor.NoLoadSpeed();
  if (!std::isfinite(hi)) {  // series: widen until the load wins
    hi = 1.0;
    while (f(hi) > 0 && hi < 1e12) hi *= 2;
    if (f(hi) > 0) {
      op.termination = MotorOperatingPoint::Termination::kRunaway;
      op.message = "runaway: a series motor without load has no steady speed";
      return op;
    }
  }
  double lo = 0.0;
  for (int k = 0; k < 200 && hi - lo > 1e-15 * hi; ++k) {
    const double mid = 0.5 * (lo + hi);
    (f(mid) > 0 ? lo : hi) = mid;
  }
  fill(0.5 * (lo + hi));
  op.message = op.within_envelope ? "running" : "running above the rated torque envelope";
  return op;
}

ControlledPoint SolveControlledPoint(const DcMotor& motor, const MotorLoad& load, double w) {
  const DcMotorSpec& s = motor.spec();
  const double i = std::abs(load.train_value);
  const double t = (load.torque_nm + load.viscous_nm_s * i * std::abs(w)) * i / load.efficiency;
  ControlledPoint c;
  c.region = s.rated_current_a > 0 ? motor.Region(w) : SpeedRegion::kConstantTorque;
  c.motor_torque_nm = t;
  const bool series = s.type == DcMotorType::kSeries;
  const double ka = motor.TorqueConstant();
  if (c.region == SpeedRegion::kConstantTorque || series) {
    // Rated field, armature voltage E = E_b + I_a R_a.
    c.field_current_a = motor.FieldCurrent();
    c.armature_current_a = series ? std::sqrt(t / ka) : t / ka;
    const double flux = series ? s.speed_constant * c.armature_current_a : motor.Flux();
    c.armature_voltage_v = flux * std::abs(w) + c.armature_current_a * s.armature_resistance_ohm;
  } else if (s.type == DcMotorType::kPermanentMagnet) {
    c.feasible = false;
    c.message = "a permanent-magnet motor has no field to weaken above the base speed";
    return c;
  } else {
    // Rated voltage; flux phi from phi^2 w - E phi + T R_a (ka/phi_r) = 0, the larger root
    // (smaller current). K_a scales with the field: K_a = ka * phi / phi_rated.
    const double phi_r = motor.Flux();
    const double k = ka / phi_r;  // K_a / (K_w I_f): 1 for the lossless motor
    const double disc = s.supply_voltage_v * s.supply_voltage_v -
                        4 * std::abs(w) * t * s.armature_resistance_ohm / k;
    if (disc < 0) {
      c.feasible = false;
      c.message = "the load needs more power than the supply can give at this speed";
      return c;
    }
    const double phi = (s.supply_voltage_v + std::sqrt(disc)) / (2 * std::abs(w));
    c.field_current_a = phi / s.speed_constant;
    c.armature_current_a = t / (k * phi);
    c.armature_voltage_v = s.supply_voltage_v;
  }
  if (s.rated_current_a > 0 && c.armature_current_a > s.rated_current_a * (1 + 1e-12)) {
    c.feasible = false;
    c.message = "the armature current exceeds the rated current";
  }
  if (c.armature_voltage_v > s.supply_voltage_v * (1 + 1e-12)) {
    c.feasible = false;
    c.message = "the armature voltage needed exceeds the supply voltage";
  }
  if (c.region == SpeedRegion::kBeyondMaximum) {
    c.feasible = false;
    c.message = "beyond the maximum speed of field weakening";
  }
  if (c.feasible) c.message = "feasible";
  return c;
}

}  // namespace tehl
