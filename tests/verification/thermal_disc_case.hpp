// A steel twin-disc line contact lubricated by SAE 40 (lubricants/sae40.toml, seed 004 Table 2)
// for the thermal verification tests and the Gupta table program: a thermal solver and its
// isothermal twin on the same grid, and the thermal loading L_T of Gupta et al. 1992
// (VALIDATION.md section 4).
#pragma once

#include <cmath>
#include <memory>
#include <string>

#include "tehl/ehl/film_effects.hpp"
#include "tehl/ehl/grid.hpp"
#include "tehl/ehl/line_contact_solver.hpp"
#include "tehl/lubricant/lubricant.hpp"
#include "tehl/units.hpp"

namespace tehl::testing {

struct ThermalDisc {
  double e_prime_pa = 226.4e9;  // steel on steel (VALIDATION.md section 1) [Pa]
  double radius_m = 0.02;       // R: two 40 mm discs [m]
  double hertz_pa = 0.8e9;      // p_H, moderate (VALIDATION.md section 4 asks 0.5-1 GPa) [Pa]
  double um_m_s = 1.0;          // entrainment speed [m/s]
  double srr = 0.0;             // slide-to-roll ratio (u1 - u2)/um [-]

  // p_H = sqrt(w E' / (2 pi R)) (Hertz line contact, VALIDATION.md section 1).
  double load_n_per_m() const { return 2.0 * M_PI * radius_m * hertz_pa * hertz_pa / e_prime_pa; }
  double half_width_m() const { return 4.0 * radius_m * hertz_pa / e_prime_pa; }
  ContactConditions Conditions(const Lubricant& oil) const {
    return ContactConditions{radius_m, um_m_s * (1.0 + 0.5 * srr), um_m_s * (1.0 - 0.5 * srr),
                             load_n_per_m(), oil.reference_temperature_k()};
  }
};

inline std::string Sae40Path() { return std::string(TEHL_SOURCE_DIR) + "/lubricants/sae40.toml"; }
// The wall heat fluxes integrated over x (trapezoidal) [W/m].
inline double HeatIntoSolids(const FilmState& s, double dx) {
  const Eigen::VectorXd q = s.temperature.q1_w_m2 + s.temperature.q2_w_m2;
  return dx * (q.sum() - 0.5 * (q[0] + q[q.size() - 1]));
}

// The surfaces' friction power -(F1 u1 + F2 u2): the dissipation of a film with p = 0 at both
// ends [W/m].
inline double FrictionPower(const FilmFriction& f, const ContactConditions& c) {
  return -(f.traction1_n_per_m * c.u1_m_s + f.traction2_n_per_m * c.u2_m_s);
}

// SAE 40 of seed 004 Table 2, read once.
inline const Lubricant& Sae40() {
  static const Lubricant oil = Lubricant::FromFile(Sae40Path());
  return oil;
}

// beta = -d ln eta / dT at (p = 0, T0): for the roelands_gamma law of SAE 40, gamma [1/K].
inline double ViscosityTemperatureCoefficient(const Lubricant& oil) {
  const auto v = oil.viscosity().Evaluate(0.0, oil.reference_temperature_k());
  return -v.deta_dT / v.eta_pa_s;
}

// Gupta et al. 1992 (VALIDATION.md section 4): L_T = beta eta0 um^2 / k_f at the inlet.
inline double ThermalLoading(const Lubricant& oil, double um_m_s) {
  const double t0 = oil.reference_temperature_k();
  const double eta0 = oil.viscosity().Evaluate(0.0, t0).eta_pa_s;
  const double k = oil.conductivity().ReferenceConductivity();
  return ViscosityTemperatureCoefficient(oil) * eta0 * um_m_s * um_m_s / k;
}
// The entrainment speed that gives the loading L_T (the inverse of ThermalLoading) [m/s].
inline double SpeedForLoading(const Lubricant& oil, double l_t) {
  return std::sqrt(l_t / ThermalLoading(oil, 1.0));
}

// phi_T = [1 + 0.1 (1 + 14.8 SRR^0.83) L_T^0.64]^-1 (VALIDATION.md section 4).
inline double GuptaFactor(double l_t, double srr) {
  return 1.0 / (1.0 + 0.1 * (1.0 + 14.8 * std::pow(std::abs(srr), 0.83)) * std::pow(l_t, 0.64));
}

// A solver on the disc's grid (-4.5 b .. 1.5 b, DESIGN.md section 5), steady, Newtonian unless
// `eyring` (the lubricant's Ree-Eyring law, effect non_newtonian).
inline LineContactSolver DiscSolver(const ThermalDisc& d,
                                    const Lubricant& oil,
                                    int n,
                                    bool thermal,
                                    const LineContactSolver::Options& o = {},
                                    const ContactSolids& solids = ContactSolids{},
                                    bool eyring = false) {
  FilmEffects e;
  e.transient = false;
  e.thermal = thermal;
  e.non_newtonian = eyring;
  return LineContactSolver(UniformGrid::AroundHertz(d.half_width_m(), n), d.e_prime_pa, oil, e, o,
                           nullptr, nullptr, solids);
}

}  // namespace tehl::testing
