// A lubricant: its property laws, read from a lubricant file (lubricants/*.toml; the format
// is in docs/case_format.md). Immutable once built; copies share the laws. Thread-safe to read.
#pragma once

#include <memory>
#include <optional>
#include <string>

#include "tehl/error.hpp"
#include "tehl/lubricant/density_model.hpp"
#include "tehl/lubricant/thermal_properties.hpp"
#include "tehl/lubricant/viscosity_model.hpp"

namespace tehl {

// Ree-Eyring shear thinning with an optional limiting shear stress tau_L = tau_L0 + Lambda p
// (effect non_newtonian). Absent from a lubricant file = the effect cannot be switched on.
struct EyringParameters {
  double eyring_stress_pa = 0;       // tau_0 [Pa]
  double limiting_stress_pa = 0;     // tau_L0 [Pa]; >= 0
  double limiting_stress_slope = 0;  // Lambda = d tau_L / d p [-]; both 0 = no limit
};

class Lubricant {
 public:
  // Throws InputError if a law is missing, t0 <= 0, cp <= 0 or beta < 0.
  Lubricant(std::string name,
            std::string source,
            double reference_temperature_k,
            double heat_capacity_j_kgk,
            double expansivity_per_k,
            std::unique_ptr<ViscosityModel> viscosity,
            std::unique_ptr<DensityModel> density,
            std::unique_ptr<ConductivityModel> conductivity,
            std::optional<EyringParameters> eyring = std::nullopt);

  // Reads a lubricant file; throws InputError listing every problem (file:line: key ...).
  static Lubricant FromFile(const std::string& path);
  // The same for the text of a lubricant file; `name` stands for the path in messages.
  static Lubricant FromString(const std::string& text, const std::string& name);

  const std::string& name() const { return name_; }
  const std::string& source() const { return source_; }     // citation of the data
  double reference_temperature_k() const { return t0_k_; }  // T0 of the laws [K]
  double heat_capacity_j_kgk() const { return cp_; }        // c_p [J/(kg K)]
  double expansivity_per_k() const { return beta_; }        // thermal expansivity [1/K]
  const ViscosityModel& viscosity() const { return *viscosity_; }
  const DensityModel& density() const { return *density_; }
  const ConductivityModel& conductivity() const { return *conductivity_; }
  const std::optional<EyringParameters>& eyring() const { return eyring_; }
  std::string Describe() const;  // several lines: every law and parameter

 private:
  std::string name_, source_;
  double t0_k_, cp_, beta_;
  std::shared_ptr<const ViscosityModel> viscosity_;
  std::shared_ptr<const DensityModel> density_;
  std::shared_ptr<const ConductivityModel> conductivity_;
  std::optional<EyringParameters> eyring_;
};

}  // namespace tehl
