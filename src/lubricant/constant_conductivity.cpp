#include "tehl/lubricant/constant_conductivity.hpp"

#include "lubricant/law_check.hpp"

namespace tehl {

std::vector<InputProblem> ConstantConductivity::Parameters::Validate() const {
  std::vector<InputProblem> bad;
  internal::RequireParameter(conductivity_w_mk > 0, "conductivity_w_mk", conductivity_w_mk,
                             "must be > 0 [W/(m K)]", "a positive conductivity [W/(m K)]", &bad);
  return bad;
}

ConstantConductivity::ConstantConductivity(const Parameters& parameters) : parameters_(parameters) {
  internal::ThrowIfInvalid("ConstantConductivity", parameters_.Validate());
}

ConductivityValue ConstantConductivity::Evaluate(double /*p_pa*/) const {
  return {parameters_.conductivity_w_mk, 0.0};
}

std::string ConstantConductivity::Describe() const {
  return "constant: k = " + internal::Num(parameters_.conductivity_w_mk) + " W/(m K)";
}

}  // namespace tehl
