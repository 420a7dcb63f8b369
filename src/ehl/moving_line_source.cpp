// Jaeger's moving line source (include/tehl/ehl/moving_line_source.hpp).
#include "tehl/ehl/moving_line_source.hpp"

#include <cmath>
#include <limits>

namespace tehl {

namespace {

constexpr double kAsymptoticFrom = 30.0;  // [-]

// e^x K_nu(x) ~ sqrt(pi/(2x)) sum_k a_k(nu) / x^k, a_k = a_(k-1) (4 nu^2 - (2k-1)^2) / (8k)
// (Abramowitz & Stegun 9.7.2). At x >= 30 the terms fall below 1e-17 of the first well
// before they start to grow (near k = 2x).
double ScaledKAsymptotic(double nu, double x) {
  const double mu = 4 * nu * nu;
  double term = 1, sum = 1;
  for (int k = 1; k < 60; ++k) {
    term *= (mu - (2.0 * k - 1) * (2.0 * k - 1)) / (8.0 * k * x);
    sum += term;
    if (std::abs(term) < 1e-17 * std::abs(sum)) break;
  }
  return std::sqrt(M_PI / (2 * x)) * sum;
}

}  // namespace

ScaledBesselK ScaledBesselK01(double x) {
  if (!(std::isfinite(x) && x > 0)) {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    return {nan, nan};
  }
  if (x >= kAsymptoticFrom) return {ScaledKAsymptotic(0, x), ScaledKAsymptotic(1, x)};
  const double e = std::exp(x);
  return {e * std::cyl_bessel_k(0.0, x), e * std::cyl_bessel_k(1.0, x)};
}

double MovingLineSourceIntegral(double s) {
  if (s == 0) return 0.0;
  const double a = std::abs(s);
  const ScaledBesselK k = ScaledBesselK01(a);
  if (s > 0) return a * (k.k0 + k.k1) - 1.0;
  // |s| e^-|s| (K0 - K1) = |s| e^(-2|s|) (e^|s| K0 - e^|s| K1).
  return -(a * std::exp(-2 * a) * (k.k0 - k.k1) + 1.0);
}

}  // namespace tehl
