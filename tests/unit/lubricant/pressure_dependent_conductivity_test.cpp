// Pressure-dependent conductivity k0 [1 + 1.73e-9 p / (1 + 6.91e-10 p)] (seed 004 eq. 13).
#include "tehl/lubricant/pressure_dependent_conductivity.hpp"

#include <gtest/gtest.h>

#include "unit/lubricant/derivative_check.hpp"

namespace tehl {
namespace {
using testing::CentralDifference;
using testing::CentredPressure;
using testing::Close;

// k0 of SAE 40, seed 004 Table 2.
PressureDependentConductivity Sae40() { return PressureDependentConductivity({0.125}); }

TEST(PressureDependentConductivity, EqualsK0AtZeroPressure) {
  EXPECT_DOUBLE_EQ(Sae40().Evaluate(0.0).k_w_mk, 0.125);
  EXPECT_DOUBLE_EQ(Sae40().ReferenceConductivity(), 0.125);
}

TEST(PressureDependentConductivity, PressureDerivativeMatchesCentralDifference) {
  const PressureDependentConductivity law = Sae40();
  for (double p0 : testing::TestPressures()) {
    const double p = CentredPressure(p0);
    const double fd = CentralDifference([&](double x) { return law.Evaluate(x).k_w_mk; }, p,
                                        testing::kPressureStep);
    EXPECT_TRUE(Close(law.Evaluate(p).dk_dp, fd, 1e-6)) << p;
  }
}

TEST(PressureDependentConductivity, RatioAtOneGigapascalMatchesHandCalculation) {
  // 1 + 1.73e-9 * 1e9 / (1 + 6.91e-10 * 1e9) = 1 + 1.73 / 1.691 = 2.0230633.
  EXPECT_NEAR(Sae40().Evaluate(1e9).k_w_mk / 0.125, 2.0230633, 1e-7);
}

TEST(PressureDependentConductivity, RatioTendsToOnePlus173Over0691AtLargePressure) {
  // lim = 1 + 1.73/0.691 = 3.5036179; at 1e14 Pa the remainder is 2.5036/(1 + 6.91e4) = 3.6e-5.
  EXPECT_NEAR(Sae40().Evaluate(1e14).k_w_mk / 0.125, 1.0 + 1.73 / 0.691, 1e-4);
}

}  // namespace
}  // namespace tehl
