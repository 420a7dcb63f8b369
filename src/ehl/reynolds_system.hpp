// The discrete Reynolds equation of a line contact at one time level (docs/theory.md):
//   r_i = [e_{i+1/2}(p_{i+1} - p_i) - e_{i-1/2}(p_i - p_{i-1})]/dx^2
//         - D_i(F h) - d(rho_e h)_i/dt,             i = 1 .. n-2,
// e = Phi h^3/12, e_{i+1/2} = (e_i + e_{i+1})/2, D_i the first- or second-order upwind
// difference, and d/dt a BDF combination a0 q_i + sum_k a_k q_i^{n-k} of q = rho_e h.
// Classical (isothermal, Newtonian): Phi = rho/eta, F = rho um, rho_e = rho. With a film
// temperature field or a viscosity factor across the film (thermal or non-Newtonian runs) the
// generalized coefficients of ehl/cross_film.hpp (Yang & Wen 1990).
// Besides r it returns the local derivatives of each row: with respect to p_k (at fixed h)
// and to h_k (at fixed p) for k = i-2 .. i+1. The full Jacobian is then
//   dr_i/dp_j = A_ij + sum_k B_ik dh_k/dp_j,   dh_k/dp_j = K_kj (elastic matrix).
#pragma once

#include <Eigen/Core>
#include <vector>

#include "tehl/ehl/film_effects.hpp"
#include "tehl/lubricant/density_model.hpp"
#include "tehl/lubricant/viscosity_model.hpp"

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
  // Generalized Reynolds (both null = classical): the film temperature T(x_i, xi_j) and a
  // factor on the viscosity eta_eff = f eta(p, T) (non-Newtonian), n x nz each [K], [-].
  const Eigen::MatrixXd* film_temperature_k = nullptr;
  const Eigen::MatrixXd* viscosity_factor = nullptr;
  double u1_m_s = 0, u2_m_s = 0;  // surface speeds (generalized Couette term) [m/s]
  bool generalized() const { return film_temperature_k || viscosity_factor; }
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
  // rho_e h at the nodes from the last Evaluate (the stored mass) [kg/m^2].
  const Eigen::VectorXd& rho_h() const { return st_; }
  // Mass flow per unit width between nodes i and i+1 (central differences) [kg/(m s)].
  Eigen::VectorXd MassFlow(double um_m_s, const Eigen::VectorXd& p) const;

 private:
  int n_;
  double dx_;
  int order_;
  // Node coefficients: e = Phi h^3/12, Couette flux F h, stored mass rho_e h, with their
  // derivatives in p (at fixed h) and the factors F, rho_e (their derivative in h).
  void ClassicalNodes(const FluidLaws& fluid, double um, const Eigen::VectorXd& p,
                      const Eigen::VectorXd& h);
  void GeneralizedNodes(const FluidLaws& fluid, const Eigen::VectorXd& p,
                        const Eigen::VectorXd& h);
  Eigen::VectorXd r_, e_, de_dp_, de_dh_, fl_, dfl_dp_, flr_, st_, dst_dp_, str_;
  std::vector<double> work_;
  std::vector<double> law_p_, law_t_;  // ClassicalNodes: the laws' arguments [Pa], [K]
  std::vector<ViscosityValue> visc_;
  std::vector<DensityValue> dens_;
  Eigen::Matrix<double, Eigen::Dynamic, 4> a_, b_;
};

}  // namespace tehl::internal
