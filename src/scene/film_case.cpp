#include "scene/film_case.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>
#include <utility>

#include "scene/case_reader.hpp"
#include "tehl/ehl/inlet_truncation.hpp"
#include "tehl/error.hpp"
#include "tehl/lubricant/barus_viscosity.hpp"
#include "tehl/lubricant/roelands_gamma_viscosity.hpp"
#include "tehl/units.hpp"

namespace tehl::internal {
namespace {

std::shared_ptr<const SurfaceShape> ReadSurface(Document& doc, const std::string& section) {
  const std::string kind = doc.String(section, "roughness");
  if (kind == "sinusoidal" && doc.Given(section, "wavelength_m"))
    return std::make_shared<SinusoidalWaviness>(doc.Real(section, "amplitude_m"),
                                                doc.Real(section, "wavelength_m"),
                                                doc.Real(section, "phase_rad"));
  if (kind == "profile" && !doc.String(section, "profile_file").empty()) {
    std::filesystem::path file(doc.String(section, "profile_file"));
    if (file.is_relative()) file = std::filesystem::path(doc.path()).parent_path() / file;
    try {
      return std::make_shared<MeasuredProfile>(MeasuredProfile::ReadFile(file.string()));
    } catch (const InputError& e) {
      // The profile reader's own problems: where in the profile file, and what is wrong.
      for (const InputProblem& p : e.problems()) {
        std::string where = p.file.empty() ? file.string() : p.file;
        if (p.line > 0) where += ":" + std::to_string(p.line);
        doc.Problem(section, "profile_file",
                    "the profile file is not usable: " + where + ": " + p.rule,
                    p.allowed.empty() ? "a two-column text file (x [m], height [m])" : p.allowed);
      }
    }
  }
  return nullptr;
}

}  // namespace

GridUnits GridUnitsFor(const FilmCase& film,
                       double b_m,
                       double r_m,
                       double um_m_s,
                       double w_n_per_m,
                       bool isoviscous_inlet) {
  if (!film.lubricant || (film.effects.elastic && !isoviscous_inlet)) return {b_m, b_m};
  const double eta0 = film.lubricant->viscosity().Evaluate(0.0, film.inlet_temperature_k).eta_pa_s;
  if (!film.effects.elastic) {
    const double h0 = 4.896 * eta0 * um_m_s * r_m / w_n_per_m;  // Martin [m]
    const double l = std::sqrt(2.0 * r_m * h0);
    return {kRigidInletUnit * l, kRigidOutletUnit * l};
  }
  // Elastic films: b, unless the film is nearly isoviscous (alpha p_H below the Grubin regime
  // of the inlet estimate) and nearly rigid (h_M R / b^2 ~ 1/M^2 not small): its inlet then
  // reaches -l_iso at the default x_start_b (IsoviscousInletLength,
  // include/tehl/ehl/inlet_truncation.hpp: the rigid film's 40 sqrt(2 R h_M) weighted by that
  // ratio, at most R/2), its outlet as far as the rigid film's in proportion.
  const ViscosityValue inlet = film.lubricant->viscosity().Evaluate(0.0, film.inlet_temperature_k);
  const double p_hertz = b_m > 0 ? 2.0 * w_n_per_m / (kPi * b_m) : 0.0;
  if (film.effects.piezoviscous && inlet.deta_dp / inlet.eta_pa_s * p_hertz >= kGrubinMinAlphaP)
    return {b_m, b_m};
  const double l_iso = IsoviscousInletLength(r_m, b_m, um_m_s, eta0, w_n_per_m);
  const double unit = kRigidInletUnit * l_iso / kIsoviscousInletLengths;
  // The outlet as the rigid film's, 2 sqrt(2 R h_M) at the default x_end_b, with the same
  // weight h_M R / b^2 but not the inlet's R/2 cap: a thick film ruptures at 0.475 sqrt(2 R h)
  // however short the inlet.
  const double h_martin = kMartinFilm * eta0 * um_m_s * r_m / w_n_per_m;
  const double weight = b_m > 0 ? std::min(1.0, h_martin * r_m / (b_m * b_m)) : 1.0;
  const double outlet = kRigidOutletUnit * std::sqrt(2.0 * r_m * h_martin) * weight;
  return {std::max(b_m, unit), std::max(b_m, outlet)};
}

void CheckRoughnessResolution(Document& doc, const FilmCase& film, double dx_m) {
  if (!film.effects.roughness) return;
  // A measured profile is one period of its surface: a period shorter than two cells is not
  // represented either.
  const std::pair<const char*, const SurfaceShape*> shapes[] = {
      {"surfaces.surface1", film.surface1.get()}, {"surfaces.surface2", film.surface2.get()}};
  for (const auto& [section, shape] : shapes) {
    const auto* profile = dynamic_cast<const MeasuredProfile*>(shape);
    if (!profile || profile->period_m() >= 2.0 * dx_m) continue;
    doc.Problem(section, "profile_file",
                "the profile spans one period of " + FormatShort(profile->period_m()) +
                    " m, shorter than two cells of the film grid (dx = " + FormatShort(dx_m) +
                    " m): the grid cannot represent it",
                "a profile over at least " + FormatShort(2.0 * dx_m) +
                    " m on this grid, or more [numerics] grid_points");
  }
  for (const char* section : {"surfaces.surface1", "surfaces.surface2"}) {
    if (!doc.HasSection(section) || doc.String(section, "roughness") != "sinusoidal" ||
        !doc.Given(section, "wavelength_m"))
      continue;
    const double wavelength = doc.Real(section, "wavelength_m");
    if (wavelength >= 2.0 * dx_m) continue;
    doc.Problem(section, "wavelength_m",
                "a waviness of " + FormatShort(wavelength) +
                    " m is shorter than two cells of the film grid (dx = " + FormatShort(dx_m) +
                    " m): the grid cannot represent it",
                "wavelength_m >= " + FormatShort(2.0 * dx_m) +
                    " m on this grid, or more [numerics] grid_points");
  }
}

std::string RoughnessResolutionNote(const FilmCase& film, double dx_m, int nodes) {
  if (!film.effects.roughness || !(dx_m > 0) || nodes < 2) return "";
  double shortest = 0;
  const char* which = "";
  const std::pair<const char*, const SurfaceShape*> shapes[] = {{"surface1", film.surface1.get()},
                                                                {"surface2", film.surface2.get()}};
  for (const auto& [name, shape] : shapes) {
    const auto* wave = dynamic_cast<const SinusoidalWaviness*>(shape);
    if (!wave || !(wave->amplitude_m() > 0)) continue;
    if (shortest == 0 || wave->wavelength_m() < shortest) {
      shortest = wave->wavelength_m();
      which = name;
    }
  }
  const double cells = shortest / dx_m;
  if (shortest == 0 || cells >= kWaveCellsNote) return "";
  const double need = (nodes - 1) * kWaveCellsResolved / cells;
  long long suggested = 2;
  while (suggested < need) suggested *= 2;
  char text[480];
  std::snprintf(text, sizeof text,
                "the waviness of %s (%.4g um) spans %.1f cells of the film grid (dx = %.3g um): "
                "the thinnest film of a wave is within about 1.5 %% of the grid-converged one "
                "from about %.0f cells per wavelength, and too thin and too highly pressed "
                "below (docs/studies.md, \"Roughness grid\"); [numerics] grid_points = %lld "
                "gives %.0f with the same x range",
                which, shortest * 1e6, cells, dx_m * 1e6, kWaveCellsResolved, suggested + 1,
                shortest / (dx_m * (nodes - 1) / suggested));
  return text;
}

std::vector<std::string> LongWavinessNotes(const FilmCase& film, double dx_m, int nodes) {
  std::vector<std::string> notes;
  if (!film.effects.roughness || !(dx_m > 0) || nodes < 2) return notes;
  const double span_m = dx_m * (nodes - 1);
  const std::pair<const char*, const SurfaceShape*> shapes[] = {{"surface1", film.surface1.get()},
                                                                {"surface2", film.surface2.get()}};
  for (const auto& [name, shape] : shapes) {
    const auto* wave = dynamic_cast<const SinusoidalWaviness*>(shape);
    if (!wave || !(wave->amplitude_m() > 0)) continue;
    const double spans = wave->wavelength_m() / span_m;
    if (spans <= kLongWaveSpans) continue;
    char text[480];
    std::snprintf(text, sizeof text,
                  "the waviness of %s (wavelength_m = %.4g m) is %.3g times as long as the film "
                  "grid (%.4g mm): across the contact it is a nearly uniform offset and tilt, "
                  "which the film takes up, so it does not act as roughness (only the steps it "
                  "needs, dt um <= dx, remain); a wavelength in micrometres written in metres? "
                  "(50 um = 5e-05 m)",
                  name, wave->wavelength_m(), spans, span_m * 1e3);
    notes.push_back(text);
  }
  return notes;
}

std::vector<std::string> InputNotes(const FilmCase& film, double dx_m, int nodes) {
  std::vector<std::string> notes;
  const std::string wave = RoughnessResolutionNote(film, dx_m, nodes);
  if (!wave.empty()) notes.push_back(wave);
  for (std::string& n : LongWavinessNotes(film, dx_m, nodes)) notes.push_back(std::move(n));
  if (film.lubricant) {
    const ViscosityModel& law = film.lubricant->viscosity();
    const char* name = dynamic_cast<const RoelandsGammaViscosity*>(&law) ? "roelands_gamma"
                       : dynamic_cast<const BarusViscosity*>(&law)       ? "barus"
                                                                         : nullptr;
    const bool exponential = name != nullptr;
    const double t0 = film.lubricant->reference_temperature_k();
    const double dt = film.inlet_temperature_k - t0;
    if (exponential && std::abs(dt) > kGammaLawNoteK) {
      char text[480];
      std::snprintf(text, sizeof text,
                    "the inlet (%.2f K) is %.0f K %s the lubricant's reference temperature "
                    "(%.2f K): its %s law takes the viscosity there from one exponential "
                    "temperature coefficient and keeps the pressure response of T0, which real "
                    "oils follow only within a few tens of K (docs/case_format.md, \"Lubricant "
                    "files\"): a file at that temperature, or one with the roelands (S0) law, "
                    "is closer",
                    film.inlet_temperature_k, std::abs(dt), dt > 0 ? "above" : "below", t0, name);
      notes.push_back(text);
    }
  }
  return notes;
}

ContactSolids ReadContactSolids(const Document& doc) {
  auto solid = [&](const std::string& section, const std::string& suffix) {
    return SolidThermal{doc.Real(section, "density" + suffix + "_kg_m3"),
                        doc.Real(section, "heat_capacity" + suffix + "_j_kgk"),
                        doc.Real(section, "conductivity" + suffix + "_w_mk")};
  };
  ContactSolids solids;
  if (doc.HasSection("contact")) {
    solids.body1 = solid("contact", "_1");
    solids.body2 = solid("contact", "_2");
  } else if (doc.HasSection("gear")) {
    solids.body1 = solid("gear.pinion", "");
    solids.body2 = solid("gear.wheel", "");
  }
  return solids;
}

FilmCase ReadFilmCase(Document& doc) {
  FilmCase f;
  const std::string name = doc.String("lubricant", "name");
  const std::string path = ResolveLubricantPath(name, doc.path());
  if (!path.empty()) {
    try {
      f.lubricant = std::make_shared<const Lubricant>(Lubricant::FromFile(path));
    } catch (const InputError& e) {
      for (const auto& p : e.problems())
        doc.Problem("lubricant", "name",
                    "the lubricant file has a problem: " + p.file +
                        (p.line > 0 ? ":" + std::to_string(p.line) : std::string()) + ": " + p.key +
                        (p.value.empty() ? "" : " = " + p.value) + ": " + p.rule,
                    p.allowed);
    }
  }
  f.inlet_temperature_k = doc.Given("lubricant", "inlet_temperature_k")
                              ? doc.Real("lubricant", "inlet_temperature_k")
                              : (f.lubricant ? f.lubricant->reference_temperature_k() : 0.0);

  // The oil at the inlet temperature must stay within the viscosities the lubricant files
  // accept (eta0 <= 1e4 Pa s; Roelands' eta_inf = 6.31e-5 Pa s below): a law extrapolated
  // far beyond its reference temperature leaves that range.
  if (f.lubricant && doc.Given("lubricant", "inlet_temperature_k")) {
    const double eta = f.lubricant->viscosity().Evaluate(0.0, f.inlet_temperature_k).eta_pa_s;
    if (!(eta >= kMinInletViscosityPaS && eta <= kMaxInletViscosityPaS))
      doc.Problem("lubricant", "inlet_temperature_k",
                  "the lubricant's viscosity at this temperature is " + FormatShort(eta) +
                      " Pa s, outside the range of lubricant laws (" +
                      FormatShort(kMinInletViscosityPaS) + " ... " +
                      FormatShort(kMaxInletViscosityPaS) + " Pa s): the law is extrapolated " +
                      "too far from its reference temperature " +
                      FormatShort(f.lubricant->reference_temperature_k()) + " K",
                  "an inlet temperature nearer the lubricant's reference temperature");
  }

  f.effects.elastic = doc.Bool("effects", "elastic");
  f.effects.piezoviscous = doc.Bool("effects", "piezoviscous");
  f.effects.compressible = doc.Bool("effects", "compressible");
  f.effects.transient = doc.Bool("effects", "transient");
  f.effects.roughness = doc.Bool("effects", "roughness");
  f.effects.thermal = doc.Bool("effects", "thermal");
  f.effects.non_newtonian = doc.Bool("effects", "non_newtonian");
  f.effects.finite_peclet = doc.Bool("effects", "finite_peclet");
  if (f.effects.finite_peclet && !f.effects.thermal)
    doc.Problem("effects", "finite_peclet", "surface temperatures need the energy equation",
                "finite_peclet = false, or thermal = true");
  if (doc.Bool("effects", "dynamic_load") && !doc.HasSection("gear"))
    doc.Problem("effects", "dynamic_load", "the dynamic tooth load needs a [gear] pair",
                "dynamic_load = false for a [contact] case");
  if (f.effects.non_newtonian && f.lubricant && !f.lubricant->eyring())
    doc.Problem("effects", "non_newtonian",
                "the lubricant '" + name + "' has no [eyring] section (Eyring stress)",
                "non_newtonian = false, or a lubricant with [eyring] eyring_stress_pa");

  f.solids = ReadContactSolids(doc);

  f.grid_points = static_cast<int>(doc.Int("numerics", "grid_points"));
  f.x_start_b = doc.Real("numerics", "x_start_b");
  f.x_end_b = doc.Real("numerics", "x_end_b");
  auto& o = f.options;
  o.upwind_order = static_cast<int>(doc.Int("numerics", "upwind_order"));
  o.time_scheme = TimeSchemeFromString(doc.String("numerics", "time_scheme"));
  o.time_tolerance = doc.Real("numerics", "time_tolerance");
  // The estimate cannot resolve errors below the Newton solves' own (newton_tolerance, 1e-8
  // by default): a smaller tolerance only drives every substep to the smallest size.
  if (o.time_tolerance > 0 && o.time_tolerance < kMinTimeTolerance)
    doc.Problem("numerics", "time_tolerance",
                "a local time error below " + FormatShort(kMinTimeTolerance) +
                    " is below what the Newton solves resolve: every substep would take the "
                    "smallest size (1/4096 of the step)",
                "0 (no control) or " + FormatShort(kMinTimeTolerance) + " ... 1");
  o.linear_solver = LinearSolverKindFromString(doc.String("numerics", "linear_solver"));
  o.tolerance = doc.Real("numerics", "newton_tolerance");
  o.max_iterations = static_cast<int>(doc.Int("numerics", "max_newton_iterations"));
  o.film_nodes = static_cast<int>(doc.Int("numerics", "film_nodes"));
  const std::string failed_step = doc.String("numerics", "failed_step");
  f.steady_restart = failed_step != "stop";
  f.skip_failed = failed_step == "steady_restart_or_skip";

  if (f.effects.roughness) {
    f.surface1 = ReadSurface(doc, "surfaces.surface1");
    f.surface2 = ReadSurface(doc, "surfaces.surface2");
    // A surface whose data was reported (e.g. a profile file that cannot be read) is not
    // smooth: the roughness switch is not the problem then.
    auto rough = [&](const char* section) {
      return doc.HasSection(section) && doc.String(section, "roughness") != "smooth";
    };
    if (!f.surface1 && !f.surface2 && !rough("surfaces.surface1") && !rough("surfaces.surface2"))
      doc.Problem("effects", "roughness", "roughness is on but both surfaces are smooth",
                  "a [surfaces.surface1] or [surfaces.surface2] with roughness = \"sinusoidal\" "
                  "or \"profile\", or roughness = false");
  }
  return f;
}

ViscosityValue InletViscosity(const FilmCase& film) {
  ViscosityValue v = film.lubricant->viscosity().Evaluate(0.0, film.inlet_temperature_k);
  if (!film.effects.piezoviscous) v.deta_dp = 0.0;
  return v;
}

}  // namespace tehl::internal
