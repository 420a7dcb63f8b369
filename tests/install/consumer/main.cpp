// The library example of docs/library.md, built against the installed package only (public
// headers, tehl::tehl) and run by the install test: a gear pair's pitch point from the gear
// layer, its steady film from the film layer, then a transient load step.
//
// Checks, each against a number of its own source: the seed 004 pitch point (VALIDATION.md
// section 5: R = 8.978 mm, um = 1.254 m/s, w = 116.14 kN/m, p_H ~ 522 MPa) and its central
// film between Pan-Hamrock and Moes (0.73 and 0.88 um by their fits, VALIDATION.md section 3
// band [0.97 PH, 1.03 Moes]).
#include <cmath>
#include <cstdio>
#include <string>

#include "tehl/ehl/grid.hpp"
#include "tehl/ehl/line_contact_solver.hpp"
#include "tehl/error.hpp"
#include "tehl/gear/gear_pair.hpp"
#include "tehl/gear/path_of_contact.hpp"
#include "tehl/lubricant/lubricant.hpp"
#include "tehl/units.hpp"

int main() {
  try {
    // The lubricant: an installed file (tehl_LUBRICANT_DIR from find_package(tehl)).
    const tehl::Lubricant oil =
        tehl::Lubricant::FromFile(std::string(TEHL_LUBRICANT_DIR) + "/sae40.toml");

    // The gear pair of seed 004: 35/105 teeth, m = 2 mm, 20 deg, b = 25 mm, aluminium bronze.
    tehl::GearPairSpec spec;
    spec.module_m = 0.002;
    spec.face_width_m = 0.025;
    spec.pinion.teeth = 35;
    spec.wheel.teeth = 105;
    for (tehl::GearMemberSpec* g : {&spec.pinion, &spec.wheel}) {
      g->material.youngs_modulus_pa = 117e9;
      g->material.poisson_ratio = 0.34;
    }
    const tehl::GearPair pair(spec);
    const double w1 = tehl::RpmToRadPerS(1000.0);  // pinion speed [rad/s]
    const tehl::PathOfContact path(pair, w1);
    const tehl::ContactPoint c = path.At(path.s_c_m());  // the pitch point C

    // 10 kW: tooth load per unit face width along the line of action, one pair at C.
    const double torque_nm = 10e3 / w1;
    const double w = torque_nm / path.line().pinion_base_radius_m / spec.face_width_m;
    // E' (2/E' = (1-nu1^2)/E1 + (1-nu2^2)/E2): twice Johnson's E*.
    const double e_prime = tehl::ReducedModulus(117e9, 0.34, 117e9, 0.34);
    const tehl::HertzScales hz = tehl::LineContactHertz(w, c.reduced_radius_m, e_prime);
    std::printf(
        "pitch point: eps_alpha = %.4f, R = %.3f mm, um = %.3f m/s, w = %.2f kN/m, "
        "p_H = %.1f MPa, b = %.1f um\n",
        path.contact_ratio(), c.reduced_radius_m * 1e3, c.um_m_s, w * 1e-3,
        hz.max_pressure_pa * 1e-6, hz.half_width_m * 1e6);

    // The film: a grid -4.5 b .. 1.5 b around the contact, isothermal, quasi-steady first.
    const tehl::UniformGrid grid = tehl::UniformGrid::AroundHertz(hz.half_width_m, 513);
    tehl::FilmEffects effects;  // elastic, piezoviscous, compressible, transient
    tehl::LineContactSolver solver(grid, e_prime, oil, effects, {});
    tehl::ContactConditions cond;
    cond.reduced_radius_m = c.reduced_radius_m;
    cond.u1_m_s = c.u1_m_s;
    cond.u2_m_s = c.u2_m_s;
    cond.load_n_per_m = w;
    cond.temperature_k = 313.15;  // the inlet, in kelvin
    tehl::FilmState film;         // empty: a cold start
    const tehl::LineContactSolver::Summary steady = solver.SolveSteady(cond, &film);
    std::printf("steady: %s; h_c = %.3f um, h_min = %.3f um, p_max = %.1f MPa\n",
                steady.BriefReport().c_str(), film.CentralFilm(grid) * 1e6, film.MinFilm() * 1e6,
                film.MaxPressure() * 1e-6);
    if (!steady.usable()) return 1;

    // A transient: the load rises by 20 % over 10 steps of 5 us (squeeze film).
    solver.BeginTransient(cond, film);
    for (int k = 1; k <= 10; ++k) {
      tehl::ContactConditions next = cond;
      next.load_n_per_m = w * (1.0 + 0.02 * k);
      const tehl::LineContactSolver::Summary step = solver.Step(next, 5e-6, &film);
      if (!step.usable()) {
        std::fprintf(stderr, "step %d: %s\n", k, step.BriefReport().c_str());
        return 1;
      }
    }
    std::printf("after the load step: t = %.0f us, h_c = %.3f um, h_min = %.3f um\n",
                film.time_s * 1e6, film.CentralFilm(grid) * 1e6, film.MinFilm() * 1e6);

    // The checks of the header: the steady film again, from a cold start, must converge and
    // lie in VALIDATION.md's band [0.97 Pan-Hamrock, 1.03 Moes] (0.73 and 0.88 um at C).
    const double hc = [&] {
      tehl::FilmState s;
      return solver.SolveSteady(cond, &s).usable() ? s.CentralFilm(grid) : 0.0;
    }();
    if (std::abs(c.reduced_radius_m - 8.978e-3) > 2e-6 || std::abs(c.um_m_s - 1.254) > 2e-3 ||
        std::abs(w - 116.14e3) > 100 || std::abs(hz.max_pressure_pa - 522e6) > 2e6)
      return 1;
    if (!(hc > 0.97 * 0.73e-6 && hc < 1.03 * 0.88e-6)) return 1;
  } catch (const tehl::InputError& e) {
    std::fprintf(stderr, "%s\n", e.what());
    return 2;
  }
  return 0;
}
