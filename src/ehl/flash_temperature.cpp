#include "tehl/ehl/flash_temperature.hpp"

#include <cmath>
#include <string>
#include <vector>

#include "tehl/error.hpp"

namespace tehl {
namespace {

// e sqrt(u) = sqrt(k rho c u) of a solid at its speed [W s^(1/2) / (m^2 K) (m/s)^(1/2)].
double Admittance(const SolidThermal& s, double u) {
  return std::sqrt(s.conductivity_w_mk * s.density_kg_m3 * s.heat_capacity_j_kgk * u);
}

void Check(
    bool ok, const char* key, double value, const char* allowed, std::vector<InputProblem>* bad) {
  if (!ok)
    bad->push_back({"", 0, key, std::to_string(value), std::string("must be ") + allowed, allowed});
}

void CheckSpeedsAndSolids(double u1,
                          double u2,
                          const SolidThermal& b1,
                          const SolidThermal& b2,
                          std::vector<InputProblem>* bad) {
  Check(std::isfinite(u1) && u1 >= 0, "u1_m_s", u1, "a speed >= 0 [m/s]", bad);
  Check(std::isfinite(u2) && u2 >= 0, "u2_m_s", u2, "a speed >= 0 [m/s]", bad);
  Check(u1 > 0 || u2 > 0, "u1_m_s", u1, "not both speeds 0", bad);
  for (const SolidThermal* s : {&b1, &b2}) {
    Check(std::isfinite(s->density_kg_m3) && s->density_kg_m3 > 0, "density_kg_m3",
          s->density_kg_m3, "> 0 [kg/m^3]", bad);
    Check(std::isfinite(s->heat_capacity_j_kgk) && s->heat_capacity_j_kgk > 0,
          "heat_capacity_j_kgk", s->heat_capacity_j_kgk, "> 0 [J/(kg K)]", bad);
    Check(std::isfinite(s->conductivity_w_mk) && s->conductivity_w_mk > 0, "conductivity_w_mk",
          s->conductivity_w_mk, "> 0 [W/(m K)]", bad);
  }
}

}  // namespace

double BlokFlashTemperature(const FlashTemperatureInputs& in,
                            const SolidThermal& body1,
                            const SolidThermal& body2) {
  std::vector<InputProblem> bad;
  CheckSpeedsAndSolids(in.u1_m_s, in.u2_m_s, body1, body2, &bad);
  Check(std::isfinite(in.friction_coefficient) && in.friction_coefficient >= 0,
        "friction_coefficient", in.friction_coefficient, ">= 0", &bad);
  Check(std::isfinite(in.load_n_per_m) && in.load_n_per_m >= 0, "load_n_per_m", in.load_n_per_m,
        ">= 0 [N/m]", &bad);
  const double heat = in.friction_coefficient * in.load_n_per_m * std::abs(in.u1_m_s - in.u2_m_s);
  Check(std::isfinite(in.half_width_m) && (in.half_width_m > 0 || !(heat > 0)), "half_width_m",
        in.half_width_m, "> 0 [m] when there is friction heat", &bad);
  if (!bad.empty()) throw InputError(std::move(bad));
  if (!(heat > 0)) return 0.0;
  return kBlokFactor * heat /
         (std::sqrt(in.half_width_m) *
          (Admittance(body1, in.u1_m_s) + Admittance(body2, in.u2_m_s)));
}

double BlokWeightedRise(double theta1_k,
                        double theta2_k,
                        double u1_m_s,
                        double u2_m_s,
                        const SolidThermal& body1,
                        const SolidThermal& body2) {
  std::vector<InputProblem> bad;
  CheckSpeedsAndSolids(u1_m_s, u2_m_s, body1, body2, &bad);
  if (!bad.empty()) throw InputError(std::move(bad));
  const double a1 = Admittance(body1, u1_m_s), a2 = Admittance(body2, u2_m_s);
  return (theta1_k * a1 + theta2_k * a2) / (a1 + a2);
}

}  // namespace tehl
