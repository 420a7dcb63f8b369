// Flow fields built analytically for the film energy tests and benchmark: what the pressure
// solver would hand over, made so that continuity holds exactly (constant mass flow).
#pragma once

#include <algorithm>
#include <cmath>

#include "tehl/ehl/film_energy.hpp"
#include "tehl/ehl/grid.hpp"
#include "tehl/lubricant/constant_conductivity.hpp"
#include "tehl/lubricant/constant_viscosity.hpp"
#include "tehl/lubricant/dowson_higginson_density.hpp"
#include "tehl/lubricant/lubricant.hpp"
#include "tehl/lubricant/pressure_dependent_conductivity.hpp"

namespace tehl::testing {

// An SAE 40-like oil for the energy tests: Dowson-Higginson density with expansivity beta
// (seed 004 Table 2 gives beta = 6.5e-4 1/K for its oils), k(p) of seed 004 eq. 13 with
// k0 = 0.14 W/(m K), cp = 2000 J/(kg K). The viscosity law is not used by the energy solver.
inline Lubricant EnergyTestOil(double beta_per_k = 6.5e-4, double t0_k = 313.15) {
  DowsonHigginsonDensity::Parameters d;
  d.density_kg_m3 = 880.0;
  d.reference_temperature_k = t0_k;
  d.expansivity_per_k = beta_per_k;
  return Lubricant("energy_test_oil", "test", t0_k, 2000.0, beta_per_k,
                   std::make_unique<ConstantViscosity>(ConstantViscosity::Parameters{0.1}),
                   std::make_unique<DowsonHigginsonDensity>(d),
                   std::make_unique<PressureDependentConductivity>(
                       PressureDependentConductivity::Parameters{0.14}));
}

// Aluminium bronze UNS C61300 (VALIDATION.md section 5): rho 7890 kg/m^3, c 375 J/(kg K),
// k 55 W/(m K).
inline SolidThermal Bronze() { return SolidThermal{7890.0, 375.0, 55.0}; }

// An EHL-like film on the grid: Hertzian pressure p = p_H sqrt(1 - (x/b)^2) for |x| < b, a film
// flat (h_c) for |x| <= b and parabolic outside, h = h_c + (|x| - b)^2/(2R); and the
// Couette-Poiseuille profile u(xi) = u1 + (u2 - u1) xi + A(x) xi (1 - xi) whose Poiseuille
// strength A = 6 (q/(rho h) - um) makes the mass flow q = rho(p_c, T0) h_c um the same at every
// x (integral of rho u h dxi over [0, 1] = rho h (um + A/6)). Where h > 3 h_c rho_c/rho the
// mid-film velocity um + A/4 < 0: reverse flow in the inlet. Heating eta (du/dz)^2 with
// eta = eta0 exp(alpha p) (a Barus-like piezoviscous oil; the field is not a Reynolds
// solution, which the energy equation does not need).
struct EhlLikeParameters {
  double half_width_m = 1e-4;      // b [m]
  double max_pressure_pa = 0.5e9;  // p_H [Pa]
  double central_film_m = 0.5e-6;  // h_c [m]
  double radius_m = 0.01;          // R of the parabolic part [m]
  double u1_m_s = 1.0, u2_m_s = 1.5;
  double eta0_pa_s = 0.05;     // [Pa s]
  double alpha_per_pa = 1e-8;  // [1/Pa]
};

inline FilmFlowField EhlLikeField(const UniformGrid& g,
                                  int nz,
                                  const Lubricant& oil,
                                  const EhlLikeParameters& c) {
  const int n = g.size();
  FilmFlowField f;
  f.p_pa.resize(n);
  f.h_m.resize(n);
  f.u_m_s.resize(n, nz);
  f.heating_w_m3.resize(n, nz);
  f.u1_m_s = c.u1_m_s;
  f.u2_m_s = c.u2_m_s;
  const double b = c.half_width_m, t0 = oil.reference_temperature_k();
  const double um = 0.5 * (c.u1_m_s + c.u2_m_s);
  const double q = oil.density().Evaluate(c.max_pressure_pa, t0).rho_kg_m3 * c.central_film_m * um;
  for (int i = 0; i < n; ++i) {
    const double x = g.x(i), s = std::max(0.0, std::abs(x) - b);
    f.p_pa[i] = std::abs(x) < b ? c.max_pressure_pa * std::sqrt(1 - (x / b) * (x / b)) : 0.0;
    f.h_m[i] = c.central_film_m + s * s / (2 * c.radius_m);
    const double rho = oil.density().Evaluate(f.p_pa[i], t0).rho_kg_m3;
    const double a = 6 * (q / (rho * f.h_m[i]) - um);
    const double eta = c.eta0_pa_s * std::exp(c.alpha_per_pa * f.p_pa[i]);
    for (int j = 0; j < nz; ++j) {
      const double xi = static_cast<double>(j) / (nz - 1);
      f.u_m_s(i, j) = c.u1_m_s + (c.u2_m_s - c.u1_m_s) * xi + a * xi * (1 - xi);
      const double dudz = ((c.u2_m_s - c.u1_m_s) + a * (1 - 2 * xi)) / f.h_m[i];
      f.heating_w_m3(i, j) = eta * dudz * dudz;
    }
  }
  return f;
}

// Polymer-like solids: rho 1300 kg/m^3, c 1340 J/(kg K), k 0.25 W/(m K) (effusivity 660
// against 12 600 for bronze).
inline SolidThermal Polymer() { return SolidThermal{1300.0, 1340.0, 0.25}; }

// The EHL-like film under a 0.1 um film on 257 nodes and 11 film nodes. Each unit of wall
// flux warms polymer solids here some 200 times more than bronze (film conduction k/h times
// F 2 sqrt(L)), so the surface history lagged outside the energy solver's factorized matrix
// stalls its chord steps.
struct ThinEhlFilm {
  EhlLikeParameters c = [] {
    EhlLikeParameters p;
    p.central_film_m = 1e-7;
    return p;
  }();
  Lubricant oil = EnergyTestOil();
  UniformGrid g = UniformGrid::AroundHertz(c.half_width_m, 257);
  FilmFlowField f = EhlLikeField(g, 11, oil, c);
};

}  // namespace tehl::testing
