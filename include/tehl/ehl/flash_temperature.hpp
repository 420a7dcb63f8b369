// Blok's flash temperature of a sliding line contact: the peak rise of the surfaces above
// their bulk temperature when the friction heat mu w |u1 - u2| is released over the Hertz
// zone with the Hertz (semi-elliptic) distribution and shared by the two solids so that their
// peak rises are equal (H. Blok, Proc. General Discussion on Lubrication, IMechE 2 (1937)
// 222-235; K.L. Johnson, Contact Mechanics, 1985, section 13.3). Each solid is a half-space
// at a high Peclet number, as in the moving heat source of surface_temperature.hpp:
//
//   theta_i(x) = 1/sqrt(pi rho_i c_i k_i u_i) int_{-b}^{x} q_i(x') / sqrt(x - x') dx'.
//
// For q_i = Q_i (2 / (pi b)) sqrt(1 - (x/b)^2), with s = x/b,
//   max theta_i = c_B Q_i / (sqrt(b) e_i sqrt(u_i)),  e_i = sqrt(k_i rho_i c_i),
//   c_B = 2 max_s I(s) / pi^(3/2),  I(s) = int_{-1}^{s} sqrt(1 - t^2) / sqrt(s - t) dt,
// the maximum at s = 0.65223 (I = 2.1883067). Equal peaks with Q_1 + Q_2 = mu w |u1 - u2|:
//
//   theta_f = c_B mu w |u1 - u2| / (sqrt(b) (e_1 sqrt(u1) + e_2 sqrt(u2))),
//
// c_B = 0.7859834; c_B sqrt(2) = 1.1115 is Blok's 1.11 with the contact width 2b. For equal
// solids theta_f = c_B mu w |sqrt(u1) - sqrt(u2)| / (sqrt(b) e).
//
// Whatever the partition, c_B (Q_1 + Q_2) / sqrt(b) = theta_1 e_1 sqrt(u1) + theta_2 e_2
// sqrt(u2) for two semi-elliptic sources: theta_f is also the weighted mean of the two peak
// rises, weights e_i sqrt(u_i) (BlokWeightedRise), which compares a film solution's surface
// temperatures with theta_f without assuming equal peaks.
#pragma once

#include "tehl/ehl/surface_temperature.hpp"

namespace tehl {

// c_B = 2 max_s I(s) / pi^(3/2) above (Gauss-Legendre quadrature of I after t = s - (1 + s)
// sin^2(phi), which makes the integrand smooth, maximized by golden section; 1e-9 relative).
inline constexpr double kBlokFactor = 0.7859833957;

// A full film carries as shear stress at most about a tenth of its pressure (the limiting
// shear stress of lubricants, tau_L0 + Lambda p with Lambda of about 0.1 or less; Bair & Winer
// 1979): a Newtonian film's mu above twice that, and a flash temperature from it, are not
// physical (docs/results.md, "The friction note") [-].
inline constexpr double kPhysicalFrictionLimit = 0.2;

struct FlashTemperatureInputs {
  double friction_coefficient = 0;  // mu [-]; >= 0
  double load_n_per_m = 0;          // w [N/m]; >= 0
  double u1_m_s = 0, u2_m_s = 0;    // surface speeds through the contact [m/s]; >= 0
  double half_width_m = 0;          // Hertz half-width b [m]; > 0 when mu w > 0
};

// theta_f [K]; 0 without friction heat (mu w = 0 or u1 = u2). Throws InputError on negative
// or non-finite inputs, on b <= 0 with friction heat, or when both speeds are 0.
double BlokFlashTemperature(const FlashTemperatureInputs& in,
                            const SolidThermal& body1,
                            const SolidThermal& body2);

// Blok's partition (equal peak rises) with the finite-Peclet surface temperatures of
// surface_temperature.hpp (Jaeger's moving line source at each solid's own Peclet number
// u_i b / (2 kappa_i), conduction along the surface included): M_i, the peak rise of solid i
// carrying the whole heat mu w |u1 - u2| with the semi-elliptic distribution (exact cell
// means on `cells` cells across 2b), and theta_f = M_1 M_2 / (M_1 + M_2) (with one solid at
// rest, the other's M). Tends to BlokFlashTemperature at high Peclet numbers and stays below
// it. Same input rules, and cells >= 8; O(cells^2).
double FinitePecletFlashTemperature(const FlashTemperatureInputs& in,
                                    const SolidThermal& body1,
                                    const SolidThermal& body2,
                                    int cells = 256);

// Blok's flash temperature with a run's surface model: FinitePecletFlashTemperature when
// finite_peclet (effect `finite_peclet`), else BlokFlashTemperature.
double FlashTemperature(const FlashTemperatureInputs& in,
                        const SolidThermal& body1,
                        const SolidThermal& body2,
                        bool finite_peclet);

// (theta_1 e_1 sqrt(u1) + theta_2 e_2 sqrt(u2)) / (e_1 sqrt(u1) + e_2 sqrt(u2)) [K]: the peak
// rises theta_1, theta_2 of the two surfaces weighted as above; equal to theta_f for any
// partition of a semi-elliptic heat source. Same input rules for the speeds.
double BlokWeightedRise(double theta1_k,
                        double theta2_k,
                        double u1_m_s,
                        double u2_m_s,
                        const SolidThermal& body1,
                        const SolidThermal& body2);

}  // namespace tehl
