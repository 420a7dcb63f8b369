// Lubricant::FromFile: the schema check, then each law built by the factory with its
// problems mapped back to the file's lines, all reported at once.
#include <algorithm>
#include <optional>

#include "base/schema.hpp"
#include "lubricant/lubricant_schema.hpp"
#include "tehl/lubricant/lubricant.hpp"
#include "tehl/lubricant/model_factory.hpp"

namespace tehl {
namespace {
using internal::Document;

// True when the key was written but rejected by the schema (already reported).
bool Rejected(const Document& doc, const std::string& section, const std::string& key) {
  const std::string full = section.empty() ? key : section + "." + key;
  return std::any_of(doc.problems().begin(), doc.problems().end(),
                     [&](const InputProblem& p) { return p.key == full; });
}

class LawReader {
 public:
  explicit LawReader(Document* doc) : doc_(*doc) {
    t0_ok_ = doc_.Has("", "reference_temperature_k");
    t0_ = doc_.Real("", "reference_temperature_k");
  }

  // The law's parameters as given in `section` (every numeric key but `model_key`), or
  // nullopt when one of them was rejected by the schema.
  std::optional<LawParameters> Parameters(const std::string& section) const {
    LawParameters p;
    const internal::SectionSpec* spec = internal::LubricantSchema().Find(section);
    for (const auto& k : spec->keys) {
      if (k.kind != internal::ValueKind::kDouble) continue;
      if (Rejected(doc_, section, k.name)) return std::nullopt;
      if (doc_.Given(section, k.name)) p[k.name] = doc_.Real(section, k.name);
    }
    return p;
  }

  // Runs a factory call; its problems go to the document at the lines of their keys.
  template <typename Make>
  auto Build(const std::string& section, Make make) -> decltype(make()) {
    try {
      return make();
    } catch (const InputError& e) {
      for (const auto& p : e.problems()) {
        if (p.key == "reference_temperature_k") {
          if (t0_ok_) doc_.Problem("", p.key, p.rule, p.allowed);
        } else {
          doc_.Problem(section, p.key, p.rule, p.allowed);
        }
      }
      return nullptr;
    }
  }

  double t0() const { return t0_; }

