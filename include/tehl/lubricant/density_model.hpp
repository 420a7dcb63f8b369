// Density laws rho(p, T) of a lubricant, each returning the value and its partial
// derivatives.
#pragma once

#include <string>

namespace tehl {

struct DensityValue {
  double rho_kg_m3 = 0;  // density [kg/m^3]
  double drho_dp = 0;    // d rho / d p [kg/m^3 / Pa]
  double drho_dT = 0;    // d rho / d T [kg/m^3 / K]
};

// Contract: p_pa >= 0, T_k > 0. Pure and thread-safe.
class DensityModel {
 public:
  virtual ~DensityModel() = default;
  virtual DensityValue Evaluate(double p_pa, double T_k) const = 0;
  virtual void EvaluateMany(const double* p_pa, const double* T_k, int n, DensityValue* out) const;
  virtual double ReferenceDensity() const = 0;  // rho at p = 0, T0 [kg/m^3]
  virtual std::string Describe() const = 0;
};

}  // namespace tehl
