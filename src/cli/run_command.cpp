// tehl run CASE: runs a case. A [gear] case runs the mesh cycle from A to E (HDF5 result and
// CSV of the cycle table); a [contact] case runs the plain line contact (CSV files).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include "cli/commands.hpp"
#include "scene/case_reader.hpp"
#include "tehl/ehl/inlet_truncation.hpp"
#include "tehl/ehl/outlet_spike.hpp"
#include "tehl/ehl/surface_temperature.hpp"
#include "tehl/scene/contact_scene.hpp"
#include "tehl/scene/mesh_cycle_scene.hpp"
#include "tehl/units.hpp"

namespace tehl::cli {
namespace {

// The outlet spike's height converges only once the grid resolves it (docs/accuracy.md,
// include/tehl/ehl/outlet_spike.hpp): say so when it spans fewer than kSpikeResolvedCells.
constexpr const char* kSpikeAdvice =
    "p_max (and a temperature peak on the spike) is not grid-converged: more "
    "[numerics] grid_points resolve it (docs/results.md)";

void NoteContactSpike(const OutletSpike& spike) {
  if (spike.resolved()) return;
  std::printf(
      "note: the outlet pressure spike (%.4g GPa at x = %.4g mm) spans %.1f cells at half its "
      "height above the dip before it, fewer than %.0f: %s\n",
      spike.pressure_pa * 1e-9, spike.x_m * 1e3, spike.width_cells, kSpikeResolvedCells,
      kSpikeAdvice);
}

// Whether step k of a run converged: the notes and figures below are over those steps only (a
// run stops at a failed step, or leaves it behind with failed_step = "steady_restart_or_skip").
template <typename Run>
bool Usable(const Run& r, size_t k) {
  return r.steps[k].summary.usable();
}

template <typename Run>
size_t UsableSteps(const Run& r) {
  size_t n = 0;
  for (size_t k = 0; k < r.steps.size(); ++k) n += Usable(r, k);
  return n;
}

// Blok's flash temperature along the converged steps, and in thermal runs the film's own
// hottest surfaces beside it (docs/thermal.md "Flash temperature").
void PrintCycleFlash(const MeshCycleResult& r) {
  if (UsableSteps(r) == 0 || !r.elastic) return;
  const std::vector<double> flash = r.BlokFlashRises();
  size_t at = 0;
  for (size_t k = 1; k < r.steps.size(); ++k)
    if (Usable(r, k) && flash[k] > flash[at]) at = k;
  std::printf("flash temperature (Blok%s, with each step's mu): max rise %.3g K at s = %.4g mm",
              r.finite_peclet ? ", finite Peclet" : "", flash[at], r.steps[at].s_m * 1e3);
  if (r.thermal) {
    double t1 = 0, t2 = 0;
    const double t0 = r.inlet_temperature_k;
    for (size_t k = 0; k < r.steps.size(); ++k) {
      if (!Usable(r, k)) continue;
      t1 = std::max(t1, r.steps[k].t1_max_k - t0);
      t2 = std::max(t2, r.steps[k].t2_max_k - t0);
    }
    std::printf("; the film's surfaces: max rise %.3g K (pinion), %.3g K (wheel)", t1, t2);
  }
  std::printf("\n");
}

// The surface temperatures (seed 004 eqs. 14-15) and Blok's estimate use the high-speed
// moving heat source, 1-D conduction into the depth, which needs a Peclet number
// Pe = u b / (2 kappa) of about 5 or more (K.L. Johnson, Contact Mechanics, 1985, section
// 13.3). Notes the smallest Pe of either solid along a thermal cycle when it is below that.
constexpr double kHighPeclet = 5.0;

// The smallest Peclet number u b / (2 kappa) of either solid over (b, u1, u2) samples, and
// where: the sample index and the body (0, 1). Samples with b or a speed <= 0 are skipped.
struct LowestPeclet {
  double pe = std::numeric_limits<double>::infinity();
  size_t at = 0;
  int body = 0;
  bool Low() const { return pe < kHighPeclet; }
};

void ConsiderPeclet(
    const ContactSolids& solids, double b, double u1, double u2, size_t k, LowestPeclet* lowest) {
  if (!(b > 0)) return;
  const SolidThermal* solid[] = {&solids.body1, &solids.body2};
  const double speed[] = {std::abs(u1), std::abs(u2)};
  for (int i = 0; i < 2; ++i) {
    if (!(speed[i] > 0)) continue;
    const double pe = MovingHeatSource::DecayRate(*solid[i], speed[i]) * b;
    if (pe < lowest->pe) *lowest = {pe, k, i};
  }
}

constexpr const char* kPecletAdvice =
    "there the surface temperatures, which neglect conduction along the surface (the "
    "high-speed moving heat source of seed 004 eqs. 14-15, and Blok's estimate), overstate the "
    "rise; [effects] finite_peclet = true includes it (docs/thermal.md \"Surface temperatures "
    "at any Peclet number\")";

void NoteCyclePeclet(const MeshCycleResult& r) {
  // With effects.finite_peclet the surfaces and the flash temperature conduct along x.
  if (!r.thermal || !r.elastic || r.finite_peclet) return;
  LowestPeclet lowest;
  for (size_t k = 0; k < r.steps.size(); ++k) {
    const MeshCycleStep& st = r.steps[k];
    if (!Usable(r, k) || !(st.load_n_per_m > 0)) continue;
    const double b =
        LineContactHertz(st.load_n_per_m, st.reduced_radius_m, r.e_prime_pa).half_width_m;
    ConsiderPeclet(r.solids, b, st.u1_m_s, st.u2_m_s, k, &lowest);
  }
  if (!lowest.Low()) return;
  std::printf(
      "note: the Peclet number u b / (2 kappa) of the %s falls to %.3g (at s = %.4g mm), below "
      "about %.0f: %s\n",
      lowest.body == 0 ? "pinion" : "wheel", lowest.pe, r.steps[lowest.at].s_m * 1e3, kHighPeclet,
      kPecletAdvice);
}

// The same for a [contact] run, over its converged levels.
void NoteContactPeclet(const ContactRunResult& r) {
  if (!r.thermal || r.finite_peclet) return;
  LowestPeclet lowest;
  for (size_t k = 0; k < r.steps.size(); ++k)
    if (r.steps[k].summary.usable())
      ConsiderPeclet(r.solids, r.steps[k].half_width_m, r.steps[k].u1_m_s, r.steps[k].u2_m_s, k,
                     &lowest);
  if (!lowest.Low()) return;
  std::printf(
      "note: the Peclet number u b / (2 kappa) of body %d falls to %.3g (at t = %.4g s), below "
      "about %.0f: %s\n",
      lowest.body + 1, lowest.pe, r.steps[lowest.at].time_s, kHighPeclet, kPecletAdvice);
}

// Steps whose transient solve failed and whose film is the steady one at their time
// ([numerics] failed_step = "steady_restart"): where they are, and why the first one failed.
// `where(k, step)` names step k ("step 70 (s = 4.913 mm)").
template <typename Step, typename Where>
void NoteRestarts(const std::vector<Step>& steps, Where where) {
  constexpr size_t kListed = 8;
  size_t count = 0;
  std::string list, first;
  for (size_t k = 0; k < steps.size(); ++k) {
    if (!steps[k].restarted()) continue;
    if (count == 0) first = steps[k].restart_reason;
    if (count < kListed) list += (count ? ", " : "") + where(k, steps[k]);
    ++count;
  }
  if (count == 0) return;
  if (count > kListed) list += ", ...";
  std::printf(
      "note: %zu of %zu time steps did not converge; each such film is the steady one at its "
      "time, and the run marched on from it ([numerics] failed_step; \"stop\" ends the run "
      "there instead): %s. The first failure: %s\n",
      count, steps.size() - 1, list.c_str(), first.c_str());
}

std::string Where(const char* format, size_t k, double value) {
  char buf[96];
  std::snprintf(buf, sizeof buf, format, k, value);
  return buf;
}

// On stderr: the steps that did not converge (the one where the run stopped, and those left
// behind with failed_step = "steady_restart_or_skip") and why the first one failed.
template <typename Step, typename Where>
void ReportFailedSteps(const std::vector<Step>& steps, Where where) {
  constexpr size_t kListed = 8;
  std::vector<size_t> failed;
  for (size_t k = 0; k < steps.size(); ++k)
    if (!steps[k].summary.usable()) failed.push_back(k);
  if (failed.empty()) {  // not expected: a run ends early only at a failed step
    std::fprintf(stderr, "tehl run: the run did not reach its last step\n");
    return;
  }
  const Step& first = steps[failed.front()];
  if (failed.size() == 1) {
    std::fprintf(stderr, "tehl run: %s did not converge: %s\n",
                 where(failed.front(), first).c_str(), first.summary.message.c_str());
    return;
  }
  std::string list;
  for (size_t i = 0; i < failed.size() && i < kListed; ++i)
    list += (i ? ", " : "") + where(failed[i], steps[failed[i]]);
  if (failed.size() > kListed) list += ", ...";
  std::fprintf(stderr, "tehl run: %zu steps did not converge (%s); the first: %s\n", failed.size(),
               list.c_str(), first.summary.message.c_str());
}

void NoteCycleSpikes(const MeshCycleResult& r) {
  const std::vector<OutletSpike> spikes = r.OutletSpikes();
  int narrow = 0;
  OutletSpike narrowest;
  size_t at = 0;
  for (size_t k = 0; k < r.steps.size() && k < spikes.size(); ++k) {
    if (!Usable(r, k) || spikes[k].resolved()) continue;
    ++narrow;
    if (narrow == 1 || spikes[k].width_cells < narrowest.width_cells) {
      narrowest = spikes[k];
      at = k;
    }
  }
  if (narrow == 0) return;
  std::printf(
      "note: in %d of the %zu films along the path (A and the steps) the outlet pressure spike "
      "spans fewer than %.0f cells at half its height (narrowest %.1f cells, %.4g GPa, at s = %.4g "
      "mm): %s\n",
      narrow, UsableSteps(r), kSpikeResolvedCells, narrowest.width_cells,
      narrowest.pressure_pa * 1e-9, r.steps[at].s_m * 1e3, kSpikeAdvice);
}

// The inlet note: a film thinned by more than kInletNoteDeficit by the truncated inlet
// (EstimateInletTruncation; docs/results.md, "The inlet note"), with the x_start_b that brings
// the deficit to kInletTargetDeficit (p_in ~ |x0|^-3).
constexpr double kInletNoteDeficit = 0.005;
constexpr double kInletTargetDeficit = 0.002;
constexpr const char* kInletAdvice = "with grid_points raised in proportion (same spacing)";

void NoteContactInlet(const InletTruncation& t, double x_start_b) {
  if (!t.estimated || t.film_deficit <= kInletNoteDeficit) return;
  std::printf(
      "note: the inlet at x_start_b = %.3g cuts off %.3g MPa of inlet pressure: the film is "
      "about %.2g %% thinner than with an unbounded inlet (Grubin estimate, docs/results.md); "
      "[numerics] x_start_b = %.3g %s brings that to about %.2g %%\n",
      x_start_b, t.missing_pressure_pa * 1e-6, 100 * t.film_deficit,
      t.InletFor(x_start_b, kInletTargetDeficit), kInletAdvice, 100 * kInletTargetDeficit);
}

void NoteCycleInlet(const MeshCycleResult& r) {
  const std::vector<InletTruncation> inlet = r.InletTruncations();
  size_t worst = inlet.size();
  for (size_t k = 0; k < r.steps.size() && k < inlet.size(); ++k)
    if (Usable(r, k) && inlet[k].estimated &&
        (worst == inlet.size() || inlet[k].film_deficit > inlet[worst].film_deficit))
      worst = k;
  if (worst == inlet.size() || inlet[worst].film_deficit <= kInletNoteDeficit) return;
  const size_t pitch = static_cast<size_t>(r.PitchStep());
  std::string at_pitch;
  if (pitch < r.steps.size() && Usable(r, pitch) && pitch < inlet.size() &&
      inlet[pitch].estimated) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "; %.2g %% at the pitch point", 100 * inlet[pitch].film_deficit);
    at_pitch = buf;
  }
  std::printf(
      "note: the inlet at x_start_b = %.3g thins the films by up to %.2g %% against an "
      "unbounded inlet (at s = %.4g mm%s; Grubin estimate, docs/results.md): [numerics] "
      "x_start_b = %.3g %s brings that to about %.2g %%\n",
      r.x_start_b, 100 * inlet[worst].film_deficit, r.steps[worst].s_m * 1e3, at_pitch.c_str(),
      inlet[worst].InletFor(r.x_start_b, kInletTargetDeficit), kInletAdvice,
      100 * kInletTargetDeficit);
}

