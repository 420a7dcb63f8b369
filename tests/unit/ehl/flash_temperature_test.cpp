// Blok's flash temperature (include/tehl/ehl/flash_temperature.hpp) against
//   - its factor c_B = 2 max_s I(s) / pi^(3/2), I(s) = int_{-1}^{s} sqrt(1 - t^2)/sqrt(s - t) dt,
//     recomputed here by another quadrature (midpoint rule in u = sqrt(s - t), Richardson-
//     extrapolated) and a scan in s, and Blok's published 1.11 for the contact width 2b
//     (H. Blok 1937; K.L. Johnson, Contact Mechanics, 1985, eq. 13.43);
//   - the moving heat source of surface_temperature.hpp (itself checked against Carslaw &
//     Jaeger) under a semi-elliptic flux shared so that the peaks are equal, for unlike solids
//     and speeds;
//   - the partition-free weighted mean of the two peaks.
// And its finite-Peclet form (Jaeger's moving line source) against Blok at high Peclet
// numbers and, for one solid at low Peclet numbers, against the logarithmic limit of the
// kernel: with e^z -> 1 and K0(z) = -ln(z/2) - gamma, the peak (at x = 0 by symmetry) of a
// semi-elliptic source Q is (Q/(pi k)) [-ln(omega b/2) - gamma - <ln|t|>], <ln|t|> the mean
// of ln|t| under (2/pi) sqrt(1 - t^2) on [-1, 1], = (4/pi) int_0^1 sqrt(1 - t^2) ln t dt =
// -(1 + 2 ln 2)/2 (Gradshteyn & Ryzhik 4.241): (Q/(pi k)) [ln(4/Pe) - gamma + 1/2], Pe = omega b,
// to O(Pe^2 ln Pe) relative.
#include "tehl/ehl/flash_temperature.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "tehl/error.hpp"

