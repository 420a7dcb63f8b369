#include "tehl/lubricant/constant_viscosity.hpp"

#include "lubricant/law_check.hpp"

namespace tehl {

std::vector<InputProblem> ConstantViscosity::Parameters::Validate() const {
  std::vector<InputProblem> bad;
  internal::RequireParameter(viscosity_pa_s > 0, "viscosity_pa_s", viscosity_pa_s,
                             "must be > 0 [Pa s]", "a positive viscosity [Pa s]", &bad);
  return bad;
}

ConstantViscosity::ConstantViscosity(const Parameters& parameters) : parameters_(parameters) {
  internal::ThrowIfInvalid("ConstantViscosity", parameters_.Validate());
}

ViscosityValue ConstantViscosity::Evaluate(double /*p_pa*/, double /*T_k*/) const {
  return {parameters_.viscosity_pa_s, 0.0, 0.0};
}

std::string ConstantViscosity::Describe() const {
  return "constant: eta = " + internal::Num(parameters_.viscosity_pa_s) + " Pa s";
}

}  // namespace tehl