struct RunArgs {
  std::string case_path;
  std::string output_dir;
  bool quiet = false;
  bool resume = false;
  int checkpoint_every = 10;
};

int RunGear(const RunArgs& a) {
  MeshCycleRunOptions o;
  o.quiet = a.quiet;
  o.output_dir = a.output_dir;
  o.resume = a.resume;
  o.checkpoint_every = a.checkpoint_every;
  const MeshCycleResult r = RunMeshCycle(a.case_path, o);
  if (r.already_complete) {
    std::printf("%s is complete: nothing to resume\n", r.hdf5_path.c_str());
    return kExitOk;
  }
  if (r.resumed_from_step > 0)
    std::printf("resumed from the checkpoint at step %d\n", r.resumed_from_step);
  // A cycle reports only its converged steps (not the failed one where it stopped, nor failed
  // steps it left behind: failed_step = "steady_restart_or_skip").
  const size_t ok = UsableSteps(r);
  std::printf("mesh cycle A..E: %zu of %d steps (%s), grid %zu nodes, %.1f s\n", r.steps.size() - 1,
              r.planned_steps, r.step_rule.c_str(), r.x_m.size(), r.wall_time_s);
  if (r.begin_m > 0 || r.end_m < r.length_m)
    std::printf(
        "tip relief: the tracked pair carries under 1 %% of F_bt before s = %.4g mm and "
        "after %.4g mm (A..E = 0..%.4g mm); the films are solved in between\n",
        r.begin_m * 1e3, r.end_m * 1e3, r.length_m * 1e3);
  const size_t pitch_step = static_cast<size_t>(r.PitchStep());
  const bool passed_pitch = !r.steps.empty() && r.steps.back().s_m >= r.s_c_m;
  if (pitch_step < r.steps.size() && Usable(r, pitch_step) &&
      (passed_pitch || r.steps.size() == static_cast<size_t>(r.planned_steps) + 1)) {
    const MeshCycleStep& pitch = r.steps[pitch_step];
    std::printf("at the pitch point (s = %.4g mm): h_c = %.6g m, h_min = %.6g m, p_max = %.6g Pa\n",
                pitch.s_m * 1e3, pitch.h_c_m, pitch.h_min_m, pitch.p_max_pa);
  } else if (passed_pitch) {
    std::printf("the step at the pitch point (s = %.4g mm) did not converge\n", r.s_c_m * 1e3);
  } else {
    std::printf("the cycle stopped before the pitch point (s = %.4g mm)\n", r.s_c_m * 1e3);
  }
  if (r.thermal && ok > 0) {  // the hottest converged step and the mean friction along the path
    size_t hottest = 0;
    double mu = 0;
    for (size_t k = 0; k < r.steps.size(); ++k) {
      if (!Usable(r, k)) continue;
      if (r.steps[k].t_max_k > r.steps[hottest].t_max_k) hottest = k;
      mu += r.steps[k].friction_coefficient;
    }
    const MeshCycleStep& h = r.steps[hottest];
    std::printf("thermal: T_max = %.5g K at s = %.4g mm (SRR %+.3f), mean mu = %.4g%s\n", h.t_max_k,
                h.s_m * 1e3, h.srr, mu / static_cast<double>(ok),
                ok == r.steps.size() ? "" : " (converged steps)");
  }
  PrintCycleFlash(r);
  NoteCyclePeclet(r);
  NoteCycleSpikes(r);
  NoteCycleInlet(r);
  NoteRestarts(r.steps, [](size_t k, const MeshCycleStep& s) {
    return Where("step %zu (s = %.4g mm)", k, s.s_m * 1e3);
  });
  std::printf("wrote %s%s%s\n", r.hdf5_path.c_str(), r.csv_path.empty() ? "" : " and ",
              r.csv_path.c_str());
  if (!r.converged()) {
    ReportFailedSteps(r.steps, [](size_t k, const MeshCycleStep& s) {
      return Where("step %zu (s = %.4g mm)", k, s.s_m * 1e3);
    });
    return kExitNotConverged;
  }
  return kExitOk;
}

