// The involute function and the relations of one involute flank (seed 000 eqs. 2.7-2.13,
// Mabie & Reinholtz ch. 2). Angles in radians, lengths in metres. Pure functions,
// thread-safe.
#pragma once

namespace tehl {

// inv(phi) = tan(phi) - phi (seed 000 eq. 2.10). phi in [0, pi/2) [rad] -> [rad].
double Involute(double phi_rad);

// The angle phi in [0, pi/2) with inv(phi) = value, by Newton's method on
// f(phi) = tan(phi) - phi - value, f'(phi) = tan^2(phi), started from the series
// phi ~ (3 value)^(1/3) and safeguarded by bisection. Converges to |f| < 1e-15 (relative).
// value >= 0 [rad]; throws std::domain_error for a negative or non-finite value.
double InverseInvolute(double value_rad);

// Profile (pressure) angle of an involute at radius r on base radius rb:
// cos(phi) = rb / r (seed 000 eq. 2.9). Requires r >= rb > 0 [m] -> [rad].
double ProfileAngleAtRadius(double base_radius_m, double radius_m);

// Roll distance from the base-circle tangent point to the point at radius r:
// sqrt(r^2 - rb^2) = rb tan(phi(r)), the radius of curvature of the involute there [m].
double RollDistance(double base_radius_m, double radius_m);

}  // namespace tehl
