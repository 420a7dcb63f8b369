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
//
// Finite Peclet number (effect `finite_peclet`): the solid also conducts along its surface,
// ahead of the heat and behind it. The kernel 1/sqrt(x - x') becomes Jaeger's steady moving
// line source (include/tehl/ehl/moving_line_source.hpp), in the same normalization
//   g(X) = sqrt(u_s/(pi kappa_s)) e^(omega X) K0(omega |X|),  omega = u_s/(2 kappa_s),
// kappa_s = k_s/(rho_s c_s), g(X) -> 1/sqrt(X) for omega X -> inf; so T_s - T0 = F sum G q
// as before, with G_ik the exact integral of g(x_i - x') over cell k (primitive
// sqrt(2/(pi omega)) J(omega X)). G is then full (the surface warms upstream of a source
// too, over a length of about 1/omega), Toeplitz apart from the half cells at both ends, and
// depends on the solid and its speed through omega. Heat still enters only on the grid.
//
// Transient runs (high-Peclet form): the flux a surface point met along its way through the
// grid changes with time. A point at x_i at time t was at x' = x_i - l at the time its
// surface had l still to travel, so the integral takes each lag l = x_i - x' from the flux of
// the time level during which the surface covered that stretch (Duhamel's integral along the
// point's path; docs/theory.md, "The solids' heat history"). The lags a step covers itself,
// l <= u_s dt, see the step's own (unknown) flux: the kernel restricted to them (Recent); the
// earlier levels' part is known (History).
#pragma once

#include <Eigen/Core>
#include <limits>
#include <vector>

#include "tehl/ehl/grid.hpp"

namespace tehl {

// Thermal properties of a solid body (gear tooth, disc).
struct SolidThermal {
  double density_kg_m3 = 0;        // rho_s [kg/m^3]; > 0
  double heat_capacity_j_kgk = 0;  // c_s [J/(kg K)]; > 0
  double conductivity_w_mk = 0;    // k_s [W/(m K)]; > 0
};

// One earlier time level of the flux into a solid, seen by the history integral.
struct FluxSpan {
  const Eigen::VectorXd* q_w_m2 = nullptr;  // the level's flux at the nodes [W/m^2]
  double travel_m = 0;  // how far the surface moved during the level (u_s dt) [m]; >= 0,
                        // infinite for a steady level (its flux had always acted)
  double speed_m_s = 0;  // the surface's speed during the level [m/s]; 0: the step's own
};

// The moving-heat-source integral on a UniformGrid. Immutable; thread-safe to read.
class MovingHeatSource {
 public:
  MovingHeatSource() = default;
  // The high-Peclet form of seed 004 eqs. (14)-(15).
  explicit MovingHeatSource(const UniformGrid& grid);
  // The high-Peclet form restricted to the lags 0 <= x_i - x' <= reach_m: the flux of the
  // last reach_m of travel (a transient step's own, reach = u_s dt). reach_m = infinity is
  // the whole kernel. Throws InputError unless reach_m > 0.
  static MovingHeatSource Recent(const UniformGrid& grid, double reach_m);
  // Jaeger's kernel at the decay rate omega = u_s/(2 kappa_s) [1/m] (DecayRate); throws
  // InputError unless omega is finite and > 0.
  MovingHeatSource(const UniformGrid& grid, double omega_1_m);

  int size() const { return n_; }
  bool high_peclet() const { return omega_ == 0; }
  double reach_m() const { return reach_; }    // infinite unless made by Recent [m]
  double omega_1_m() const { return omega_; }  // 0 for the high-Peclet form [1/m]
  // G_ik [m^(1/2)]: the exact integral of the kernel over cell k seen from node i; in the
  // high-Peclet form only up to x_i (0 for k > i).
  double Weight(int i, int k) const;
  // F = 1/sqrt(pi rho_s c_s k_s u_s) [K m^(3/2) / W]. Throws InputError unless the solid's
  // properties and u_s are finite and > 0.
  static double Factor(const SolidThermal& solid, double speed_m_s);
  // omega = u_s rho_s c_s / (2 k_s) [1/m], the inverse of the length over which the surface
  // conducts heat ahead of a source (u_s b / (2 kappa_s) = omega b is the Peclet number of a
  // contact of half-width b). Throws InputError as Factor.
  static double DecayRate(const SolidThermal& solid, double speed_m_s);
  // T_s(x_i) - T0 at every node for the flux q_w_m2 [W/m^2] at the nodes (size n) [K].
  // O(n^2). In the finite-Peclet form speed_m_s must be the speed omega was made for. Throws
  // InputError as Factor, or if q has the wrong size.
  Eigen::VectorXd Rise(const SolidThermal& solid,
                       double speed_m_s,
                       const Eigen::VectorXd& q_w_m2) const;
  // The cell length of node k: dx, dx/2 at both ends [m] (the cells the flux is constant on).
  double CellLength(int k) const;
  // The earlier levels' part of the high-Peclet integral, beyond the lag reach_m (> 0) of a
  // step at the surface speed speed_m_s (> 0): Duhamel's integral in time, written in lags
  // at that speed,
  //   H_i = sum_j integral over x' in cell k, l = x_i - x' in span j, of
  //         q_j(x') / sqrt(tau_j(l)) dl (u / u_j),
  // tau_j(l) = reach + u (time the surface took from x' to the start of the step's own
  // travel), the spans following each other upstream from l = reach_m (span 0 the newest),
  // the last one unbounded whatever its travel; a span of the step's speed u_j = u counts
  // lags as they are. Each flux piecewise constant on the cells of its nodes; exact
  // integrals of the kernel over the pieces [W/m^2 m^(1/2)]: T_s - T0 = F(u) (sum of the
  // Recent(reach_m) weights times the step's own flux + H). Zero without spans.
  // O(n^2 + n spans). Throws InputError on a flux of the wrong size, a travel < 0 or a speed
  // <= 0.
  Eigen::VectorXd History(double reach_m,
                          double speed_m_s,
                          const std::vector<FluxSpan>& spans) const;

 private:
  void FillHighPeclet();  // the weights of the high-Peclet form within reach_
  int n_ = 0;
  double dx_ = 0;
  double omega_ = 0;  // 0: high-Peclet form [1/m]
  double reach_ = std::numeric_limits<double>::infinity();  // lags kept (Recent) [m]
  // G_ik of the interior cells 1 <= k <= n - 2 as a function of the lag i - k, stored at
  // n - 1 + i - k (lags -(n-1) ... n-1; zero below 0 in the high-Peclet form) [m^(1/2)].
  std::vector<double> toeplitz_;
  std::vector<double> inlet_;   // G_i0 for the inlet half cell [m^(1/2)]
  std::vector<double> outlet_;  // G_i(n-1) for the outlet half cell [m^(1/2)]
};

}  // namespace tehl
