#include "tehl/scene/contact_scene.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>

#include "io/atomic_file.hpp"
#include "scene/automatic_grid.hpp"
#include "scene/case_reader.hpp"
#include "scene/contact_case.hpp"
#include "scene/contact_csv.hpp"
#include "scene/film_case.hpp"
#include "scene/step_restart.hpp"
#include "tehl/ehl/flash_temperature.hpp"
#include "tehl/error.hpp"
#include "tehl/units.hpp"

namespace tehl {
namespace {
namespace fs = std::filesystem;
using internal::ContactInputs;
using internal::Document;
using internal::ReadContact;

double Interpolate(const std::vector<double>& t, const std::vector<double>& v, double x) {
  if (v.size() == 1 || x <= t.front()) return v.front();
  if (x >= t.back()) return v.back();
  const auto it = std::upper_bound(t.begin(), t.end(), x);
  const size_t k = static_cast<size_t>(it - t.begin()) - 1;
  const double f = (x - t[k]) / (t[k + 1] - t[k]);
  return (1 - f) * v[k] + f * v[k + 1];
}

}  // namespace

bool ContactRunResult::converged() const {
  return std::all_of(steps.begin(), steps.end(),
                     [](const ContactStepRecord& r) { return r.summary.usable(); });
}

int ContactRunResult::Restarts() const {
  return static_cast<int>(std::count_if(steps.begin(), steps.end(),
                                        [](const ContactStepRecord& r) { return r.restarted(); }));
}

ContactRunResult RunContactCase(const std::string& case_path, const ContactRunOptions& ro) {
  Document doc = internal::ReadCaseDocument(case_path);
  // ReadCaseDocument has reported a file without [gear] or [contact] (or one it cannot read).
  if (doc.problems().empty() && !doc.HasSection("contact"))
    doc.Problem("contact", "", "this is a gear case: `tehl run` runs its mesh cycle",
                "a case with a [contact] section");
  doc.ThrowIfProblems();
  const ContactInputs in = ReadContact(doc);
  internal::FilmCase film = internal::ReadFilmCase(doc);
  if (doc.problems().empty()) internal::CheckFilmScale(doc, in, film);
  doc.ThrowIfProblems();

  const double r = in.ReducedRadius();
  const internal::ContactGridPlan plan = internal::PlanContactGrid(doc, in, film);
  const UniformGrid& grid = plan.grid;
  doc.ThrowIfProblems();
  if (!ro.quiet && film.grid_points == 0 && grid.size() > internal::kAutomaticGridMinNodes)
    std::fprintf(stderr, "grid %d nodes (%s)\n", grid.size(), plan.rule.c_str());
  LineContactSolver solver(grid, in.e_prime, *film.lubricant, film.effects, film.options,
                           film.surface1, film.surface2, film.solids);
  auto conditions = [&](double t) {
    return ContactConditions{r, Interpolate(in.t, in.u1, t), Interpolate(in.t, in.u2, t),
                             Interpolate(in.t, in.w, t), film.inlet_temperature_k};
  };
  ContactRunResult result;
  result.x_start_b = film.x_start_b;
  result.x_start_m = grid.x_start_m();
  result.x_end_m = grid.x_end_m();
  result.grid_points = grid.size();
  result.grid_rule = plan.rule;
  result.input_notes = plan.input_notes;
  result.inlet_temperature_k = film.inlet_temperature_k;
  result.finite_peclet = film.effects.finite_peclet;
  result.thermal = film.effects.thermal;
  result.time_tolerance = film.options.time_tolerance;
  result.non_newtonian = film.effects.non_newtonian;
  result.solids = film.solids;
  FilmState state;
  const bool thermal = film.effects.thermal;
  const int nz = film.options.film_nodes;
  using Clock = std::chrono::steady_clock;
  const ViscosityValue inlet_law = internal::InletViscosity(film);
  auto record = [&](double t, const ContactConditions& c, const LineContactSolver::Summary& s,
                    Clock::time_point start, std::string restart_reason = {}) {
    ContactStepRecord rec;
    rec.restart_reason = std::move(restart_reason);
    rec.wall_time_s = std::chrono::duration<double>(Clock::now() - start).count();
    rec.time_s = t;
    rec.load_n_per_m = c.load_n_per_m;
    rec.u1_m_s = c.u1_m_s;
    rec.u2_m_s = c.u2_m_s;
    rec.h_min_m = state.MinFilm();
    rec.h_c_m = state.CentralFilm(grid);
    rec.p_max_pa = state.MaxPressure();
    rec.outlet_spike = FindOutletSpike(state.p_pa, grid.x_start_m(), grid.dx_m());
    InletTruncationInputs inlet;
    inlet.x_start_m = grid.x_start_m();
    inlet.dx_m = grid.dx_m();
    inlet.reduced_radius_m = r;
    inlet.half_width_m =
        film.effects.elastic ? LineContactHertz(c.load_n_per_m, r, in.e_prime).half_width_m : 0.0;
    inlet.um_m_s = c.um();
    inlet.inlet_viscosity_pa_s = inlet_law.eta_pa_s;
    inlet.pressure_viscosity_per_pa =
        film.effects.piezoviscous ? inlet_law.deta_dp / inlet_law.eta_pa_s : 0.0;
    inlet.load_n_per_m = c.load_n_per_m;
    rec.inlet = EstimateInletTruncation(state.p_pa, state.h_m, inlet);
    rec.hertz_edge = EstimateHertzEdge(r, inlet.half_width_m, rec.h_c_m, grid.dx_m());
    // The same quantities as the mesh cycle's /cycle/T_max and /cycle/mu (mesh_cycle_scene.cpp).
    // A failed step's film may touch (h <= 0), where friction is undefined: 0 then, and the
    // step's status column says it failed.
    const double mu = solver.Friction(c, state).coefficient;
    rec.friction_coefficient = std::isfinite(mu) ? mu : 0.0;
    const bool heated = thermal && state.temperature.Matches(grid.size(), nz);
    rec.t_max_k = heated ? state.temperature.MaxTemperature() : film.inlet_temperature_k;
    rec.t1_max_k = heated ? state.temperature.t1_k.maxCoeff() : film.inlet_temperature_k;
    rec.t2_max_k = heated ? state.temperature.t2_k.maxCoeff() : film.inlet_temperature_k;
    // Each surface's own speed through the contact, whichever way it moves.
    const double v1 = std::abs(c.u1_m_s), v2 = std::abs(c.u2_m_s);
    rec.half_width_m = inlet.half_width_m;
    rec.flash_rise_blok_k =
        !film.effects.elastic ? -1.0
        : v1 + v2 > 0 && c.load_n_per_m > 0
            ? FlashTemperature(
                  {rec.friction_coefficient, c.load_n_per_m, v1, v2, inlet.half_width_m},
                  film.solids.body1, film.solids.body2, film.effects.finite_peclet)
            : 0.0;
    rec.summary = s;
    result.steps.push_back(rec);
    if (!ro.quiet)
      std::fprintf(stderr, "step %zu/%d  t = %.4g s  h_min = %.4g um  %s%s\n", result.steps.size(),
                   in.steps + 1, t, rec.h_min_m * 1e6,
                   rec.restarted() ? "steady restart of a failed step: " : "",
                   s.BriefReport().c_str());
  };
  const double t0 = in.t.front();
  ContactConditions c = conditions(t0);
  Clock::time_point start = Clock::now();
  record(t0, c, solver.SolveSteady(c, &state), start);
  if (in.steps > 0 && result.steps.back().summary.usable()) {
    solver.BeginTransient(c, state);
    const double dt = (in.t.back() - t0) / in.steps;
    int skipped = 0;  // failed steps in a row left behind (failed_step = "..._or_skip")
    for (int k = 1; k <= in.steps; ++k) {
      const double t = t0 + k * dt;
      c = conditions(t);
      start = Clock::now();
      // From the last converged level, across the skipped steps.
      internal::MarchedStep m = internal::StepOrRestart(solver, c, (1 + skipped) * dt, &state,
                                                        film.steady_restart, film.skip_failed);
      record(t, c, m.summary, start, std::move(m.restart_reason));
      if (m.skipped && ++skipped < internal::kMaxSkippedInARow && k < in.steps) {
        internal::ResumeAfterSkip(solver, &m, &state);
        continue;
      }
      if (!result.steps.back().summary.usable()) break;
      skipped = 0;
    }
  }

  fs::path dir =
      ro.output_dir.empty() ? fs::path(doc.String("output", "directory")) : fs::path(ro.output_dir);
  std::string name = doc.String("output", "name");
  if (name.empty()) name = fs::path(case_path).stem().string();
  const bool profiles = doc.Bool("output", "profiles");
  result.profile_csv = profiles ? (dir / (name + "_profile.csv")).string() : std::string();
  result.history_csv = (dir / (name + "_steps.csv")).string();
  // Both texts are formatted (and every number checked) before either file is written.
  // Mid-film and surface temperatures, as the mesh cycle's /profiles/T_mid, T1, T2.
  std::vector<double> t_mid, t1, t2;
  if (thermal && state.temperature.Matches(grid.size(), nz)) {
    const FilmTemperature& t = state.temperature;
    const Eigen::VectorXd mid = 0.5 * (t.t_k.col((nz - 1) / 2) + t.t_k.col(nz / 2));
    t_mid.assign(mid.data(), mid.data() + mid.size());
    t1.assign(t.t1_k.data(), t.t1_k.data() + t.t1_k.size());
    t2.assign(t.t2_k.data(), t.t2_k.data() + t.t2_k.size());
  }
  const std::string profile =
      !profiles ? std::string()
                : internal::ContactProfileCsv(
                      result.profile_csv, grid.Nodes(),
                      std::vector<double>(state.p_pa.data(), state.p_pa.data() + state.p_pa.size()),
                      std::vector<double>(state.h_m.data(), state.h_m.data() + state.h_m.size()),
                      t_mid, t1, t2);
  const std::string history = internal::ContactStepsCsv(result.history_csv, result.steps);
  // The steps file marks a finished run (a study's result file): it is written last.
  if (profiles) internal::WriteTextAtomically(result.profile_csv, profile);
  internal::WriteTextAtomically(result.history_csv, history);
  return result;
}

}  // namespace tehl
