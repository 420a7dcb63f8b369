// The mesh cycle of a gear case (mesh_cycle_scene.hpp): the step positions along the path, and
// the run itself, from the case file to the result files, resumed from a checkpoint on request.
#include "tehl/scene/mesh_cycle_scene.hpp"

#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <filesystem>

#include "scene/automatic_grid.hpp"
#include "scene/case_inputs.hpp"
#include "scene/case_reader.hpp"
#include "scene/dynamic_load.hpp"
#include "scene/film_case.hpp"
#include "scene/gear_case.hpp"
#include "scene/mesh_cycle_checkpoint.hpp"
#include "scene/mesh_cycle_output.hpp"
#include "scene/mesh_cycle_plan.hpp"
#include "scene/step_restart.hpp"
#include "tehl/error.hpp"
#include "tehl/gear/load_sharing.hpp"
#include "tehl/gear/path_of_contact.hpp"
#include "tehl/units.hpp"

namespace tehl {
namespace {
namespace fs = std::filesystem;
using internal::Document;
using Clock = std::chrono::steady_clock;
using internal::CyclePath;
using internal::PathState;
using internal::SegmentEnds;

std::string Zone(const MeshCycleResult& r, double s) {
  if (r.s_b_m < r.s_d_m) return s <= r.s_b_m ? "A-B" : (s <= r.s_d_m ? "B-D" : "D-E");
  return s <= r.s_d_m ? "A-D" : (s <= r.s_b_m ? "D-B" : "B-E");  // eps_alpha >= 2
}

}  // namespace

std::vector<double> MeshCycleStepPositions(double g,
                                           double sb,
                                           double sd,
                                           int steps,
                                           const std::vector<int>& min_per_segment,
                                           double begin,
                                           double end) {
  if (end < 0) end = g;
  const std::vector<double> ends = SegmentEnds(g, sb, sd, begin, end);
  const size_t m = ends.size();
  std::vector<double> len(m);
  for (size_t i = 0; i < m; ++i) len[i] = ends[i] - (i ? ends[i - 1] : begin);
  // Largest-remainder apportionment of `steps` by length, then the minimum per segment.
  std::vector<int> n(m);
  std::vector<std::pair<double, size_t>> rest;
  int used = 0;
  for (size_t i = 0; i < m; ++i) {
    const double exact = steps * len[i] / (end - begin);
    n[i] = static_cast<int>(std::floor(exact));
    used += n[i];
    rest.push_back({exact - n[i], i});
  }
  std::sort(rest.rbegin(), rest.rend());
  for (size_t j = 0; used < steps && j < rest.size(); ++j, ++used) ++n[rest[j].second];
  for (size_t i = 0; i < m; ++i) {
    const int floor_i = i < min_per_segment.size() ? min_per_segment[i] : 1;
    n[i] = std::max({n[i], floor_i, 1});
  }
  std::vector<double> s = {begin};
  for (size_t i = 0; i < m; ++i) {
    const double a = i ? ends[i - 1] : begin;
    for (int k = 1; k <= n[i]; ++k) s.push_back(k == n[i] ? ends[i] : a + len[i] * k / n[i]);
  }
  return s;
}

int AutomaticMeshCycleSteps(double transits) {
  const double n = std::ceil(4.0 * transits);
  return static_cast<int>(std::clamp(n, 100.0, 200.0));
}

MeshCycleResult RunMeshCycle(const std::string& case_path, const MeshCycleRunOptions& ro) {
  const auto t_start = Clock::now();
  Document doc = internal::ReadCaseDocument(case_path);
  if (doc.problems().empty() && !doc.HasSection("gear"))
    doc.Problem("gear", "", "a mesh cycle needs a [gear] pair", "a case with [gear]");
  doc.ThrowIfProblems();
  std::optional<internal::GearCase> gear = internal::ReadGearCase(doc);
  internal::FilmCase film = internal::ReadFilmCase(doc);
  doc.ThrowIfProblems();
  if (!gear || !gear->pair) {  // ReadGearCase has reported why
    doc.Problem("gear", "", "the gear pair could not be built", "a valid gear pair");
    doc.ThrowIfProblems();
  }
  const CyclePath cycle(*gear);
  const PathOfContact& path = cycle.path();
  const double e_prime = gear->ReducedModulusPa();

  MeshCycleResult r;
  r.length_m = path.length_m();
  r.begin_m = cycle.begin_m();
  r.end_m = cycle.end_m();
  r.s_b_m = path.s_b_m();
  r.s_c_m = path.s_c_m();
  r.s_d_m = path.s_d_m();
  const PathState pitch = cycle.At(r.s_c_m, true);
  r.r0_m = pitch.contact.reduced_radius_m;
  r.u0_m_s = pitch.contact.um_m_s;
  r.w0_n_per_m = pitch.load_n_per_m;

  const internal::MeshCyclePlan plan = internal::PlanMeshCycle(doc, cycle, e_prime, film);
  doc.ThrowIfProblems();
  r.max_half_width_m = plan.max_half_width_m;
  const UniformGrid& grid = plan.grid;
  const std::vector<double>& s_steps = plan.s_steps;
  r.planned_steps = static_cast<int>(s_steps.size()) - 1;
  r.step_rule = plan.step_rule;
  r.grid_rule = plan.grid_rule;
  r.input_notes = plan.input_notes;
  if (!ro.quiet && film.grid_points == 0 && grid.size() > internal::kAutomaticGridMinNodes)
    std::fprintf(stderr, "grid %d nodes (%s)\n", grid.size(), plan.grid_rule.c_str());

  // The result file is open (under its temporary name) for the whole run.
  std::unique_ptr<Hdf5Writer> h5;
  std::string csv_path, checkpoint_path;
  if (ro.write_files) {
    const fs::path dir = ro.output_dir.empty() ? fs::path(doc.String("output", "directory"))
                                               : fs::path(ro.output_dir);
    std::string name = doc.String("output", "name");
    if (name.empty()) name = fs::path(case_path).stem().string();
    const std::string final_path = (dir / (name + ".h5")).string();
    if (ro.resume && fs::exists(final_path)) {  // complete results are never rewritten
      r.hdf5_path = final_path;
      r.already_complete = true;
      return r;
    }
    h5 = internal::BeginMeshCycleHdf5(final_path, doc, case_path);
    csv_path = (dir / (name + "_cycle.csv")).string();
    checkpoint_path = (dir / (name + ".checkpoint")).string();
  }

  LineContactSolver solver(grid, e_prime, *film.lubricant, film.effects, film.options,
                           film.surface1, film.surface2, film.solids);
  r.x_m = grid.Nodes();
  r.e_prime_pa = e_prime;
  r.x_start_b = film.x_start_b;
  r.elastic = film.effects.elastic;
  r.solids = film.solids;
  r.inlet_temperature_k = film.inlet_temperature_k;
  const ViscosityValue inlet = internal::InletViscosity(film);
  r.inlet_viscosity_pa_s = inlet.eta_pa_s;
  r.pressure_viscosity_per_pa = film.effects.piezoviscous ? inlet.deta_dp / inlet.eta_pa_s : 0.0;
  r.thermal = film.effects.thermal;
  r.time_tolerance = film.options.time_tolerance;
  r.non_newtonian = film.effects.non_newtonian;
  r.finite_peclet = film.effects.finite_peclet;
  r.film_nodes = film.options.film_nodes;
  const bool keep_field = r.thermal && doc.Bool("output", "temperature_field");
  FilmState state;
  const auto t_solve = Clock::now();
  const bool tty = isatty(STDERR_FILENO);
  auto conditions = [&](const PathState& st) {
    return ContactConditions{st.contact.reduced_radius_m, st.contact.u1_m_s, st.contact.u2_m_s,
                             st.load_n_per_m, film.inlet_temperature_k};
  };
  auto record = [&](const PathState& st, const LineContactSolver::Summary& sum,
                    std::string restart_reason = {}) {
    MeshCycleStep k;
    k.restart_reason = std::move(restart_reason);
    const ContactPoint& c = st.contact;
    k.s_m = c.s_m;
    k.time_s = c.time_s;
    k.reduced_radius_m = c.reduced_radius_m;
    k.u1_m_s = c.u1_m_s;
    k.u2_m_s = c.u2_m_s;
    k.um_m_s = c.um_m_s;
    k.srr = c.srr;
    k.load_n_per_m = st.load_n_per_m;
    k.static_load_n_per_m = st.static_load_n_per_m;
    k.pairs_in_contact = c.pairs_in_contact;
    k.h_min_m = state.MinFilm();
    k.h_c_m = state.CentralFilm(grid);
    k.p_max_pa = state.MaxPressure();
    // A failed step's film may touch (h <= 0), where friction is undefined: 0 then, and the
    // step's termination (and the CSV's converged = 0) says it failed.
    const double mu = solver.Friction(conditions(st), state).coefficient;
    k.friction_coefficient = std::isfinite(mu) ? mu : 0.0;
    k.t_max_k = k.t_mid_max_k = k.t1_max_k = k.t2_max_k = film.inlet_temperature_k;
    if (r.thermal && state.temperature.Matches(grid.size(), r.film_nodes)) {
      const FilmTemperature& t = state.temperature;
      const int nz = r.film_nodes;
      const Eigen::VectorXd mid = 0.5 * (t.t_k.col((nz - 1) / 2) + t.t_k.col(nz / 2));
      k.t_max_k = t.MaxTemperature();
      k.t_mid_max_k = mid.maxCoeff();
      k.t1_max_k = t.t1_k.maxCoeff();
      k.t2_max_k = t.t2_k.maxCoeff();
      r.t_mid_k.emplace_back(mid.data(), mid.data() + mid.size());
      r.t1_k.emplace_back(t.t1_k.data(), t.t1_k.data() + t.t1_k.size());
      r.t2_k.emplace_back(t.t2_k.data(), t.t2_k.data() + t.t2_k.size());
      if (keep_field) {
        // Row-major (x, z) per step.
        std::vector<double> field(static_cast<size_t>(grid.size()) * nz);
        for (int i = 0; i < grid.size(); ++i)
          for (int j = 0; j < nz; ++j) field[static_cast<size_t>(i) * nz + j] = t.t_k(i, j);
        r.t_field_k.push_back(std::move(field));
      }
    }
    k.c_rt = k.reduced_radius_m / r.r0_m;
    k.c_ut = k.um_m_s / r.u0_m_s;
    k.c_wt = k.load_n_per_m / r.w0_n_per_m;
    k.zone = Zone(r, k.s_m);
    k.summary = sum;
    r.p_pa.emplace_back(state.p_pa.data(), state.p_pa.data() + state.p_pa.size());
    r.h_m.emplace_back(state.h_m.data(), state.h_m.data() + state.h_m.size());
    r.steps.push_back(std::move(k));
    if (ro.quiet) return;
    const int done = static_cast<int>(r.steps.size()) - 1;
    const double elapsed = std::chrono::duration<double>(Clock::now() - t_solve).count();
    const double left = done > 0 ? elapsed / (done + 1) * (r.planned_steps - done) : 0.0;
    const MeshCycleStep& b = r.steps.back();
    std::fprintf(stderr, "%sstep %d/%d  s = %6.3f mm (%s)  h_min = %.4f um  %s  ~%.0f s left%s",
                 tty ? "\r" : "", done, r.planned_steps, b.s_m * 1e3, b.zone.c_str(),
                 b.h_min_m * 1e6,
                 b.restarted()  ? "steady restart"
                 : sum.usable() ? "ok"
                                : ToString(sum.termination).c_str(),
                 left, tty ? "   " : "\n");
  };

  // Resume from a checkpoint of the same case (docs/results.md, "Checkpoints and --resume").
  // The case as run, and the lubricant and profile files it read: a checkpoint of the same
  // case with an edited oil is another run.
  const std::uint64_t fingerprint =
      internal::CaseFingerprint(doc.ToToml() + internal::ReferencedInputsText(doc));
  size_t first = 1;
  double elapsed_before = 0;
  std::optional<internal::CheckpointWriter> checkpoints;
  bool checkpoints_off = false;  // a checkpoint could not be written
  if (!checkpoint_path.empty()) checkpoints.emplace(checkpoint_path);
  if (ro.resume && !checkpoint_path.empty()) {
    const internal::ResumePoint at =
        internal::ResumeFromCheckpoint(checkpoint_path, fingerprint, s_steps.size(), grid.size(),
                                       ro.quiet, &*checkpoints, &r, &state, &solver);
    first = at.first_step;
    elapsed_before = at.elapsed_s;
    r.resumed_from_step = at.resumed_from_step;
  }
  auto elapsed = [&] {
    return elapsed_before + std::chrono::duration<double>(Clock::now() - t_start).count();
  };
  PathState st = cycle.At(s_steps[first - 1], true);
  ContactConditions c = conditions(st);
  if (first == 1) {  // the steady film where the cycle starts: A, or A' with tip relief
    st = cycle.At(s_steps[0], false);
    c = conditions(st);
    record(st, solver.SolveSteady(c, &state));
    if (r.steps.back().summary.usable()) solver.BeginTransient(c, state);
  }
  if (r.steps.back().summary.usable()) {
    size_t skipped = 0;  // failed steps in a row left behind (failed_step = "..._or_skip")
    for (size_t k = first; k < s_steps.size(); ++k) {
      st = cycle.At(s_steps[k], true);
      c = conditions(st);
      // From the last converged level, across the skipped steps.
      const double dt = (s_steps[k] - s_steps[k - 1 - skipped]) / path.contact_speed_m_s();
      // Substeps go from the conditions just after the last level: where the load jumps
      // there (B, D), the new load holds over the whole step.
      const ContactConditions c_start = conditions(cycle.At(s_steps[k - 1 - skipped], false));
      internal::MarchedStep m = internal::StepOrRestart(solver, c, dt, &state, film.steady_restart,
                                                        film.skip_failed, &c_start);
      record(st, m.summary, std::move(m.restart_reason));
      if (m.skipped && ++skipped < internal::kMaxSkippedInARow && k + 1 < s_steps.size()) {
        internal::ResumeAfterSkip(solver, &m, &state);
        continue;
      }
      if (!r.steps.back().summary.usable()) break;
      skipped = 0;
      if (checkpoints && !checkpoints_off && ro.checkpoint_every > 0 &&
          k % ro.checkpoint_every == 0 && k + 1 < s_steps.size()) {
        // A checkpoint is a convenience: one that cannot be written (a full disk, a path
        // taken by a folder) is reported once and the run goes on without checkpoints.
        try {
          checkpoints->Write(fingerprint, static_cast<int>(k + 1), elapsed(), r, state,
                             solver.SaveTransient());
        } catch (const std::exception& e) {
          checkpoints_off = true;
          std::fprintf(stderr, "%swarning: %s; the run goes on without checkpoints\n",
                       !ro.quiet && tty ? "\n" : "", e.what());
          continue;
        }
        if (ro.after_checkpoint) ro.after_checkpoint(static_cast<int>(k + 1));
      }
    }
  }
  if (!ro.quiet && tty) std::fprintf(stderr, "\n");
  r.wall_time_s = elapsed();

  if (h5) {
    // The CSV first: a complete NAME.h5 marks a finished run (--resume leaves it as it is),
    // so it is committed last, and the checkpoint is spent only then.
    if (doc.Bool("output", "csv")) {
      r.csv_path = csv_path;
      internal::WriteMeshCycleCsv(r.csv_path, r);
    }
    internal::FinishMeshCycleHdf5(*h5, r, doc.Bool("output", "profiles"));
    r.hdf5_path = h5->final_path();
    checkpoints->Remove();
  }
  return r;
}

}  // namespace tehl
