#include "scene/contact_case.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "scene/automatic_grid.hpp"
#include "scene/profile_memory.hpp"
#include "tehl/units.hpp"

namespace tehl::internal {

ContactInputs ReadContact(Document& doc) {
  ContactInputs in;
  in.r1 = doc.Real("contact", "radius_1_m");
  in.r2 = doc.Given("contact", "radius_2_m") ? doc.Real("contact", "radius_2_m") : 0.0;
  in.e_prime = ReducedModulus(
      doc.Real("contact", "youngs_modulus_1_pa"), doc.Real("contact", "poisson_ratio_1"),
      doc.Real("contact", "youngs_modulus_2_pa"), doc.Real("contact", "poisson_ratio_2"));
  in.steps = static_cast<int>(doc.Int("contact", "steps"));
  const double w = doc.Real("contact", "load_n_per_m");
  const double u1 = doc.Real("contact", "speed_1_m_s"), u2 = doc.Real("contact", "speed_2_m_s");
  in.t = doc.Reals("contact", "time_s");
  auto table = [&](const char* key, double fallback) {
    return doc.Given("contact", key)
               ? doc.Reals("contact", key)
               : std::vector<double>(std::max<size_t>(in.t.size(), 1), fallback);
  };
  if (in.t.empty()) in.t = {0.0};
  in.w = table("load_table_n_per_m", w);
  in.u1 = table("speed_1_table_m_s", u1);
  in.u2 = table("speed_2_table_m_s", u2);
  if (in.steps == 0) {  // steady: the first table row (or the scalar keys)
    in.w = {w};
    in.u1 = {u1};
    in.u2 = {u2};
    in.t = {0.0};
  }
  for (size_t i = 0; i < in.u1.size() && i < in.u2.size(); ++i)
    if (!(in.u1[i] + in.u2[i] > 0)) {
      doc.Problem("contact", "speed_1_m_s",
                  "the entrainment speed (u1 + u2)/2 must be > 0 "
                  "(the inlet is at the grid start)",
                  "speeds with u1 + u2 > 0 at every time");
      break;
    }
  // The surface temperatures of thermal runs are those of heat sources moving with each
  // surface into the contact (seed 004 eqs. 14-15; Jaeger's moving line source with
  // finite_peclet): a surface at rest, or moving out of the contact, has none.
  if (doc.Bool("effects", "thermal")) {
    const bool tables = in.steps > 0;
    const char* keys[2][2] = {{"speed_1_m_s", "speed_1_table_m_s"},
                              {"speed_2_m_s", "speed_2_table_m_s"}};
    const std::vector<double>* speeds[2] = {&in.u1, &in.u2};
    for (int j = 0; j < 2; ++j) {
      const auto slow =
          std::find_if(speeds[j]->begin(), speeds[j]->end(), [](double u) { return !(u > 0); });
      if (slow == speeds[j]->end()) continue;
      const bool table_key = tables && doc.Given("contact", keys[j][1]);
      doc.Problem("contact", keys[j][table_key ? 1 : 0],
                  "a thermal run needs both surfaces moving into the contact: the surface "
                  "temperatures are those of heat sources moving with each surface (seed 004 "
                  "eqs. 14-15), and a surface at " +
                      std::string(*slow == 0 ? "rest" : "a negative speed") + " (" +
                      FormatShort(*slow) + " m/s) has none",
                  "speeds > 0 at every time, or [effects] thermal = false");
    }
  }
  const char* load_key = doc.Given("contact", "load_table_n_per_m") && in.steps > 0
                             ? "load_table_n_per_m"
                             : "load_n_per_m";
  for (double wi : in.w)
    if (!(wi > 0)) {
      doc.Problem("contact", load_key, "every load must be > 0", "loads > 0 [N/m]");
      break;
    }
  const double w_limit = MaxHertzLoad(in.ReducedRadius(), in.e_prime);
  for (double wi : in.w)
    if (wi > w_limit) {
      const HertzScales hz = LineContactHertz(wi, in.ReducedRadius(), in.e_prime);
      doc.Problem("contact", load_key,
                  "a load of " + FormatShort(wi) + " N/m gives a Hertz half-width b = " +
                      FormatShort(hz.half_width_m) + " m against R = " +
                      FormatShort(in.ReducedRadius()) + " m (p_H = " +
                      FormatShort(hz.max_pressure_pa) + " Pa, E' = " + FormatShort(in.e_prime) +
                      " Pa): Hertz line-contact theory needs b << R",
                  "loads <= " + FormatShort(w_limit) + " N/m (b <= 0.2 R) for these bodies");
      break;
    }
  return in;
}

void CheckFilmScale(Document& doc, const ContactInputs& in, const FilmCase& film) {
  if (!film.lubricant) return;
  const double r = in.ReducedRadius();
  const double eta0 = film.lubricant->viscosity().Evaluate(0.0, film.inlet_temperature_k).eta_pa_s;
  const size_t rows = std::max({in.w.size(), in.u1.size(), in.u2.size()});
  for (size_t i = 0; i < rows; ++i) {
    const double w = in.w[std::min(i, in.w.size() - 1)];
    const double um =
        0.5 * (in.u1[std::min(i, in.u1.size() - 1)] + in.u2[std::min(i, in.u2.size() - 1)]);
    const double h_martin = kMartinFilm * eta0 * um * r / w;
    if (!(w > 0) || !(um > 0) || h_martin <= kMaxFilmToRadius * r) continue;
    const char* key = doc.Given("contact", "load_table_n_per_m") && in.steps > 0
                          ? "load_table_n_per_m"
                          : "load_n_per_m";
    doc.Problem("contact", key,
                "a load of " + FormatShort(w) + " N/m at um = " + FormatShort(um) +
                    " m/s carries a film of at least " + FormatShort(h_martin) +
                    " m (Martin's rigid film 4.896 eta0 um R / w) against R = " + FormatShort(r) +
                    " m: Reynolds' thin-film theory needs h << R",
                "loads >= " + FormatShort(kMartinFilm * eta0 * um / kMaxFilmToRadius) +
                    " N/m at this speed (h <= " + FormatShort(kMaxFilmToRadius) + " R)");
    return;
  }
}

ContactGridPlan PlanContactGrid(Document& doc, const ContactInputs& in, const FilmCase& film) {
  const double r = in.ReducedRadius();
  GridUnits units;
  GridChoice choice(film, in.e_prime);
  for (size_t i = 0; i < std::max({in.w.size(), in.u1.size(), in.u2.size()}); ++i) {
    const double w = in.w[std::min(i, in.w.size() - 1)];
    const double b = LineContactHertz(w, r, in.e_prime).half_width_m;
    const double um =
        0.5 * (in.u1[std::min(i, in.u1.size() - 1)] + in.u2[std::min(i, in.u2.size() - 1)]);
    units = units.Max(GridUnitsFor(film, b, r, um, w));
    choice.Add(r, um, w);
  }
  ContactGridPlan plan{choice.Grid(units), choice.Rule(units), choice.InletNote(units), {}};
  plan.input_notes = InputNotes(film, plan.grid.dx_m(), plan.grid.size());
  CheckRoughnessResolution(doc, film, plan.grid.dx_m());
  CheckContactRoughSteps(doc, in, film, plan.grid.dx_m());
  CheckProfileMemory(doc, film, plan.grid.size(), in.steps > 0 ? in.steps + 1LL : 1LL,
                     /*journal=*/false, "contact", "steps", plan.input_notes);
  return plan;
}

void CheckContactRoughSteps(Document& doc,
                            const ContactInputs& in,
                            const FilmCase& film,
                            double dx_m) {
  if (!film.effects.roughness || in.steps <= 0 || in.t.size() < 2 || !(dx_m > 0)) return;
  // The distance the entrainment moves over the tables (um linear between rows).
  double travel = 0;
  for (size_t i = 1; i < in.t.size(); ++i) {
    const auto um = [&](size_t k) {
      return 0.5 *
             std::abs(in.u1[std::min(k, in.u1.size() - 1)] + in.u2[std::min(k, in.u2.size() - 1)]);
    };
    travel += 0.5 * (um(i - 1) + um(i)) * (in.t[i] - in.t[i - 1]);
  }
  const long long need = static_cast<long long>(std::ceil(travel / dx_m - 1e-9));
  if (in.steps >= need) return;
  doc.Problem("contact", "steps",
              "with moving roughness a step may move the surfaces by one grid cell at most (dt "
              "um <= dx): the tables move them " +
                  FormatShort(travel) + " m, " + FormatShort(travel / dx_m) +
                  " cells of dx = " + FormatShort(dx_m) + " m",
              "steps >= " + std::to_string(need) + " on this grid, or fewer grid_points");
}

}  // namespace tehl::internal
