// A point (M, L) of the isothermal EHL line-contact map for the reference oil of
// VALIDATION.md section 3 (eta0 = 0.04 Pa s, Z = 0.68, alpha from Houpert) on steel
// (E' = 226.4 GPa) with R = 10 mm, and a steady solver set up for it. Shared by the
// ehl_*_test verification binaries and the validation-table program.
#pragma once

#include <cmath>
#include <memory>

#include "support/test_lubricants.hpp"
#include "tehl/ehl/film_effects.hpp"
#include "tehl/ehl/film_thickness_formulas.hpp"
#include "tehl/ehl/grid.hpp"
#include "tehl/ehl/line_contact_solver.hpp"
#include "tehl/units.hpp"

namespace tehl::testing {

struct MoesPoint {
  double M = 20;                // Moes load parameter [-]
  double L = 10;                // Moes material parameter [-]
  double e_prime_pa = 226.4e9;  // steel-steel E' (VALIDATION.md section 1) [Pa]
  double radius_m = 0.01;       // R [m]
  double eta0_pa_s = 0.04;      // [Pa s]
  double z = 0.68;              // Roelands pressure index [-]
  double x_start_b = -4.5;      // inlet end of the grid in Hertz half-widths [-]

  // VALIDATION.md section 1: alpha = Z (ln eta0 + 9.67)/p0, p0 = 1.96e8 Pa [1/Pa].
  double alpha() const { return z * (std::log(eta0_pa_s) + 9.67) / 1.96e8; }
  double G() const { return alpha() * e_prime_pa; }
  // Inverting L = G (2U)^(1/4) and M = W (2U)^(-1/2) (VALIDATION.md section 1).
  double U() const { return 0.5 * std::pow(L / G(), 4.0); }
  double W() const { return M * std::sqrt(2.0 * U()); }
  double um_m_s() const { return U() * e_prime_pa * radius_m / eta0_pa_s; }
  double load_n_per_m() const { return W() * e_prime_pa * radius_m; }
  HertzScales Hertz() const { return LineContactHertz(load_n_per_m(), radius_m, e_prime_pa); }
  // The contact's transit time b / um [s], the time scale of transient films.
  double TransitTime() const { return Hertz().half_width_m / um_m_s(); }
  // H_M = h / (R sqrt(2U)): h [m] = H_M * FilmScale().
  double FilmScale() const { return radius_m * std::sqrt(2.0 * U()); }
  double MoesHc() const { return MoesCentralFilm(M, L); }
  double PanHamrockHc() const {
    return PanHamrockCentralFilmM(U(), G(), W(), radius_m) / FilmScale();
  }
  double PanHamrockHmin() const {
    return PanHamrockMinimumFilmM(U(), G(), W(), radius_m) / FilmScale();
  }
  ContactConditions Conditions(double load_factor = 1.0) const {
    return ContactConditions{radius_m, um_m_s(), um_m_s(), load_factor * load_n_per_m(),
                             kReferenceT0};
  }
  // DESIGN.md section 5: -4.5 b .. 1.5 b (x_start_b b .. 1.5 b).
  UniformGrid Grid(int n) const {
    return UniformGrid::AroundHertz(Hertz().half_width_m, n, x_start_b, 1.5);
  }
};

// Everything a steady or transient film solve at a Moes point needs, kept alive together
// (the solver holds a reference to the lubricant).
struct MoesSolver {
  MoesSolver(const MoesPoint& point, int n, const LineContactSolver::Options& options = {},
             bool transient = false)
      : mp(point),
        grid(point.Grid(n)),
        oil(std::make_unique<Lubricant>(ReferenceOil(point.eta0_pa_s, point.z))),
        solver(grid, point.e_prime_pa, *oil, Effects(transient), options) {}

  static FilmEffects Effects(bool transient) {
    FilmEffects e;
    e.transient = transient;
    return e;
  }
  double Hc(const FilmState& s) const { return s.CentralFilm(grid) / mp.FilmScale(); }
  double Hmin(const FilmState& s) const { return s.MinFilm() / mp.FilmScale(); }

  MoesPoint mp;
  UniformGrid grid;
  std::unique_ptr<Lubricant> oil;
  LineContactSolver solver;
};

}  // namespace tehl::testing
