#include "tehl/scene/contact_scene.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>

#include "scene/case_reader.hpp"
#include "scene/contact_csv.hpp"
#include "scene/film_case.hpp"
#include "tehl/error.hpp"
#include "tehl/units.hpp"

namespace tehl {
namespace {
namespace fs = std::filesystem;
using internal::Document;

struct ContactInputs {
  double r1 = 0, r2 = 0;             // radii; r2 = 0 means a plane [m]
  double e_prime = 0;                // [Pa]
  std::vector<double> t, w, u1, u2;  // tables (size 1 for a steady run)
  int steps = 0;
  double ReducedRadius() const { return r2 > 0 ? r1 * r2 / (r1 + r2) : r1; }
};

double Interpolate(const std::vector<double>& t, const std::vector<double>& v, double x) {
  if (v.size() == 1 || x <= t.front()) return v.front();
  if (x >= t.back()) return v.back();
  const auto it = std::upper_bound(t.begin(), t.end(), x);
  const size_t k = static_cast<size_t>(it - t.begin()) - 1;
  const double f = (x - t[k]) / (t[k + 1] - t[k]);
  return (1 - f) * v[k] + f * v[k + 1];
}

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
  for (double wi : in.w)
    if (!(wi > 0)) {
      doc.Problem("contact", "load_table_n_per_m", "every load must be > 0", "loads > 0 [N/m]");
      break;
    }
  return in;
}

// Writes `text` to `path` through a temporary file renamed when complete.
void WriteAtomically(const fs::path& path, const std::string& text) {
  fs::create_directories(path.parent_path().empty() ? fs::path(".") : path.parent_path());
  const fs::path tmp = path.string() + ".tmp";
  {
    std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
    out << text;
    out.flush();
    if (!out) throw std::runtime_error("cannot write " + tmp.string());
  }
  fs::rename(tmp, path);
}

}  // namespace

bool ContactRunResult::converged() const {
  return std::all_of(steps.begin(), steps.end(),
                     [](const ContactStepRecord& r) { return r.summary.usable(); });
}

ContactRunResult RunContactCase(const std::string& case_path, const ContactRunOptions& ro) {
  Document doc = internal::ReadCaseDocument(case_path);
  if (!doc.HasSection("contact")) {
    doc.Problem("contact", "",
                "`tehl run` takes a [contact] case; gear cases are reported by "
                "`tehl gear` (the mesh-cycle film run is not part of this version)",
                "a case with a [contact] section");
  }
  doc.ThrowIfProblems();
  const ContactInputs in = ReadContact(doc);
  internal::FilmCase film = internal::ReadFilmCase(doc);
  doc.ThrowIfProblems();

  const double r = in.ReducedRadius();
  const double w_max = *std::max_element(in.w.begin(), in.w.end());
  const HertzScales hz = LineContactHertz(w_max, r, in.e_prime);
  const UniformGrid grid =
      UniformGrid::AroundHertz(hz.half_width_m, film.grid_points, film.x_start_b, film.x_end_b);
  LineContactSolver solver(grid, in.e_prime, *film.lubricant, film.effects, film.options,
                           film.surface1, film.surface2, film.solids);
  auto conditions = [&](double t) {
    return ContactConditions{r, Interpolate(in.t, in.u1, t), Interpolate(in.t, in.u2, t),
                             Interpolate(in.t, in.w, t), film.inlet_temperature_k};
  };
  ContactRunResult result;
  FilmState state;
  const bool thermal = film.effects.thermal;
  const int nz = film.options.film_nodes;
  using Clock = std::chrono::steady_clock;
  auto record = [&](double t, const ContactConditions& c, const LineContactSolver::Summary& s,
                    Clock::time_point start) {
    ContactStepRecord rec;
    rec.wall_time_s = std::chrono::duration<double>(Clock::now() - start).count();
    rec.time_s = t;
    rec.load_n_per_m = c.load_n_per_m;
    rec.u1_m_s = c.u1_m_s;
    rec.u2_m_s = c.u2_m_s;
    rec.h_min_m = state.MinFilm();
    rec.h_c_m = state.CentralFilm(grid);
    rec.p_max_pa = state.MaxPressure();
    // The same quantities as the mesh cycle's /cycle/T_max and /cycle/mu (mesh_cycle_scene.cpp).
    rec.friction_coefficient = solver.Friction(c, state).coefficient;
    rec.t_max_k = thermal && state.temperature.Matches(grid.size(), nz)
                      ? state.temperature.MaxTemperature()
                      : film.inlet_temperature_k;
    rec.summary = s;
    result.steps.push_back(rec);
    if (!ro.quiet)
      std::fprintf(stderr, "step %zu/%d  t = %.4g s  h_min = %.4g um  %s\n", result.steps.size(),
                   in.steps + 1, t, rec.h_min_m * 1e6, s.BriefReport().c_str());
  };
  const double t0 = in.t.front();
  ContactConditions c = conditions(t0);
  Clock::time_point start = Clock::now();
  record(t0, c, solver.SolveSteady(c, &state), start);
  if (in.steps > 0 && result.steps.back().summary.usable()) {
    solver.BeginTransient(c, state);
    const double dt = (in.t.back() - t0) / in.steps;
    for (int k = 1; k <= in.steps; ++k) {
      const double t = t0 + k * dt;
      c = conditions(t);
      start = Clock::now();
      record(t, c, solver.Step(c, dt, &state), start);
      if (!result.steps.back().summary.usable()) break;
    }
  }

  fs::path dir =
      ro.output_dir.empty() ? fs::path(doc.String("output", "directory")) : fs::path(ro.output_dir);
  std::string name = doc.String("output", "name");
  if (name.empty()) name = fs::path(case_path).stem().string();
  result.profile_csv = (dir / (name + "_profile.csv")).string();
  result.history_csv = (dir / (name + "_steps.csv")).string();
  // Both texts are formatted (and every number checked) before either file is written.
  std::vector<double> t_mid;  // mid-film temperature, as the mesh cycle's /profiles/T_mid
  if (thermal && state.temperature.Matches(grid.size(), nz)) {
    const Eigen::MatrixXd& tk = state.temperature.t_k;
    const Eigen::VectorXd mid = 0.5 * (tk.col((nz - 1) / 2) + tk.col(nz / 2));
    t_mid.assign(mid.data(), mid.data() + mid.size());
  }
  const std::string profile = internal::ContactProfileCsv(
      result.profile_csv, grid.Nodes(),
      std::vector<double>(state.p_pa.data(), state.p_pa.data() + state.p_pa.size()),
      std::vector<double>(state.h_m.data(), state.h_m.data() + state.h_m.size()), t_mid);
  const std::string history = internal::ContactStepsCsv(result.history_csv, result.steps);
  // The steps file marks a finished run (a study's result file): it is written last.
  WriteAtomically(result.profile_csv, profile);
  WriteAtomically(result.history_csv, history);
  return result;
}

}  // namespace tehl
