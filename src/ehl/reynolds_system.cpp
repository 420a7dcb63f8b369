#include "ehl/reynolds_system.hpp"

#include <algorithm>
#include <cmath>

#include "tehl/lubricant/density_model.hpp"
#include "tehl/lubricant/viscosity_model.hpp"

namespace tehl::internal {

ReynoldsSystem::ReynoldsSystem(int n, double dx_m, int upwind_order)
    : n_(n), dx_(dx_m), order_(upwind_order) {
  for (Eigen::VectorXd* v : {&r_, &rho_, &drho_, &eta_, &deta_, &q_, &e_, &de_dp_, &de_dh_})
    v->setZero(n);
  a_.setZero(n, 4);
  b_.setZero(n, 4);
}

void ReynoldsSystem::Evaluate(const FluidLaws& fluid, double um, const Eigen::VectorXd& p,
                              const Eigen::VectorXd& h, const TimeDerivative& dt,
                              bool linearize) {
  const double t = fluid.temperature_k;
  // Node properties. Cavitated or negative iterates are evaluated at p = 0 (the laws'
  // contract), with zero pressure derivative there.
  const DensityValue d0 = fluid.density->Evaluate(0.0, t);
  const ViscosityValue v0 = fluid.viscosity->Evaluate(0.0, t);
  const double s = fluid.pressure_scale;
  for (int k = 0; k < n_; ++k) {
    const double pk = std::max(p[k], 0.0);
    const bool positive = p[k] > 0.0;
    if (fluid.compressible && positive) {
      const DensityValue d = fluid.density->Evaluate(pk, t);
      rho_[k] = d.rho_kg_m3;
      drho_[k] = d.drho_dp;
    } else {
      rho_[k] = d0.rho_kg_m3;
      drho_[k] = 0.0;
    }
    if (fluid.piezoviscous && positive) {
      const ViscosityValue v = fluid.viscosity->Evaluate(s * pk, t);
      eta_[k] = v.eta_pa_s;
      deta_[k] = s * v.deta_dp;
    } else {
      eta_[k] = v0.eta_pa_s;
      deta_[k] = 0.0;
    }
    const double hk = h[k], h3 = hk * hk * hk;
    q_[k] = rho_[k] * hk;
    e_[k] = rho_[k] * h3 / (12.0 * eta_[k]);
    de_dp_[k] = h3 / 12.0 * (drho_[k] / eta_[k] - rho_[k] * deta_[k] / (eta_[k] * eta_[k]));
    de_dh_[k] = 3.0 * rho_[k] * hk * hk / (12.0 * eta_[k]);
  }

  const double idx2 = 1.0 / (dx_ * dx_);
  r_.setZero();
  if (linearize) {
    a_.setZero();
    b_.setZero();
  }
  for (int i = 1; i < n_ - 1; ++i) {
    const double e_p = 0.5 * (e_[i] + e_[i + 1]);
    const double e_m = 0.5 * (e_[i] + e_[i - 1]);
    const double dp_p = p[i + 1] - p[i];
    const double dp_m = p[i] - p[i - 1];
    // Upwind weights of D_i on nodes i-2, i-1, i (entrainment toward +x, um > 0).
    double c[3];
    if (order_ == 2 && i >= 2) {
      c[0] = 0.5 / dx_;
      c[1] = -2.0 / dx_;
      c[2] = 1.5 / dx_;
    } else {
      c[0] = 0.0;
      c[1] = -1.0 / dx_;
      c[2] = 1.0 / dx_;
    }
    const double couette = c[0] * (i >= 2 ? q_[i - 2] : 0.0) + c[1] * q_[i - 1] + c[2] * q_[i];
    double squeeze = 0.0;
    if (dt.active) squeeze = dt.a0 * q_[i] + dt.a1 * dt.q1[i] + dt.a2 * dt.q2[i];
    r_[i] = (e_p * dp_p - e_m * dp_m) * idx2 - um * couette - squeeze;
    if (!linearize) continue;
    // Columns: 0 -> i-2, 1 -> i-1, 2 -> i, 3 -> i+1.
    a_(i, 3) = (e_p + 0.5 * de_dp_[i + 1] * dp_p) * idx2;
    a_(i, 1) = (e_m - 0.5 * de_dp_[i - 1] * dp_m) * idx2 - um * c[1] * drho_[i - 1] * h[i - 1];
    a_(i, 2) = (-e_p - e_m + 0.5 * de_dp_[i] * (dp_p - dp_m)) * idx2 -
               um * c[2] * drho_[i] * h[i];
    b_(i, 3) = 0.5 * de_dh_[i + 1] * dp_p * idx2;
    b_(i, 1) = -0.5 * de_dh_[i - 1] * dp_m * idx2 - um * c[1] * rho_[i - 1];
    b_(i, 2) = 0.5 * de_dh_[i] * (dp_p - dp_m) * idx2 - um * c[2] * rho_[i];
    if (i >= 2) {
      a_(i, 0) = -um * c[0] * drho_[i - 2] * h[i - 2];
      b_(i, 0) = -um * c[0] * rho_[i - 2];
    }
    if (dt.active) {
      a_(i, 2) -= dt.a0 * drho_[i] * h[i];
      b_(i, 2) -= dt.a0 * rho_[i];
    }
  }
}

Eigen::VectorXd ReynoldsSystem::MassFlow(double um, const Eigen::VectorXd& p) const {
  Eigen::VectorXd flow(n_ - 1);
  for (int i = 0; i < n_ - 1; ++i) {
    const double e = 0.5 * (e_[i] + e_[i + 1]);
    const double q = 0.5 * (q_[i] + q_[i + 1]);
    flow[i] = q * um - e * (p[i + 1] - p[i]) / dx_;
  }
  return flow;
}

}  // namespace tehl::internal
