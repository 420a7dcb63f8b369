#include "ehl/reynolds_system.hpp"

#include <algorithm>
#include <cmath>

#include "ehl/cross_film.hpp"
#include "tehl/lubricant/density_model.hpp"
#include "tehl/lubricant/viscosity_model.hpp"

namespace tehl::internal {

ReynoldsSystem::ReynoldsSystem(int n, double dx_m, int upwind_order)
    : n_(n), dx_(dx_m), order_(upwind_order) {
  for (Eigen::VectorXd* v :
       {&r_, &e_, &de_dp_, &de_dh_, &fl_, &dfl_dp_, &flr_, &st_, &dst_dp_, &str_})
    v->setZero(n);
  a_.setZero(n, 4);
  b_.setZero(n, 4);
}

void ReynoldsSystem::ClassicalNodes(const FluidLaws& fluid, double um, const Eigen::VectorXd& p,
                                    const Eigen::VectorXd& h) {
  // Each law over the whole grid in one call (one temperature, so a law can reuse its
  // temperature factor). Cavitated or negative iterates are evaluated at p = 0 (the laws'
  // contract), with zero pressure derivative there.
  const double s = fluid.pressure_scale;
  law_p_.resize(n_);
  law_t_.assign(n_, fluid.temperature_k);
  visc_.resize(n_);
  dens_.resize(n_);
  if (fluid.piezoviscous) {
    for (int k = 0; k < n_; ++k) law_p_[k] = s * std::max(p[k], 0.0);
    fluid.viscosity->EvaluateMany(law_p_.data(), law_t_.data(), n_, visc_.data());
  } else {
    std::fill(visc_.begin(), visc_.end(), fluid.viscosity->Evaluate(0.0, fluid.temperature_k));
  }
  if (fluid.compressible) {
    for (int k = 0; k < n_; ++k) law_p_[k] = std::max(p[k], 0.0);
    fluid.density->EvaluateMany(law_p_.data(), law_t_.data(), n_, dens_.data());
  } else {
    std::fill(dens_.begin(), dens_.end(), fluid.density->Evaluate(0.0, fluid.temperature_k));
  }
  for (int k = 0; k < n_; ++k) {
    const bool positive = p[k] > 0.0;
    const double rho = dens_[k].rho_kg_m3, eta = visc_[k].eta_pa_s;
    const double drho = fluid.compressible && positive ? dens_[k].drho_dp : 0.0;
    const double deta = fluid.piezoviscous && positive ? s * visc_[k].deta_dp : 0.0;
    const double hk = h[k], h3 = hk * hk * hk;
    e_[k] = rho * h3 / (12.0 * eta);
    de_dp_[k] = h3 / 12.0 * (drho / eta - rho * deta / (eta * eta));
    de_dh_[k] = 3.0 * rho * hk * hk / (12.0 * eta);
    flr_[k] = um * rho;
    fl_[k] = flr_[k] * hk;
    dfl_dp_[k] = um * drho * hk;
    str_[k] = rho;
    st_[k] = rho * hk;
    dst_dp_[k] = drho * hk;
  }
}

void ReynoldsSystem::GeneralizedNodes(const FluidLaws& fluid, const Eigen::VectorXd& p,
                                      const Eigen::VectorXd& h) {
  const Eigen::MatrixXd* tf = fluid.film_temperature_k;
  const Eigen::MatrixXd* vf = fluid.viscosity_factor;
  const int nz = static_cast<int>(tf ? tf->cols() : vf->cols());
  work_.resize(7 * static_cast<size_t>(nz));
  double* pz = work_.data();
  double* tz = pz + nz;
  double* eta = tz + nz;
  double* deta = eta + nz;
  double* rho = deta + nz;
  double* drho = rho + nz;
  std::vector<ViscosityValue> vv(nz);
  std::vector<DensityValue> dv(nz);
  const double s = fluid.pressure_scale;
  for (int k = 0; k < n_; ++k) {
    const bool positive = p[k] > 0.0;
    const double pk = std::max(p[k], 0.0);
    for (int j = 0; j < nz; ++j) tz[j] = tf ? (*tf)(k, j) : fluid.temperature_k;
    std::fill(pz, pz + nz, fluid.piezoviscous && positive ? s * pk : 0.0);
    fluid.viscosity->EvaluateMany(pz, tz, nz, vv.data());
    std::fill(pz, pz + nz, fluid.compressible && positive ? pk : 0.0);
    fluid.density->EvaluateMany(pz, tz, nz, dv.data());
    for (int j = 0; j < nz; ++j) {
      const double f = vf ? (*vf)(k, j) : 1.0;
      eta[j] = f * vv[j].eta_pa_s;
      deta[j] = fluid.piezoviscous && positive ? f * s * vv[j].deta_dp : 0.0;
      rho[j] = dv[j].rho_kg_m3;
      drho[j] = fluid.compressible && positive ? dv[j].drho_dp : 0.0;
    }
    const CrossFilmCoefficients c =
        CrossFilmIntegrals(eta, deta, rho, drho, nz, fluid.u1_m_s, fluid.u2_m_s);
    const double hk = h[k], h3 = hk * hk * hk;
    e_[k] = c.phi * h3 / 12.0;
    de_dp_[k] = c.dphi_dp * h3 / 12.0;
    de_dh_[k] = c.phi * hk * hk / 4.0;
    flr_[k] = c.flux;
    fl_[k] = c.flux * hk;
    dfl_dp_[k] = c.dflux_dp * hk;
    str_[k] = c.rho_e;
    st_[k] = c.rho_e * hk;
    dst_dp_[k] = c.drho_e_dp * hk;
  }
}

void ReynoldsSystem::Evaluate(const FluidLaws& fluid, double um, const Eigen::VectorXd& p,
                              const Eigen::VectorXd& h, const TimeDerivative& dt,
                              bool linearize) {
  if (fluid.generalized()) {
    GeneralizedNodes(fluid, p, h);
  } else {
    ClassicalNodes(fluid, um, p, h);
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
    const double couette = c[0] * (i >= 2 ? fl_[i - 2] : 0.0) + c[1] * fl_[i - 1] + c[2] * fl_[i];
    double squeeze = 0.0;
    if (dt.active) squeeze = dt.a0 * st_[i] + dt.a1 * dt.q1[i] + dt.a2 * dt.q2[i];
    r_[i] = (e_p * dp_p - e_m * dp_m) * idx2 - couette - squeeze;
    if (!linearize) continue;
    // Columns: 0 -> i-2, 1 -> i-1, 2 -> i, 3 -> i+1.
    a_(i, 3) = (e_p + 0.5 * de_dp_[i + 1] * dp_p) * idx2;
    a_(i, 1) = (e_m - 0.5 * de_dp_[i - 1] * dp_m) * idx2 - c[1] * dfl_dp_[i - 1];
    a_(i, 2) = (-e_p - e_m + 0.5 * de_dp_[i] * (dp_p - dp_m)) * idx2 - c[2] * dfl_dp_[i];
    b_(i, 3) = 0.5 * de_dh_[i + 1] * dp_p * idx2;
    b_(i, 1) = -0.5 * de_dh_[i - 1] * dp_m * idx2 - c[1] * flr_[i - 1];
    b_(i, 2) = 0.5 * de_dh_[i] * (dp_p - dp_m) * idx2 - c[2] * flr_[i];
    if (i >= 2) {
      a_(i, 0) = -c[0] * dfl_dp_[i - 2];
      b_(i, 0) = -c[0] * flr_[i - 2];
    }
    if (dt.active) {
      a_(i, 2) -= dt.a0 * dst_dp_[i];
      b_(i, 2) -= dt.a0 * str_[i];
    }
  }
}

Eigen::VectorXd ReynoldsSystem::MassFlow(double /*um_m_s*/, const Eigen::VectorXd& p) const {
  Eigen::VectorXd flow(n_ - 1);
  for (int i = 0; i < n_ - 1; ++i) {
    const double e = 0.5 * (e_[i] + e_[i + 1]);
    const double q = 0.5 * (fl_[i] + fl_[i + 1]);
    flow[i] = q - e * (p[i + 1] - p[i]) / dx_;
  }
  return flow;
}

}  // namespace tehl::internal
