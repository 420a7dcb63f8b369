#include "tehl/lubricant/dowson_higginson_density.hpp"

#include "lubricant/law_check.hpp"

namespace tehl {
namespace {
constexpr double kA = 0.6e-9;  // [1/Pa], Dowson & Higginson 1966
constexpr double kB = 1.7e-9;  // [1/Pa]
}  // namespace

std::vector<InputProblem> DowsonHigginsonDensity::Parameters::Validate() const {
  std::vector<InputProblem> bad;
  internal::RequireParameter(density_kg_m3 > 0, "density_kg_m3", density_kg_m3,
                             "must be > 0 [kg/m^3]", "a positive density [kg/m^3]", &bad);
  internal::RequireParameter(reference_temperature_k > 0, "reference_temperature_k",
                             reference_temperature_k, "must be > 0 [K]",
                             "an absolute temperature [K]", &bad);
  internal::RequireParameter(expansivity_per_k >= 0 && expansivity_per_k < 0.01,
                             "expansivity_per_k", expansivity_per_k, "out of range",
                             "beta in [0, 0.01) [1/K]", &bad);
  return bad;
}

DowsonHigginsonDensity::DowsonHigginsonDensity(const Parameters& parameters)
    : parameters_(parameters) {
  internal::ThrowIfInvalid("DowsonHigginsonDensity", parameters_.Validate());
}

inline DensityValue DowsonHigginsonDensity::Eval(double p_pa, double T_k) const {
  const Parameters& q = parameters_;
  const double den = 1.0 + kB * p_pa;
  const double fp = 1.0 + kA * p_pa / den;  // pressure factor
  const double dfp = kA / (den * den);      // its derivative [1/Pa]
  const double ft = 1.0 - q.expansivity_per_k * (T_k - q.reference_temperature_k);
  const double r0 = q.density_kg_m3;
  return {r0 * fp * ft, r0 * dfp * ft, -r0 * fp * q.expansivity_per_k};
}

DensityValue DowsonHigginsonDensity::Evaluate(double p_pa, double T_k) const {
  return Eval(p_pa, T_k);
}

void DowsonHigginsonDensity::EvaluateMany(const double* p_pa,
                                          const double* T_k,
                                          int n,
                                          DensityValue* out) const {
  for (int i = 0; i < n; ++i) out[i] = Eval(p_pa[i], T_k[i]);
}

std::string DowsonHigginsonDensity::Describe() const {
  const Parameters& q = parameters_;
  return "dowson_higginson: rho0 = " + internal::Num(q.density_kg_m3) +
         " kg/m^3 at T0 = " + internal::Num(q.reference_temperature_k) +
         " K, beta = " + internal::Num(q.expansivity_per_k) + " 1/K";
}

}  // namespace tehl
