// The [motor] section shared by train files and case files: its keys (for the declarative
// schema) and the reading of a DcMotorSpec with every problem at its file line. Private.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "base/schema.hpp"
#include "tehl/drive/dc_motor.hpp"

namespace tehl::internal {

// Keys of [motor]: type, supply_voltage_v, armature_resistance_ohm, speed_constant,
// torque_constant, field_current_a, field_resistance_ohm, rated_current_a, max_speed_rpm,
// speed_command_rpm.
std::vector<KeySpec> MotorKeys();

// Reads the motor of `section`; problems (including the cross-key rules of the motor type
// and DcMotor's own validation) go to `doc`. Nothing when the section has problems.
std::optional<DcMotorSpec> ReadMotorSection(Document& doc, const std::string& section);

// The commanded motor speed of `section` [rad/s], if speed_command_rpm is given.
std::optional<double> MotorSpeedCommand(const Document& doc, const std::string& section);

// Keys of a case file's [motor]: MotorKeys() plus train_value and efficiency (the drive
// between the motor and the pinion).
std::vector<KeySpec> CaseMotorKeys();

// The pinion speed of a gear case whose pinion a DC motor drives: the motor's operating point
// against the pinion torque reflected through [motor] train_value and efficiency (or the
// speed command). Problems go to `doc` at the [motor] keys; nothing when there are any.
// [rad/s], > 0.
std::optional<double> MotorPinionSpeed(Document& doc, const std::string& section,
                                       double pinion_torque_nm);

}  // namespace tehl::internal