int RunContact(const RunArgs& a) {
  ContactRunOptions o;
  o.quiet = a.quiet;
  o.output_dir = a.output_dir;
  const ContactRunResult r = RunContactCase(a.case_path, o);
  const auto& last = r.steps.back();
  std::printf("h_min = %.6g m, h_c = %.6g m, p_max = %.6g Pa\n", last.h_min_m, last.h_c_m,
              last.p_max_pa);
  if (last.summary.usable() && last.flash_rise_blok_k > 0) {  // sliding, elastic
    std::printf("mu = %.4g; flash temperature (Blok%s, with this mu): rise %.3g K",
                last.friction_coefficient, r.finite_peclet ? ", finite Peclet" : "",
                last.flash_rise_blok_k);
    if (last.t_max_k > r.inlet_temperature_k)  // thermal: the film's own surfaces beside it
      std::printf("; the film's surfaces: max rise %.3g K (body 1), %.3g K (body 2)",
                  last.t1_max_k - r.inlet_temperature_k, last.t2_max_k - r.inlet_temperature_k);
    std::printf("\n");
  }
  if (last.summary.usable()) {
    NoteContactSpike(last.outlet_spike);
    NoteContactInlet(last.inlet, r.x_start_b);
  }
  NoteContactPeclet(r);
  NoteRestarts(r.steps, [](size_t k, const ContactStepRecord& s) {
    return Where("step %zu (t = %.4g s)", k, s.time_s);
  });
  std::printf("wrote %s and %s\n", r.profile_csv.c_str(), r.history_csv.c_str());
  if (!r.converged()) {
    ReportFailedSteps(r.steps, [](size_t k, const ContactStepRecord& s) {
      return Where("step %zu (t = %.4g s)", k, s.time_s);
    });
    return kExitNotConverged;
  }
  return kExitOk;
}

}  // namespace

