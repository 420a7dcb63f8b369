#include "tehl/ehl/inlet_truncation.hpp"

#include <algorithm>
#include <cmath>

#include "tehl/units.hpp"

namespace tehl {
namespace {

// Dry Hertz separation outside the contact, |X| = |x|/b >= 1: the gap of two cylinders pressed
// by a Hertz pressure, minus its value at the edge [m].
double HertzSeparation(double x, double b, double r) {
  const double a = std::abs(x) / b, s = std::sqrt(a * a - 1.0);
  return b * b / (2.0 * r) * (a * s - std::log(a + s));
}

// p_in = int_{-inf}^{x0} 12 eta um (h - h*)/h^3 dx for the gap h(x0) = h0 continued upstream
// with the dry Hertz separation of half-width b (the rigid parabola when b = 0) [Pa].
double MissingPressure(
    double x0, double b, double r, double eta, double um, double h0, double h_star) {
  auto gap = [&](double x) {
    return b > 0 ? h0 + HertzSeparation(x, b, r) - HertzSeparation(x0, b, r)
                 : h0 + (x * x - x0 * x0) / (2.0 * r);
  };
  // x = x0 / t, t in (0, 1]: dx = -x0 / t^2 dt; the integrand vanishes like t^2 at t -> 0.
  // Composite Simpson (the integrand is smooth in t; 512 intervals agree with 8192 to 1e-9).
  constexpr int kIntervals = 512;
  auto integrand = [&](double t) {
    if (t <= 0) return 0.0;
    const double x = x0 / t, h = gap(x);
    return 12.0 * eta * um * (h - h_star) / (h * h * h) * (-x0) / (t * t);
  };
  double sum = integrand(0.0) + integrand(1.0);
  for (int k = 1; k < kIntervals; ++k)
    sum += (k % 2 ? 4.0 : 2.0) * integrand(static_cast<double>(k) / kIntervals);
  return sum / (3.0 * kIntervals);
}

// `out` with the missing pressure p_in and Grubin's deficit 1 - exp(-(8/11) alpha p_in); as
// it was (no estimate) when p_in is not finite.
InletTruncation WithGrubinDeficit(InletTruncation out, double p_in, double alpha) {
  if (!std::isfinite(p_in)) return out;
  out.estimated = true;
  out.missing_pressure_pa = p_in;
  out.film_deficit = -std::expm1(-kGrubinExponent * alpha * p_in);
  return out;
}

}  // namespace

double IsoviscousInletLength(double r, double b, double um, double eta, double w) {
  if (!(r > 0) || !(um > 0) || !(eta > 0) || !(w > 0) || !(b >= 0)) return 0.0;
  const double h_martin = 4.896 * eta * um * r / w;  // Martin 1916 (VALIDATION.md section 2)
  const double weight = b > 0 ? std::min(1.0, h_martin * r / (b * b)) : 1.0;
  return std::min(kIsoviscousInletLengths * std::sqrt(2.0 * r * h_martin) * weight,
                  kIsoviscousInletMaxRadii * r);
}

double InletTruncation::InletFor(double x0, double target) const {
  if (!estimated || !(film_deficit > 0) || !(target > 0)) return x0;
  return x0 * std::cbrt(film_deficit / target);
}

InletTruncation EstimateInletTruncation(const Eigen::VectorXd& p_pa,
                                        const Eigen::VectorXd& h_m,
                                        const InletTruncationInputs& in) {
  InletTruncation out;
  const Eigen::Index n = p_pa.size();
  const double eta = in.inlet_viscosity_pa_s, um = in.um_m_s, r = in.reduced_radius_m;
  const double x0 = in.x_start_m, b = in.half_width_m;
  if (n < 3 || h_m.size() != n || !(in.pressure_viscosity_per_pa >= 0) || !(eta > 0) || !(um > 0) ||
      !(r > 0) || !(in.dx_m > 0) || !(x0 < 0) || (b > 0 && -x0 <= b))
    return out;
  const double h0 = h_m[0];
  if (!std::isfinite(h0) || !(h0 > 0) || !p_pa.head(3).allFinite()) return out;
  out.alpha_p_max = in.pressure_viscosity_per_pa * p_pa.maxCoeff();
  if (!(out.alpha_p_max >= kGrubinMinAlphaP)) {
    out.isoviscous_inlet_m = IsoviscousInletLength(r, b, um, eta, in.load_n_per_m);
    // Martin's load at l_iso is within 0.1 % of its limit and the deficit of a shorter inlet
    // grows about as (l_iso / |x0|)^2: only an inlet shorter than half of it is noted.
    out.short_isoviscous_inlet = -x0 < kShortIsoviscousInlet * out.isoviscous_inlet_m;
    const double w = in.load_n_per_m;
    if (w > 0) {
      const double h_martin = 4.896 * eta * um * r / w;
      const double l = std::sqrt(2.0 * r * h_martin);
      const bool rigid = b <= 0 || h_martin * r >= b * b;
      if (rigid && kIsoviscousInletLengths * l > kIsoviscousInletMaxRadii * r)
        out.rigid_film_deficit = 1.0 - RigidInletFilmRatio(x0 / l);
    }
    return out;
  }
  // h* from the flux at x0 (p = 0 there, so eta and rho are the inlet's): q / (rho um) =
  // h - h^3/(12 eta um) dp/dx, dp/dx one-sided to second order.
  const double dpdx = (-3.0 * p_pa[0] + 4.0 * p_pa[1] - p_pa[2]) / (2.0 * in.dx_m);
  const double h_star = h0 - h0 * h0 * h0 / (12.0 * eta * um) * dpdx;
  const double p_in = MissingPressure(x0, b, r, eta, um, h0, h_star);
  return WithGrubinDeficit(out, p_in, in.pressure_viscosity_per_pa);
}

InletTruncation PredictInletTruncation(const InletTruncationInputs& in, double central_film_m) {
  InletTruncation out;
  const double eta = in.inlet_viscosity_pa_s, um = in.um_m_s, r = in.reduced_radius_m;
  const double x0 = in.x_start_m, b = in.half_width_m, w = in.load_n_per_m;
  if (!(in.pressure_viscosity_per_pa >= 0) || !(eta > 0) || !(um > 0) || !(r > 0) || !(w > 0) ||
      !(x0 < 0) || !(b > 0) || -x0 <= b || !(central_film_m > 0))
    return out;
  out.alpha_p_max = in.pressure_viscosity_per_pa * 2.0 * w / (kPi * b);  // alpha p_H
  if (!(out.alpha_p_max >= kGrubinMinAlphaP)) {
    out.isoviscous_inlet_m = IsoviscousInletLength(r, b, um, eta, w);
    out.short_isoviscous_inlet = -x0 < kShortIsoviscousInlet * out.isoviscous_inlet_m;
    return out;
  }
  // The film is about flat at h_c over the Hertz zone and opens with the dry separation
  // outside it; h* (where dp/dx = 0) is taken as h_c.
  const double h0 = central_film_m + HertzSeparation(x0, b, r);
  const double p_in = MissingPressure(x0, b, r, eta, um, h0, central_film_m);
  return WithGrubinDeficit(out, p_in, in.pressure_viscosity_per_pa);
}

double RigidInletFilmRatio(double x0_over_l) {
  if (!(x0_over_l < 0)) return 0.0;
  // Martin's film in h0 and l = sqrt(2 R h0): H = 1 + X^2, dP/dX = (H - H*)/H^3 from P(X0) = 0
  // to the Reynolds exit P = P' = 0 at Xc = sqrt(H* - 1). With the antiderivatives
  //   F2 = X / (2 H) + atan(X) / 2,  F3 = X / (4 H^2) + 3 X / (8 H) + 3 atan(X) / 8
  // of 1/H^2 and 1/H^3, P(Xc) = 0 fixes H*, and by parts the load is
  //   W = -1/(2 H0) + H*/(4 H0^2) + 1/(4 H*),  H0 = 1 + X0^2,
  // 1/(4 H*) for an unbounded inlet (24 W = 4.896, Martin's constant). At a given load h0
  // scales with W.
  const auto f2 = [](double x) { return x / (2 * (1 + x * x)) + 0.5 * std::atan(x); };
  const auto f3 = [](double x) {
    const double h = 1 + x * x;
    return x / (4 * h * h) + 3 * x / (8 * h) + 0.375 * std::atan(x);
  };
  const auto exit_pressure = [&](double x0, double hs) {
    const double xc = std::sqrt(hs - 1);
    return f2(xc) - f2(x0) - hs * (f3(xc) - f3(x0));
  };
  const auto load = [&](double x0) {
    double lo = 1.0 + 1e-12, hi = 2.0;  // P(Xc) > 0 at lo, < 0 at hi
    for (int k = 0; k < 200 && hi - lo > 1e-15; ++k) {
      const double mid = 0.5 * (lo + hi);
      (exit_pressure(x0, mid) > 0 ? lo : hi) = mid;
    }
    const double hs = 0.5 * (lo + hi), h0 = 1 + x0 * x0;
    return -1 / (2 * h0) + hs / (4 * h0 * h0) + 1 / (4 * hs);
  };
  // The inlet is fixed in x, and x0 / sqrt(2 R h0) moves with the film it thins: in units of
  // Martin's length l_M the film ratio r solves r = W(X0 / sqrt(r)) / W(-inf) (a contraction:
  // W changes slowly with X0).
  const double unbounded = load(-1e8);
  double ratio = load(x0_over_l) / unbounded;
  for (int k = 0; k < 50; ++k) {
    const double next = load(x0_over_l / std::sqrt(ratio)) / unbounded;
    if (std::abs(next - ratio) < 1e-13) return next;
    ratio = next;
  }
  return ratio;
}

}  // namespace tehl
