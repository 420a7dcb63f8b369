// Constant viscosity, density and conductivity: the value everywhere, zero derivatives.
#include <gtest/gtest.h>

#include "tehl/lubricant/constant_conductivity.hpp"
#include "tehl/lubricant/constant_density.hpp"
#include "tehl/lubricant/constant_viscosity.hpp"
#include "unit/lubricant/derivative_check.hpp"

namespace tehl {
namespace {

TEST(ConstantViscosity, IsEta0WithZeroDerivativesEverywhere) {
  const ConstantViscosity law({0.04});
  for (double T : testing::TestTemperatures())
    for (double p : testing::TestPressures()) {
      const ViscosityValue v = law.Evaluate(p, T);
      EXPECT_EQ(v.eta_pa_s, 0.04);
      EXPECT_EQ(v.deta_dp, 0.0);
      EXPECT_EQ(v.deta_dT, 0.0);
    }
  EXPECT_EQ(law.PressureViscosityCoefficient(), 0.0);
  EXPECT_EQ(law.ReferenceViscosity(), 0.04);
}

TEST(ConstantDensity, IsRho0WithZeroDerivativesEverywhere) {
  const ConstantDensity law({870.0});
  for (double T : testing::TestTemperatures())
    for (double p : testing::TestPressures()) {
      const DensityValue v = law.Evaluate(p, T);
      EXPECT_EQ(v.rho_kg_m3, 870.0);
      EXPECT_EQ(v.drho_dp, 0.0);
      EXPECT_EQ(v.drho_dT, 0.0);
    }
}

TEST(ConstantConductivity, IsK0WithZeroDerivativeEverywhere) {
  const ConstantConductivity law({0.13});
  for (double p : testing::TestPressures()) {
    EXPECT_EQ(law.Evaluate(p).k_w_mk, 0.13);
    EXPECT_EQ(law.Evaluate(p).dk_dp, 0.0);
  }
}

TEST(ConstantLaws, RejectNonPositiveValues) {
  EXPECT_THROW(ConstantViscosity({0.0}), InputError);
  EXPECT_THROW(ConstantDensity({-870.0}), InputError);
  EXPECT_THROW(ConstantConductivity({0.0}), InputError);
}

}  // namespace
}  // namespace tehl
