// Dowson-Higginson density with linear thermal expansion (Dowson & Higginson 1966; seed 004
// eq. 6 in dimensional form, DESIGN.md section 4):
//   rho(p, T) = rho0 [1 + 0.6e-9 p / (1 + 1.7e-9 p)] [1 - beta (T - T0)]     (p in Pa)
// The pressure factor rises from 1 to 1 + 0.6/1.7 = 1.353 as p -> infinity.
#pragma once

#include <string>
#include <vector>

#include "tehl/error.hpp"
#include "tehl/lubricant/density_model.hpp"

namespace tehl {

class DowsonHigginsonDensity final : public DensityModel {
 public:
  // Field names are the keys of a lubricant file (docs/case_format.md).
  struct Parameters {
    double density_kg_m3 = 0;                    // rho0 at p = 0, T0 [kg/m^3]; > 0
    double reference_temperature_k = 0;          // T0 [K]; > 0
    double expansivity_per_k = 0;                // beta [1/K]; in [0, 0.01)
    std::vector<InputProblem> Validate() const;  // every violated rule; empty = valid
  };

  explicit DowsonHigginsonDensity(const Parameters& parameters);  // throws InputError

  // Contract: p_pa >= 0, 0 < T_k < T0 + 1/beta (the density stays positive). Pure and
  // thread-safe.
  DensityValue Evaluate(double p_pa, double T_k) const override;
  void EvaluateMany(const double* p_pa, const double* T_k, int n, DensityValue* out) const override;
  double ReferenceDensity() const override { return parameters_.density_kg_m3; }
  std::string Describe() const override;
  const Parameters& parameters() const { return parameters_; }

 private:
  DensityValue Eval(double p_pa, double T_k) const;
  Parameters parameters_;
};

}  // namespace tehl
