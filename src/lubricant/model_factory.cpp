// The only place that knows the lubricant model names and the keys each law reads.
#include "tehl/lubricant/model_factory.hpp"

#include <algorithm>
#include <array>
#include <utility>

#include "base/schema.hpp"
#include "tehl/error.hpp"
#include "tehl/lubricant/barus_viscosity.hpp"
#include "tehl/lubricant/constant_conductivity.hpp"
#include "tehl/lubricant/constant_density.hpp"
#include "tehl/lubricant/constant_viscosity.hpp"
#include "tehl/lubricant/dowson_higginson_density.hpp"
#include "tehl/lubricant/pressure_dependent_conductivity.hpp"
#include "tehl/lubricant/roelands_gamma_viscosity.hpp"
#include "tehl/lubricant/roelands_viscosity.hpp"

namespace tehl {
namespace {

constexpr std::array<std::pair<ViscosityLaw, const char*>, 4> kViscosityNames = {{
    {ViscosityLaw::kRoelands, "roelands"},
    {ViscosityLaw::kRoelandsGamma, "roelands_gamma"},
    {ViscosityLaw::kBarus, "barus"},
    {ViscosityLaw::kConstant, "constant"},
}};
constexpr std::array<std::pair<DensityLaw, const char*>, 2> kDensityNames = {{
    {DensityLaw::kDowsonHigginson, "dowson_higginson"},
    {DensityLaw::kConstant, "constant"},
}};
constexpr std::array<std::pair<ConductivityLaw, const char*>, 2> kConductivityNames = {{
    {ConductivityLaw::kPressureDependent, "pressure_dependent"},
    {ConductivityLaw::kConstant, "constant"},
}};

template <typename Table>
std::vector<std::string> Names(const Table& table) {
  std::vector<std::string> out;
  for (const auto& [law, name] : table) out.emplace_back(name);
  return out;
}

std::string QuotedList(const std::vector<std::string>& names) {
  std::string s;
  for (const auto& n : names) s += (s.empty() ? "\"" : ", \"") + n + "\"";
  return s;
}

template <typename Law, typename Table>
std::string NameOf(const Table& table, Law law) {
  for (const auto& [l, name] : table)
    if (l == law) return name;
  return "?";
}

template <typename Law, typename Table>
Law FromName(const Table& table, std::string_view name, const char* what) {
  for (const auto& [law, n] : table)
    if (name == n) return law;
  throw InputError(InputProblem{"", 0, "model", "\"" + std::string(name) + "\"",
                                std::string("unknown ") + what + " model",
                                "one of " + QuotedList(Names(table))});
}

// Missing and unused keys of one law, all at once.
void CheckKeys(const std::string& law,
               const std::vector<std::string>& keys,
               const LawParameters& given) {
  std::vector<InputProblem> bad;
  for (const auto& k : keys)
    if (!given.count(k))
      bad.push_back({"", 0, k, "", "required by model \"" + law + "\"",
                     "model \"" + law + "\" reads " + QuotedList(keys)});
  for (const auto& [k, v] : given)
    if (std::find(keys.begin(), keys.end(), k) == keys.end())
      bad.push_back({"", 0, k, internal::FormatReal(v), "not used by model \"" + law + "\"",
                     "model \"" + law + "\" reads " + QuotedList(keys) +
                         "; remove the key or choose another model"});
  if (!bad.empty()) throw InputError(std::move(bad));
}

// Builds a law after its own Validate(), so problems carry the file's key names.
template <typename Model>
std::unique_ptr<Model> Build(const typename Model::Parameters& p) {
  auto bad = p.Validate();
  if (!bad.empty()) throw InputError(std::move(bad));
  return std::make_unique<Model>(p);
}

}  // namespace

std::string ToString(ViscosityLaw law) { return NameOf(kViscosityNames, law); }
std::string ToString(DensityLaw law) { return NameOf(kDensityNames, law); }
std::string ToString(ConductivityLaw law) { return NameOf(kConductivityNames, law); }

ViscosityLaw ViscosityLawFromString(std::string_view name) {
  return FromName<ViscosityLaw>(kViscosityNames, name, "viscosity");
}
DensityLaw DensityLawFromString(std::string_view name) {
  return FromName<DensityLaw>(kDensityNames, name, "density");
}
ConductivityLaw ConductivityLawFromString(std::string_view name) {
  return FromName<ConductivityLaw>(kConductivityNames, name, "conductivity");
}

std::vector<std::string> ViscosityLawNames() { return Names(kViscosityNames); }
std::vector<std::string> DensityLawNames() { return Names(kDensityNames); }
std::vector<std::string> ConductivityLawNames() { return Names(kConductivityNames); }

std::vector<std::string> ParameterKeys(ViscosityLaw law) {
  switch (law) {
    case ViscosityLaw::kRoelands:
      return {"viscosity_pa_s", "pressure_index", "temperature_index"};
    case ViscosityLaw::kRoelandsGamma:
      return {"viscosity_pa_s", "pressure_index", "temperature_coefficient_per_k"};
    case ViscosityLaw::kBarus:
      return {"viscosity_pa_s", "pressure_coefficient_per_pa", "temperature_coefficient_per_k"};
    case ViscosityLaw::kConstant:
      return {"viscosity_pa_s"};
  }
  return {};
}

std::vector<std::string> ParameterKeys(DensityLaw law) {
  switch (law) {
    case DensityLaw::kDowsonHigginson:
      return {"density_kg_m3", "expansivity_per_k"};
    case DensityLaw::kConstant:
      return {"density_kg_m3"};
  }
  return {};
}

std::unique_ptr<ViscosityModel> MakeViscosityModel(ViscosityLaw law,
                                                   double reference_temperature_k,
                                                   const LawParameters& p) {
  CheckKeys(ToString(law), ParameterKeys(law), p);
  const auto get = [&](const char* key) { return p.at(key); };
  switch (law) {
    case ViscosityLaw::kRoelands:
      return Build<RoelandsViscosity>({get("viscosity_pa_s"), reference_temperature_k,
                                       get("pressure_index"), get("temperature_index")});
    case ViscosityLaw::kRoelandsGamma:
      return Build<RoelandsGammaViscosity>({get("viscosity_pa_s"), reference_temperature_k,
                                            get("pressure_index"),
                                            get("temperature_coefficient_per_k")});
    case ViscosityLaw::kBarus:
      return Build<BarusViscosity>({get("viscosity_pa_s"), reference_temperature_k,
                                    get("pressure_coefficient_per_pa"),
                                    get("temperature_coefficient_per_k")});
    case ViscosityLaw::kConstant:
      return Build<ConstantViscosity>({get("viscosity_pa_s")});
  }
  return nullptr;
}

std::unique_ptr<DensityModel> MakeDensityModel(DensityLaw law,
                                               double reference_temperature_k,
                                               const LawParameters& p) {
  CheckKeys(ToString(law), ParameterKeys(law), p);
  switch (law) {
    case DensityLaw::kDowsonHigginson:
      return Build<DowsonHigginsonDensity>(
          {p.at("density_kg_m3"), reference_temperature_k, p.at("expansivity_per_k")});
    case DensityLaw::kConstant:
      return Build<ConstantDensity>({p.at("density_kg_m3")});
  }
  return nullptr;
}

std::unique_ptr<ConductivityModel> MakeConductivityModel(ConductivityLaw law,
                                                         double conductivity_w_mk) {
  switch (law) {
    case ConductivityLaw::kPressureDependent:
      return Build<PressureDependentConductivity>({conductivity_w_mk});
    case ConductivityLaw::kConstant:
      return Build<ConstantConductivity>({conductivity_w_mk});
  }
  return nullptr;
}

}  // namespace tehl
