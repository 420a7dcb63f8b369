// Surface temperature of a solid moving under a line heat source: the Carslaw-Jaeger moving
// heat source integral of seed 004 eqs. (14)-(15) in dimensional form (DESIGN.md section 4;
// Carslaw & Jaeger 1959, section 10.7; Jaeger 1942; docs/theory.md, "Energy equation and
// surface temperatures"):
//
//   T_s(x) = T0 + 1/sqrt(pi rho_s c_s k_s u_s) * integral_{x_0}^{x} q(x') / sqrt(x - x') dx'
//
// q(x') [W/m^2] is the heat flux entering the solid at x', u_s > 0 the speed of its surface
// through the contact frame (in +x), rho_s, c_s, k_s its density, heat capacity and
// conductivity. The form holds for a high Peclet number u_s L / (k_s/(rho_s c_s)) >> 1: the
// solid conducts only into its depth, each surface point seeing the flux history of 1-D
// transient conduction into a half-space, with time t = (x - x_0) / u_s. No heat enters before
// x_0 (the inlet end of the grid).
//
// Quadrature: q is piecewise constant on the cells of the grid's nodes, cell k = [x_k - dx/2,
// x_k + dx/2] clipped to [x_0, x_{n-1}] (the finite-volume cells of the film energy equation),
// and the 1/sqrt kernel is integrated exactly over each cell:
//   T_s(x_i) - T0 = F * sum_{k <= i} G_ik q_k,   F = 1/sqrt(pi rho_s c_s k_s u_s),
//   G_ik = 2 [ sqrt(x_i - a_k) - sqrt(x_i - min(b_k, x_i)) ]   for the cell [a_k, b_k].
// G is lower triangular and Toeplitz apart from the inlet half cell; it depends only on the
// grid, so it is computed once and F carries the solid and its speed.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "tehl/ehl/grid.hpp"

namespace tehl {

// Thermal properties of a solid body (gear tooth, disc).
struct SolidThermal {
  double density_kg_m3 = 0;        // rho_s [kg/m^3]; > 0
  double heat_capacity_j_kgk = 0;  // c_s [J/(kg K)]; > 0
  double conductivity_w_mk = 0;    // k_s [W/(m K)]; > 0
};

// The moving-heat-source integral on a UniformGrid. Immutable; thread-safe to read.
class MovingHeatSource {
 public:
  MovingHeatSource() = default;
  explicit MovingHeatSource(const UniformGrid& grid);

  int size() const { return n_; }
  // G_ik [m^(1/2)]: the exact integral of 1/sqrt(x_i - x') over cell k up to x_i; 0 for k > i.
  double Weight(int i, int k) const;
  // F = 1/sqrt(pi rho_s c_s k_s u_s) [K m^(3/2) / W]. Throws InputError unless the solid's
  // properties and u_s are finite and > 0.
  static double Factor(const SolidThermal& solid, double speed_m_s);
  // T_s(x_i) - T0 at every node for the flux q_w_m2 [W/m^2] at the nodes (size n) [K].
  // O(n^2). Throws InputError as Factor, or if q has the wrong size.
  Eigen::VectorXd Rise(const SolidThermal& solid,
                       double speed_m_s,
                       const Eigen::VectorXd& q_w_m2) const;
  // The cell length of node k: dx, dx/2 at both ends [m] (the cells the flux is constant on).
  double CellLength(int k) const;

 private:
  int n_ = 0;
  double dx_ = 0;
  std::vector<double> toeplitz_;  // G_ik for 1 <= k <= i as a function of i - k [m^(1/2)]
  std::vector<double> inlet_;     // G_i0 for the inlet half cell [m^(1/2)]
};

}  // namespace tehl
