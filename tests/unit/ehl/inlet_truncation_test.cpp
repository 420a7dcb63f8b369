// EstimateInletTruncation: the missing inlet pressure against closed forms and an independent
// quadrature, and Grubin's deficit built from it.
#include "tehl/ehl/inlet_truncation.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

namespace tehl {
namespace {

constexpr double kEta = 0.1;     // inlet viscosity [Pa s]
constexpr double kUm = 2.0;      // entrainment speed [m/s]
constexpr double kR = 0.01;      // reduced radius [m]
constexpr double kAlpha = 2e-8;  // pressure-viscosity coefficient [1/Pa]
constexpr double kDx = 1e-6;     // node spacing [m]

// A film whose first three nodes carry p = 0, g dx, 2 g dx (so dp/dx = g at x0 exactly) and
// h0 at x0, with a peak p_peak downstream (alpha p_peak = 10 by default: a piezoviscous film;
// the rest is not read).
struct Film {
  Eigen::VectorXd p, h;
  Film(double h0, double g, double p_peak = 10 / kAlpha) : p(8), h(8) {
    for (int i = 0; i < 8; ++i) {
      p[i] = g * kDx * i;
      h[i] = h0;
    }
    p[7] = p_peak;
  }
};

InletTruncationInputs Inputs(double x0, double b) {
  InletTruncationInputs in;
  in.x_start_m = x0;
  in.dx_m = kDx;
  in.reduced_radius_m = kR;
  in.half_width_m = b;
  in.um_m_s = kUm;
  in.inlet_viscosity_pa_s = kEta;
  in.pressure_viscosity_per_pa = kAlpha;
  return in;
}

// Rigid far field h = (x^2 + c^2)/2R: int_{-inf}^{x0} dx/(x^2+c^2)^2 and ^3 in closed form
// (the antiderivatives of the standard tables, arctan -> -pi/2 at -inf).
double I2(double x, double c) {
  return x / (2 * c * c * (x * x + c * c)) + (std::atan(x / c) + M_PI / 2) / (2 * c * c * c);
}
double I3(double x, double c) {
  const double s = x * x + c * c;
  return x / (4 * c * c * s * s) + 3 * x / (8 * std::pow(c, 4) * s) +
         3 * (std::atan(x / c) + M_PI / 2) / (8 * std::pow(c, 5));
}

TEST(InletTruncation, RigidFarFieldMatchesTheClosedForm) {
  const double x0 = -5e-4, h0 = 20e-6, g = 5e9;
  const Film f(h0, g);
  const InletTruncation t = EstimateInletTruncation(f.p, f.h, Inputs(x0, 0.0));
  ASSERT_TRUE(t.estimated);
  const double h_star = h0 - h0 * h0 * h0 / (12 * kEta * kUm) * g;
  const double c = std::sqrt(2 * kR * h0 - x0 * x0);
  // p_in = 12 eta um [(2R)^2 I2 - h* (2R)^3 I3]
  const double expected =
      12 * kEta * kUm *
      (std::pow(2 * kR, 2) * I2(x0, c) - h_star * std::pow(2 * kR, 3) * I3(x0, c));
  EXPECT_NEAR(t.missing_pressure_pa, expected, 1e-8 * expected);
  EXPECT_NEAR(t.film_deficit, 1 - std::exp(-kGrubinExponent * kAlpha * expected), 1e-12);
}

// Hertz far field: an independent quadrature in u = ln(-x) (Simpson, 20000 intervals over
// 12 e-foldings; the integrand falls like e^-3u).
TEST(InletTruncation, HertzFarFieldMatchesAnIndependentQuadrature) {
  const double b = 1e-4, x0 = -4.5 * b, h0 = 8e-6, g = 2e10;
  const Film f(h0, g);
  const InletTruncation t = EstimateInletTruncation(f.p, f.h, Inputs(x0, b));
  ASSERT_TRUE(t.estimated);
  auto sep = [&](double x) {  // dry Hertz separation, |x| > b
    const double a = std::abs(x) / b, s = std::sqrt(a * a - 1);
    return b * b / (2 * kR) * (a * s - std::log(a + s));
  };
  const double h_star = h0 - h0 * h0 * h0 / (12 * kEta * kUm) * g;
  const double u0 = std::log(-x0), u1 = u0 + 12.0;
  const int m = 20000;
  double sum = 0;
  for (int k = 0; k <= m; ++k) {
    const double u = u0 + (u1 - u0) * k / m, x = -std::exp(u);
    const double h = h0 + sep(x) - sep(x0);
    const double f_u = 12 * kEta * kUm * (h - h_star) / (h * h * h) * std::exp(u);
    sum += (k == 0 || k == m ? 1 : (k % 2 ? 4 : 2)) * f_u;
  }
  const double expected = sum * (u1 - u0) / (3.0 * m);
  EXPECT_NEAR(t.missing_pressure_pa, expected, 1e-7 * expected);
  // The Hertz gap is narrower than the rigid parabola upstream: more pressure is missing.
  const InletTruncation rigid = EstimateInletTruncation(f.p, f.h, Inputs(x0, 0.0));
  EXPECT_GT(t.missing_pressure_pa, rigid.missing_pressure_pa);
}

// p_in ~ |x0|^-3 far upstream (h ~ x^2/2R >> h*): InletFor inverts it.
TEST(InletTruncation, InletForScalesWithTheCubeRoot) {
  InletTruncation t;
  t.estimated = true;
  t.film_deficit = 0.027;
  EXPECT_NEAR(t.InletFor(-4.5, 0.001), -4.5 * 3.0, 1e-12);
  t.estimated = false;
  EXPECT_EQ(t.InletFor(-4.5, 0.001), -4.5);
}

TEST(InletTruncation, NoEstimateWhereTheArgumentDoesNotHold) {
  const Film f(10e-6, 1e9);
  InletTruncationInputs in = Inputs(-4.5e-4, 1e-4);
  in.pressure_viscosity_per_pa = 0;  // isoviscous: the film is not set by 1/alpha
  EXPECT_FALSE(EstimateInletTruncation(f.p, f.h, in).estimated);
  in = Inputs(-0.5e-4, 1e-4);  // x0 inside the Hertz zone
  EXPECT_FALSE(EstimateInletTruncation(f.p, f.h, in).estimated);
  in = Inputs(-4.5e-4, 1e-4);
  in.um_m_s = -1;  // entrainment toward -x: x0 is the outlet
  EXPECT_FALSE(EstimateInletTruncation(f.p, f.h, in).estimated);
  Film bad(std::nan(""), 1e9);
  EXPECT_FALSE(EstimateInletTruncation(bad.p, bad.h, Inputs(-4.5e-4, 1e-4)).estimated);
}

// A nearly isoviscous film (alpha p_max = 0.5, below kGrubinMinAlphaP): no Grubin estimate,
// but a note when its inlet is shorter than l_iso. Martin's film h_M = 4.896 eta um R / w
// (VALIDATION.md section 2) with w = 1000 N/m: h_M = 9.792 um, sqrt(2 R h_M) = 0.44254 mm.
TEST(InletTruncation, ANearlyIsoviscousFilmIsFlaggedWhenItsInletIsShort) {
  const double w = 1000;
  const Film f(10e-6, 1e9, 0.5 / kAlpha);
  InletTruncationInputs in = Inputs(-4.5e-4, 1e-5);
  in.load_n_per_m = w;
  InletTruncation t = EstimateInletTruncation(f.p, f.h, in);
  EXPECT_FALSE(t.estimated);
  EXPECT_NEAR(t.alpha_p_max, 0.5, 1e-12);
  // b = 10 um: h_M R / b^2 = 979 > 1, so l_iso = 40 sqrt(2 R h_M) = 17.7 mm, above R/2 = 5 mm.
  EXPECT_NEAR(t.isoviscous_inlet_m, kIsoviscousInletMaxRadii * kR, 1e-15);
  EXPECT_TRUE(t.short_isoviscous_inlet);
  in.x_start_m = -0.5 * kR;
  EXPECT_FALSE(EstimateInletTruncation(f.p, f.h, in).short_isoviscous_inlet);
  // The same film piezoviscous (alpha p_max = 10): estimated, never flagged.
  const Film g(10e-6, 1e9);
  t = EstimateInletTruncation(g.p, g.h, Inputs(-4.5e-4, 1e-5));
  EXPECT_TRUE(t.estimated);
  EXPECT_FALSE(t.short_isoviscous_inlet);
  // l_iso: the rigid film's 40 l (b = 0), weighted by h_M R / b^2 when that is below 1; at
  // w = 1e5 N/m, h_M = 97.92 nm and 40 l = 1.770 mm, below R/2.
  const double w2 = 1e5, h2 = 4.896 * kEta * kUm * kR / w2, l2 = std::sqrt(2 * kR * h2);
  EXPECT_NEAR(IsoviscousInletLength(kR, 0.0, kUm, kEta, w2), 40 * l2, 1e-15);
  const double b = 2 * std::sqrt(h2 * kR);  // h_M R / b^2 = 1/4
  EXPECT_NEAR(IsoviscousInletLength(kR, b, kUm, kEta, w2), 40 * l2 / 4, 1e-15);
  EXPECT_EQ(IsoviscousInletLength(kR, b, kUm, kEta, 0.0), 0.0);
}

// Martin's rigid isoviscous film with its inlet at X0 (in units of l = sqrt(2 R h0), H = h/h0
// = 1 + X^2): Reynolds gives dP/dX = (H - H*)/H^3 with P(X0) = 0 and P = P' = 0 at the exit
// Xe = sqrt(H* - 1), and the load W = integral of P dX = integral (Xe - X)(H - H*)/H^3 dX
// (order of integration swapped). With X = tan(t): (H - H*)/H^3 dX = (1 - H* cos^2 t) cos^2 t
// dt, smooth up to t = -pi/2 (the unbounded inlet). H* by bisection on the first integral,
// each integral by Simpson's rule on 4000 intervals (converged: 2000 give the same to 1e-12). At a
// fixed load and speed the film scales with W, and a fixed physical inlet lies at X0 / sqrt(r) in
// the units of a film r times as thick: the film ratio is the fixed point r = W(X0 / sqrt(r)) /
// W(-inf).
double MartinLoad(double x0) {
  const double t0 = std::atan(x0);
  auto simpson = [](double a, double b, auto f) {
    const int n = 4000;
    const double step = (b - a) / n;
    double sum = f(a) + f(b);
    for (int i = 1; i < n; ++i) sum += (i % 2 ? 4 : 2) * f(a + i * step);
    return sum * step / 3;
  };
  auto pressure_at_exit = [&](double h_star) {  // P(Xe) for this H*
    const double te = std::atan(std::sqrt(h_star - 1));
    return simpson(t0, te, [&](double t) {
      const double c2 = std::cos(t) * std::cos(t);
      return (1 - h_star * c2) * c2;
    });
  };
  double lo = 1.0 + 1e-12, hi = 2.0;  // P(Xe) > 0 for H* near 1, < 0 for H* = 2
  for (int it = 0; it < 60; ++it) {
    const double mid = 0.5 * (lo + hi);
    (pressure_at_exit(mid) > 0 ? lo : hi) = mid;
  }
  const double h_star = 0.5 * (lo + hi), xe = std::sqrt(h_star - 1);
  return simpson(t0, std::atan(xe), [&](double t) {
    const double c2 = std::cos(t) * std::cos(t);
    return (xe - std::tan(t)) * (1 - h_star * c2) * c2;
  });
}

double MartinFilmRatio(double x0) {
  const double w_inf = MartinLoad(-1e12);
  double r = 1.0;
  for (int it = 0; it < 100; ++it) {
    const double next = MartinLoad(x0 / std::sqrt(r)) / w_inf;
    if (std::abs(next - r) < 1e-10) return next;
    r = next;
  }
  return r;
}

TEST(InletTruncation, RigidInletFilmRatioMatchesAQuadratureOfMartinsProblem) {
  // Martin's load (VALIDATION.md section 2): w = 4.896 eta um R / h0 is 24 W(-inf); 4.896 is
  // twice the classical 2.448 (for the sum of the speeds), so good to its rounding: 4.8950.
  EXPECT_NEAR(24 * MartinLoad(-1e12), 4.896, 1.1e-3);
  for (double x0 : {-3.0, -4.7, -10.0}) {
    const double want = MartinFilmRatio(x0);
    std::printf("X0 = %.1f: film ratio %.5f (quadrature), %.5f (RigidInletFilmRatio)\n", x0, want,
                RigidInletFilmRatio(x0));
    EXPECT_NEAR(RigidInletFilmRatio(x0), want, 1e-5) << "X0 = " << x0;
  }
  EXPECT_NEAR(RigidInletFilmRatio(-1e6), 1.0, 1e-9);
  EXPECT_EQ(RigidInletFilmRatio(1.0), 0.0);
}

// A rigid-like film (Martin film thick against b^2/R) whose flooded inlet would pass R/2 gets
// the deficit of its inlet against Martin's: the disc of 100 N/m at 1 m/s (R = 10 mm, SAE 40:
// h_M = 55.8 um, sqrt(2 R h_M) = 1.056 mm, 40 of them far beyond R/2 = 5 mm) on an inlet at R/2.
TEST(InletTruncation, AThickRigidFilmCappedAtHalfTheRadiusGetsItsDeficit) {
  const double eta = 0.1140574, um = 1.0, r = 0.01, w = 100.0;
  const double b = std::sqrt(8 * w * r / (M_PI * 226.4e9));
  Film f(60e-6, 0.0, 1e3);
  InletTruncationInputs in;
  in.x_start_m = -0.5 * r;
  in.dx_m = kDx;
  in.reduced_radius_m = r;
  in.half_width_m = b;
  in.um_m_s = um;
  in.inlet_viscosity_pa_s = eta;
  in.pressure_viscosity_per_pa = kAlpha;
  in.load_n_per_m = w;
  const InletTruncation t = EstimateInletTruncation(f.p, f.h, in);
  EXPECT_FALSE(t.estimated);
  const double l = std::sqrt(2 * r * 4.896 * eta * um * r / w);
  EXPECT_NEAR(t.rigid_film_deficit, 1 - RigidInletFilmRatio(-0.5 * r / l), 1e-12);
  EXPECT_GT(t.rigid_film_deficit, 0.09);  // X0 = -4.7
  // A moderate load, whose inlet need not pass R/2: none.
  in.load_n_per_m = 1e5;
  in.half_width_m = std::sqrt(8 * 1e5 * r / (M_PI * 226.4e9));
  in.x_start_m = -4.5 * in.half_width_m;
  EXPECT_EQ(EstimateInletTruncation(f.p, f.h, in).rigid_film_deficit, 0.0);
}

}  // namespace
}  // namespace tehl
