#include "tehl/lubricant/constant_density.hpp"

#include "lubricant/law_check.hpp"

namespace tehl {

std::vector<InputProblem> ConstantDensity::Parameters::Validate() const {
  std::vector<InputProblem> bad;
  internal::RequireParameter(density_kg_m3 > 0, "density_kg_m3", density_kg_m3,
                             "must be > 0 [kg/m^3]", "a positive density [kg/m^3]", &bad);
  return bad;
}

ConstantDensity::ConstantDensity(const Parameters& parameters) : parameters_(parameters) {
  internal::ThrowIfInvalid("ConstantDensity", parameters_.Validate());
}

DensityValue ConstantDensity::Evaluate(double /*p_pa*/, double /*T_k*/) const {
  return {parameters_.density_kg_m3, 0.0, 0.0};
}

std::string ConstantDensity::Describe() const {
  return "constant: rho = " + internal::Num(parameters_.density_kg_m3) + " kg/m^3";
}

}  // namespace tehl
