#include "drive/motor_schema.hpp"

#include <algorithm>
#include <cmath>

#include "tehl/units.hpp"

namespace tehl::internal {
namespace {

bool Rejected(const Document& doc, const std::string& section) {
  const std::string prefix = section + ".";
  return std::any_of(doc.problems().begin(), doc.problems().end(), [&](const InputProblem& p) {
    return p.key.rfind(prefix, 0) == 0 || p.key == "[" + section + "]";
  });
}

}  // namespace

std::vector<KeySpec> MotorKeys() {
  return {
      Required(Text("type", "", "DC motor type (seed 001 section 3)",
                    {"separately_excited", "shunt", "permanent_magnet", "series"}),
               "\"shunt\""),
      // Up to 1e5 V: DC drives run at most a few kV (traction); beyond, stall torque and power
      // leave the range of numbers.
      Required(Real("supply_voltage_v", "V", "", "terminal (supply) voltage E", 0.0, 1e5, false),
               "220.0"),
      Required(Positive("armature_resistance_ohm", "Ohm", "",
                        "armature circuit resistance R_a (series: with the series field)"),
               "0.5"),
      Required(Positive("speed_constant", "V s/(A rad)", "",
                        "K_w of E_b = K_w I_f w (shunt, separately excited), E_b = K_w I_a w "
                        "(series); permanent magnet: E_b = K_w w [V s/rad]"),
               "1.2"),
      Real("torque_constant", "N m/A", "0.0",
           "K_a of T = K_a I_a (series: T = K_a I_a^2 [N m/A^2]); 0 = lossless, from K_w", 0.0),
      Positive("field_current_a", "A", "", "field current I_f (separately_excited only)"),
      Positive("field_resistance_ohm", "Ohm", "",
               "shunt field resistance R_f, I_f = E / R_f (shunt only)"),
      Positive("rated_current_a", "A", "",
               "rated armature current I_r: base speed and the constant-torque / "
               "constant-power envelope"),
      Positive("max_speed_rpm", "rpm", "", "end of field weakening (needs rated_current_a)"),
      Positive("speed_command_rpm", "rpm", "",
               "speed-controlled drive: the motor runs at this speed (armature voltage "
               "below the base speed, field weakening above); absent = fixed supply"),
  };
}

std::optional<DcMotorSpec> ReadMotorSection(Document& doc, const std::string& section) {
  if (Rejected(doc, section)) return std::nullopt;
  DcMotorSpec s;
  s.type =
      DcMotorTypeFromString(doc.String(section, "type")).value_or(DcMotorType::kPermanentMagnet);
  s.supply_voltage_v = doc.Real(section, "supply_voltage_v");
  s.armature_resistance_ohm = doc.Real(section, "armature_resistance_ohm");
  s.speed_constant = doc.Real(section, "speed_constant");
  s.torque_constant = doc.Real(section, "torque_constant");
  s.field_current_a = doc.Real(section, "field_current_a");
  s.field_resistance_ohm = doc.Real(section, "field_resistance_ohm");
  s.rated_current_a = doc.Real(section, "rated_current_a");
  s.max_speed_rad_s = RpmToRadPerS(doc.Real(section, "max_speed_rpm"));
  bool ok = true;
  auto only = [&](const char* key, DcMotorType t) {
    if (doc.Given(section, key) && s.type != t) {
      doc.Problem(section, key, "only a " + ToString(t) + " motor has this key",
                  "remove it, or type = \"" + ToString(t) + "\"");
      ok = false;
    }
  };
  only("field_current_a", DcMotorType::kSeparatelyExcited);
  only("field_resistance_ohm", DcMotorType::kShunt);
  if (doc.Given(section, "max_speed_rpm") && !doc.Given(section, "rated_current_a")) {
    doc.Problem(section, "max_speed_rpm", "field weakening needs the rated current",
                "rated_current_a with max_speed_rpm");
    ok = false;
  }
  if (!ok) return std::nullopt;
  try {
    const DcMotor motor(s);
    if (s.max_speed_rad_s > 0 && s.max_speed_rad_s < motor.BaseSpeed()) {
      doc.Problem(section, "max_speed_rpm",
                  "below the base speed " + FormatReal(RadPerSToRpm(motor.BaseSpeed())) + " rpm",
                  "a speed >= the base speed [rpm]");
      return std::nullopt;
    }
  } catch (const InputError& e) {
    for (const auto& p : e.problems()) {
      const std::string key = p.key == "max_speed_rad_s" ? "max_speed_rpm" : p.key;
      doc.Problem(
          section,
          doc.Given(section, key) || p.key == "field_current_a" || p.key == "field_resistance_ohm"
              ? key
              : "type",
          p.rule, p.allowed);
    }
    return std::nullopt;
  }
  return s;
}

std::vector<KeySpec> CaseMotorKeys() {
  std::vector<KeySpec> keys = MotorKeys();
  keys.push_back(Real("train_value", "-", "1.0",
                      "w_pinion / w_motor of the drive between motor and pinion (sign ignored)",
                      0.0, std::nullopt, false));
  keys.push_back(Real("efficiency", "-", "1.0", "efficiency of that drive", 0.0, 1.0, false));
  return keys;
}

std::optional<double> MotorPinionSpeed(Document& doc,
                                       const std::string& section,
                                       double pinion_torque_nm) {
  const std::optional<DcMotorSpec> spec = ReadMotorSection(doc, section);
  if (!spec) return std::nullopt;
  const DcMotor motor(*spec);
  MotorLoad load;
  load.torque_nm = pinion_torque_nm;
  load.train_value = std::abs(doc.Real(section, "train_value"));
  load.efficiency = doc.Real(section, "efficiency");
  if (const auto w = MotorSpeedCommand(doc, section)) {
    const ControlledPoint c = SolveControlledPoint(motor, load, *w);
    if (!c.feasible) {
      doc.Problem(section, "speed_command_rpm",
                  "the drive cannot carry the pinion torque at "
                  "this speed: " +
                      c.message,
                  "a speed and load inside the motor's envelope");
      return std::nullopt;
    }
    return load.train_value * *w;
  }
  const MotorOperatingPoint op = SolveOperatingPoint(motor, load);
  if (!op.usable() || op.motor_speed_rad_s <= 0) {
    doc.Problem(section, "type",
                "no running operating point against the pinion torque: " + op.message,
                "a motor whose torque-speed line meets the load");
    return std::nullopt;
  }
  return load.train_value * op.motor_speed_rad_s;
}

std::optional<double> MotorSpeedCommand(const Document& doc, const std::string& section) {
  if (!doc.Given(section, "speed_command_rpm")) return std::nullopt;
  return RpmToRadPerS(doc.Real(section, "speed_command_rpm"));
}

}  // namespace tehl::internal
