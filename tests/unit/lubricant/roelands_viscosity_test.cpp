// Roelands viscosity, S0 form (DESIGN.md section 4; VALIDATION.md sections 1 and 3).
#include "tehl/lubricant/roelands_viscosity.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "unit/lubricant/derivative_check.hpp"

namespace tehl {
namespace {
using testing::CentralDifference;
using testing::CentredPressure;
using testing::Close;

// The reference oil of VALIDATION.md section 3 (eta0 = 0.04 Pa s, Z = 0.68) with S0 = 1.1.
RoelandsViscosity ReferenceOil() { return RoelandsViscosity({0.04, 313.15, 0.68, 1.1}); }

TEST(RoelandsViscosity, EqualsEta0AtZeroPressureAndReferenceTemperature) {
  EXPECT_DOUBLE_EQ(ReferenceOil().Evaluate(0.0, 313.15).eta_pa_s, 0.04);
  const RoelandsViscosity sae40({0.1140574, 313.15, 0.62, 1.3});  // seed 004 Table 2 eta0, Z
  EXPECT_DOUBLE_EQ(sae40.Evaluate(0.0, 313.15).eta_pa_s, 0.1140574);
  EXPECT_DOUBLE_EQ(sae40.ReferenceViscosity(), 0.1140574);
}

TEST(RoelandsViscosity, PressureDerivativeMatchesCentralDifference) {
  const RoelandsViscosity law = ReferenceOil();
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

TEST(RoelandsViscosity, TemperatureDerivativeMatchesCentralDifference) {
  const RoelandsViscosity law = ReferenceOil();
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

TEST(RoelandsViscosity, ViscosityAtOneGigapascalMatchesHandCalculation) {
  // ln(eta/eta0) = (ln 0.04 + 9.67) [(1 + 5.1e-9 * 1e9)^0.68 - 1]
  //             = (-3.2188758 + 9.67) (6.1^0.68 - 1) = 6.4511242 * 2.4199857 = 15.611628.
  const double eta = ReferenceOil().Evaluate(1e9, 313.15).eta_pa_s;
  EXPECT_NEAR(std::log(eta / 0.04), 15.611628, 1e-6);
}

TEST(RoelandsViscosity, ViscosityAtHundredCelsiusMatchesHandCalculation) {
  // p = 0, T = 373.15 K: ln(eta/eta0) = 6.4511242 [((373.15 - 138)/(313.15 - 138))^-1.1 - 1]
  //   = 6.4511242 * (1.3425635^-1.1 - 1) = 6.4511242 * (0.72322208 - 1) = -1.7855288.
  const double eta = ReferenceOil().Evaluate(0.0, 373.15).eta_pa_s;
  EXPECT_NEAR(std::log(eta / 0.04), -1.7855288, 1e-6);
}

TEST(RoelandsViscosity, TemperatureIndexRelatesToViscosityTemperatureCoefficient) {
  // VALIDATION.md section 1: S0 = beta (T0 - 138) / (ln eta0 + 9.67), beta = -(1/eta) deta/dT
  // at p = 0 and T0.
  const ViscosityValue v = ReferenceOil().Evaluate(0.0, 313.15);
  const double beta = -v.deta_dT / v.eta_pa_s;
  EXPECT_NEAR(beta * (313.15 - 138.0) / (std::log(0.04) + 9.67), 1.1, 1e-12);
}

TEST(RoelandsViscosity, HoupertAlphaOfReferenceOilMatchesValidationTable) {
  // VALIDATION.md section 3: eta0 = 0.04 Pa s, Z = 0.68 -> alpha = 2.238e-8 1/Pa (Houpert).
  EXPECT_NEAR(ReferenceOil().PressureViscosityCoefficient(), 2.238e-8, 0.0005e-8);
}

TEST(RoelandsViscosity, HoupertAlphaIsTheInitialPressureViscosityCoefficient) {
  // d ln(eta)/dp at p = 0, T0 is (ln eta0 + 9.67) Z 5.1e-9; Houpert divides by 1.96e8 instead
  // of multiplying by 5.1e-9: the two differ by 1 - 5.1e-9 * 1.96e8 = 4e-4.
  const RoelandsViscosity law = ReferenceOil();
  const ViscosityValue v = law.Evaluate(0.0, 313.15);
  EXPECT_NEAR(v.deta_dp / v.eta_pa_s / law.PressureViscosityCoefficient(), 1.0, 5e-4);
}

TEST(RoelandsViscosity, RisesWithPressureAndFallsWithTemperature) {
  const RoelandsViscosity law = ReferenceOil();
  for (double T : testing::TestTemperatures())
    for (double p : testing::TestPressures()) {
      const ViscosityValue v = law.Evaluate(p, T);
      EXPECT_GT(v.deta_dp, 0.0) << p << " " << T;
      EXPECT_LT(v.deta_dT, 0.0) << p << " " << T;
      EXPECT_TRUE(std::isfinite(v.eta_pa_s));
    }
}

TEST(RoelandsViscosity, EvaluateManyMatchesEvaluate) {
  const RoelandsViscosity law = ReferenceOil();
  const double p[] = {0.0, 3e8, 1.2e9}, T[] = {313.15, 350.0, 400.0};
  ViscosityValue out[3];
  law.EvaluateMany(p, T, 3, out);
  for (int i = 0; i < 3; ++i) {
    const ViscosityValue one = law.Evaluate(p[i], T[i]);
    EXPECT_EQ(out[i].eta_pa_s, one.eta_pa_s);
    EXPECT_EQ(out[i].deta_dp, one.deta_dp);
    EXPECT_EQ(out[i].deta_dT, one.deta_dT);
  }
}

// A batch reuses the temperature factor over a run of equal temperatures (an isothermal
// grid) and the pressure factor over a run of equal pressures (a film column): runs that
// start, end and come back must still give the point-by-point values bit for bit.
TEST(RoelandsViscosity, EvaluateManyReusesFactorsOnlyWithinRuns) {
  const RoelandsViscosity law = ReferenceOil();
  const double p[] = {0.0, 0.0, 2e8, 2e8, 2e8, 9e8, 0.0, 9e8};
  const double T[] = {313.15, 313.15, 313.15, 350.0, 313.15, 313.15, 400.0, 400.0};
  ViscosityValue out[8];
  law.EvaluateMany(p, T, 8, out);
  for (int i = 0; i < 8; ++i) {
    const ViscosityValue one = law.Evaluate(p[i], T[i]);
    EXPECT_EQ(out[i].eta_pa_s, one.eta_pa_s) << i;
    EXPECT_EQ(out[i].deta_dp, one.deta_dp) << i;
    EXPECT_EQ(out[i].deta_dT, one.deta_dT) << i;
  }
}

TEST(RoelandsViscosity, RejectsViscosityBelowEtaInfinity) {
  // Roelands: eta_inf = exp(-9.67) = 6.31e-5 Pa s; below it eta would fall with pressure.
  try {
    RoelandsViscosity({5e-5, 313.15, 0.68, 1.1});
    FAIL() << "no InputError";
  } catch (const InputError& e) {
    ASSERT_EQ(e.problems().size(), 1u);
    EXPECT_EQ(e.problems()[0].key, "RoelandsViscosity.viscosity_pa_s");
  }
}

TEST(RoelandsViscosity, RejectsEveryBadParameterAtOnce) {
  try {
    RoelandsViscosity({0.04, 100.0, 0.0, -1.0});
    FAIL() << "no InputError";
  } catch (const InputError& e) {
    EXPECT_EQ(e.problems().size(), 3u) << e.what();  // T0 <= 138 K, Z <= 0, S0 <= 0
  }
}

}  // namespace
}  // namespace tehl
