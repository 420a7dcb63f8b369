// Roelands viscosity with the S0 temperature index (Roelands 1966; DESIGN.md section 4, the
// form of seed 004 eq. 7 with the exponent and the constant corrected):
//   eta(p, T) = eta0 exp{ (ln eta0 + 9.67) [ -1 + (1 + 5.1e-9 p)^Z ((T - 138)/(T0 - 138))^-S0 ] }
// with p in Pa, T in K, eta0 in Pa s. 9.67 = -ln(eta_inf / 1 Pa s), eta_inf = 6.31e-5 Pa s, and
// 5.1e-9 Pa^-1 = 1/p0 with p0 = 1.96e8 Pa. At (p = 0, T = T0) the bracket is 0, so eta = eta0.
#pragma once

#include <string>
#include <vector>

#include "tehl/error.hpp"
#include "tehl/lubricant/viscosity_model.hpp"

namespace tehl {

class RoelandsViscosity final : public ViscosityModel {
 public:
  // Field names are the keys of a lubricant file (docs/case_format.md).
  struct Parameters {
    double viscosity_pa_s = 0;           // eta0 at p = 0, T0 [Pa s]; > 6.31e-5 (eta_inf)
    double reference_temperature_k = 0;  // T0 [K]; > 138
    double pressure_index = 0;           // Z [-]; in (0, 1.5], mineral oils 0.5-0.7
    double temperature_index = 0;        // S0 [-]; in (0, 5], mineral oils 1.0-1.5
    // Every violated rule, key = field name; empty = valid.
    std::vector<InputProblem> Validate() const;
  };

  explicit RoelandsViscosity(const Parameters& parameters);  // throws InputError if invalid

  // Contract: p_pa >= 0, T_k > 138. Pure and thread-safe.
  ViscosityValue Evaluate(double p_pa, double T_k) const override;
  void EvaluateMany(const double* p_pa,
                    const double* T_k,
                    int n,
                    ViscosityValue* out) const override;
  double ReferenceViscosity() const override { return parameters_.viscosity_pa_s; }
  // Houpert: alpha = Z (ln eta0 + 9.67) / 1.96e8 [1/Pa] (VALIDATION.md section 1).
  double PressureViscosityCoefficient() const override;
  std::string Describe() const override;
  const Parameters& parameters() const { return parameters_; }

 private:
  ViscosityValue Eval(double p_pa, double T_k) const;
  double TemperatureFactor(double T_k) const;
  ViscosityValue Finish(double base, double pz, double T_k, double ts) const;
  Parameters parameters_;
  double a_;  // ln eta0 + 9.67 [-]
};

}  // namespace tehl
