// Roelands pressure dependence with an exponential temperature term, the form of seed 004
// eq. (7) as corrected in DESIGN.md section 4 (exponent Z, constant 9.67):
//   eta(p, T) = eta0 exp{ (ln eta0 + 9.67) [ -1 + (1 + 5.1e-9 p)^Z ] - gamma (T - T0) }
// with p in Pa, T in K, eta0 in Pa s. Written with the leading eta0 so that eta(0, T0) = eta0
// exactly (the printed eq. 7 leaves it out of the dimensional form). gamma is the
// viscosity-temperature coefficient of seed 004 Table 2.
#pragma once

#include <string>
#include <vector>

#include "tehl/error.hpp"
#include "tehl/lubricant/viscosity_model.hpp"

namespace tehl {

class RoelandsGammaViscosity final : public ViscosityModel {
 public:
  // Field names are the keys of a lubricant file (docs/case_format.md).
  struct Parameters {
    double viscosity_pa_s = 0;                 // eta0 at p = 0, T0 [Pa s]; > 6.31e-5 (eta_inf)
    double reference_temperature_k = 0;        // T0 [K]; > 0
    double pressure_index = 0;                 // Z [-]; in (0, 1.5]
    double temperature_coefficient_per_k = 0;  // gamma = -d ln(eta)/dT [1/K]; in [0, 1]
    // Every violated rule, key = field name; empty = valid.
    std::vector<InputProblem> Validate() const;
  };

  explicit RoelandsGammaViscosity(const Parameters& parameters);  // throws InputError

  // Contract: p_pa >= 0, T_k > 0. Pure and thread-safe.
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
  ViscosityValue Finish(double base, double pz, double T_k) const;
  Parameters parameters_;
  double a_;  // ln eta0 + 9.67 [-]
};

}  // namespace tehl
