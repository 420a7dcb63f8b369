#include "tehl/gear/involute.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "tehl/units.hpp"

namespace tehl {

double Involute(double phi) { return std::tan(phi) - phi; }

double InverseInvolute(double value) {
  if (!(value >= 0.0) || !std::isfinite(value))
    throw std::domain_error("InverseInvolute: value must be finite and >= 0");
  if (value == 0.0) return 0.0;
  // Bracket [lo, hi] with inv(lo) <= value <= inv(hi); inv is increasing on [0, pi/2).
  double lo = 0.0, hi = 0.5 * kPi;
  // Start from the series inv(phi) = phi^3/3 + ..., accurate for small angles and an
  // over-estimate otherwise, then Newton with bisection as a safeguard.
  double phi = std::min(std::cbrt(3.0 * value), 0.5 * kPi * (1.0 - 1e-12));
  for (int i = 0; i < 100; ++i) {
    const double f = Involute(phi) - value;
    if (f > 0.0)
      hi = phi;
    else
      lo = phi;
    if (std::abs(f) <= 1e-15 * value) break;
    const double t = std::tan(phi);
    double next = phi - f / (t * t);
    if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
    if (next == phi) break;
    phi = next;
  }
  return phi;
}

double ProfileAngleAtRadius(double rb, double r) {
  const double c = rb / r;
  return std::acos(c >= 1.0 ? 1.0 : c);
}

double RollDistance(double rb, double r) {
  const double d = r * r - rb * rb;
  return d > 0.0 ? std::sqrt(d) : 0.0;
}

}  // namespace tehl
