#include "tehl/ehl/flash_temperature.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
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

// The checks of both flash temperatures; returns the friction heat mu w |u1 - u2| [W/m].
double CheckedHeat(const FlashTemperatureInputs& in,
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
  return heat;
}

// Cell means of the semi-elliptic density (2/(pi b)) sqrt(1 - (x/b)^2) on the cells of g
// (half cells at both ends), exact: the primitive of sqrt(1 - s^2) is (s sqrt(1 - s^2) +
// asin s)/2 [1/m].
Eigen::VectorXd SemiEllipticCellMeans(const UniformGrid& g, double b) {
  auto primitive = [](double s) {
    s = std::clamp(s, -1.0, 1.0);
    return 0.5 * (s * std::sqrt(1 - s * s) + std::asin(s));
  };
  const int n = g.size();
  const double dx = g.dx_m();
  Eigen::VectorXd q(n);
  for (int k = 0; k < n; ++k) {
    const double lo = k == 0 ? g.x(0) : g.x(k) - 0.5 * dx;
    const double hi = k == n - 1 ? g.x(n - 1) : g.x(k) + 0.5 * dx;
    q[k] = (2 / M_PI) * (primitive(hi / b) - primitive(lo / b)) / (hi - lo);
  }
  return q;
}

}  // namespace

double BlokFlashTemperature(const FlashTemperatureInputs& in,
                            const SolidThermal& body1,
                            const SolidThermal& body2) {
  const double heat = CheckedHeat(in, body1, body2);
  if (!(heat > 0)) return 0.0;
  return kBlokFactor * heat /
         (std::sqrt(in.half_width_m) *
          (Admittance(body1, in.u1_m_s) + Admittance(body2, in.u2_m_s)));
}

double FinitePecletFlashTemperature(const FlashTemperatureInputs& in,
                                    const SolidThermal& body1,
                                    const SolidThermal& body2,
                                    int cells) {
  const double heat = CheckedHeat(in, body1, body2);
  if (cells < 8)
    throw InputError(InputProblem{"", 0, "cells", std::to_string(cells), "must be >= 8", ">= 8"});
  if (!(heat > 0)) return 0.0;
  // The grid: 2b in `cells` cells, and b/2 on either side (the peak lies inside the band).
  const double b = in.half_width_m, dx = 2 * b / cells;
  const int margin = cells / 4, n = cells + 1 + 2 * margin;
  const UniformGrid g(-b - margin * dx, -b + (cells + margin) * dx, n);
  const Eigen::VectorXd q = heat * SemiEllipticCellMeans(g, b);
  // Peak rise of each solid carrying the whole heat; a solid at rest would warm without
  // bound under a steady source, so the other one carries it all.
  double peak[2];
  const SolidThermal* body[] = {&body1, &body2};
  const double speed[] = {in.u1_m_s, in.u2_m_s};
  for (int s = 0; s < 2; ++s)
    peak[s] = speed[s] > 0 ? MovingHeatSource(g, MovingHeatSource::DecayRate(*body[s], speed[s]))
                                 .Rise(*body[s], speed[s], q)
                                 .maxCoeff()
                           : std::numeric_limits<double>::infinity();
  if (std::isinf(peak[0])) return peak[1];
  if (std::isinf(peak[1])) return peak[0];
  // Equal peaks: theta = phi M_1 = (1 - phi) M_2.
  return peak[0] * peak[1] / (peak[0] + peak[1]);
}

double FlashTemperature(const FlashTemperatureInputs& in,
                        const SolidThermal& body1,
                        const SolidThermal& body2,
                        bool finite_peclet) {
  return finite_peclet ? FinitePecletFlashTemperature(in, body1, body2)
                       : BlokFlashTemperature(in, body1, body2);
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
