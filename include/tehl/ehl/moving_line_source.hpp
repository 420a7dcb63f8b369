// Jaeger's steady moving line heat source on the surface of a half-space, at any Peclet
// number (Jaeger 1942; Carslaw & Jaeger 1959, section 10.7; K.L. Johnson, Contact Mechanics,
// 1985, section 13.3). A line source of strength Q' [W/m] is fixed in the contact frame and
// the solid's surface moves past it at u > 0 in +x; with kappa = k/(rho c) the steady surface
// temperature rise a distance X = x - x' downstream of the source is
//
//   theta(X) = Q'/(pi k) e^(omega X) K0(omega |X|),   omega = u / (2 kappa)  [1/m],
//
// K0 the modified Bessel function of the second kind. Downstream (X -> +inf) it tends to
// Q' / sqrt(pi rho c k u X), the high-Peclet kernel of seed 004 eqs. (14)-(15)
// (include/tehl/ehl/surface_temperature.hpp); upstream it decays like e^(-2 omega |X|): the
// heat the solid conducts ahead of the source, which the high-Peclet form leaves out.
//
// Cell weights need the kernel's integral, which is closed-form (differentiate to check,
// with K0' = -K1 and K1' = -K0 - K1/x):
//   J(s) = int_0^s e^t K0(|t|) dt = s e^s (K0(s) + K1(s)) - 1            for s >= 0,
//                                 = -(|s| e^-|s| (K0(|s|) - K1(|s|)) + 1)  for s < 0,
// J(s) ~ sqrt(2 pi s) as s -> +inf and J(-inf) = -1 (int_0^inf e^-t K0(t) dt = 1,
// Gradshteyn & Ryzhik 6.611.9).
#pragma once

namespace tehl {

// e^x K0(x) and e^x K1(x) for x > 0 (exponentially scaled, finite for every x > 0).
struct ScaledBesselK {
  double k0 = 0;  // e^x K0(x) [-]
  double k1 = 0;  // e^x K1(x) [-]
};
// std::cyl_bessel_k below x = 30, the asymptotic series of Hankel above (error < 1e-16 there).
// x must be finite and > 0 (else NaN).
ScaledBesselK ScaledBesselK01(double x);

// J(s) above, any finite s [-].
double MovingLineSourceIntegral(double s);

}  // namespace tehl
