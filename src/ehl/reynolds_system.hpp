// The discrete Reynolds equation of a line contact at one time level (docs/theory.md):
//   r_i = [e_{i+1/2}(p_{i+1} - p_i) - e_{i-1/2}(p_i - p_{i-1})]/dx^2
//         - um D_i(rho h) - d(rho h)_i/dt,             i = 1 .. n-2,
// e = rho h^3/(12 eta), e_{i+1/2} = (e_i + e_{i+1})/2, D_i the first- or second-order upwind
// difference, and d/dt a BDF combination a0 q_i + sum_k a_k q_i^{n-k}.
// Besides r it returns the local derivatives of each row: with respect to p_k (at fixed h)
// and to h_k (at fixed p) for k = i-2 .. i+1. The full Jacobian is then
//   dr_i/dp_j = A_ij + sum_k B_ik dh_k/dp_j,   dh_k/dp_j = K_kj (elastic matrix).
#pragma once

#include <Eigen/Core>

#include "tehl/ehl/film_effects.hpp"

namespace tehl {
class ViscosityModel;
class DensityModel;
}  // namespace tehl

namespace tehl::internal {

// The BDF time derivative d q/dt = a0 q + a1 q1 + a2 q2 (a_k in 1/s); inactive = steady.
struct TimeDerivative {
  bool active = false;
  double a0 = 0, a1 = 0, a2 = 0;
  Eigen::VectorXd q1, q2;  // rho h at the previous two levels [kg/m^2]
};

// Fluid properties at the nodes, with the effects that are off frozen at p = 0.
struct FluidLaws {
  const ViscosityModel* viscosity = nullptr;
  const DensityModel* density = nullptr;
  bool piezoviscous = true;
  bool compressible = true;
  double temperature_k = 0;
  double pressure_scale = 1.0;  // continuation: eta evaluated at s p (alpha_eff = s alpha) [-]
};

class ReynoldsSystem {
 public:
  ReynoldsSystem(int n, double dx_m, int upwind_order);

  // Residual r (size n, rows 0 and n-1 are zero) and, when `linearize`, the local
  // derivatives (n x 4, column c for node k = i - 2 + c).
  void Evaluate(const FluidLaws& fluid, double um_m_s, const Eigen::VectorXd& p,
                const Eigen::VectorXd& h, const TimeDerivative& dt, bool linearize);

  const Eigen::VectorXd& residual() const { return r_; }
  const Eigen::Matrix<double, Eigen::Dynamic, 4>& dr_dp() const { return a_; }
  const Eigen::Matrix<double, Eigen::Dynamic, 4>& dr_dh() const { return b_; }
  const Eigen::VectorXd& rho() const { return rho_; }
  const Eigen::VectorXd& eta() const { return eta_; }
  // rho h at the nodes from the last Evaluate [kg/m^2].
  const Eigen::VectorXd& rho_h() const { return q_; }
  // Mass flow per unit width between nodes i and i+1 (central differences) [kg/(m s)].
  Eigen::VectorXd MassFlow(double um_m_s, const Eigen::VectorXd& p) const;

 private:
  int n_;
  double dx_;
  int order_;
  Eigen::VectorXd r_, rho_, drho_, eta_, deta_, q_, e_, de_dp_, de_dh_;
  Eigen::Matrix<double, Eigen::Dynamic, 4> a_, b_;
};

}  // namespace tehl::internal
