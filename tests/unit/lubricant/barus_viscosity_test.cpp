// Barus viscosity eta0 exp(alpha p - gamma (T - T0)).
#include "tehl/lubricant/barus_viscosity.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "tehl/lubricant/roelands_viscosity.hpp"
#include "unit/lubricant/derivative_check.hpp"

namespace tehl {
namespace {
using testing::CentralDifference;
using testing::CentredPressure;
using testing::Close;

// alpha of the reference oil (VALIDATION.md section 3), gamma of SAE 40 (seed 004 Table 2).
BarusViscosity Law() { return BarusViscosity({0.04, 313.15, 2.238e-8, 0.046}); }

TEST(BarusViscosity, EqualsEta0AtZeroPressureAndReferenceTemperature) {
  EXPECT_DOUBLE_EQ(Law().Evaluate(0.0, 313.15).eta_pa_s, 0.04);
}

TEST(BarusViscosity, PressureDerivativeMatchesCentralDifference) {
  const BarusViscosity law = Law();
  for (double T : testing::TestTemperatures())
    for (double p0 : testing::TestPressures()) {
      const double p = CentredPressure(p0);
      const double fd = CentralDifference([&](double x) { return law.Evaluate(x, T).eta_pa_s; }, p,
                                          testing::kPressureStep);
      EXPECT_TRUE(Close(law.Evaluate(p, T).deta_dp, fd, 1e-6)) << p << " " << T;
    }
}

TEST(BarusViscosity, TemperatureDerivativeMatchesCentralDifference) {
  const BarusViscosity law = Law();
  for (double T : testing::TestTemperatures())
    for (double p : testing::TestPressures()) {
      const double fd = CentralDifference([&](double x) { return law.Evaluate(p, x).eta_pa_s; }, T,
                                          testing::kTemperatureStep);
      EXPECT_TRUE(Close(law.Evaluate(p, T).deta_dT, fd, 1e-6)) << p << " " << T;
    }
}

TEST(BarusViscosity, LogViscosityIsLinearInPressureWithSlopeAlpha) {
  // ln(eta(1 GPa)/eta0) = 2.238e-8 * 1e9 = 22.38 at T0.
  EXPECT_NEAR(std::log(Law().Evaluate(1e9, 313.15).eta_pa_s / 0.04), 22.38, 1e-9);
  EXPECT_DOUBLE_EQ(Law().PressureViscosityCoefficient(), 2.238e-8);
}

TEST(BarusViscosity, ExceedsRoelandsWithTheSameInitialSlopeAtHighPressure) {
  // Known behaviour: with alpha from Houpert, Barus overpredicts Roelands at high pressure
  // (the Roelands pressure term grows like p^Z, Z < 1).
  const RoelandsViscosity roelands({0.04, 313.15, 0.68, 1.1});
  EXPECT_GT(Law().Evaluate(1e9, 313.15).eta_pa_s, roelands.Evaluate(1e9, 313.15).eta_pa_s);
}

TEST(BarusViscosity, RejectsNegativePressureCoefficient) {
  try {
    BarusViscosity({0.04, 313.15, -1e-8, 0.0});
    FAIL() << "no InputError";
  } catch (const InputError& e) {
    ASSERT_EQ(e.problems().size(), 1u);
    EXPECT_EQ(e.problems()[0].key, "BarusViscosity.pressure_coefficient_per_pa");
  }
}

TEST(BarusViscosity, NamesACoefficientGivenInOneOverGigapascal) {
  // 23.7 1/GPa, the SAE 40 of seed 004 (Table 2), written without the 1e-9.
  try {
    BarusViscosity({0.04, 313.15, 23.7, 0.0});
    FAIL() << "no InputError";
  } catch (const InputError& e) {
    ASSERT_EQ(e.problems().size(), 1u);
    EXPECT_NE(e.problems()[0].allowed.find("in 1/GPa? (23.7 1/GPa = 2.37e-08 1/Pa)"),
              std::string::npos)
        << e.problems()[0].allowed;
  }
  // A value beyond any unit slip gets no hint.
  try {
    BarusViscosity({0.04, 313.15, 1e3, 0.0});
    FAIL() << "no InputError";
  } catch (const InputError& e) {
    ASSERT_EQ(e.problems().size(), 1u);
    EXPECT_EQ(e.problems()[0].allowed.find("1/GPa"), std::string::npos);
  }
}

}  // namespace
}  // namespace tehl
