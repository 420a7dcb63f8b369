// Pressure-dependent thermal conductivity of a mineral oil (seed 004 eq. 13, after its ref.
// [11]; DESIGN.md section 4):
//   k(p) = k0 [1 + 1.73e-9 p / (1 + 6.91e-10 p)]     (p in Pa)
// The factor rises from 1 to 1 + 1.73/0.691 = 3.50 as p -> infinity.
#pragma once

#include <string>
#include <vector>

#include "tehl/error.hpp"
#include "tehl/lubricant/thermal_properties.hpp"

namespace tehl {

class PressureDependentConductivity final : public ConductivityModel {
 public:
  struct Parameters {
    double conductivity_w_mk = 0;                // k0 at p = 0 [W/(m K)]; > 0
    std::vector<InputProblem> Validate() const;  // every violated rule; empty = valid
  };

  explicit PressureDependentConductivity(const Parameters& parameters);  // throws InputError

  // Contract: p_pa >= 0. Pure and thread-safe.
  ConductivityValue Evaluate(double p_pa) const override;
  double ReferenceConductivity() const override { return parameters_.conductivity_w_mk; }
  std::string Describe() const override;

 private:
  Parameters parameters_;
};

}  // namespace tehl
