// Exact cell weights of the moving-heat-source integral (include/tehl/ehl/surface_temperature.hpp).
#include "tehl/ehl/surface_temperature.hpp"

#include <cmath>
#include <string>

#include "base/schema.hpp"
#include "tehl/error.hpp"

namespace tehl {

namespace {

// 2 [sqrt(a) - sqrt(b)] for a >= b >= 0, written as 2 (a - b) / (sqrt(a) + sqrt(b)) so that
// far cells (a ~ b) keep full relative precision.
double TwoRootDifference(double a, double b) {
  const double s = std::sqrt(a) + std::sqrt(b);
  return s > 0 ? 2.0 * (a - b) / s : 0.0;
}

}  // namespace

MovingHeatSource::MovingHeatSource(const UniformGrid& grid)
    : n_(grid.size()), dx_(grid.dx_m()), toeplitz_(grid.size()), inlet_(grid.size()) {
  // Cell k >= 1 seen from node i = k + m: [x_i - (m + 1/2) dx, x_i - (m - 1/2) dx], clipped at
  // x_i for m = 0 (the integral stops at x_i).
  toeplitz_[0] = TwoRootDifference(0.5 * dx_, 0.0);
  for (int m = 1; m < n_; ++m) toeplitz_[m] = TwoRootDifference((m + 0.5) * dx_, (m - 0.5) * dx_);
  // The inlet half cell [x_0, x_0 + dx/2] seen from node i: nothing at i = 0.
  inlet_[0] = 0.0;
  for (int i = 1; i < n_; ++i) inlet_[i] = TwoRootDifference(i * dx_, (i - 0.5) * dx_);
}

double MovingHeatSource::Weight(int i, int k) const {
  if (k > i || i < 0 || k < 0 || i >= n_) return 0.0;
  return k == 0 ? inlet_[i] : toeplitz_[i - k];
}

double MovingHeatSource::CellLength(int k) const {
  return (k == 0 || k == n_ - 1) ? 0.5 * dx_ : dx_;
}

double MovingHeatSource::Factor(const SolidThermal& s, double speed_m_s) {
  ProblemList bad;
  auto rule = [&](double v, const char* key, const char* allowed) {
    if (!(std::isfinite(v) && v > 0))
      bad.Add({"", 0, key, internal::FormatReal(v), "must be finite and > 0", allowed});
  };
  rule(s.density_kg_m3, "SolidThermal::density_kg_m3", "a density > 0 [kg/m^3]");
  rule(s.heat_capacity_j_kgk, "SolidThermal::heat_capacity_j_kgk",
       "a heat capacity > 0 [J/(kg K)]");
  rule(s.conductivity_w_mk, "SolidThermal::conductivity_w_mk", "a conductivity > 0 [W/(m K)]");
  rule(speed_m_s, "surface speed",
       "a surface speed > 0 [m/s] in +x (the moving-heat-source integral needs the solid to "
       "move through the contact from the inlet)");
  bad.ThrowIfAny();
  return 1.0 / std::sqrt(M_PI * s.density_kg_m3 * s.heat_capacity_j_kgk * s.conductivity_w_mk *
                         speed_m_s);
}

Eigen::VectorXd MovingHeatSource::Rise(const SolidThermal& solid,
                                       double speed_m_s,
                                       const Eigen::VectorXd& q_w_m2) const {
  const double f = Factor(solid, speed_m_s);
  if (q_w_m2.size() != n_)
    throw InputError(InputProblem{"", 0, "q_w_m2", std::to_string(q_w_m2.size()) + " values",
                                  "must have one value per grid node",
                                  std::to_string(n_) + " values"});
  Eigen::VectorXd rise = Eigen::VectorXd::Zero(n_);
  for (int i = 1; i < n_; ++i) {
    double sum = inlet_[i] * q_w_m2[0];
    for (int k = 1; k <= i; ++k) sum += toeplitz_[i - k] * q_w_m2[k];
    rise[i] = f * sum;
  }
  return rise;
}

}  // namespace tehl
