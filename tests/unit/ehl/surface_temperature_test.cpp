// The moving-heat-source integral (seed 004 eqs. 14-15, DESIGN.md section 4) against closed
// forms of Carslaw & Jaeger.
//
// Derivation used by every reference below. A half-space moving at speed u under a surface
// flux q(x), at high Peclet number, conducts only into its depth: each surface point sees 1-D
// transient conduction with time t = (x - x_0)/u. A constant flux q switched on at t = 0 gives
// the surface rise 2 q sqrt(t) / sqrt(pi rho c k) (Carslaw & Jaeger 1959, section 2.9, eq. 4);
// Duhamel's superposition of flux steps gives (1/sqrt(pi rho c k)) int q(tau)/sqrt(t - tau) dtau,
// and with tau = x'/u, t - tau = (x - x')/u:
//   T(x) - T0 = 1/sqrt(pi rho c k u) int_{x_0}^{x} q(x') / sqrt(x - x') dx'.
// (a) uniform q over the band [-a, a], zero outside:
//   T - T0 = 2 q [sqrt(x + a) - sqrt(max(x - a, 0))] / sqrt(pi rho c k u)      (x >= -a);
// (b) linear q(x') = q0 (x' + a)/(2a) on [-a, a], for -a <= x <= a, with s = x - x':
//   int_0^{x+a} q0 ((x + a) - s)/(2a) s^-1/2 ds = q0 (4/3) (x + a)^{3/2} / (2a).
#include "tehl/ehl/surface_temperature.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <vector>

#include "tehl/error.hpp"

