#include "tehl/lubricant/barus_viscosity.hpp"

#include <cmath>
#include <string>

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
  // Mineral oils have alpha of 1e-8 ... 4e-8 1/Pa, often quoted as 10 ... 40 1/GPa: a value
  // of 0.5 ... 100 is most likely in 1/GPa (K.L. Johnson, Contact Mechanics, 1985, Table 13.1).
  const double a = pressure_coefficient_per_pa;
  std::string allowed = "alpha in [0, 1e-7] [1/Pa]";
  if (a >= 0.5 && a <= 100)
    allowed += ": in 1/GPa? (" + Num(a) + " 1/GPa = " + Num(a * 1e-9) + " 1/Pa)";
  internal::RequireParameter(a >= 0 && a <= 1e-7, "pressure_coefficient_per_pa", a, "out of range",
                             allowed, &bad);
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
