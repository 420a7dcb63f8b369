#include "tehl/lubricant/lubricant.hpp"

#include <cmath>
#include <utility>
#include <vector>

#include "lubricant/law_check.hpp"
#include "lubricant/lubricant_schema.hpp"

namespace tehl {
using internal::Num;

Lubricant::Lubricant(std::string name,
                     std::string source,
                     double reference_temperature_k,
                     double heat_capacity_j_kgk,
                     double expansivity_per_k,
                     std::unique_ptr<ViscosityModel> viscosity,
                     std::unique_ptr<DensityModel> density,
                     std::unique_ptr<ConductivityModel> conductivity,
                     std::optional<EyringParameters> eyring)
    : name_(std::move(name)),
      source_(std::move(source)),
      t0_k_(reference_temperature_k),
      cp_(heat_capacity_j_kgk),
      beta_(expansivity_per_k),
      viscosity_(std::move(viscosity)),
      density_(std::move(density)),
      conductivity_(std::move(conductivity)),
      eyring_(eyring) {
  std::vector<InputProblem> bad;
  auto rule = [&](bool ok, const char* key, double value, const char* r, const char* allowed) {
    internal::RequireParameter(ok, key, value, r, allowed, &bad);
  };
  rule(t0_k_ > 0, "reference_temperature_k", t0_k_, "must be > 0 [K]",
       "an absolute temperature [K]");
  rule(cp_ > 0, "heat_capacity_j_kgk", cp_, "must be > 0 [J/(kg K)]", "a positive heat capacity");
  rule(beta_ >= 0 && std::isfinite(beta_), "expansivity_per_k", beta_, "must be >= 0 [1/K]",
       "a finite expansivity >= 0 [1/K]");
  auto missing = [&](bool ok, const char* key) {
    if (!ok) bad.push_back({"", 0, key, "", "no law given", "a non-null model"});
  };
  missing(viscosity_ != nullptr, "viscosity");
  missing(density_ != nullptr, "density");
  missing(conductivity_ != nullptr, "conductivity");
  if (eyring_) {
    rule(eyring_->eyring_stress_pa > 0, "eyring_stress_pa", eyring_->eyring_stress_pa,
         "must be > 0 [Pa]", "a positive stress [Pa]");
    rule(eyring_->limiting_stress_pa >= 0, "limiting_stress_pa", eyring_->limiting_stress_pa,
         "must be >= 0 [Pa]", "a stress >= 0 [Pa]");
    rule(eyring_->limiting_stress_slope >= 0, "limiting_stress_slope",
         eyring_->limiting_stress_slope, "must be >= 0 [-]", "a slope >= 0 [-]");
    rule(!(eyring_->limiting_stress_slope > 0) || eyring_->limiting_stress_pa > 0,
         "limiting_stress_slope", eyring_->limiting_stress_slope, internal::kSlopeNeedsStressRule,
         internal::kSlopeNeedsStressAllowed);
  }
  internal::ThrowIfInvalid("Lubricant", std::move(bad));
}

std::string Lubricant::Describe() const {
  std::string s = "lubricant \"" + name_ + "\"\n";
  s += "  source: " + source_ + "\n";
  s += "  reference temperature T0 = " + Num(t0_k_) + " K\n";
  s += "  viscosity: " + viscosity_->Describe() + "\n";
  s += "  density: " + density_->Describe() + "\n";
  s += "  conductivity: " + conductivity_->Describe() + "\n";
  s += "  heat capacity c_p = " + Num(cp_) + " J/(kg K), expansivity beta = " + Num(beta_) +
       " 1/K\n";
  if (eyring_) {
    s += "  Eyring: tau_0 = " + Num(eyring_->eyring_stress_pa) + " Pa";
    if (eyring_->limiting_stress_pa > 0 || eyring_->limiting_stress_slope > 0)
      s += ", tau_L = " + Num(eyring_->limiting_stress_pa) + " Pa + " +
           Num(eyring_->limiting_stress_slope) + " p";
    else
      s += ", no limiting shear stress";
    s += "\n";
  } else {
    s += "  Eyring: not given (effects.non_newtonian unavailable)\n";
  }
  return s;
}

}  // namespace tehl
