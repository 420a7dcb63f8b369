// tehl_thermal_gupta_table: the thermal reduction table of docs/validation.md ("Thermal
// reduction factor (Gupta et al. 1992)").
//
// On the steel twin disc of tests/verification/thermal_disc_case.hpp (R = 20 mm, p_H = 0.8 GPa,
// SAE 40 of seed 004 Table 2) the steady central film is solved isothermal and thermal
// (Newtonian) at every L_T in {0.1, 0.3, 1, 3, 5} and SRR in {0, 0.25, 0.5, 1}; um sets L_T =
// beta eta0 um^2 / k_f. Prints a markdown table of h_thermal / h_isothermal next to
// phi_T = [1 + 0.1 (1 + 14.8 SRR^0.83) L_T^0.64]^-1 (VALIDATION.md section 4) and whether the
// ratio lies within +-15 % of phi_T. Nothing is tuned toward phi_T. Two more ratios say where
// the film differs: h_min, and the mass flow per unit width q (constant along x in a steady
// film, read at the centre), which the inlet sets; q_thermal / q_iso differs from the h_c ratio
// by the density of the hot Hertz zone (the film there thickens as rho falls).
//
// Usage: tehl_thermal_gupta_table [nodes = 513] [film_nodes = 11] [eyring] [srr,...]
//   eyring: the thermal films use the lubricant's Ree-Eyring law (effect non_newtonian; the
//   isothermal reference stays Newtonian). srr,...: only these slide-to-roll ratios.
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "tehl/lubricant/lubricant.hpp"
#include "verification/thermal_disc_case.hpp"

namespace {

using tehl::FilmState;
using tehl::LineContactSolver;
using tehl::Lubricant;
using tehl::testing::ThermalDisc;

constexpr double kLoadings[] = {0.1, 0.3, 1.0, 3.0, 5.0};
constexpr double kSrrs[] = {0.0, 0.25, 0.5, 1.0};

}  // namespace

int main(int argc, char** argv) {
  const int n = argc > 1 ? std::atoi(argv[1]) : 513;
  const int nz = argc > 2 ? std::atoi(argv[2]) : 11;
  const bool eyring = argc > 3 && std::string(argv[3]) == "eyring";
  std::vector<double> srrs(std::begin(kSrrs), std::end(kSrrs));
  if (argc > 4) {
    srrs.clear();
    for (const char* s = argv[4]; *s != '\0';) {
      char* end = nullptr;
      srrs.push_back(std::strtod(s, &end));
      s = (*end == ',') ? end + 1 : end;
      if (end == s && *end != '\0') break;
    }
  }
  const Lubricant oil = Lubricant::FromFile(tehl::testing::Sae40Path());
  LineContactSolver::Options o;
  o.film_nodes = nz;
  ThermalDisc disc;
  std::printf(
      "Steel discs R = %.0f mm, p_H = %.2f GPa (w = %.1f kN/m), %s, T0 = %.2f K, "
      "beta = %.4f 1/K; %d nodes, %d across the film; %s thermal films.\n\n",
      disc.radius_m * 1e3, disc.hertz_pa / 1e9, disc.load_n_per_m() / 1e3, oil.name().c_str(),
      oil.reference_temperature_k(), tehl::testing::ViscosityTemperatureCoefficient(oil), n, nz,
      eyring ? "Ree-Eyring" : "Newtonian");
  std::printf(
      "| L_T | um [m/s] | SRR | h_c iso [um] | h_c thermal [um] | ratio | phi_T | "
      "ratio/phi_T - 1 | within 15 %% | h_min ratio | q ratio | q ratio/phi_T - 1 | "
      "T_max - T0 [K] | mu | balance error | coupling it. | T back-offs | time [s] |\n");
  std::printf("|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n");
  int outside = 0, failed = 0;
  for (double l_t : kLoadings) {
    disc.um_m_s = tehl::testing::SpeedForLoading(oil, l_t);
    disc.srr = 0.0;
    LineContactSolver iso = tehl::testing::DiscSolver(disc, oil, n, false, o);
    FilmState si;
    const auto isum = iso.SolveSteady(disc.Conditions(oil), &si);
    const double hc_iso = si.CentralFilm(iso.grid());
    const int centre = static_cast<int>(std::lround(-iso.grid().x_start_m() / iso.grid().dx_m()));
    const double q_iso = iso.MassFlow(disc.Conditions(oil), si)[centre];
    for (double srr : srrs) {
      disc.srr = srr;
      const auto t0 = std::chrono::steady_clock::now();
      LineContactSolver th = tehl::testing::DiscSolver(disc, oil, n, true, o, {}, eyring);
      FilmState st;
      const auto c = disc.Conditions(oil);
      const auto sum = th.SolveSteady(c, &st);
      const double seconds =
          std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
      if (!sum.usable() || !isum.usable()) {
        ++failed;
        std::printf(
            "| %.1f | %.3f | %.2f | failed: %s (%d coupling it., %d T back-offs, %.1f s) |\n", l_t,
            disc.um_m_s, srr, (!isum.usable() ? isum : sum).BriefReport().c_str(),
            sum.coupling_iterations, sum.temperature_backoffs, seconds);
        std::fflush(stdout);
        continue;
      }
      const double ratio = st.CentralFilm(th.grid()) / hc_iso;
      const double hmin_ratio = st.MinFilm() / si.MinFilm();
      const double q_ratio = th.MassFlow(c, st)[centre] / q_iso;
      const double phi = tehl::testing::GuptaFactor(l_t, srr);
      const bool in = std::abs(ratio / phi - 1.0) <= 0.15;
      if (!in) ++outside;
      std::printf(
          "| %.1f | %.3f | %.2f | %.4f | %.4f | %.3f | %.3f | %+.1f %% | %s | %.3f | %.3f | "
          "%+.1f %% | %.2f | %.4f | %.1e | %d | %d | %.1f |\n",
          l_t, disc.um_m_s, srr, hc_iso * 1e6, st.CentralFilm(th.grid()) * 1e6, ratio, phi,
          100.0 * (ratio / phi - 1.0), in ? "yes" : "**no**", hmin_ratio, q_ratio,
          100.0 * (q_ratio / phi - 1.0), st.temperature.MaxTemperature() - c.temperature_k,
          th.Friction(c, st).coefficient, sum.energy_balance_error, sum.coupling_iterations,
          sum.temperature_backoffs, seconds);
      std::fflush(stdout);
    }
  }
  std::printf("\n%d points outside +-15 %% of phi_T, %d solves failed.\n", outside, failed);
  return 0;
}
