// Dowson-Higginson density with thermal expansion (DESIGN.md section 4; seed 004 eq. 6).
#include "tehl/lubricant/dowson_higginson_density.hpp"

#include <gtest/gtest.h>

#include "unit/lubricant/derivative_check.hpp"

namespace tehl {
namespace {
using testing::CentralDifference;
using testing::CentredPressure;
using testing::Close;

// SAE 40 of seed 004 Table 2: rho0 = 879.625 kg/m^3, beta = 7.71e-4 1/K.
DowsonHigginsonDensity Sae40() { return DowsonHigginsonDensity({879.625, 313.15, 7.71e-4}); }

TEST(DowsonHigginsonDensity, EqualsRho0AtZeroPressureAndReferenceTemperature) {
  EXPECT_DOUBLE_EQ(Sae40().Evaluate(0.0, 313.15).rho_kg_m3, 879.625);
  EXPECT_DOUBLE_EQ(Sae40().ReferenceDensity(), 879.625);
}

TEST(DowsonHigginsonDensity, PressureDerivativeMatchesCentralDifference) {
  const DowsonHigginsonDensity law = Sae40();
  for (double T : testing::TestTemperatures())
    for (double p0 : testing::TestPressures()) {
      const double p = CentredPressure(p0);
      const double fd = CentralDifference([&](double x) { return law.Evaluate(x, T).rho_kg_m3; }, p,
                                          testing::kPressureStep);
      EXPECT_TRUE(Close(law.Evaluate(p, T).drho_dp, fd, 1e-6))
          << p << " " << T << ": " << law.Evaluate(p, T).drho_dp << " vs " << fd;
    }
}

TEST(DowsonHigginsonDensity, TemperatureDerivativeMatchesCentralDifference) {
  const DowsonHigginsonDensity law = Sae40();
  for (double T : testing::TestTemperatures())
    for (double p : testing::TestPressures()) {
      const double fd = CentralDifference([&](double x) { return law.Evaluate(p, x).rho_kg_m3; }, T,
                                          testing::kTemperatureStep);
      EXPECT_TRUE(Close(law.Evaluate(p, T).drho_dT, fd, 1e-6)) << p << " " << T;
    }
}

TEST(DowsonHigginsonDensity, RatioAtOneGigapascalMatchesHandCalculation) {
  // 1 + 0.6e-9 * 1e9 / (1 + 1.7e-9 * 1e9) = 1 + 0.6 / 2.7 = 1.2222222.
  EXPECT_NEAR(Sae40().Evaluate(1e9, 313.15).rho_kg_m3 / 879.625, 1.0 + 0.6 / 2.7, 1e-14);
}

TEST(DowsonHigginsonDensity, RatioTendsToOnePlusPointSixOverOnePointSevenAtLargePressure) {
  // lim p->inf of 1 + 0.6e-9 p/(1 + 1.7e-9 p) = 1 + 0.6/1.7 = 1.3529412; at p = 1e14 Pa the
  // remainder is 0.6/1.7 / (1 + 1.7e5) = 2.1e-6.
  EXPECT_NEAR(Sae40().Evaluate(1e14, 313.15).rho_kg_m3 / 879.625, 1.0 + 0.6 / 1.7, 1e-5);
  EXPECT_LT(Sae40().Evaluate(1e14, 313.15).rho_kg_m3 / 879.625, 1.0 + 0.6 / 1.7);
}

TEST(DowsonHigginsonDensity, ExpandsLinearlyWithTemperature) {
  // rho(0, T0 + 50) = rho0 (1 - 50 * 7.71e-4) = rho0 * 0.96145.
  EXPECT_NEAR(Sae40().Evaluate(0.0, 363.15).rho_kg_m3 / 879.625, 0.96145, 1e-12);
}

TEST(DowsonHigginsonDensity, EvaluateManyMatchesEvaluate) {
  const DowsonHigginsonDensity law = Sae40();
  const double p[] = {0.0, 5e8, 2e9}, T[] = {300.0, 313.15, 400.0};
  DensityValue out[3];
  law.EvaluateMany(p, T, 3, out);
  for (int i = 0; i < 3; ++i) {
    EXPECT_EQ(out[i].rho_kg_m3, law.Evaluate(p[i], T[i]).rho_kg_m3);
    EXPECT_EQ(out[i].drho_dp, law.Evaluate(p[i], T[i]).drho_dp);
    EXPECT_EQ(out[i].drho_dT, law.Evaluate(p[i], T[i]).drho_dT);
  }
}

TEST(DowsonHigginsonDensity, RejectsNegativeExpansivityAndDensity) {
  try {
    DowsonHigginsonDensity({-1.0, 313.15, -1e-4});
    FAIL() << "no InputError";
  } catch (const InputError& e) {
    ASSERT_EQ(e.problems().size(), 2u);
    EXPECT_EQ(e.problems()[0].key, "DowsonHigginsonDensity.density_kg_m3");
    EXPECT_EQ(e.problems()[1].key, "DowsonHigginsonDensity.expansivity_per_k");
  }
}

}  // namespace
}  // namespace tehl
