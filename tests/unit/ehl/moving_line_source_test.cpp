// Jaeger's moving line source at any Peclet number (include/tehl/ehl/moving_line_source.hpp)
// and the finite-Peclet cell weights of MovingHeatSource (include/tehl/ehl/surface_
// temperature.hpp), against tabulated Bessel values, the derivative of the closed-form
// integral, its limits, an independent quadrature of the kernel, and the two asymptotic
// regimes of a uniform band source.
//
// Band source references (uniform flux q on [-a, a] into a half-space of conductivity k
// moving at u, kappa = k/(rho c), Pe = u a/(2 kappa) = omega a):
//   theta(x) = q/(pi k) int_{-a}^{a} e^(omega (x - x')) K0(omega |x - x'|) dx'
// (Carslaw & Jaeger 1959, section 10.7; K.L. Johnson 1985, section 13.3).
// (a) Pe -> inf: theta -> the high-Peclet closed form 2 q [sqrt(x + a) - sqrt(max(x - a, 0))]
//     / sqrt(pi rho c k u) (tests/unit/ehl/surface_temperature_test.cpp), with a relative
//     correction O(1/Pe).
// (b) Pe -> 0 at the centre: e^z -> 1 and K0(z) = -ln(z/2) - gamma + O(z^2 ln z) give
//     theta(0) = (2 q a/(pi k)) (1 - gamma - ln(Pe/2)) + O(Pe^2 ln Pe) relative to the
//     leading terms (the odd term z K0 integrates to zero over the symmetric band).
#include "tehl/ehl/moving_line_source.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <initializer_list>

#include "tehl/ehl/surface_temperature.hpp"
#include "tehl/error.hpp"

