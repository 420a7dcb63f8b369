// Incompressible lubricant: rho(p, T) = rho0 (no pressure or thermal dependence).
#pragma once

#include <string>
#include <vector>

#include "tehl/error.hpp"
#include "tehl/lubricant/density_model.hpp"

namespace tehl {

class ConstantDensity final : public DensityModel {
 public:
  struct Parameters {
    double density_kg_m3 = 0;                    // rho0 [kg/m^3]; > 0
    std::vector<InputProblem> Validate() const;  // every violated rule; empty = valid
  };

  explicit ConstantDensity(const Parameters& parameters);  // throws InputError if invalid

  // Contract: any p_pa, T_k. Pure and thread-safe.
  DensityValue Evaluate(double p_pa, double T_k) const override;
  double ReferenceDensity() const override { return parameters_.density_kg_m3; }
  std::string Describe() const override;

 private:
  Parameters parameters_;
};

}  // namespace tehl
