// Viscosity laws eta(p, T) of a lubricant, each returning the value and its partial
// derivatives (the Newton Jacobians of the film solver need them).
#pragma once

#include <memory>
#include <string>

namespace tehl {

struct ViscosityValue {
  double eta_pa_s = 0;  // dynamic viscosity [Pa s]
  double deta_dp = 0;   // d eta / d p [Pa s / Pa = s]
  double deta_dT = 0;   // d eta / d T [Pa s / K]
};

// Contract: p_pa >= 0 (callers clamp cavitated nodes to 0), T_k > 0. Pure and thread-safe.
class ViscosityModel {
 public:
  virtual ~ViscosityModel() = default;
  virtual ViscosityValue Evaluate(double p_pa, double T_k) const = 0;
  // Batch form for hot loops: one virtual call per array. out[i] = Evaluate(p[i], T[i]).
  virtual void EvaluateMany(const double* p_pa,
                            const double* T_k,
                            int n,
                            ViscosityValue* out) const;
  // eta at p = 0 and the reference temperature T0 [Pa s].
  virtual double ReferenceViscosity() const = 0;
  // Pressure-viscosity coefficient alpha for dimensionless groups (G = alpha E'): for
  // Roelands, Houpert's alpha = Z (ln eta0 + 9.67) / 1.96e8 at T0 [1/Pa].
  virtual double PressureViscosityCoefficient() const = 0;
  virtual std::string Describe() const = 0;  // one line, for logs and result files
};

}  // namespace tehl