namespace tehl {
namespace {

constexpr double kEulerGamma = 0.57721566490153286;
const SolidThermal kSteel{7850.0, 470.0, 46.0};  // the case file's default solid

TEST(ScaledBesselK, TabulatedValuesAndTheAsymptoticBranch) {
  // K0(1) = 0.4210244382, K1(1) = 0.6019072302 (Abramowitz & Stegun, Table 9.8, 10 digits).
  const ScaledBesselK one = ScaledBesselK01(1.0);
  EXPECT_NEAR(one.k0 / std::exp(1.0), 0.4210244382, 1e-10);
  EXPECT_NEAR(one.k1 / std::exp(1.0), 0.6019072302, 1e-10);
  // The two branches meet at x = 30: the asymptotic series against the library there, and
  // both against e^x K_nu ~ sqrt(pi/(2x)) (1 + (4 nu^2 - 1)/(8x)) to O(x^-2).
  for (double x : {29.999999, 30.0, 30.5, 60.0}) {
    const double e = std::exp(x);
    const ScaledBesselK k = ScaledBesselK01(x);
    EXPECT_NEAR(k.k0, e * std::cyl_bessel_k(0.0, x), 1e-13 * k.k0) << x;
    EXPECT_NEAR(k.k1, e * std::cyl_bessel_k(1.0, x), 1e-13 * k.k1) << x;
    const double lead = std::sqrt(M_PI / (2 * x));
    EXPECT_NEAR(k.k0, lead * (1 - 1 / (8 * x)), lead / (x * x)) << x;
    EXPECT_NEAR(k.k1, lead * (1 + 3 / (8 * x)), lead / (x * x)) << x;
  }
  // Far beyond the range where K0 itself underflows (x > ~700) the scaled values stay finite.
  const ScaledBesselK far = ScaledBesselK01(1e4);
  EXPECT_NEAR(far.k0, std::sqrt(M_PI / 2e4) * (1 - 1 / 8e4 + 9 / (128 * 1e8)), 1e-15);
  EXPECT_TRUE(std::isnan(ScaledBesselK01(0.0).k0));
  EXPECT_TRUE(std::isnan(ScaledBesselK01(-1.0).k1));
}

TEST(MovingLineSourceIntegral, DerivativeIsTheKernel) {
  // J'(s) = e^s K0(|s|), central differences with step 1e-5 |s|: truncation O(h^2 J''')
  // and round-off about eps |J| / h.
  for (double s : {-8.0, -2.0, -0.5, -0.05, 0.05, 0.5, 2.0, 8.0, 29.0, 31.0, 200.0}) {
    const double h = 1e-5 * std::abs(s);
    const double fd = (MovingLineSourceIntegral(s + h) - MovingLineSourceIntegral(s - h)) / (2 * h);
    const double kernel = std::exp(s) * std::cyl_bessel_k(0.0, std::abs(s));
    const double round_off = 1e-15 * (1 + std::abs(MovingLineSourceIntegral(s))) / h;
    EXPECT_NEAR(fd, kernel, 1e-7 * kernel + round_off) << "s = " << s;
  }
}

TEST(MovingLineSourceIntegral, LimitsAndAnIndependentQuadrature) {
  EXPECT_EQ(MovingLineSourceIntegral(0.0), 0.0);
  // int_0^inf e^-t K0(t) dt = 1 (Gradshteyn & Ryzhik 6.611.9 at alpha = beta): J(-inf) = -1.
  EXPECT_NEAR(MovingLineSourceIntegral(-40.0), -1.0, 1e-15);
  // s -> +inf: J(s) + 1 = s e^s (K0 + K1)
  //   = sqrt(2 pi s) (1 + 1/(8s) - 3/(128 s^2) + 15/(1024 s^3) + O(s^-4))
  // (the sum of the asymptotic series of K0 and K1, Abramowitz & Stegun 9.7.2).
  for (double s : {100.0, 1e3, 1e5}) {
    const double series = 1 + 1 / (8 * s) - 3 / (128 * s * s) + 15 / (1024 * s * s * s);
    const double expect = std::sqrt(2 * M_PI * s) * series - 1;
    EXPECT_NEAR(MovingLineSourceIntegral(s), expect,
                std::sqrt(2 * M_PI * s) * (0.1 / std::pow(s, 4) + 1e-14))
        << s;
  }
  // s -> 0: J(s) = s (1 - gamma - ln(|s|/2)) + O(s^2 ln s), both signs.
  for (double s : {1e-4, -1e-4}) {
    const double expect = s * (1 - kEulerGamma - std::log(std::abs(s) / 2));
    EXPECT_NEAR(MovingLineSourceIntegral(s), expect, 1e-3 * std::abs(expect)) << s;
  }
  // An independent quadrature of the kernel: t = X^4 tames the log singularity at 0,
  // int_0^b e^(+-t) K0(t) dt = int_0^(b^1/4) 4 X^3 e^(+-X^4) K0(X^4) dX, composite Simpson.
  for (double b : {0.3, 2.0, 6.0}) {
    for (int sign : {1, -1}) {
      const int m = 20000;
      const double top = std::pow(b, 0.25), h = top / m;
      auto f = [&](double x) {
        const double t = x * x * x * x;
        return x == 0 ? 0.0 : 4 * x * x * x * std::exp(sign * t) * std::cyl_bessel_k(0.0, t);
      };
      double sum = f(0) + f(top);
      for (int j = 1; j < m; ++j) sum += (j % 2 ? 4 : 2) * f(j * h);
      const double simpson = sum * h / 3;
      EXPECT_NEAR(std::abs(MovingLineSourceIntegral(sign * b)), simpson, 1e-9 * simpson)
          << "b " << b << " sign " << sign;
    }
  }
}

// A uniform band [-a, a] on a grid whose cell faces fall on +-a and whose centre is a node.
struct Band {
  double a = 1e-4, q = 1e7;  // [m], [W/m^2]
  int cells = 65;            // odd: x = 0 is a node
  UniformGrid grid() const {
    const double dx = 2 * a / cells;
    const int before = 40, after = 40, n = before + cells + after;
    const double x0 = -a + 0.5 * dx - before * dx;
    return UniformGrid(x0, x0 + (n - 1) * dx, n);
  }
  Eigen::VectorXd Flux(const UniformGrid& g) const {
    Eigen::VectorXd f = Eigen::VectorXd::Zero(g.size());
    for (int k = 0; k < g.size(); ++k)
      if (std::abs(g.x(k)) < a) f[k] = q;
    return f;
  }
};

TEST(MovingHeatSourceFinitePeclet, UniformBandTendsToTheHighPecletForm) {
  // Reference (a): the relative difference at the band's end (the hottest node) is O(1/Pe):
  // the heat conducted ahead, sqrt(2/(pi omega)) per unit flux, is made up by the kernel's
  // deficit against 1/sqrt(X) within about 1/omega downstream of each source.
  const Band band;
  const UniformGrid g = band.grid();
  const Eigen::VectorXd q = band.Flux(g);
  const MovingHeatSource high(g);
  for (double pe : {10.0, 100.0, 1000.0}) {
    const double u = 2 * pe * kSteel.conductivity_w_mk /
                     (kSteel.density_kg_m3 * kSteel.heat_capacity_j_kgk * band.a);
    const MovingHeatSource finite(g, MovingHeatSource::DecayRate(kSteel, u));
    EXPECT_NEAR(finite.omega_1_m() * band.a, pe, 1e-12 * pe);
    const Eigen::VectorXd a = high.Rise(kSteel, u, q), b = finite.Rise(kSteel, u, q);
    const double rel = std::abs(b.maxCoeff() / a.maxCoeff() - 1);
    std::printf("Pe %6.0f: max rise %.4f K (high-Peclet form %.4f K), relative %.2e\n", pe,
                b.maxCoeff(), a.maxCoeff(), rel);
    EXPECT_LT(rel, 1.0 / pe) << pe;
  }
}

TEST(MovingHeatSourceFinitePeclet, UniformBandCentreAtLowPecletNumber) {
  // Reference (b). The weights are exact cell integrals, so only the O(Pe^2 ln Pe) of the
  // asymptotic form separates the two.
  const Band band;
  const UniformGrid g = band.grid();
  const int centre = 40 + 32;
  ASSERT_NEAR(g.x(centre), 0.0, 1e-12 * band.a);
  for (double pe : {1e-2, 1e-3}) {
    const double u = 2 * pe * kSteel.conductivity_w_mk /
                     (kSteel.density_kg_m3 * kSteel.heat_capacity_j_kgk * band.a);
    const MovingHeatSource finite(g, MovingHeatSource::DecayRate(kSteel, u));
    const double rise = finite.Rise(kSteel, u, band.Flux(g))[centre];
    const double expect = 2 * band.q * band.a / (M_PI * kSteel.conductivity_w_mk) *
                          (1 - kEulerGamma - std::log(pe / 2));
    std::printf("Pe %.0e: centre rise %.6f K, asymptotic %.6f K\n", pe, rise, expect);
    EXPECT_NEAR(rise, expect, 10 * pe * pe * std::abs(std::log(pe)) * expect) << pe;
  }
}

TEST(MovingHeatSourceFinitePeclet, HeatIsConductedAheadOfTheSource) {
  // Upstream of a source the high-Peclet form has no rise. Jaeger's kernel there is
  // e^(-omega d) K0(omega d) ~ sqrt(pi/(2 omega d)) e^(-2 omega d) at a distance d, so a node
  // at d ahead of the band's front sees (integrating from d on) a rise proportional to
  // d^(-1/2) e^(-2 omega d) (1 + O(1/(omega d))): between d1 and d2,
  //   ln(theta2/theta1) = 2 omega (d1 - d2) + ln(d1/d2)/2.
  const Band band;
  const UniformGrid g = band.grid();
  const double pe = 5.0;
  const double u = 2 * pe * kSteel.conductivity_w_mk /
                   (kSteel.density_kg_m3 * kSteel.heat_capacity_j_kgk * band.a);
  const MovingHeatSource finite(g, MovingHeatSource::DecayRate(kSteel, u));
  const Eigen::VectorXd rise = finite.Rise(kSteel, u, band.Flux(g));
  EXPECT_EQ(MovingHeatSource(g).Rise(kSteel, u, band.Flux(g))[0], 0.0);
  EXPECT_GT(rise[0], 0.0);
  const double dx = g.dx_m(), omega = finite.omega_1_m();
  const double d1 = 39.5 * dx, d2 = 19.5 * dx;  // nodes 0 and 20 to the front at -a
  const double expect = 2 * omega * (d1 - d2) + 0.5 * std::log(d1 / d2);
  const double got = std::log(rise[20] / rise[0]);
  std::printf("Pe %.0f: ln(theta2/theta1) %.4f, asymptotic %.4f (omega d1 %.2f, d2 %.2f)\n", pe,
              got, expect, omega * d1, omega * d2);
  EXPECT_NEAR(got / expect, 1.0, 0.03);
}

TEST(MovingHeatSourceFinitePeclet, RejectsABadDecayRate) {
  const UniformGrid g(-1e-4, 1e-4, 17);
  EXPECT_THROW(MovingHeatSource(g, 0.0), InputError);
  EXPECT_THROW(MovingHeatSource(g, -1.0), InputError);
  EXPECT_THROW(MovingHeatSource(g, std::nan("")), InputError);
  EXPECT_THROW(MovingHeatSource::DecayRate(kSteel, 0.0), InputError);
}

}  // namespace
}  // namespace tehl
