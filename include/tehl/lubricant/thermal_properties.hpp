// Thermal conductivity k(p) and heat capacity of a lubricant.
#pragma once

#include <string>

namespace tehl {

struct ConductivityValue {
  double k_w_mk = 0;  // thermal conductivity [W/(m K)]
  double dk_dp = 0;   // d k / d p [W/(m K) / Pa]
};

// Contract: p_pa >= 0. Pure and thread-safe.
class ConductivityModel {
 public:
  virtual ~ConductivityModel() = default;
  virtual ConductivityValue Evaluate(double p_pa) const = 0;
  virtual double ReferenceConductivity() const = 0;  // k at p = 0 [W/(m K)]
  virtual std::string Describe() const = 0;
};

}  // namespace tehl
