// Isoviscous lubricant: eta(p, T) = eta0. For the rigid-isoviscous verification limit
// (VALIDATION.md section 2) and for isoviscous comparisons.
#pragma once

#include <string>
#include <vector>

#include "tehl/error.hpp"
#include "tehl/lubricant/viscosity_model.hpp"

namespace tehl {

class ConstantViscosity final : public ViscosityModel {
 public:
  struct Parameters {
    double viscosity_pa_s = 0;                   // eta0 [Pa s]; > 0
    std::vector<InputProblem> Validate() const;  // every violated rule; empty = valid
  };

  explicit ConstantViscosity(const Parameters& parameters);  // throws InputError if invalid

  // Contract: any p_pa, T_k. Pure and thread-safe.
  ViscosityValue Evaluate(double p_pa, double T_k) const override;
  double ReferenceViscosity() const override { return parameters_.viscosity_pa_s; }
  double PressureViscosityCoefficient() const override { return 0.0; }  // [1/Pa]
  std::string Describe() const override;

 private:
  Parameters parameters_;
};

}  // namespace tehl
