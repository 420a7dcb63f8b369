#include "tehl/lubricant/pressure_dependent_conductivity.hpp"

#include "lubricant/law_check.hpp"

namespace tehl {
namespace {
constexpr double kA = 1.73e-9;   // [1/Pa], seed 004 eq. 13 with p in Pa
constexpr double kB = 6.91e-10;  // [1/Pa]
}  // namespace

std::vector<InputProblem> PressureDependentConductivity::Parameters::Validate() const {
  std::vector<InputProblem> bad;
  internal::RequireParameter(conductivity_w_mk > 0, "conductivity_w_mk", conductivity_w_mk,
                             "must be > 0 [W/(m K)]", "a positive conductivity [W/(m K)]", &bad);
  return bad;
}

PressureDependentConductivity::PressureDependentConductivity(const Parameters& parameters)
    : parameters_(parameters) {
  internal::ThrowIfInvalid("PressureDependentConductivity", parameters_.Validate());
}

ConductivityValue PressureDependentConductivity::Evaluate(double p_pa) const {
  const double k0 = parameters_.conductivity_w_mk;
  const double den = 1.0 + kB * p_pa;
  return {k0 * (1.0 + kA * p_pa / den), k0 * kA / (den * den)};
}

std::string PressureDependentConductivity::Describe() const {
  return "pressure_dependent: k0 = " + internal::Num(parameters_.conductivity_w_mk) +
         " W/(m K), k = k0 [1 + 1.73e-9 p / (1 + 6.91e-10 p)]";
}

}  // namespace tehl
