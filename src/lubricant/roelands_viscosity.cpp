#include "tehl/lubricant/roelands_viscosity.hpp"

#include <cmath>

#include "lubricant/law_check.hpp"
#include "lubricant/roelands_column.hpp"

namespace tehl {
using internal::kHoupertPressure;
using internal::kRoelandsLnEtaInf;
using internal::kRoelandsPressureScale;
using internal::kRoelandsTemperatureOffset;
using internal::Num;

std::vector<InputProblem> RoelandsViscosity::Parameters::Validate() const {
  std::vector<InputProblem> bad;
  const double eta_inf = std::exp(-kRoelandsLnEtaInf);
  internal::RequireParameter(viscosity_pa_s > eta_inf, "viscosity_pa_s", viscosity_pa_s,
                             "Roelands needs eta0 above eta_inf = 6.31e-5 [Pa s]",
                             "a viscosity > 6.31e-5 [Pa s]", &bad);
  internal::RequireParameter(reference_temperature_k > kRoelandsTemperatureOffset,
                             "reference_temperature_k", reference_temperature_k,
                             "the S0 form needs T0 > 138 [K]", "an absolute temperature > 138 [K]",
                             &bad);
  internal::RequireParameter(pressure_index > 0 && pressure_index <= 1.5, "pressure_index",
                             pressure_index, "out of range", "Z in (0, 1.5] [-]", &bad);
  internal::RequireParameter(temperature_index > 0 && temperature_index <= 5, "temperature_index",
                             temperature_index, "out of range", "S0 in (0, 5] [-]", &bad);
  return bad;
}

RoelandsViscosity::RoelandsViscosity(const Parameters& parameters) : parameters_(parameters) {
  internal::ThrowIfInvalid("RoelandsViscosity", parameters_.Validate());
  a_ = std::log(parameters_.viscosity_pa_s) + kRoelandsLnEtaInf;
}

inline ViscosityValue RoelandsViscosity::Eval(double p_pa, double T_k) const {
  const double base = 1.0 + kRoelandsPressureScale * p_pa;
  // (1 + p/p0)^Z
  return Finish(base, std::pow(base, parameters_.pressure_index), T_k, TemperatureFactor(T_k));
}

// ((T - 138)/(T0 - 138))^-S0.
inline double RoelandsViscosity::TemperatureFactor(double T_k) const {
  const Parameters& q = parameters_;
  const double t_rel =
      (T_k - kRoelandsTemperatureOffset) / (q.reference_temperature_k - kRoelandsTemperatureOffset);
  return std::pow(t_rel, -q.temperature_index);
}

// The law from base = 1 + p/p0, pz = base^Z and ts = TemperatureFactor(T).
inline ViscosityValue RoelandsViscosity::Finish(double base,
                                                double pz,
                                                double T_k,
                                                double ts) const {
  const Parameters& q = parameters_;
  const double eta = q.viscosity_pa_s * std::exp(a_ * (pz * ts - 1.0));
  // d ln(eta)/dp = a Z (1/p0) (1 + p/p0)^(Z-1) ts;  d ln(eta)/dT = -a S0 pz ts / (T - 138).
  const double dln_dp = a_ * q.pressure_index * kRoelandsPressureScale * (pz / base) * ts;
  const double dln_dT = -a_ * q.temperature_index * pz * ts / (T_k - kRoelandsTemperatureOffset);
  return {eta, eta * dln_dp, eta * dln_dT};
}

ViscosityValue RoelandsViscosity::Evaluate(double p_pa, double T_k) const {
  return Eval(p_pa, T_k);
}

void RoelandsViscosity::EvaluateMany(const double* p_pa,
                                     const double* T_k,
                                     int n,
                                     ViscosityValue* out) const {
  internal::EvaluateColumn(
      p_pa, T_k, n, kRoelandsPressureScale, parameters_.pressure_index,
      [this](double t) { return TemperatureFactor(t); },
      [this](double base, double pz, double t, double ts) { return Finish(base, pz, t, ts); }, out);
}

double RoelandsViscosity::PressureViscosityCoefficient() const {
  return parameters_.pressure_index * a_ / kHoupertPressure;
}

std::string RoelandsViscosity::Describe() const {
  const Parameters& q = parameters_;
  return "roelands: eta0 = " + Num(q.viscosity_pa_s) +
         " Pa s at T0 = " + Num(q.reference_temperature_k) + " K, Z = " + Num(q.pressure_index) +
         ", S0 = " + Num(q.temperature_index) +
         "; Houpert alpha = " + Num(PressureViscosityCoefficient()) + " 1/Pa";
}

}  // namespace tehl