namespace tehl {
namespace {

const SolidThermal kBronze{7890.0, 375.0, 55.0};  // VALIDATION.md section 5, UNS C61300
constexpr double kSpeed = 1.254;                  // um at the seed 004 pitch point [m/s]

TEST(MovingHeatSource, UniformBandFluxMatchesCarslawJaegerToRoundOff) {
  // Cell faces fall on -a and +a, so the piecewise-constant flux is exact and the only error
  // is round-off in the exact weights: closed form (a) above.
  const double a = 1.42e-4, q = 2.0e7;
  for (int m : {16, 64, 256}) {
    const double dx = 2 * a / m;
    const int n = m + 5 + 40;
    const UniformGrid g(-a - 4.5 * dx, -a - 4.5 * dx + (n - 1) * dx, n);
    Eigen::VectorXd flux = Eigen::VectorXd::Zero(n);
    for (int k = 5; k < 5 + m; ++k) flux[k] = q;  // cells [-a + (k-5) dx, -a + (k-4) dx]
    const MovingHeatSource source(g);
    const Eigen::VectorXd rise = source.Rise(kBronze, kSpeed, flux);
    const double f = 1 / std::sqrt(M_PI * 7890.0 * 375.0 * 55.0 * kSpeed);
    double worst = 0, at_band_end = 0;
    for (int i = 0; i < n; ++i) {
      const double x = g.x(i);
      const double exact =
          x <= -a ? 0.0 : 2 * q * f * (std::sqrt(x + a) - std::sqrt(std::max(x - a, 0.0)));
      const double err = std::abs(rise[i] - exact) / (2 * q * f * std::sqrt(2 * a));
      worst = std::max(worst, err);
      if (i == 4 + m) at_band_end = err;  // the last node inside the band
    }
    std::printf("m = %3d cells on the band: max error %.2e, at the band's end %.2e (relative)\n", m,
                worst, at_band_end);
    EXPECT_LT(worst, 1e-12) << m;
  }
}

TEST(MovingHeatSource, LinearFluxConvergesAtOrderOneAndAHalf) {
  // Closed form (b). A linear q sampled at cell centres is exact in the mean on each cell; the
  // remaining error comes from the cells next to x, where the kernel is singular: the last half
  // cell contributes q' dx^{3/2}, the others q' K' dx^3 summed to dx^2 int K' ~ dx^{3/2}.
  // Expected order 1.5.
  const double a = 1.0e-4, q0 = 1.0e7;
  const double f = 1 / std::sqrt(M_PI * 7890.0 * 375.0 * 55.0 * kSpeed);
  std::vector<double> errors;
  for (int m : {32, 64, 128, 256, 512}) {
    const double dx = 2 * a / m;
    // Nodes from -a + dx/2 ... the first cell [x_0, x_0 + dx/2] starts the band at x_0 = -a.
    const UniformGrid g(-a, a, m + 1);
    Eigen::VectorXd flux(m + 1);
    for (int k = 0; k <= m; ++k) flux[k] = q0 * (g.x(k) + a) / (2 * a);
    // Cells at both ends are half cells: sample the flux at their centres instead.
    flux[0] = q0 * (0.25 * dx) / (2 * a);
    flux[m] = q0 * (2 * a - 0.25 * dx) / (2 * a);
    const Eigen::VectorXd rise = MovingHeatSource(g).Rise(kBronze, kSpeed, flux);
    const double scale = f * q0 * (4.0 / 3.0) * std::pow(2 * a, 1.5) / (2 * a);
    double worst = 0;
    for (int i = 0; i <= m; ++i) {
      const double exact = f * q0 * (4.0 / 3.0) * std::pow(g.x(i) + a, 1.5) / (2 * a);
      worst = std::max(worst, std::abs(rise[i] - exact) / scale);
    }
    errors.push_back(worst);
  }
  for (size_t i = 1; i < errors.size(); ++i) {
    const double order = std::log2(errors[i - 1] / errors[i]);
    std::printf("refinement %zu: max error %.3e, order %.3f\n", i, errors[i], order);
    EXPECT_NEAR(order, 1.5, 0.1) << "refinement " << i;
  }
}

TEST(MovingHeatSource, WeightsAreLowerTriangularAndSumToTheExactIntegral) {
  // Sum_k G_ik = int_{x_0}^{x_i} dx'/sqrt(x_i - x') = 2 sqrt(x_i - x_0) (unit flux).
  const UniformGrid g(-4.5e-4, 1.5e-4, 97);
  const MovingHeatSource s(g);
  for (int i = 0; i < g.size(); ++i) {
    double sum = 0;
    for (int k = 0; k < g.size(); ++k) {
      if (k > i) {
        EXPECT_EQ(s.Weight(i, k), 0.0);
      }
      sum += s.Weight(i, k);
    }
    EXPECT_NEAR(sum, 2 * std::sqrt(g.x(i) - g.x(0)), 1e-15) << i;
  }
}

TEST(MovingHeatSource, RejectsNonPositiveSolidPropertiesAndSpeed) {
  EXPECT_THROW(MovingHeatSource::Factor(kBronze, 0.0), InputError);
  EXPECT_THROW(MovingHeatSource::Factor(kBronze, -1.0), InputError);
  EXPECT_THROW(MovingHeatSource::Factor(SolidThermal{0.0, 375.0, 55.0}, 1.0), InputError);
  EXPECT_THROW(MovingHeatSource::Factor(SolidThermal{7890.0, 375.0, NAN}, 1.0), InputError);
  try {
    MovingHeatSource::Factor(SolidThermal{7890.0, -1.0, 55.0}, 0.0);
    FAIL() << "no InputError";
  } catch (const InputError& e) {
    ASSERT_EQ(e.problems().size(), 2u);  // every problem in one pass
    EXPECT_EQ(e.problems()[0].key, "SolidThermal::heat_capacity_j_kgk");
    EXPECT_EQ(e.problems()[0].value, "-1.0");
  }
  const UniformGrid g(0.0, 1e-3, 11);
  EXPECT_THROW(MovingHeatSource(g).Rise(kBronze, 1.0, Eigen::VectorXd::Zero(10)), InputError);
}

}  // namespace
}  // namespace tehl
