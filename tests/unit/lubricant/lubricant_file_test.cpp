// The shipped lubricant files load and carry the published data (VALIDATION.md sections 3
// and 5; seed 004 Table 2).
#include <gtest/gtest.h>

#include <cmath>

#include "tehl/lubricant/dowson_higginson_density.hpp"
#include "tehl/lubricant/lubricant.hpp"
#include "tehl/lubricant/roelands_gamma_viscosity.hpp"
#include "tehl/units.hpp"

namespace tehl {
namespace {

std::string Shipped(const std::string& name) {
  return std::string(TEHL_SOURCE_DIR) + "/lubricants/" + name + ".toml";
}

struct Table2 {
  const char* file;
  double rho0, eta0, z, gamma, beta, cp, k;
};

// Seed 004 Table 2, as transcribed in VALIDATION.md section 5.
constexpr Table2 kTable2[] = {
    {"sae40", 879.625, 0.1140574, 0.62, 0.046, 7.71e-4, 1900.0, 0.125},
    {"sae90", 892.80, 0.1946304, 0.5685, 0.05763, 7.40e-4, 1870.0, 0.126},
};

TEST(LubricantFile, ShippedSaeOilsCarrySeed004Table2) {
  for (const Table2& t : kTable2) {
    SCOPED_TRACE(t.file);
    const Lubricant lube = Lubricant::FromFile(Shipped(t.file));
    EXPECT_EQ(lube.reference_temperature_k(), 313.15);  // VALIDATION.md section 5
    EXPECT_EQ(lube.heat_capacity_j_kgk(), t.cp);
    EXPECT_EQ(lube.expansivity_per_k(), t.beta);
    EXPECT_EQ(lube.density().ReferenceDensity(), t.rho0);
    EXPECT_EQ(lube.viscosity().ReferenceViscosity(), t.eta0);
    EXPECT_EQ(lube.conductivity().ReferenceConductivity(), t.k);
    const auto* eta = dynamic_cast<const RoelandsGammaViscosity*>(&lube.viscosity());
    ASSERT_NE(eta, nullptr) << "viscosity model must be roelands_gamma";
    EXPECT_EQ(eta->parameters().pressure_index, t.z);
    EXPECT_EQ(eta->parameters().temperature_coefficient_per_k, t.gamma);
    const auto* rho = dynamic_cast<const DowsonHigginsonDensity*>(&lube.density());
    ASSERT_NE(rho, nullptr) << "density model must be dowson_higginson";
    EXPECT_EQ(rho->parameters().expansivity_per_k, t.beta);
    // eta(0, T0) = eta0 and rho(0, T0) = rho0 through the laws, not only the parameters.
    EXPECT_DOUBLE_EQ(lube.viscosity().Evaluate(0.0, 313.15).eta_pa_s, t.eta0);
    EXPECT_DOUBLE_EQ(lube.density().Evaluate(0.0, 313.15).rho_kg_m3, t.rho0);
    // k rises with pressure (seed 004 eq. 13).
    EXPECT_GT(lube.conductivity().Evaluate(1e9).k_w_mk, t.k);
    ASSERT_TRUE(lube.eyring().has_value());
    EXPECT_GT(lube.eyring()->eyring_stress_pa, 0.0);
    EXPECT_FALSE(lube.source().empty());
  }
}

TEST(LubricantFile, HoupertAlphaOfSae40MatchesHandCalculation) {
  // alpha = Z (ln eta0 + 9.67) / 1.96e8 with Z = 0.62, eta0 = 0.1140574 Pa s:
  // ln 0.1140574 = -2.1710534; (-2.1710534 + 9.67) * 0.62 / 1.96e8 = 2.3721157e-8 1/Pa.
  const Lubricant sae40 = Lubricant::FromFile(Shipped("sae40"));
  EXPECT_NEAR(sae40.viscosity().PressureViscosityCoefficient(), 2.3721157e-8, 1e-15);
}

TEST(LubricantFile, ReferenceOilGivesTheHoupertAlphaOfTheValidationTable) {
  // VALIDATION.md section 3: eta0 = 0.04 Pa s, Z = 0.68, alpha = 2.238e-8 1/Pa.
  const Lubricant ref = Lubricant::FromFile(Shipped("reference_z068"));
  EXPECT_EQ(ref.viscosity().ReferenceViscosity(), 0.04);
  EXPECT_NEAR(ref.viscosity().PressureViscosityCoefficient(), 2.238e-8, 0.0005e-8);
  EXPECT_EQ(ref.density().ReferenceDensity(), 870.0);
}

TEST(LubricantFile, SaeOilsGiveTheMoesGroupsOfTheSeed004PitchPoint) {
  // VALIDATION.md section 5: pitch point R = 8.978 mm, um = 1.254 m/s, w = 116.14 kN/m,
  // UNS C61300 (E = 117 GPa, nu = 0.34) on both gears; SAE 40: M ~ 6.3, L ~ 12.4;
  // SAE 90: M ~ 4.8, L ~ 13.9 (two or three digits printed: tolerance half a unit of the
  // last digit plus the rounding of the inputs, 0.06).
  const double e_prime = ReducedModulus(117e9, 0.34, 117e9, 0.34);
  const struct {
    const char* file;
    double m, l;
  } expected[] = {{"sae40", 6.3, 12.4}, {"sae90", 4.8, 13.9}};
  for (const auto& x : expected) {
    const Lubricant lube = Lubricant::FromFile(Shipped(x.file));
    const DimensionlessGroups g = LineContactGroups(lube.viscosity().ReferenceViscosity(),
                                                    lube.viscosity().PressureViscosityCoefficient(),
                                                    1.254, 116.14e3, 8.978e-3, e_prime);
    EXPECT_NEAR(g.M, x.m, 0.06) << x.file;
    EXPECT_NEAR(g.L, x.l, 0.06) << x.file;
  }
}

TEST(LubricantFile, DescribeNamesEveryLaw) {
  const std::string d = Lubricant::FromFile(Shipped("sae40")).Describe();
  for (const char* word : {"roelands_gamma", "dowson_higginson", "pressure_dependent", "313.15",
                           "0.1140574", "1900", "Eyring"})
    EXPECT_NE(d.find(word), std::string::npos) << word << " in\n" << d;
}

TEST(LubricantFile, CopiesShareTheLaws) {
  const Lubricant a = Lubricant::FromFile(Shipped("sae90"));
  const Lubricant b = a;
  EXPECT_EQ(&a.viscosity(), &b.viscosity());
  EXPECT_EQ(b.viscosity().Evaluate(5e8, 350.0).eta_pa_s,
            a.viscosity().Evaluate(5e8, 350.0).eta_pa_s);
}

TEST(Lubricant, ConstructorRejectsMissingLawsAndBadScalars) {
  try {
    Lubricant("x", "y", -1.0, 0.0, -1.0, nullptr, nullptr, nullptr);
    FAIL() << "no InputError";
  } catch (const InputError& e) {
    EXPECT_EQ(e.problems().size(), 6u) << e.what();
  }
}

}  // namespace
}  // namespace tehl
