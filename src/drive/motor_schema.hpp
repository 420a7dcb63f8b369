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

}  // namespace tehl::internal