Command AddRunCommand(CLI::App& app) {
  auto args = std::make_shared<RunArgs>();
  CLI::App* sub = app.add_subcommand(
      "run", "Run a case: the mesh cycle of a [gear] case, or a [contact] line contact");
  sub->add_option("CASE", args->case_path, "Case file (.toml)")->required();
  sub->add_option("-o,--output-dir", args->output_dir, "Folder for the results ([output])");
  sub->add_flag("-q,--quiet", args->quiet, "No progress line on stderr");
  sub->add_flag("--resume", args->resume,
                "Mesh cycle: leave a complete result alone, else continue from its checkpoint");
  sub->add_option("--checkpoint-every", args->checkpoint_every,
                  "Mesh cycle: write a checkpoint every N steps (0 = never)")
      ->check(CLI::Range(0, 10000000));
  return {sub, [args]() {
            // The scene is chosen by the section the file has; each scene reports every
            // problem of its own (a file with neither section is reported by the contact
            // scene, which names both).
            const internal::Document doc = internal::ReadCaseDocument(args->case_path);
            const bool gear = doc.HasSection("gear") || doc.HasSection("gear.pinion") ||
                              doc.HasSection("gear.wheel");
            return gear && !doc.HasSection("contact") ? RunGear(*args) : RunContact(*args);
          }};
}

}  // namespace tehl::cli
