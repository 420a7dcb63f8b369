#include "ehl/eyring_wall_stress.hpp"

namespace tehl::internal {

double EyringWallStress(const EyringLaw& law,
                        const double* eta,
                        int nz,
                        double h,
                        double dpdx,
                        double du,
                        double /*newtonian_guess*/) {
  const double g = h * dpdx;  // tau(xi) = tau_1 + g xi
  double lo_limit = -1e300, hi_limit = 1e300;
  if (law.tau_l > 0) {
    // Keep |tau| < tau_l across the film.
    lo_limit = -law.tau_l * (1 - 1e-9) - std::min(0.0, g);
    hi_limit = law.tau_l * (1 - 1e-9) - std::max(0.0, g);
    if (lo_limit >= hi_limit) return 0.5 * (lo_limit + hi_limit);
  }
  double inv_mean = 0;
  for (int j = 0; j < nz; ++j) inv_mean += ((j == 0 || j == nz - 1) ? 0.5 : 1.0) / eta[j];
  const double eta_h = (nz - 1.0) / inv_mean;
  // Without a pressure gradient the stress is uniform across the film and the rate is
  // Rate(tau, 1) / eta(xi): the integral is h Rate(tau, 1) / eta_h, one sinh per evaluation
  // instead of nz (the Eyring factor of a thermal Ree-Eyring film calls this at every node of
  // every coupling iteration; the sinh and its expm1 were a quarter of such a run). Without a
  // limiting stress its root is the asinh law itself.
  const bool uniform = g == 0;
  if (uniform && !(law.tau_l > 0)) return law.tau0 * std::asinh(eta_h * du / (h * law.tau0));
  auto residual = [&](double t1, double* slope) {
    const double scale = h / (nz - 1.0);
    if (uniform) {
      *slope = law.Slope(t1, 1.0) * inv_mean * scale;
      return law.Rate(t1, 1.0) * inv_mean * scale - du;
    }
    double f = 0, d = 0;
    for (int j = 0; j < nz; ++j) {
      const double w = (j == 0 || j == nz - 1) ? 0.5 : 1.0;
      const double tau = t1 + g * j / (nz - 1.0);
      f += w * law.Rate(tau, eta[j]);
      d += w * law.Slope(tau, eta[j]);
    }
    *slope = d * scale;
    return f * scale - du;
  };
  double t = law.tau0 * std::asinh(eta_h * du / (h * law.tau0)) - 0.5 * g;
  t = std::clamp(t, lo_limit, hi_limit);
  // Grow a bracket [lo, hi] around the root.
  double slope;
  double lo = t, hi = t;
  double r_lo = residual(lo, &slope), r_hi = r_lo;
  for (double step = law.tau0; r_lo > 0 && lo > lo_limit; step *= 2) {
    hi = lo;
    r_hi = r_lo;
    lo = std::max(lo - step, lo_limit);
    r_lo = residual(lo, &slope);
  }
  for (double step = law.tau0; r_hi < 0 && hi < hi_limit; step *= 2) {
    lo = hi;
    r_lo = r_hi;
    hi = std::min(hi + step, hi_limit);
    r_hi = residual(hi, &slope);
  }
  if (r_lo > 0) return lo;
  if (r_hi < 0) return hi;
  t = 0.5 * (lo + hi);
  for (int it = 0; it < 100; ++it) {
    const double r = residual(t, &slope);
    if (r > 0)
      hi = t;
    else
      lo = t;
    if (std::abs(r) <= 1e-12 * std::abs(du) || hi - lo <= 1e-13 * (std::abs(t) + law.tau0)) break;
    double next = t - r / slope;
    if (!(next > lo && next < hi) || !std::isfinite(next)) next = 0.5 * (lo + hi);
    t = next;
  }
  return t;
}

}  // namespace tehl::internal
