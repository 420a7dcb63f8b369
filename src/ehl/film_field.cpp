// FilmField: the fields of a film between the pressure and energy solves (viscosity, flow,
// heating, friction); the energy updates are in film_field_energy.cpp (src/ehl/film_field.hpp).
#include "ehl/film_field.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <vector>

#include "base/number_text.hpp"
#include "ehl/cross_film.hpp"
#include "ehl/eyring_wall_stress.hpp"
#include "tehl/error.hpp"
#include "tehl/lubricant/lubricant.hpp"

namespace tehl::internal {

FilmField::FilmField(const UniformGrid& grid,
                     const Lubricant& lubricant,
                     const FilmEffects& effects,
                     const ContactSolids& solids,
                     const LineContactSolver::Options& options)
    : grid_(grid),
      lub_(lubricant),
      eff_(effects),
      solids_(solids),
      opt_(options),
      nz_(options.film_nodes),
      thermal_(effects.thermal),
      eyring_(effects.non_newtonian) {
  if (eyring_ && !lubricant.eyring())
    throw InputError(
        InputProblem{"", 0, "effects.non_newtonian", "true",
                     "the lubricant '" + lubricant.name() + "' has no [eyring] parameters",
                     "add eyring_stress_pa to the lubricant file"});
  if (nz_ < 3)
    throw InputError(
        InputProblem{"", 0, "film_nodes", std::to_string(nz_), "must be >= 3", ">= 3"});
}

void FilmField::Energy(double t0_k) {
  if (energy_ && energy_->inlet_temperature_k() == t0_k) return;
  FilmEnergySolver::Options o;
  o.film_nodes = nz_;
  o.finite_peclet = eff_.finite_peclet;
  energy_ = std::make_unique<FilmEnergySolver>(grid_, lub_, solids_.body1, solids_.body2, t0_k, o);
}

void FilmField::Begin(const ContactConditions& c, const FilmState& s) {
  const int n = grid_.size();
  outer_ = AndersonMixer(5);
  last_change_k_ = kFirstCouplingChangeK;
  if (thermal_) {
    if (s.temperature.Matches(n, nz_) && s.temperature.t_k.allFinite()) {
      t_ = s.temperature;
    } else {
      Energy(c.temperature_k);
      t_ = energy_->Initial();
    }
  }
  if (eyring_) {
    factor_.setOnes(n, nz_);
    // The factor of the given state, relaxed as the coupling relaxes it (line_contact_
    // coupling.cpp): in full in thermal runs. A re-solve from a settled thermal film then
    // settles in 4 coupling iterations instead of 26 (thermal_coupling_test.cpp).
    if (s.valid() && s.p_pa.size() == n)
      UpdateRheology(c, s, thermal_ ? 1.0 : kEyringRelaxation);
  }
}

void FilmField::RestartRheology(const ContactConditions& c, const FilmState& s, double relaxation) {
  if (!eyring_) return;
  factor_.setOnes(grid_.size(), nz_);
  if (relaxation > 0 && s.valid() && s.p_pa.size() == grid_.size())
    UpdateRheology(c, s, relaxation);
}

double FilmField::Slope(const Eigen::VectorXd& p, int i) const {
  const int n = grid_.size();
  const double dx = grid_.dx_m();
  if (i == 0) return (p[1] - p[0]) / dx;
  if (i == n - 1) return (p[n - 1] - p[n - 2]) / dx;
  return (p[i + 1] - p[i - 1]) / (2 * dx);
}

void FilmField::NodeViscosity(
    const ContactConditions& c, const FilmState& s, int i, double* eta, bool newtonian) const {
  std::vector<double> pz(nz_, eff_.piezoviscous ? std::max(s.p_pa[i], 0.0) : 0.0), tz(nz_);
  for (int j = 0; j < nz_; ++j) tz[j] = thermal_ ? t_.t_k(i, j) : c.temperature_k;
  std::vector<ViscosityValue> v(nz_);
  lub_.viscosity().EvaluateMany(pz.data(), tz.data(), nz_, v.data());
  for (int j = 0; j < nz_; ++j)
    eta[j] = v[j].eta_pa_s * (eyring_ && !newtonian ? factor_(i, j) : 1.0);
}

double FilmField::UpdateRheology(const ContactConditions& c,
                                 const FilmState& s,
                                 double relaxation,
                                 bool accelerate) {
  if (!eyring_) return 0.0;
  const EyringParameters& e = *lub_.eyring();
  const int n = grid_.size();
  std::vector<double> eta(nz_);
  double change = 0.0;
  factor_in_ = factor_;
  for (int i = 0; i < n; ++i) {
    NodeViscosity(c, s, i, eta.data(), true);
    // The factor follows the sliding (Couette) shear stress: dp/dx = 0 in the root, so f
    // depends on p, T and h but not on the pressure gradient, whose spike would make the
    // frozen-factor iteration oscillate (docs/theory.md, "Ree-Eyring film").
    const double h = s.h_m[i], dpdx = 0.0, du = c.u2_m_s - c.u1_m_s;
    EyringLaw law;
    law.tau0 = e.eyring_stress_pa;
    law.tau_l = (e.limiting_stress_pa > 0 || e.limiting_stress_slope > 0)
                    ? e.limiting_stress_pa + e.limiting_stress_slope * std::max(s.p_pa[i], 0.0)
                    : 0.0;
    const double t1 = EyringWallStress(law, eta.data(), nz_, h, dpdx, du, 0.0);
    // The stress t1 is uniform across the film (dp/dx = 0 here), so f = tau / (eta gdot) =
    // t1 / Rate(t1, 1) is the same at every xi.
    const double rate = law.Rate(t1, 1.0);
    const double f = std::abs(rate) > 0 ? t1 / rate : 1.0;
    const double target = std::isfinite(f) && f > 0 ? std::min(f, 1.0) : 1.0;
    for (int j = 0; j < nz_; ++j) {
      // Under-relaxed in log f: the factor spans many decades across the contact.
      const double step = std::log(target / factor_(i, j));
      change = std::max(change, std::abs(step));
      factor_(i, j) = accelerate ? target : factor_(i, j) * std::exp(relaxation * step);
    }
  }
  if (accelerate) {
    // log f -> log f_target is the coupling's fixed point; its relaxed iteration converges
    // linearly and slowly on sliding films (90 iterations on a disc at SRR 1, docs/thermal.md
    // "Ree-Eyring film"), Anderson's step on the same map settles it in far fewer.
    const Eigen::MatrixXd x = factor_in_.array().log(), g = factor_.array().log();
    factor_ = outer_.Mix(x, g, relaxation).array().exp().min(1.0);
  }
  return change;
}

FilmFlowField FilmField::Flow(const ContactConditions& c,
                              const FilmState& s,
                              const FilmState* previous,
                              double dt_s,
                              const FilmTemperature** prev_t) const {
  const int n = grid_.size();
  FilmFlowField flow;
  flow.p_pa = s.p_pa.cwiseMax(0.0);
  flow.h_m = s.h_m;
  flow.u1_m_s = c.u1_m_s;
  flow.u2_m_s = c.u2_m_s;
  flow.u_m_s.resize(n, nz_);
  flow.heating_w_m3.resize(n, nz_);
  flow.heating_decay_1_k.resize(n, nz_);
  const bool transient = dt_s > 0 && previous && previous->valid();
  if (transient) {
    flow.dpdt_pa_s = (flow.p_pa - previous->p_pa.cwiseMax(0.0)) / dt_s;
    flow.dhdt_m_s = (s.h_m - previous->h_m) / dt_s;
  }
  *prev_t =
      transient && previous->temperature.Matches(n, nz_) ? &previous->temperature : nullptr;
  return flow;
}

void FilmField::Heating(const ContactConditions& c,
                        const FilmState& s,
                        FilmFlowField* flow) const {
  const int n = grid_.size();
  std::vector<double> eta(nz_), u(nz_), tau(nz_), u_c(nz_), tau_c(nz_), pz(nz_), tz(nz_);
  std::vector<ViscosityValue> visc(nz_);
  for (int i = 0; i < n; ++i) {
    const double slope = Slope(flow->p_pa, i);
    NodeViscosity(c, s, i, eta.data(), false);
    CrossFilmProfile(eta.data(), nz_, s.h_m[i], slope, c.u1_m_s, c.u2_m_s, u.data(), tau.data());
    // The sliding (Couette) part of the dissipation, tau_c^2 / eta ~ eta (du/h)^2, falls
    // with the viscosity as the film warms: beta = -d ln eta / dT on the fraction
    // tau_c^2 / tau^2 of the heating (the pressure-driven part, ~ 1/eta, is left explicit).
    // Without it, heating from a cold viscosity heats the film by thousands of kelvin and
    // the next heating, at the overheated film, is far too small.
    CrossFilmProfile(eta.data(), nz_, s.h_m[i], 0.0, c.u1_m_s, c.u2_m_s, u_c.data(),
                     tau_c.data());
    for (int j = 0; j < nz_; ++j) {
      pz[j] = eff_.piezoviscous ? std::max(s.p_pa[i], 0.0) : 0.0;
      tz[j] = t_.t_k(i, j);
    }
    lub_.viscosity().EvaluateMany(pz.data(), tz.data(), nz_, visc.data());
    for (int j = 0; j < nz_; ++j) {
      flow->u_m_s(i, j) = u[j];
      flow->heating_w_m3(i, j) = tau[j] * tau[j] / eta[j];
      const double beta = std::max(-visc[j].deta_dT / visc[j].eta_pa_s, 0.0);
      const double couette =
          tau[j] != 0.0 ? std::min(tau_c[j] * tau_c[j] / (tau[j] * tau[j]), 1.0) : 1.0;
      flow->heating_decay_1_k(i, j) = std::isfinite(beta) ? beta * couette : 0.0;
    }
  }
  flow->heating_reference_t_k = t_.t_k;
}

void FilmField::SetTemperature(const Eigen::MatrixXd& t_k) {
  t_.t_k = t_k;
  t_.t1_k = t_.t_k.col(0);
  t_.t2_k = t_.t_k.col(nz_ - 1);
}

Eigen::VectorXd FilmField::CouplingState() const {
  const Eigen::Index m = t_.t_k.size();
  Eigen::VectorXd x(eyring_ ? 2 * m : m);
  x.head(m) = t_.t_k.reshaped();
  if (eyring_) x.tail(m) = kLogFactorWeightK * factor_.array().log().reshaped();
  return x;
}

void FilmField::SetCouplingState(const Eigen::VectorXd& x) {
  const Eigen::Index n = t_.t_k.rows(), m = t_.t_k.size();
  SetTemperature(x.head(m).reshaped(n, nz_));
  if (eyring_) factor_ = (x.tail(m) / kLogFactorWeightK).array().min(0.0).exp().reshaped(n, nz_);
}

void FilmField::CouplingBounds(double t0_k, Eigen::VectorXd* lower, Eigen::VectorXd* upper) const {
  const Eigen::Index m = t_.t_k.size();
  lower->resize(eyring_ ? 2 * m : m);
  upper->resize(lower->size());
  lower->head(m).setConstant(MinTemperature(t0_k));
  upper->head(m).setConstant(MaxTemperature(t0_k));
  if (eyring_) {
    lower->tail(m).setConstant(-std::numeric_limits<double>::max());
    upper->tail(m).setZero();
  }
}

void FilmField::Store(FilmState* s) const {
  if (thermal_) s->temperature = t_;
}

FilmFriction FilmField::Friction(const ContactConditions& c, const FilmState& s) const {
  return IntegrateFriction(grid_, s, c, nz_,
                           [&](int i, double* eta) { NodeViscosity(c, s, i, eta, false); });
}

FilmFriction IntegrateFriction(const UniformGrid& grid,
                               const FilmState& s,
                               const ContactConditions& c,
                               int nz,
                               const std::function<void(int, double*)>& viscosity) {
  const int n = grid.size();
  const double dx = grid.dx_m();
  std::vector<double> eta(nz), u(nz), tau(nz);
  FilmFriction f;
  double f1 = 0, f2 = 0;
  for (int i = 0; i < n; ++i) {
    viscosity(i, eta.data());
    const double dpdx = i == 0       ? (s.p_pa[1] - s.p_pa[0]) / dx
                        : i == n - 1 ? (s.p_pa[n - 1] - s.p_pa[n - 2]) / dx
                                     : (s.p_pa[i + 1] - s.p_pa[i - 1]) / (2 * dx);
    CrossFilmProfile(eta.data(), nz, s.h_m[i], dpdx, c.u1_m_s, c.u2_m_s, u.data(), tau.data());
    const double w = (i == 0 || i == n - 1) ? 0.5 * dx : dx;
    f1 += w * tau[0];
    f2 -= w * tau[nz - 1];
    f.max_shear_stress_pa =
        std::max({f.max_shear_stress_pa, std::abs(tau[0]), std::abs(tau[nz - 1])});
  }
  f.traction1_n_per_m = f1;
  f.traction2_n_per_m = f2;
  f.coefficient = 0.5 * (std::abs(f1) + std::abs(f2)) / c.load_n_per_m;
  return f;
}

}  // namespace tehl::internal
