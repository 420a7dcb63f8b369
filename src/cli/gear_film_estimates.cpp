// `tehl gear`: the films the published isothermal fits expect at the points A .. E of the
// path, before anything is solved (VALIDATION.md section 3: Pan & Hamrock 1989, Moes).
#include "cli/gear_film_estimates.hpp"

#include <cmath>
#include <ostream>

#include "cli/number_format.hpp"
#include "scene/mesh_cycle_plan.hpp"
#include "tehl/ehl/film_thickness_formulas.hpp"
#include "tehl/lubricant/lubricant.hpp"
#include "tehl/units.hpp"

namespace tehl::cli {

double CompositeWavinessRq(const internal::Document& doc) {
  double sum = 0;
  for (const char* s : {"surfaces.surface1", "surfaces.surface2"})
    if (doc.Bool("effects", "roughness") && doc.String(s, "roughness") == "sinusoidal") {
      const double rq = doc.Real(s, "amplitude_m") / std::sqrt(2.0);  // of a sinusoid
      sum += rq * rq;
    }
  return std::sqrt(sum);
}

void FilmEstimates(std::ostream& o,
                   const internal::GearCase& c,
                   const internal::FilmCase& film,
                   double rq_m) {
  if (!film.lubricant || !c.pair) return;
  const double t0 = film.inlet_temperature_k;
  const ViscosityValue v = film.lubricant->viscosity().Evaluate(0.0, t0);
  const double eta0 = v.eta_pa_s, alpha = v.deta_dp / v.eta_pa_s;
  const double e_prime = c.ReducedModulusPa();
  const internal::CyclePath cycle(c);
  const PathOfContact& path = cycle.path();
  o << "\nFilm estimates (isothermal fits at the inlet, " << Fmt("%.2f", t0)
    << " K: eta0 = " << Fmt("%.4g", eta0) << " Pa s, alpha = " << Fmt("%.4g", alpha)
    << " 1/Pa = d ln(eta)/dp at p = 0;\n  Pan & Hamrock 1989 and Moes, VALIDATION.md section 3; "
       "B and D on their single-contact side):\n";
  o << "  point  s [mm]   R [mm]  um [m/s]  w [kN/m]  p_H [MPa]  h_c PH [um]  h_min PH [um]"
       "  h_c Moes [um]"
    << (rq_m > 0 ? "  lambda" : "") << "\n";
  const struct {
    const char* name;
    double s;
    bool left;
  } points[] = {{"A", 0.0, false},
                {"B", path.s_b_m(), false},
                {"C", path.s_c_m(), false},
                {"D", path.s_d_m(), true},
                {"E", path.length_m(), true}};
  for (const auto& p : points) {
    o << "  " << p.name;
    if (p.s < cycle.begin_m() - 1e-9 || p.s > cycle.end_m() + 1e-9) {
      o << "      " << Fmt("%6.3f", p.s * 1e3) << "   (the tip relief unloads the pair here)\n";
      continue;
    }
    const internal::PathState st = cycle.At(p.s, p.left);
    const double r = st.contact.reduced_radius_m, um = st.contact.um_m_s, w = st.load_n_per_m;
    const DimensionlessGroups g = LineContactGroups(eta0, alpha, um, w, r, e_prime);
    const double hc = PanHamrockCentralFilmM(g.U, g.G, g.W, r);
    const double hmin = PanHamrockMinimumFilmM(g.U, g.G, g.W, r);
    const double moes = MoesCentralFilmM(g.U, g.G, g.W, r);
    o << "      " << Fmt("%6.3f", p.s * 1e3) << "  " << Fmt("%7.3f", r * 1e3) << "  "
      << Fmt("%8.4f", um) << "  " << Fmt("%8.2f", w * 1e-3) << "  "
      << Fmt("%9.1f", LineContactHertz(w, r, e_prime).max_pressure_pa * 1e-6) << "  "
      << Fmt("%11.4f", hc * 1e6) << "  " << Fmt("%13.4f", hmin * 1e6) << "  "
      << Fmt("%13.4f", moes * 1e6);
    if (rq_m > 0) o << "  " << Fmt("%6.2f", hmin / rq_m);
    o << "\n";
  }
  o << "  The fits are isothermal and Newtonian: the inlet's shear heating thins the film "
       "(docs/validation.md section 6);\n  the solved film at a point: `tehl run CASE --at C`, "
       "along the whole path: `tehl run CASE`.\n";
  if (rq_m > 0)
    o << "  lambda = h_min / Rq with the waviness of [surfaces] (Rq = " << Fmt("%.3g", rq_m * 1e6)
      << " um, amplitude / sqrt(2) per surface, combined): below about 1 the asperities touch, "
         "above about 3 the film separates them.\n";
}

}  // namespace tehl::cli
