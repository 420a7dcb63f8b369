// Helpers shared by the lubricant laws: parameter rules and number formatting.
#pragma once

#include <string>
#include <vector>

#include "tehl/error.hpp"

namespace tehl::internal {

// Roelands constants (Roelands 1966; VALIDATION.md section 1).
inline constexpr double kRoelandsLnEtaInf = 9.67;            // -ln(eta_inf / 1 Pa s) [-]
inline constexpr double kRoelandsPressureScale = 5.1e-9;     // 1/p0 in the law [1/Pa]
inline constexpr double kHoupertPressure = 1.96e8;           // p0 in Houpert's alpha [Pa]
inline constexpr double kRoelandsTemperatureOffset = 138.0;  // T_inf of the S0 form [K]

// Appends a problem (key = the parameter's field name) when ok is false.
void RequireParameter(bool ok,
                      const char* key,
                      double value,
                      std::string rule,
                      std::string allowed,
                      std::vector<InputProblem>* problems);

// Throws InputError when problems is not empty, each key qualified as "<law>.<key>".
void ThrowIfInvalid(const char* law, std::vector<InputProblem> problems);

// A number for Describe(): 7 significant digits, no trailing zeros.
std::string Num(double x);

}  // namespace tehl::internal
