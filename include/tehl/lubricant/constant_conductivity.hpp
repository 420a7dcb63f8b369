// Thermal conductivity independent of pressure: k(p) = k0.
#pragma once

#include <string>
#include <vector>

#include "tehl/error.hpp"
#include "tehl/lubricant/thermal_properties.hpp"

namespace tehl {

class ConstantConductivity final : public ConductivityModel {
 public:
  struct Parameters {
    double conductivity_w_mk = 0;                // k0 [W/(m K)]; > 0
    std::vector<InputProblem> Validate() const;  // every violated rule; empty = valid
  };

  explicit ConstantConductivity(const Parameters& parameters);  // throws InputError

  // Contract: any p_pa. Pure and thread-safe.
  ConductivityValue Evaluate(double p_pa) const override;
  double ReferenceConductivity() const override { return parameters_.conductivity_w_mk; }
  std::string Describe() const override;

 private:
  Parameters parameters_;
};

}  // namespace tehl
