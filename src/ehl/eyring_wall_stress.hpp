// The Ree-Eyring film across one grid node (docs/theory.md, "Ree-Eyring film"): the shear rate
// of a stress and the wall stress that carries a given sliding speed. Private to src/ehl.
#pragma once

#include <algorithm>
#include <cmath>

namespace tehl::internal {

// Ree-Eyring shear rate with an optional limiting shear stress [1/s].
struct EyringLaw {
  double tau0 = 0;   // Eyring stress [Pa]
  double tau_l = 0;  // limiting shear stress at this pressure [Pa]; 0 = none
  double Rate(double tau, double eta) const {
    const double s = std::clamp(tau / tau0, -600.0, 600.0);
    double g = tau0 / eta * std::sinh(s);
    if (tau_l > 0) g /= std::max(1.0 - (tau / tau_l) * (tau / tau_l), 1e-12);
    return g;
  }
  // d Rate / d tau.
  double Slope(double tau, double eta) const {
    const double s = std::clamp(tau / tau0, -600.0, 600.0);
    double g = std::cosh(s) / eta;
    if (tau_l > 0) {
      const double r = tau / tau_l, d = std::max(1.0 - r * r, 1e-12);
      g = g / d + tau0 / eta * std::sinh(s) * 2.0 * r / (tau_l * d * d);
    }
    return g;
  }
};

// Wall stress tau_1 with h int gdot(tau_1 + h p' xi) dxi = du (trapezoidal in xi). The
// integral increases with tau_1: a bracket is grown from the Couette estimate
// tau0 asinh(eta_h du / (h tau0)) (exact for a uniform film without pressure gradient, eta_h
// the harmonic mean), then Newton's method safeguarded by bisection.
double EyringWallStress(const EyringLaw& law,
                        const double* eta,
                        int nz,
                        double h,
                        double dpdx,
                        double du,
                        double /*newtonian_guess*/);

}  // namespace tehl::internal
