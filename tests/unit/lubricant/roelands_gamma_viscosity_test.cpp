// Roelands viscosity with the gamma temperature term: seed 004 eq. (7) as corrected in
// DESIGN.md section 4, with the SAE 40 / SAE 90 data of seed 004 Table 2 (VALIDATION.md
// section 5).
#include "tehl/lubricant/roelands_gamma_viscosity.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "tehl/lubricant/roelands_viscosity.hpp"
#include "unit/lubricant/derivative_check.hpp"

namespace tehl {
namespace {
using testing::CentralDifference;
using testing::CentredPressure;
using testing::Close;

// SAE 40 of seed 004 Table 2: eta0 = 0.1140574 Pa s, Z = 0.62, gamma = 0.046 1/K.
RoelandsGammaViscosity Sae40() { return RoelandsGammaViscosity({0.1140574, 313.15, 0.62, 0.046}); }

TEST(RoelandsGammaViscosity, EqualsEta0AtZeroPressureAndReferenceTemperature) {
  EXPECT_DOUBLE_EQ(Sae40().Evaluate(0.0, 313.15).eta_pa_s, 0.1140574);
  // SAE 90 of seed 004 Table 2.
  const RoelandsGammaViscosity sae90({0.1946304, 313.15, 0.5685, 0.05763});
  EXPECT_DOUBLE_EQ(sae90.Evaluate(0.0, 313.15).eta_pa_s, 0.1946304);
}

TEST(RoelandsGammaViscosity, PressureDerivativeMatchesCentralDifference) {
  const RoelandsGammaViscosity law = Sae40();
  for (double T : testing::TestTemperatures()) {
    for (double p0 : testing::TestPressures()) {
      const double p = CentredPressure(p0);
      const double fd = CentralDifference([&](double x) { return law.Evaluate(x, T).eta_pa_s; }, p,
                                          testing::kPressureStep);
      const double exact = law.Evaluate(p, T).deta_dp;
      EXPECT_TRUE(Close(exact, fd, 1e-6)) << "p = " << p << " Pa, T = " << T << " K: analytic "
                                          << exact << ", central difference " << fd;
    }
  }
}

TEST(RoelandsGammaViscosity, TemperatureDerivativeMatchesCentralDifference) {
  const RoelandsGammaViscosity law = Sae40();
  for (double T : testing::TestTemperatures()) {
    for (double p : testing::TestPressures()) {
      const double fd = CentralDifference([&](double x) { return law.Evaluate(p, x).eta_pa_s; }, T,
                                          testing::kTemperatureStep);
      const double exact = law.Evaluate(p, T).deta_dT;
      EXPECT_TRUE(Close(exact, fd, 1e-6)) << "p = " << p << " Pa, T = " << T << " K: analytic "
                                          << exact << ", central difference " << fd;
    }
  }
}

TEST(RoelandsGammaViscosity, TemperatureFactorIsExpMinusGammaDeltaTAtAnyPressure) {
  // eta(p, T0 + 20) / eta(p, T0) = exp(-0.046 * 20) = exp(-0.92) = 0.39851904.
  const RoelandsGammaViscosity law = Sae40();
  for (double p : testing::TestPressures())
    EXPECT_NEAR(law.Evaluate(p, 333.15).eta_pa_s / law.Evaluate(p, 313.15).eta_pa_s, 0.39851904,
                1e-8)
        << p;
}

TEST(RoelandsGammaViscosity, ViscosityAtOneGigapascalMatchesHandCalculation) {
  // ln(eta/eta0) = (ln 0.1140574 + 9.67) [(1 + 5.1)^0.62 - 1]
  //             = (-2.1710534 + 9.67) (3.0683472 - 1) = 7.4989466 * 2.0683472 = 15.510425.
  EXPECT_NEAR(std::log(Sae40().Evaluate(1e9, 313.15).eta_pa_s / 0.1140574), 15.510425, 1e-6);
}

TEST(RoelandsGammaViscosity, EqualsTheS0FormAtTheReferenceTemperature) {
  // At T = T0 both Roelands forms reduce to eta0 exp{(ln eta0 + 9.67)[-1 + (1 + p/p0)^Z]}.
  const RoelandsViscosity s0_form({0.1140574, 313.15, 0.62, 1.2});
  for (double p : testing::TestPressures())
    EXPECT_TRUE(
        Close(Sae40().Evaluate(p, 313.15).eta_pa_s, s0_form.Evaluate(p, 313.15).eta_pa_s, 1e-13))
        << p;
}

TEST(RoelandsGammaViscosity, HoupertAlphaOfSae40MatchesHandCalculation) {
  // alpha = Z (ln eta0 + 9.67) / 1.96e8 = 0.62 * 7.4989466 / 1.96e8 = 2.3721157e-8 1/Pa.
  EXPECT_NEAR(Sae40().PressureViscosityCoefficient(), 2.3721157e-8, 1e-15);
}

TEST(RoelandsGammaViscosity, EvaluateManyMatchesEvaluate) {
  const RoelandsGammaViscosity law = Sae40();
  const double p[] = {0.0, 3e8, 1.2e9, 2e9}, T[] = {313.15, 350.0, 400.0, 300.0};
  ViscosityValue out[4];
  law.EvaluateMany(p, T, 4, out);
  for (int i = 0; i < 4; ++i) {
    EXPECT_EQ(out[i].eta_pa_s, law.Evaluate(p[i], T[i]).eta_pa_s);
    EXPECT_EQ(out[i].deta_dp, law.Evaluate(p[i], T[i]).deta_dp);
    EXPECT_EQ(out[i].deta_dT, law.Evaluate(p[i], T[i]).deta_dT);
  }
}

TEST(RoelandsGammaViscosity, RejectsNegativeTemperatureCoefficient) {
  try {
    RoelandsGammaViscosity({0.1, 313.15, 0.62, -0.01});
    FAIL() << "no InputError";
  } catch (const InputError& e) {
    ASSERT_EQ(e.problems().size(), 1u);
    EXPECT_EQ(e.problems()[0].key, "RoelandsGammaViscosity.temperature_coefficient_per_k");
  }
}

}  // namespace
}  // namespace tehl
