#include "tehl/lubricant/roelands_gamma_viscosity.hpp"

#include <cmath>

#include "lubricant/law_check.hpp"
#include "lubricant/roelands_column.hpp"

namespace tehl {
using internal::kHoupertPressure;
using internal::kRoelandsLnEtaInf;
using internal::kRoelandsPressureScale;
using internal::Num;

std::vector<InputProblem> RoelandsGammaViscosity::Parameters::Validate() const {
  std::vector<InputProblem> bad;
  const double eta_inf = std::exp(-kRoelandsLnEtaInf);
  internal::RequireParameter(viscosity_pa_s > eta_inf, "viscosity_pa_s", viscosity_pa_s,
                             "Roelands needs eta0 above eta_inf = 6.31e-5 [Pa s]",
                             "a viscosity > 6.31e-5 [Pa s]", &bad);
  internal::RequireParameter(reference_temperature_k > 0, "reference_temperature_k",
                             reference_temperature_k, "must be > 0 [K]",
                             "an absolute temperature [K]", &bad);
  internal::RequireParameter(pressure_index > 0 && pressure_index <= 1.5, "pressure_index",
                             pressure_index, "out of range", "Z in (0, 1.5] [-]", &bad);
  internal::RequireParameter(
      temperature_coefficient_per_k >= 0 && temperature_coefficient_per_k <= 1,
      "temperature_coefficient_per_k", temperature_coefficient_per_k, "out of range",
      "gamma in [0, 1] [1/K]", &bad);
  return bad;
}

RoelandsGammaViscosity::RoelandsGammaViscosity(const Parameters& parameters)
    : parameters_(parameters) {
  internal::ThrowIfInvalid("RoelandsGammaViscosity", parameters_.Validate());
  a_ = std::log(parameters_.viscosity_pa_s) + kRoelandsLnEtaInf;
}

inline ViscosityValue RoelandsGammaViscosity::Eval(double p_pa, double T_k) const {
  const double base = 1.0 + kRoelandsPressureScale * p_pa;
  return Finish(base, std::pow(base, parameters_.pressure_index), T_k);
}

// The law from base = 1 + p/p0 and pz = base^Z.
inline ViscosityValue RoelandsGammaViscosity::Finish(double base, double pz, double T_k) const {
  const Parameters& q = parameters_;
  const double gamma = q.temperature_coefficient_per_k;
  const double eta =
      q.viscosity_pa_s * std::exp(a_ * (pz - 1.0) - gamma * (T_k - q.reference_temperature_k));
  // d ln(eta)/dp = a Z (1/p0) (1 + p/p0)^(Z-1);  d ln(eta)/dT = -gamma.
  const double dln_dp = a_ * q.pressure_index * kRoelandsPressureScale * (pz / base);
  return {eta, eta * dln_dp, -gamma * eta};
}

ViscosityValue RoelandsGammaViscosity::Evaluate(double p_pa, double T_k) const {
  return Eval(p_pa, T_k);
}

void RoelandsGammaViscosity::EvaluateMany(const double* p_pa,
                                          const double* T_k,
                                          int n,
                                          ViscosityValue* out) const {
  internal::EvaluateColumn(
      p_pa, T_k, n, kRoelandsPressureScale, parameters_.pressure_index,
      [](double) { return 0.0; },  // the temperature enters through one exp with p
      [this](double base, double pz, double t, double) { return Finish(base, pz, t); }, out);
}

double RoelandsGammaViscosity::PressureViscosityCoefficient() const {
  return parameters_.pressure_index * a_ / kHoupertPressure;
}

std::string RoelandsGammaViscosity::Describe() const {
  const Parameters& q = parameters_;
  return "roelands_gamma: eta0 = " + Num(q.viscosity_pa_s) +
         " Pa s at T0 = " + Num(q.reference_temperature_k) + " K, Z = " + Num(q.pressure_index) +
         ", gamma = " + Num(q.temperature_coefficient_per_k) +
         " 1/K; Houpert alpha = " + Num(PressureViscosityCoefficient()) + " 1/Pa";
}

}  // namespace tehl