 private:
  Document& doc_;
  bool t0_ok_ = false;
  double t0_ = 0;
};

// eta0 outside what liquids that lubricate have, where a unit slip is the likely cause: a
// kinematic viscosity in m^2/s (320 cSt = 3.2e-4 m^2/s, about 0.29 Pa s at 900 kg/m^3) is
// below water's 0.00089 Pa s (25 C); a viscosity in mPa s is 1000 times too large, above
// the 100 Pa s that no oil reaches from 0 C up (ISO VG 3200, the heaviest grade, has about
// 3 Pa s at 40 C). Colder reference temperatures keep the schema's range.
constexpr double kMinOilViscosityPaS = 5e-4;
constexpr double kMaxOilViscosityPaS = 100.0;
constexpr double kWarmReferenceK = 273.15;

void CheckViscosityIsPlausible(Document* doc, double t0_k) {
  if (!doc->Given("viscosity", "viscosity_pa_s") || Rejected(*doc, "viscosity", "viscosity_pa_s"))
    return;
  const double eta = doc->Real("viscosity", "viscosity_pa_s");
  if (eta < kMinOilViscosityPaS) {
    doc->Problem("viscosity", "viscosity_pa_s",
                 "below any lubricating oil (water: 0.00089 Pa s at 25 C): a kinematic "
                 "viscosity in m^2/s? (eta [Pa s] = nu [mm^2/s = cSt] x rho [kg/m^3] x 1e-6)",
                 "a dynamic viscosity >= 0.0005 Pa s");
  } else if (eta > kMaxOilViscosityPaS && t0_k >= kWarmReferenceK) {
    doc->Problem("viscosity", "viscosity_pa_s",
                 "above any lubricating oil at reference_temperature_k >= 273.15 K (ISO VG 3200: "
                 "about 3 Pa s at 40 C): in mPa s? (1 mPa s = 0.001 Pa s)",
                 "a dynamic viscosity <= 100 Pa s in Pa s");
  }
}

// Roelands' indices far below any lubricating oil, where a coefficient given in the index's
// place is the likely cause. The oils of seed 004 have Z = 0.62 and 0.5685 and their
// viscosity-temperature coefficients at 40 C, 0.046 and 0.05763 1/K, give S0 = beta (T0 - 138)
// / (ln eta0 + 9.67) = 1.07 and 1.26 (VALIDATION.md sections 1 and 5); the reference oil of
// VALIDATION.md section 3 has Z = 0.68. A tenth of those is no oil: a pressure-viscosity
// coefficient alpha written as Z (2.4e-8 in 1/Pa, 0.024 in 1/MPa) or a coefficient beta written
// as S0 (0.02 to 0.07 1/K) lands there and would make the film silently near-isoviscous, or
// near-isothermal in viscosity.
constexpr double kMinOilPressureIndex = 0.05;
constexpr double kMinOilTemperatureIndex = 0.1;

void CheckRoelandsIndicesArePlausible(Document* doc) {
  if (!doc->Has("viscosity", "model")) return;
  const std::string model = doc->String("viscosity", "model");
  const bool roelands = model == ToString(ViscosityLaw::kRoelands);
  if (!roelands && model != ToString(ViscosityLaw::kRoelandsGamma)) return;
  if (doc->Given("viscosity", "pressure_index") && !Rejected(*doc, "viscosity", "pressure_index") &&
      doc->Real("viscosity", "pressure_index") < kMinOilPressureIndex) {
    doc->Problem("viscosity", "pressure_index",
                 "below any lubricating oil (Z of the seed 004 oils: 0.62, 0.5685): a "
                 "pressure-viscosity coefficient alpha in 1/Pa or 1/MPa? Z is dimensionless, "
                 "Z = alpha x 1.96e8 Pa / (ln(eta0 / 1 Pa s) + 9.67) (Houpert); or use model "
                 "\"barus\" with pressure_coefficient_per_pa",
                 "a Roelands pressure index Z >= 0.05 [-]");
  }
  if (roelands && doc->Given("viscosity", "temperature_index") &&
      !Rejected(*doc, "viscosity", "temperature_index") &&
      doc->Real("viscosity", "temperature_index") < kMinOilTemperatureIndex) {
    doc->Problem("viscosity", "temperature_index",
                 "below any lubricating oil (S0 of the seed 004 oils at 40 C: 1.07, 1.26): a "
                 "viscosity-temperature coefficient beta = -d ln(eta)/dT in 1/K? S0 is "
                 "dimensionless, S0 = beta (T0 - 138 K) / (ln(eta0 / 1 Pa s) + 9.67); or use "
                 "model \"roelands_gamma\" with temperature_coefficient_per_k",
                 "a Roelands temperature index S0 >= 0.1 [-]");
  }
}

Lubricant Read(Document doc) {
  for (const auto& p : doc.problems())
    if (p.key == "(syntax)" || p.key == "(file)") doc.ThrowIfProblems();

  LawReader laws(&doc);
  std::unique_ptr<ViscosityModel> viscosity;
  std::unique_ptr<DensityModel> density;
  std::unique_ptr<ConductivityModel> conductivity;
  if (doc.Has("viscosity", "model")) {
    if (const auto p = laws.Parameters("viscosity")) {
      const ViscosityLaw law = ViscosityLawFromString(doc.String("viscosity", "model"));
      viscosity = laws.Build("viscosity", [&] { return MakeViscosityModel(law, laws.t0(), *p); });
    }
  }
  if (doc.Has("density", "model")) {
    if (const auto p = laws.Parameters("density")) {
      const DensityLaw law = DensityLawFromString(doc.String("density", "model"));
      density = laws.Build("density", [&] { return MakeDensityModel(law, laws.t0(), *p); });
    }
  }
  if (doc.Has("thermal", "conductivity_model") && doc.Has("thermal", "conductivity_w_mk")) {
    const ConductivityLaw law =
        ConductivityLawFromString(doc.String("thermal", "conductivity_model"));
    const double k0 = doc.Real("thermal", "conductivity_w_mk");
    conductivity = laws.Build("thermal", [&] { return MakeConductivityModel(law, k0); });
  }
  CheckViscosityIsPlausible(&doc, laws.t0());
  CheckRoelandsIndicesArePlausible(&doc);
  std::optional<EyringParameters> eyring;
  if (doc.HasSection("eyring"))
    eyring = EyringParameters{doc.Real("eyring", "eyring_stress_pa"),
                              doc.Real("eyring", "limiting_stress_pa"),
                              doc.Real("eyring", "limiting_stress_slope")};
  if (eyring && eyring->limiting_stress_slope > 0 && !(eyring->limiting_stress_pa > 0))
    doc.Problem("eyring", "limiting_stress_slope", internal::kSlopeNeedsStressRule,
                internal::kSlopeNeedsStressAllowed);
  doc.ThrowIfProblems();

  const bool dh = doc.String("density", "model") == ToString(DensityLaw::kDowsonHigginson);
  return Lubricant(doc.String("", "name"), doc.String("", "source"), laws.t0(),
                   doc.Real("thermal", "heat_capacity_j_kgk"),
                   dh ? doc.Real("density", "expansivity_per_k") : 0.0, std::move(viscosity),
                   std::move(density), std::move(conductivity), eyring);
}

}  // namespace

Lubricant Lubricant::FromFile(const std::string& path) {
  return Read(Document::ReadFile(internal::LubricantSchema(), path));
}

Lubricant Lubricant::FromString(const std::string& text, const std::string& name) {
  return Read(Document::ReadString(internal::LubricantSchema(), text, name));
}

}  // namespace tehl
