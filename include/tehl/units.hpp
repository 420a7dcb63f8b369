// Units in tehl: SI throughout (m, s, kg, N, Pa, K, Pa s, W/(m K), J/(kg K)); temperatures are
// absolute. Keys in input files carry the unit in their name where it is not obvious
// (`module_m`, `inlet_temperature_k`); degrees (`_deg`) and revolutions per minute (`_rpm`)
// are the only non-SI units accepted in files, and they are converted on reading.
#pragma once

#include <numbers>

namespace tehl {

inline constexpr double kPi = std::numbers::pi;

constexpr double DegToRad(double deg) { return deg * kPi / 180.0; }
constexpr double RadToDeg(double rad) { return rad * 180.0 / kPi; }
constexpr double RpmToRadPerS(double rpm) { return rpm * 2.0 * kPi / 60.0; }
constexpr double RadPerSToRpm(double w) { return w * 60.0 / (2.0 * kPi); }

// Reduced (effective) modulus of a line contact, Dowson-Higginson convention:
// 2/E' = (1 - nu1^2)/E1 + (1 - nu2^2)/E2. Johnson's E* equals E'/2. [Pa]
constexpr double ReducedModulus(double e1_pa, double nu1, double e2_pa, double nu2) {
  return 2.0 / ((1.0 - nu1 * nu1) / e1_pa + (1.0 - nu2 * nu2) / e2_pa);
}

// Hertz scales of a line contact per unit face width (VALIDATION.md section 1).
struct HertzScales {
  double reduced_radius_m = 0;   // R, 1/R = 1/rho1 + 1/rho2 [m]
  double half_width_m = 0;       // b = sqrt(8 w R / (pi E')) [m]
  double max_pressure_pa = 0;    // p_H = sqrt(w E' / (2 pi R)) = E' b / (4 R) [Pa]
};
HertzScales LineContactHertz(double load_n_per_m, double reduced_radius_m, double e_prime_pa);

// Temperatures are absolute; anything below this is taken for degrees Celsius and refused,
// in files and in the film solver's conditions [K].
inline constexpr double kMinAbsoluteTemperatureK = 200.0;
// ... and no lubricant law describes an oil above this [K].
inline constexpr double kMaxTemperatureK = 1000.0;

// Hertz line-contact theory, on which the film model builds, needs b << R. Cases whose b / R
// exceeds this bound (p_H > E' / 20: a load or a modulus in the wrong unit) are refused.
inline constexpr double kMaxHertzWidthRatio = 0.2;  // [-]
// The largest load per unit width with b <= kMaxHertzWidthRatio R [N/m].
double MaxHertzLoad(double reduced_radius_m, double e_prime_pa);

// Dimensionless groups of Dowson-Higginson/Hamrock (U, G, W) and Moes (M, L).
// U = eta0 um / (E' R), G = alpha E', W = w / (E' R); M = W (2U)^-1/2, L = G (2U)^1/4.
struct DimensionlessGroups {
  double U = 0, G = 0, W = 0, M = 0, L = 0;
};
DimensionlessGroups LineContactGroups(double eta0_pa_s, double alpha_per_pa, double um_m_s,
                                      double load_n_per_m, double reduced_radius_m,
                                      double e_prime_pa);

}  // namespace tehl
