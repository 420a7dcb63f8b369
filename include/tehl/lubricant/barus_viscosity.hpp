// Barus viscosity with an exponential temperature term:
//   eta(p, T) = eta0 exp( alpha p - gamma (T - T0) )
// (Barus 1893; the temperature term as in Reynolds' exponential law). Overpredicts viscosity
// above about 0.5 GPa compared with Roelands; kept for analytic comparisons and the
// verification cases of the film solver.
#pragma once

#include <string>
#include <vector>

#include "tehl/error.hpp"
#include "tehl/lubricant/viscosity_model.hpp"

namespace tehl {

class BarusViscosity final : public ViscosityModel {
 public:
  // Field names are the keys of a lubricant file (docs/case_format.md).
  struct Parameters {
    double viscosity_pa_s = 0;                 // eta0 at p = 0, T0 [Pa s]; > 0
    double reference_temperature_k = 0;        // T0 [K]; > 0
    double pressure_coefficient_per_pa = 0;    // alpha [1/Pa]; in [0, 1e-7]
    double temperature_coefficient_per_k = 0;  // gamma [1/K]; in [0, 1]
    // Every violated rule, key = field name; empty = valid.
    std::vector<InputProblem> Validate() const;
  };

  explicit BarusViscosity(const Parameters& parameters);  // throws InputError if invalid

  // Contract: p_pa >= 0, T_k > 0. Pure and thread-safe.
  ViscosityValue Evaluate(double p_pa, double T_k) const override;
  double ReferenceViscosity() const override { return parameters_.viscosity_pa_s; }
  // alpha itself [1/Pa].
  double PressureViscosityCoefficient() const override {
    return parameters_.pressure_coefficient_per_pa;
  }
  std::string Describe() const override;
  const Parameters& parameters() const { return parameters_; }

 private:
  Parameters parameters_;
};

}  // namespace tehl
