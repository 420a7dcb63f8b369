// Finite-volume assembly of the film energy equation (src/ehl/film_energy_system.hpp;
// docs/theory.md, "Energy equation and surface temperatures"); its factorization and solve
// are in film_energy_factorization.cpp.
#include "ehl/film_energy_system.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

namespace tehl::internal {

void FilmEnergySystem::ComputeMassFluxes(const FilmEnergyInputs& in,
                                         const Eigen::MatrixXd& t_iter,
                                         const CellMatrix& rho,
                                         const CellMatrix& drho_dt,
                                         const CellMatrix& drho_dp) {
  const FilmFlowField& f = *in.flow;
  const bool transient = in.dt_s > 0;
  volume_.resize(n_, nz_);
  mass_.resize(n_, nz_);
  dmass_dt_.resize(n_, nz_);
  // The size of the storage rates' terms (which cancel in a film that closes as its oil
  // compresses): the scale of the mass defect where there is no flow.
  double storage_scale = 0;
  for (int i = 0; i < n_; ++i) {
    const double dxc = source_[0].CellLength(i);
    const double dhdt = f.dhdt_m_s.size() ? f.dhdt_m_s[i] : 0.0;
    const double dpdt = f.dpdt_pa_s.size() ? f.dpdt_pa_s[i] : 0.0;
    double column_terms = 0;
    for (int j = 0; j < nz_; ++j) {
      const double dxi = (j == 0 || j == nz_ - 1) ? 0.5 * dxi_ : dxi_;
      volume_(i, j) = f.h_m[i] * dxc * dxi;
      mass_(i, j) = rho(i, j) * volume_(i, j);
      // d(rho h)/dt at fixed (x, xi); dT/dt lags one Picard iteration.
      const double dtdt = transient ? (t_iter(i, j) - (*in.previous_t_k)(i, j)) / in.dt_s : 0.0;
      dmass_dt_(i, j) =
          dxc * dxi * (rho(i, j) * dhdt + f.h_m[i] * (drho_dp(i, j) * dpdt + drho_dt(i, j) * dtdt));
      column_terms += dxc * dxi *
                      (std::abs(rho(i, j) * dhdt) + f.h_m[i] * (std::abs(drho_dp(i, j) * dpdt) +
                                                                std::abs(drho_dt(i, j) * dtdt)));
    }
    storage_scale = std::max(storage_scale, column_terms);
  }
  // x-face mass fluxes: face i - 1/2 is row i; the end faces carry the end node's flux.
  fx_.resize(n_ + 1, nz_);
  for (int j = 0; j < nz_; ++j) {
    const double dxi = (j == 0 || j == nz_ - 1) ? 0.5 * dxi_ : dxi_;
    // Interior faces: product of face averages, so that the flux has the sign of the mean
    // velocity whatever rho(T) does (the upwind pattern stays fixed during a solve).
    fx_(0, j) = rho(0, j) * f.u_m_s(0, j) * f.h_m[0] * dxi;
    for (int i = 1; i < n_; ++i)
      fx_(i, j) = 0.125 * (rho(i - 1, j) + rho(i, j)) * (f.u_m_s(i - 1, j) + f.u_m_s(i, j)) *
                  (f.h_m[i - 1] + f.h_m[i]) * dxi;
    fx_(n_, j) = rho(n_ - 1, j) * f.u_m_s(n_ - 1, j) * f.h_m[n_ - 1] * dxi;
  }
  // The given velocity profile need not conserve mass cell by cell: its face fluxes are
  // products of node averages, while the pressure solver's continuity is its own Reynolds
  // discretization (and cavitated films do not fill the gap). A column whose outflow differs
  // from its inflow minus its storage would create or destroy mass, and with it energy
  // cp (T - T0) per kg (measured on a steel disc, SAE 40, p_H = 0.8 GPa, 257 nodes: 1.2 % of
  // the generated heat at L_T = 1, 4.9 % at L_T = 5). So the x-face fluxes are corrected,
  // marching from the inlet face, by a uniform velocity across the film: the total through face
  // i + 1 is the total through face i minus the column's storage rate. The largest correction
  // relative to the mass flow is reported as the mass defect of the given field.
  // (Relative to the mass flow, or to the storage rates' terms in a film at rest; 0 where
  // nothing moves.)
  double flow_scale = storage_scale;
  for (int i = 0; i <= n_; ++i) flow_scale = std::max(flow_scale, std::abs(fx_.row(i).sum()));
  mass_defect_ = 0;
  double total = fx_.row(0).sum();
  for (int i = 0; i < n_; ++i) {
    total -= dmass_dt_.row(i).sum();
    const double correction = total - fx_.row(i + 1).sum();
    for (int j = 0; j < nz_; ++j)
      fx_(i + 1, j) += correction * ((j == 0 || j == nz_ - 1) ? 0.5 * dxi_ : dxi_);
    if (flow_scale > 0) mass_defect_ = std::max(mass_defect_, std::abs(correction) / flow_scale);
  }
  // Cross-film fluxes from continuity, marching up from surface 1 (impermeable); with the
  // corrected x fluxes each column balances, so surface 2 is impermeable too (to round-off,
  // which is spread over the column by volume).
  gz_.resize(n_, nz_);
  for (int i = 0; i < n_; ++i) {
    double r = 0, v = 0;
    for (int j = 0; j < nz_; ++j) {
      r += dmass_dt_(i, j) + fx_(i + 1, j) - fx_(i, j);
      v += volume_(i, j);
    }
    double cum_c = 0, cum_v = 0;
    for (int j = 0; j < nz_; ++j) {
      cum_c += dmass_dt_(i, j) + fx_(i + 1, j) - fx_(i, j);
      cum_v += volume_(i, j);
      gz_(i, j) = j == nz_ - 1 ? 0.0 : -cum_c + r * cum_v / v;
    }
  }
}

void FilmEnergySystem::Assemble(const FilmEnergyInputs& in,
                                const Eigen::MatrixXd& t_iter,
                                const CellMatrix& rho,
                                const CellMatrix& drho_dt,
                                const CellMatrix& drho_dp,
                                const Eigen::VectorXd& k_w_mk) {
  const FilmFlowField& f = *in.flow;
  const double cp = in.cp_j_kgk;
  const bool transient = in.dt_s > 0;
  ComputeMassFluxes(in, t_iter, rho, drho_dt, drho_dp);
  for (auto* m : {&ap_, &as_, &an_, &aw_, &ae_, &b_}) m->setZero(n_, nz_);
  cp_ = cp;
  kx_face_.assign(n_, 0.0);
  for (auto* m : {&compression_, &comp_explicit_t_, &heat_t_})
    m->resize(n_, nz_);  // every entry written below
  // The heating and its decay rate at every cell at once (Eigen's vectorized exp).
  if (f.heating_decay_1_k.size()) {
    heat_slope_ = f.heating_decay_1_k;
    heat_ = f.heating_w_m3.array() *
            (-f.heating_decay_1_k.array() * (t_iter - f.heating_reference_t_k).array()).exp();
  } else {
    heat_slope_.setZero(n_, nz_);
    heat_ = f.heating_w_m3;
  }
  for (int i = 0; i < n_; ++i) {
    const double dxc = source_[0].CellLength(i);
    const double kappa = k_w_mk[i] * dxc / (f.h_m[i] * dxi_);  // conduction across the film
    // Conduction along x through the west and east faces, per unit of dxi [W/(m K)].
    const double kx_w =
        i > 0 ? 0.25 * (k_w_mk[i - 1] + k_w_mk[i]) * (f.h_m[i - 1] + f.h_m[i]) / dx_ : 0.0;
    const double kx_e =
        i < n_ - 1 ? 0.25 * (k_w_mk[i + 1] + k_w_mk[i]) * (f.h_m[i + 1] + f.h_m[i]) / dx_ : 0.0;
    kx_face_[i] = kx_w;
    const double dpdt = f.dpdt_pa_s.size() ? f.dpdt_pa_s[i] : 0.0;
    const double dpdx = i == 0        ? (f.p_pa[1] - f.p_pa[0]) / dx_
                        : i == n_ - 1 ? (f.p_pa[n_ - 1] - f.p_pa[n_ - 2]) / dx_
                                      : (f.p_pa[i + 1] - f.p_pa[i - 1]) / (2 * dx_);
    for (int j = 0; j < nz_; ++j) {
      double& ap = ap_(i, j);
      // x faces, upwinded: inflow through the west face when F > 0, the east face when F < 0.
      const double fw = fx_(i, j), fe = fx_(i + 1, j);
      if (fw > 0) {
        ap += cp * fw;
        if (i > 0) aw_(i, j) -= cp * fw;  // else fluid enters at T0: theta = 0
      }
      if (fe < 0) {
        ap -= cp * fe;
        if (i < n_ - 1) ae_(i, j) += cp * fe;
      }
      // Conduction along x between neighbouring cells (none through the ends of the film).
      // Small against the cross-film conduction wherever the film is thin (ratio (h dxi /
      // dx)^2), it decides the temperature where the velocity changes sign: without it a
      // node of the inlet's recirculation with u ~ 0 took its temperature from whichever
      // neighbour was upwind, a jump of several kelvin when the sign flipped between coupling
      // iterations (the Ree-Eyring disc at L_T 5, SRR 0.5 then swung by 3-7 K on 513 nodes).
      const double dxi_j = (j == 0 || j == nz_ - 1) ? 0.5 * dxi_ : dxi_;
      ap += (kx_w + kx_e) * dxi_j;
      aw_(i, j) -= kx_w * dxi_j;
      ae_(i, j) -= kx_e * dxi_j;
      // Cross-film faces: convection upwinded, conduction central.
      if (j > 0) {
        const double gs = gz_(i, j - 1);
        if (gs > 0) {
          ap += cp * gs;
          as_(i, j) -= cp * gs;
        }
        ap += kappa;
        as_(i, j) -= kappa;
      }
      if (j < nz_ - 1) {
        const double gn = gz_(i, j);
        if (gn < 0) {
          ap -= cp * gn;
          an_(i, j) += cp * gn;
        }
        ap += kappa;
        an_(i, j) -= kappa;
      }
      if (transient) {
        ap += cp * mass_(i, j) / in.dt_s;
        b_(i, j) += cp * mass_(i, j) * ((*in.previous_t_k)(i, j) - in.t0_k) / in.dt_s;
      }
      // Heating g(T) = H exp(-beta (T - T_ref)), Newton-linearized about the iterate:
      // g(T_it) (1 - beta (T - T_it)); beta g V on the diagonal keeps it dominant.
      const double g = heat_(i, j), beta = heat_slope_(i, j);
      heat_t_(i, j) = t_iter(i, j);
      ap += beta * g * volume_(i, j);
      b_(i, j) += g * volume_(i, j) * (1 + beta * (t_iter(i, j) - in.t0_k));
      // Compression -(T/rho) drho/dT Dp/Dt = c T: a source lagged where it heats, implicit
      // where it cools (keeps the diagonal dominant).
      const double c = -drho_dt(i, j) / rho(i, j) * (dpdt + f.u_m_s(i, j) * dpdx);
      compression_(i, j) = c;
      if (c >= 0) {
        b_(i, j) += c * volume_(i, j) * t_iter(i, j);
        comp_explicit_t_(i, j) = t_iter(i, j);
      } else {
        ap -= c * volume_(i, j);
        b_(i, j) += c * volume_(i, j) * in.t0_k;
        comp_explicit_t_(i, j) = std::nan("");
      }
    }
  }
  BuildMatrix(in);
  rhs_.assign(n_ * block_, 0.0);  // surface rows: T_s - T0 - F sum G q = F H
  for (int i = 0; i < n_; ++i)
    for (int j = 0; j < nz_; ++j) rhs_[i * block_ + j] = b_(i, j);
  if (!in.fixed_walls)
    for (int s = 0; s < 2; ++s)
      if (const Eigen::VectorXd* h = s == 0 ? in.history1 : in.history2) {
        const double factor = s == 0 ? in.factor1 : in.factor2;
        for (int i = 0; i < n_; ++i) rhs_[i * block_ + nz_ + s] = factor * (*h)[i];
      }
}

Eigen::VectorXd FilmEnergySystem::Pack(const FilmTemperature& t, double t0_k) const {
  Eigen::VectorXd x(n_ * block_);
  for (int i = 0; i < n_; ++i) {
    for (int j = 0; j < nz_; ++j) x[i * block_ + j] = t.t_k(i, j) - t0_k;
    x[i * block_ + nz_] = t.q1_w_m2[i] * dx_;
    x[i * block_ + nz_ + 1] = t.q2_w_m2[i] * dx_;
  }
  return x;
}

void FilmEnergySystem::Unpack(const Eigen::VectorXd& x, double t0_k, FilmTemperature* t) const {
  t->t_k.resize(n_, nz_);
  t->q1_w_m2.resize(n_);
  t->q2_w_m2.resize(n_);
  for (int i = 0; i < n_; ++i) {
    for (int j = 0; j < nz_; ++j) t->t_k(i, j) = t0_k + x[i * block_ + j];
    t->q1_w_m2[i] = x[i * block_ + nz_] / dx_;
    t->q2_w_m2[i] = x[i * block_ + nz_ + 1] / dx_;
  }
  t->t1_k = t->t_k.col(0);
  t->t2_k = t->t_k.col(nz_ - 1);
}

// Compressed-column matrix, rows of each column in increasing order (KLU needs no sorting,
// but a fixed order lets the pattern be compared between iterations). Column (i, j) holds the
// coefficients of T_ij in rows (i-1, j), (i, j-1), (i, j), (i, j+1), the surface relations of
// column i, (i+1, j); column s1_i the wall-cell row (i, 0) and the surface-1 relations of
// columns i' >= i (the moving-heat-source weights); s2_i likewise.
void FilmEnergySystem::BuildMatrix(const FilmEnergyInputs& in) {
  // The pattern depends on the upwind directions along x and on the walls; the surface
  // weights (n^2 entries) only on the grid and the speeds. When both are as last time, only
  // the film entries are rewritten in place.
  std::vector<char> signature(static_cast<size_t>(n_) * nz_ * 2 + 1);
  for (int i = 0; i < n_; ++i)
    for (int j = 0; j < nz_; ++j) {
      signature[2 * (i * nz_ + j)] = ae_(i, j) != 0;
      signature[2 * (i * nz_ + j) + 1] = aw_(i, j) != 0;
    }
  signature.back() = in.fixed_walls;
  moving_walls_ = !in.fixed_walls;
  const int near = near_cells_;
  const bool in_place = !values_.empty() && signature == signature_ && near == built_near_ &&
                        in.factor1 == built_factor1_ && in.factor2 == built_factor2_ &&
                        in.omega1 == built_omega1_ && in.omega2 == built_omega2_ &&
                        in.reach1_m == built_reach1_ && in.reach2_m == built_reach2_;
  const int size = n_ * block_;
  size_t cursor = 0;
  if (!in_place) {
    col_ptr_.assign(size + 1, 0);
    row_idx_.clear();
    values_.clear();
    signature_ = signature;
    // The kernels follow the speeds (finite Peclet) or the step's reach (the high-Peclet
    // history), the far parts the near band.
    if (near != built_near_ || in.omega1 != built_omega1_ || in.omega2 != built_omega2_ ||
        in.reach1_m != built_reach1_ || in.reach2_m != built_reach2_)
      for (int s = 0; s < 2; ++s) {
        const double omega = s == 0 ? in.omega1 : in.omega2;
        const double reach = s == 0 ? in.reach1_m : in.reach2_m;
        if (finite_peclet_ && omega > 0) {
          source_[s] = MovingHeatSource(grid_, omega);
        } else if (!finite_peclet_ && reach != source_[s].reach_m()) {
          source_[s] = MovingHeatSource::Recent(grid_, reach);
        }
        far_[s].Reset(source_[s], near);
      }
    built_reach1_ = in.reach1_m;
    built_reach2_ = in.reach2_m;
    built_factor1_ = in.factor1;
    built_factor2_ = in.factor2;
    built_omega1_ = in.omega1;
    built_omega2_ = in.omega2;
    built_near_ = near;
  }
  auto put = [&](int row, double v) {
    if (in_place) {
      values_[cursor++] = v;
    } else {
      row_idx_.push_back(row);
      values_.push_back(v);
    }
  };
  int col = 0;
  for (int i = 0; i < n_; ++i) {
    const int base = i * block_;
    for (int j = 0; j < nz_; ++j, ++col) {
      if (!in_place) col_ptr_[col] = static_cast<int>(row_idx_.size());
      if (i > 0 && ae_(i - 1, j) != 0) put(base - block_ + j, ae_(i - 1, j));
      if (j > 0) put(base + j - 1, an_(i, j - 1));
      put(base + j, ap_(i, j));
      if (j < nz_ - 1) put(base + j + 1, as_(i, j + 1));
      if (j == 0) put(base + nz_, 1.0);
      if (j == nz_ - 1) put(base + nz_ + 1, 1.0);
      if (i < n_ - 1 && aw_(i + 1, j) != 0) put(base + block_ + j, aw_(i + 1, j));
    }
    for (int s = 0; s < 2; ++s, ++col) {
      if (!in_place) col_ptr_[col] = static_cast<int>(row_idx_.size());
      const int wall_j = s == 0 ? 0 : nz_ - 1;
      put(base + wall_j, source_[0].CellLength(i) / dx_);  // the wall cell loses q dx_cell
      if (in.fixed_walls) continue;
      if (in_place) {  // the surface weights are unchanged
        cursor = col_ptr_[col + 1];
        continue;
      }
      const double factor = s == 0 ? in.factor1 : in.factor2;
      // The near band only; high Peclet: T_s(x_0) = T0, no weight at i' = 0.
      const MovingHeatSource& src = source_[s];
      const int last = std::min(n_ - 1, i + near);
      for (int ii = src.high_peclet() ? std::max(i, 1) : i; ii <= last; ++ii)
        put(ii * block_ + nz_ + s, -factor * src.Weight(ii, i) / dx_);
    }
  }
  if (!in_place) col_ptr_[size] = static_cast<int>(row_idx_.size());
}

EnergyBalance FilmEnergySystem::Balance(const FilmEnergyInputs& in,
                                        const FilmTemperature& ft) const {
  const Eigen::MatrixXd& t = ft.t_k;
  const double cp = in.cp_j_kgk, t0 = in.t0_k;
  const bool transient = in.dt_s > 0;
  EnergyBalance e;
  for (int i = 0; i < n_; ++i)
    for (int j = 0; j < nz_; ++j) {
      const double theta = t(i, j) - t0;
      e.shear_w_m +=
          heat_(i, j) * (1 - heat_slope_(i, j) * (t(i, j) - heat_t_(i, j))) * volume_(i, j);
      const double tc = std::isnan(comp_explicit_t_(i, j)) ? t(i, j) : comp_explicit_t_(i, j);
      e.compression_w_m += compression_(i, j) * volume_(i, j) * tc;
      e.stored_w_m += cp * theta * dmass_dt_(i, j);
      if (transient)
        e.stored_w_m += cp * mass_(i, j) * (t(i, j) - (*in.previous_t_k)(i, j)) / in.dt_s;
    }
  for (int j = 0; j < nz_; ++j) {
    if (fx_(n_, j) > 0) e.convected_out_w_m += cp * fx_(n_, j) * (t(n_ - 1, j) - t0);
    if (fx_(0, j) < 0) e.convected_out_w_m -= cp * fx_(0, j) * (t(0, j) - t0);
  }
  for (int i = 0; i < n_; ++i) {
    e.into_solid1_w_m += ft.q1_w_m2[i] * source_[0].CellLength(i);
    e.into_solid2_w_m += ft.q2_w_m2[i] * source_[0].CellLength(i);
  }
  return e;
}

}  // namespace tehl::internal