namespace tehl {
namespace {

const SolidThermal kBronze{7890.0, 375.0, 55.0};  // VALIDATION.md section 5, UNS C61300
const SolidThermal kSteel{7850.0, 470.0, 46.0};   // the default solid of ContactSolids

// I(s) by the midpoint rule in u (t = s - u^2, dt = 2u du, 1/sqrt(s - t) = 1/u):
// I = int_0^sqrt(1+s) 2 sqrt(1 - (s - u^2)^2) du, whose integrand has a square-root edge at the
// upper end (error ~ m^-1.5); two levels are Richardson-extrapolated with that order.
double IntegralI(double s, int m) {
  auto mid = [s](int k) {
    const double top = std::sqrt(1 + s), du = top / k;
    double sum = 0;
    for (int j = 0; j < k; ++j) {
      const double u = (j + 0.5) * du, t = s - u * u;
      sum += 2 * std::sqrt(std::max(1 - t * t, 0.0)) * du;
    }
    return sum;
  };
  const double a = mid(m), b = mid(2 * m), r = std::pow(2.0, 1.5);
  return (r * b - a) / (r - 1);
}

TEST(BlokFlashTemperature, FactorIsTheMaximumOfTheSemiEllipticIntegral) {
  double best = 0, at = 0;
  for (int k = 0; k <= 1000; ++k) {
    const double s = 0.5 + 0.3 * k / 1000.0;
    const double v = IntegralI(s, 20000);
    if (v > best) best = v, at = s;
  }
  const double c_b = 2 * best / std::pow(M_PI, 1.5);
  EXPECT_NEAR(c_b, kBlokFactor, 2e-6 * kBlokFactor);
  EXPECT_NEAR(at, 0.65223, 1e-3);
  // Blok's 1.11 for theta = 1.11 mu w |sqrt(u1) - sqrt(u2)| / (sqrt(2b) e), rounded to 3 digits.
  EXPECT_NEAR(kBlokFactor * std::sqrt(2.0), 1.11, 0.0016);
}

// Peak surface rise of a solid under the semi-elliptic flux carrying Q [W/m] over |x| <= b,
// by the moving heat source on a grid of `cells` cells across 2b.
double PeakRise(const SolidThermal& solid, double u, double q_total, double b, int cells) {
  const double dx = 2 * b / cells;
  const int n = cells + 1 + 10;
  const UniformGrid g(-b, -b + (n - 1) * dx, n);
  Eigen::VectorXd q(n);
  for (int i = 0; i < n; ++i) {
    const double s = g.x(i) / b;
    q[i] = std::abs(s) < 1 ? q_total * 2 / (M_PI * b) * std::sqrt(1 - s * s) : 0.0;
  }
  return MovingHeatSource(g).Rise(solid, u, q).maxCoeff();
}

TEST(BlokFlashTemperature, EqualPeaksOfTheMovingHeatSource) {
  const double b = 1.42e-4, mu = 0.05, w = 1.16e5;  // about the seed 004 pitch contact
  for (auto [u1, u2] : {std::pair{3.0, 1.0}, std::pair{0.68, 1.45}, std::pair{2.0, 0.1}}) {
    const FlashTemperatureInputs in{mu, w, u1, u2, b};
    const double theta = BlokFlashTemperature(in, kBronze, kSteel);
    const double heat = mu * w * std::abs(u1 - u2);
    // Equal peaks: Q_i proportional to e_i sqrt(u_i).
    const double a1 = std::sqrt(55.0 * 7890.0 * 375.0 * u1),
                 a2 = std::sqrt(46.0 * 7850.0 * 470.0 * u2);
    double previous_error = 0;
    for (int cells : {400, 1600}) {
      const double t1 = PeakRise(kBronze, u1, heat * a1 / (a1 + a2), b, cells);
      const double t2 = PeakRise(kSteel, u2, heat * a2 / (a1 + a2), b, cells);
      const double error = std::max(std::abs(t1 - theta), std::abs(t2 - theta)) / theta;
      if (cells == 1600) {
        EXPECT_LT(error, 2e-3) << u1 << " " << u2;
        EXPECT_LT(error, previous_error) << "refinement must reduce the error";
      }
      previous_error = error;
    }
  }
}

TEST(BlokFlashTemperature, WeightedRiseOfAnyPartitionIsTheFlashTemperature) {
  const double b = 7.15e-5, mu = 0.04, w = 4.7e4, u1 = 0.68, u2 = 1.45;  // about A of seed 004
  const double theta = BlokFlashTemperature({mu, w, u1, u2, b}, kBronze, kBronze);
  const double heat = mu * w * std::abs(u1 - u2);
  for (double f : {0.1, 0.5, 0.8}) {
    const double t1 = PeakRise(kBronze, u1, f * heat, b, 1600);
    const double t2 = PeakRise(kBronze, u2, (1 - f) * heat, b, 1600);
    EXPECT_NEAR(BlokWeightedRise(t1, t2, u1, u2, kBronze, kBronze), theta, 2e-3 * theta) << f;
  }
}

TEST(BlokFlashTemperature, EqualSolidsGiveTheSquareRootDifference) {
  const double b = 1e-4, mu = 0.06, w = 2e5, e = std::sqrt(46.0 * 7850.0 * 470.0);
  for (auto [u1, u2] : {std::pair{5.0, 1.0}, std::pair{1.0, 5.0}, std::pair{2.0, 0.0}}) {
    const double expected =
        kBlokFactor * mu * w * std::abs(std::sqrt(u1) - std::sqrt(u2)) / (std::sqrt(b) * e);
    EXPECT_NEAR(BlokFlashTemperature({mu, w, u1, u2, b}, kSteel, kSteel), expected,
                1e-12 * expected);
  }
}

TEST(BlokFlashTemperature, NoFrictionHeatNoRise) {
  EXPECT_EQ(BlokFlashTemperature({0.05, 1e5, 2.0, 2.0, 1e-4}, kSteel, kSteel), 0.0);  // rolling
  EXPECT_EQ(BlokFlashTemperature({0.0, 1e5, 3.0, 1.0, 1e-4}, kSteel, kSteel), 0.0);
  EXPECT_EQ(BlokFlashTemperature({0.05, 0.0, 3.0, 1.0, 0.0}, kSteel, kSteel), 0.0);  // unloaded
}

TEST(FinitePecletFlashTemperature, TendsToBlokAtHighPecletNumbers) {
  // Solids with the effusivities sqrt(k rho c) of bronze and steel (the same Blok value) but
  // diffusivities 10^4 times smaller: Pe = omega b of 1.8e4 and more.
  const SolidThermal slow_bronze{7890.0 * 100, 375.0, 55.0 / 100};
  const SolidThermal slow_steel{7850.0 * 100, 470.0, 46.0 / 100};
  const FlashTemperatureInputs in{0.05, 1.16e5, 3.0, 1.0, 1.42e-4};
  const double blok = BlokFlashTemperature(in, slow_bronze, slow_steel);
  EXPECT_NEAR(BlokFlashTemperature(in, kBronze, kSteel), blok, 1e-12 * blok);
  const double finite = FinitePecletFlashTemperature(in, slow_bronze, slow_steel);
  std::printf("high Pe: finite-Peclet %.4f K, Blok %.4f K\n", finite, blok);
  EXPECT_NEAR(finite, blok, 5e-3 * blok);
}

TEST(FinitePecletFlashTemperature, OneSolidAtLowPecletNumberGivesTheLogarithmicLimit) {
  // Body 2 at rest: body 1 carries all the heat (reference above).
  constexpr double kEulerGamma = 0.57721566490153286;
  const double b = 1e-4, mu = 0.05, w = 1e5;
  for (double pe : {1e-2, 1e-3}) {
    const double kappa = 46.0 / (7850.0 * 470.0);
    const double u1 = 2 * kappa * pe / b;
    const double heat = mu * w * u1;
    const double expect = heat / (M_PI * 46.0) * (std::log(4 / pe) - kEulerGamma + 0.5);
    const double got = FinitePecletFlashTemperature({mu, w, u1, 0.0, b}, kSteel, kSteel);
    std::printf("Pe %.0e: peak %.6f K, logarithmic limit %.6f K\n", pe, got, expect);
    EXPECT_NEAR(got, expect, 1e-3 * expect) << pe;
  }
}

TEST(FinitePecletFlashTemperature, BelowBlokAndCloserAsThePecletNumberGrows) {
  // Seed 004's pinion at A: Pe 1.31 (docs/thermal.md); bronze pair, 2:1 sliding, b = 71.5 um.
  const double b = 7.15e-5, kappa = 55.0 / (7890.0 * 375.0);
  double last = 0;
  for (double pe : {0.1, 0.3, 1.31, 3.0, 10.0, 100.0}) {
    const double u2 = 2 * kappa * pe / b, u1 = 2 * u2;
    const FlashTemperatureInputs in{0.05, 4.7e4, u1, u2, b};
    const double ratio = FinitePecletFlashTemperature(in, kBronze, kBronze) /
                         BlokFlashTemperature(in, kBronze, kBronze);
    std::printf("Pe %6.2f (slower solid): finite-Peclet / Blok = %.4f\n", pe, ratio);
    EXPECT_LT(ratio, 1.0) << pe;
    EXPECT_GT(ratio, last) << pe;
    last = ratio;
  }
  EXPECT_GT(last, 0.99);
}

TEST(BlokFlashTemperature, RejectsBadInput) {
  EXPECT_THROW(FinitePecletFlashTemperature({0.05, 1e5, 1, 2, 1e-4}, kSteel, kSteel, 4),
               InputError);
  EXPECT_THROW(FinitePecletFlashTemperature({0.05, 1e5, 0, 0, 1e-4}, kSteel, kSteel), InputError);
  EXPECT_EQ(FinitePecletFlashTemperature({0.0, 1e5, 1, 2, 1e-4}, kSteel, kSteel), 0.0);
  EXPECT_THROW(BlokFlashTemperature({-0.1, 1e5, 3.0, 1.0, 1e-4}, kSteel, kSteel), InputError);
  EXPECT_THROW(BlokFlashTemperature({0.1, 1e5, -3.0, 1.0, 1e-4}, kSteel, kSteel), InputError);
  EXPECT_THROW(BlokFlashTemperature({0.1, 1e5, 0.0, 0.0, 1e-4}, kSteel, kSteel), InputError);
  EXPECT_THROW(BlokFlashTemperature({0.1, 1e5, 3.0, 1.0, 0.0}, kSteel, kSteel), InputError);
  EXPECT_THROW(BlokFlashTemperature({0.1, NAN, 3.0, 1.0, 1e-4}, kSteel, kSteel), InputError);
  EXPECT_THROW(BlokFlashTemperature({0.1, 1e5, 3.0, 1.0, 1e-4}, SolidThermal{}, kSteel),
               InputError);
  EXPECT_THROW(BlokWeightedRise(1.0, 2.0, -1.0, 1.0, kSteel, kSteel), InputError);
}

}  // namespace
}  // namespace tehl
