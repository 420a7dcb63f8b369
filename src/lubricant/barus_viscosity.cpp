#include "tehl/lubricant/barus_viscosity.hpp"

#include <cmath>

#include "lubricant/law_check.hpp"

namespace tehl {
using internal::Num;

std::vector<InputProblem> BarusViscosity::Parameters::Validate() const {
  std::vector<InputProblem> bad;
  internal::RequireParameter(viscosity_pa_s > 0, "viscosity_pa_s", viscosity_pa_s,
                             "must be > 0 [Pa s]", "a positive viscosity [Pa s]", &bad);
  internal::RequireParameter(reference_temperature_k > 0, "reference_temperature_k",
                             reference_temperature_k, "must be > 0 [K]",
                             "an absolute temperature [K]", &bad);
  internal::RequireParameter(
      pressure_coefficient_per_pa >= 0 && pressure_coefficient_per_pa <= 1e-7,
      "pressure_coefficient_per_pa", pressure_coefficient_per_pa, "out of range",
      "alpha in [0, 1e-7] [1/Pa]", &bad);
  internal::RequireParameter(
      temperature_coefficient_per_k >= 0 && temperature_coefficient_per_k <= 1,
      "temperature_coefficient_per_k", temperature_coefficient_per_k, "out of range",
      "gamma in [0, 1] [1/K]", &bad);
  return bad;
}

BarusViscosity::BarusViscosity(const Parameters& parameters) : parameters_(parameters) {
  internal::ThrowIfInvalid("BarusViscosity", parameters_.Validate());
}

ViscosityValue BarusViscosity::Evaluate(double p_pa, double T_k) const {
  const Parameters& q = parameters_;
  const double alpha = q.pressure_coefficient_per_pa;
  const double gamma = q.temperature_coefficient_per_k;
  const double eta =
      q.viscosity_pa_s * std::exp(alpha * p_pa - gamma * (T_k - q.reference_temperature_k));
  return {eta, alpha * eta, -gamma * eta};
}

std::string BarusViscosity::Describe() const {
  const Parameters& q = parameters_;
  return "barus: eta0 = " + Num(q.viscosity_pa_s) +
         " Pa s at T0 = " + Num(q.reference_temperature_k) +
         " K, alpha = " + Num(q.pressure_coefficient_per_pa) +
         " 1/Pa, gamma = " + Num(q.temperature_coefficient_per_k) + " 1/K";
}

}  // namespace tehl
