// Central finite differences for the derivative tests of the lubricant laws (every model's
// derivatives against finite differences).
#pragma once

#include <algorithm>
#include <cmath>
#include <vector>

namespace tehl::testing {

// The operating range of gear contacts: p from 0 to 2 GPa, T from 300 to 400 K.
inline std::vector<double> TestPressures() {
  return {0.0, 1e5, 1e7, 1e8, 2.5e8, 5e8, 7.5e8, 1e9, 1.5e9, 2e9};  // [Pa]
}
inline std::vector<double> TestTemperatures() {
  return {300.0, 313.15, 340.0, 370.0, 400.0};  // [K]
}

// Steps: small enough that the truncation error (f''' h^2 / 6) stays below 1e-9 relative for
// d ln(eta)/dp up to 1e-7 1/Pa, large enough that rounding stays below 1e-9 relative.
inline constexpr double kPressureStep = 1e3;      // [Pa]
inline constexpr double kTemperatureStep = 1e-3;  // [K]

// The laws' contract is p >= 0: at p = 0 the difference is centred at p = h instead.
inline double CentredPressure(double p) { return std::max(p, kPressureStep); }

template <typename F>
double CentralDifference(F f, double x, double h) {
  return (f(x + h) - f(x - h)) / (2.0 * h);
}

// |a - b| <= rel |b| (+ a tiny absolute floor for derivatives that are exactly zero).
inline bool Close(double a, double b, double rel) {
  return std::abs(a - b) <= rel * std::abs(b) + 1e-300;
}

}  // namespace tehl::testing
