// The model factory: names, required and unused keys, and the laws it builds.
#include "tehl/lubricant/model_factory.hpp"

#include <gtest/gtest.h>

#include "tehl/lubricant/barus_viscosity.hpp"
#include "tehl/lubricant/roelands_viscosity.hpp"

namespace tehl {
namespace {

TEST(ModelFactory, EveryLawNameRoundTrips) {
  for (ViscosityLaw law : {ViscosityLaw::kRoelands, ViscosityLaw::kRoelandsGamma,
                           ViscosityLaw::kBarus, ViscosityLaw::kConstant})
    EXPECT_EQ(ViscosityLawFromString(ToString(law)), law) << ToString(law);
  for (DensityLaw law : {DensityLaw::kDowsonHigginson, DensityLaw::kConstant})
    EXPECT_EQ(DensityLawFromString(ToString(law)), law) << ToString(law);
  for (ConductivityLaw law : {ConductivityLaw::kPressureDependent, ConductivityLaw::kConstant})
    EXPECT_EQ(ConductivityLawFromString(ToString(law)), law) << ToString(law);
  EXPECT_EQ(ToString(ViscosityLaw::kRoelandsGamma), "roelands_gamma");
  EXPECT_EQ(ToString(DensityLaw::kDowsonHigginson), "dowson_higginson");
  EXPECT_EQ(ToString(ConductivityLaw::kPressureDependent), "pressure_dependent");
}

TEST(ModelFactory, UnknownViscosityModelListsTheKnownOnes) {
  try {
    ViscosityLawFromString("roelands2");
    FAIL() << "no InputError";
  } catch (const InputError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("\"roelands2\""), std::string::npos) << what;
    for (const auto& name : ViscosityLawNames())
      EXPECT_NE(what.find("\"" + name + "\""), std::string::npos) << name << ": " << what;
  }
  EXPECT_THROW(DensityLawFromString("tait"), InputError);
  EXPECT_THROW(ConductivityLawFromString(""), InputError);
}

TEST(ModelFactory, MissingAndUnusedKeysAreReportedTogether) {
  try {
    // Barus reads eta0, alpha and gamma; here alpha is missing and Z is not Barus's.
    MakeViscosityModel(ViscosityLaw::kBarus, 313.15,
                       {{"viscosity_pa_s", 0.04},
                        {"temperature_coefficient_per_k", 0.0},
                        {"pressure_index", 0.68}});
    FAIL() << "no InputError";
  } catch (const InputError& e) {
    ASSERT_EQ(e.problems().size(), 2u) << e.what();
    EXPECT_EQ(e.problems()[0].key, "pressure_coefficient_per_pa");
    EXPECT_NE(e.problems()[0].rule.find("required by model \"barus\""), std::string::npos);
    EXPECT_EQ(e.problems()[1].key, "pressure_index");
    EXPECT_NE(e.problems()[1].rule.find("not used by model \"barus\""), std::string::npos);
  }
}

TEST(ModelFactory, ParameterProblemsCarryTheFileKey) {
  try {
    MakeViscosityModel(
        ViscosityLaw::kRoelands, 313.15,
        {{"viscosity_pa_s", 1e-5}, {"pressure_index", 0.6}, {"temperature_index", 1.1}});
    FAIL() << "no InputError";
  } catch (const InputError& e) {
    ASSERT_EQ(e.problems().size(), 1u) << e.what();
    EXPECT_EQ(e.problems()[0].key, "viscosity_pa_s");
  }
}

TEST(ModelFactory, BuildsTheNamedLawWithItsParameters) {
  const auto built = MakeViscosityModel(
      ViscosityLaw::kRoelands, 313.15,
      {{"viscosity_pa_s", 0.04}, {"pressure_index", 0.68}, {"temperature_index", 1.1}});
  const RoelandsViscosity direct({0.04, 313.15, 0.68, 1.1});
  for (double p : {0.0, 5e8, 1e9})
    for (double T : {313.15, 380.0})
      EXPECT_EQ(built->Evaluate(p, T).eta_pa_s, direct.Evaluate(p, T).eta_pa_s);
  const auto barus = MakeViscosityModel(ViscosityLaw::kBarus, 313.15,
                                        {{"viscosity_pa_s", 0.04},
                                         {"pressure_coefficient_per_pa", 2e-8},
                                         {"temperature_coefficient_per_k", 0.03}});
  EXPECT_EQ(barus->PressureViscosityCoefficient(), 2e-8);
  const auto rho = MakeDensityModel(DensityLaw::kDowsonHigginson, 313.15,
                                    {{"density_kg_m3", 870.0}, {"expansivity_per_k", 7e-4}});
  EXPECT_DOUBLE_EQ(rho->Evaluate(0.0, 323.15).rho_kg_m3, 870.0 * (1.0 - 10.0 * 7e-4));
  const auto k = MakeConductivityModel(ConductivityLaw::kConstant, 0.13);
  EXPECT_EQ(k->Evaluate(1e9).k_w_mk, 0.13);
}

TEST(ModelFactory, EveryViscosityLawReadsEta0) {
  for (const auto& name : ViscosityLawNames()) {
    const auto keys = ParameterKeys(ViscosityLawFromString(name));
    EXPECT_EQ(keys.front(), "viscosity_pa_s") << name;
  }
}

}  // namespace
}  // namespace tehl
