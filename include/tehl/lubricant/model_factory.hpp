// The names of the lubricant laws and the factory that builds them from named parameters
// (the keys of a lubricant file). src/lubricant/model_factory.cpp is the only place that
// knows the model names and which keys each law reads.
#pragma once

#include <map>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "tehl/lubricant/density_model.hpp"
#include "tehl/lubricant/thermal_properties.hpp"
#include "tehl/lubricant/viscosity_model.hpp"

namespace tehl {

enum class ViscosityLaw {
  kRoelands,       // "roelands": RoelandsViscosity (S0 temperature index)
  kRoelandsGamma,  // "roelands_gamma": RoelandsGammaViscosity (seed 004 eq. 7, corrected)
  kBarus,          // "barus": BarusViscosity
  kConstant,       // "constant": ConstantViscosity
};
enum class DensityLaw {
  kDowsonHigginson,  // "dowson_higginson": DowsonHigginsonDensity
  kConstant,         // "constant": ConstantDensity
};
enum class ConductivityLaw {
  kPressureDependent,  // "pressure_dependent": PressureDependentConductivity
  kConstant,           // "constant": ConstantConductivity
};

std::string ToString(ViscosityLaw law);
std::string ToString(DensityLaw law);
std::string ToString(ConductivityLaw law);

// Name -> law; an unknown name throws InputError (key "model") listing the known names.
ViscosityLaw ViscosityLawFromString(std::string_view name);
DensityLaw DensityLawFromString(std::string_view name);
ConductivityLaw ConductivityLawFromString(std::string_view name);

// Every known name, in declaration order.
std::vector<std::string> ViscosityLawNames();
std::vector<std::string> DensityLawNames();
std::vector<std::string> ConductivityLawNames();

// The parameter keys each law reads from its section of a lubricant file ([viscosity],
// [density]); every one of them is required, any other parameter key is "not used".
std::vector<std::string> ParameterKeys(ViscosityLaw law);
std::vector<std::string> ParameterKeys(DensityLaw law);

// Named parameters of one law: key of the lubricant file -> value in the key's SI unit.
using LawParameters = std::map<std::string, double>;

// Build a law from its named parameters and the reference temperature T0 [K]. Throws
// InputError listing every missing key, every key the law does not use and every violated
// rule, each with the key as written in a lubricant file.
std::unique_ptr<ViscosityModel> MakeViscosityModel(ViscosityLaw law,
                                                   double reference_temperature_k,
                                                   const LawParameters& parameters);
std::unique_ptr<DensityModel> MakeDensityModel(DensityLaw law,
                                               double reference_temperature_k,
                                               const LawParameters& parameters);
// The conductivity laws read only k0 [W/(m K)].
std::unique_ptr<ConductivityModel> MakeConductivityModel(ConductivityLaw law,
                                                         double conductivity_w_mk);

}  // namespace tehl
