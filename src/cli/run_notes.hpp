// What `tehl run` prints beside a run's results (docs/results.md): the flash temperature along
// a cycle, and notes where a film's resolution, inlet or Peclet number limits what it says,
// where time steps were restarted from the steady film, and which steps did not converge.
// Private to src/cli.
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdio>
#include <string>
#include <vector>

#include "tehl/ehl/flash_temperature.hpp"
#include "tehl/ehl/hertz_edge.hpp"
#include "tehl/ehl/inlet_truncation.hpp"
#include "tehl/ehl/outlet_spike.hpp"
#include "tehl/scene/contact_scene.hpp"
#include "tehl/scene/mesh_cycle_scene.hpp"

namespace tehl::cli {

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
void PrintCycleFlash(const MeshCycleResult& r);

// Notes when the surfaces' Peclet number falls below about 5 (mesh cycle; [contact] run).
void NoteCyclePeclet(const MeshCycleResult& r);
void NoteContactPeclet(const ContactRunResult& r);

// Notes outlet spikes narrower than kSpikeResolvedCells (one film; the films of a cycle).
void NoteContactSpike(const OutletSpike& spike);
void NoteCycleSpikes(const MeshCycleResult& r);

// Notes a film whose Hertzian edge spans fewer than kEdgeResolvedCells (one film; a cycle).
void NoteContactEdge(const HertzEdge& e);
void NoteCycleEdges(const MeshCycleResult& r);

// Notes an inlet that thins the film by more than kInletNoteDeficit, or one shorter than a
// nearly isoviscous film needs (InletTruncation::short_isoviscous_inlet), with x0 the grid's
// first node [m] (one film; a cycle).
// The film grid's ends and node count, for advice that keeps its spacing.
struct GridSpan {
  double x0_m = 0, x_end_m = 0;  // first and last node [m]
  int nodes = 0;                 // [-]
};
void NoteContactInlet(const InletTruncation& t, double x_start_b, const GridSpan& g);
void NoteCycleInlet(const MeshCycleResult& r);

// `format` with k and value, e.g. Where("step %zu (s = %.4g mm)", 70, 4.913).
std::string Where(const char* format, size_t k, double value);

// kPhysicalFrictionLimit (tehl/ehl/flash_temperature.hpp): a Newtonian film has no bound on
// its shear stress, and at gear pressures its viscosity makes mu grow without limit (the
// isothermal seed 004 cycle: 0.52 at A; 20 times its load: above 1e6). Above the limit a run
// notes that mu, and the flash temperature from it, are not physical [-].
inline constexpr double kNewtonianFrictionNote = kPhysicalFrictionLimit;

void PrintNewtonianFrictionNote(size_t count, size_t films, double mu, const std::string& where);

// The note above over the converged films of a run (`where(k, step)` names film k); nothing
// when the run's film is non-Newtonian (effects.non_newtonian).
template <typename Run, typename Where>
void NoteNewtonianFriction(const Run& r, Where where) {
  if (r.non_newtonian) return;
  size_t count = 0, worst = 0;
  for (size_t k = 0; k < r.steps.size(); ++k) {
    if (!Usable(r, k) || !(r.steps[k].friction_coefficient > kNewtonianFrictionNote)) continue;
    if (count++ == 0 || r.steps[k].friction_coefficient > r.steps[worst].friction_coefficient)
      worst = k;
  }
  if (count > 0)
    PrintNewtonianFrictionNote(count, UsableSteps(r), r.steps[worst].friction_coefficient,
                               where(worst, r.steps[worst]));
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

// A step whose estimated local time error (Summary::time_error) is above this is noted: its
// film is that many parts of itself away from the film of a step resolved in time (after the
// load jumps of a gear cycle a time error of 1e-2 leaves h_min and h_c several per cent off:
// docs/case_format.md, "time_tolerance") [-].
inline constexpr double kTimeErrorNote = 1e-2;

// The converged steps whose estimated time error is above kTimeErrorNote: how many, the
// largest and where (`where(k, step)` names step k), and the key that controls it.
template <typename Step, typename Where>
void NoteTimeError(const std::vector<Step>& steps, Where where) {
  size_t count = 0, worst = 0;
  for (size_t k = 0; k < steps.size(); ++k) {
    if (!steps[k].summary.usable() || !(steps[k].summary.time_error > kTimeErrorNote)) continue;
    if (count++ == 0 || steps[k].summary.time_error > steps[worst].summary.time_error) worst = k;
  }
  if (count == 0) return;
  std::printf(
      "note: %zu of %zu time steps have an estimated local time error above %g %% (largest "
      "%.2g at %s); the estimate is per step, and errors carried over from earlier steps can "
      "make a film further off than it says: [numerics] time_tolerance splits steps into "
      "substeps until their estimate is below it, and a run with it is the check "
      "(docs/case_format.md: what it costs, and where it helps)\n",
      count, steps.size() - 1, 100 * kTimeErrorNote, steps[worst].summary.time_error,
      where(worst, steps[worst]).c_str());
}

// Steps split into substeps without time control: a whole step whose Newton solve did not
// converge (max_newton_iterations) is retried as 2 and then 4 substeps (docs/theory.md,
// "Time-step control"). The shorter steps change that film and the ones after it by the time
// error, so a run with a lower iteration limit is not the same run.
template <typename Step, typename Where>
void NoteSplitSteps(const std::vector<Step>& steps, double time_tolerance, Where where) {
  if (time_tolerance > 0) return;  // splitting is what time control does
  size_t count = 0, first = 0;
  for (size_t k = 0; k < steps.size(); ++k) {
    if (!steps[k].summary.usable() || steps[k].summary.substeps <= 1) continue;
    if (count++ == 0) first = k;
  }
  if (count == 0) return;
  std::printf(
      "note: %zu time step%s did not converge as one step and %s split into substeps (first at "
      "%s): those films and the ones after them differ from whole steps by the time error; "
      "more [numerics] max_newton_iterations keeps the steps whole, and time_tolerance "
      "controls the error (docs/case_format.md)\n",
      count, count == 1 ? "" : "s", count == 1 ? "was" : "were",
      where(first, steps[first]).c_str());
}

// The converged steps of a run's step list.
template <typename Step>
size_t UsableCount(const std::vector<Step>& steps) {
  size_t n = 0;
  for (const Step& s : steps) n += s.summary.usable();
  return n;
}

// A film thinner than this is a few molecular layers thick: the boundary films that
// lubricant additives form on steel are tens of nm thick (Spikes 2004, Tribol. Lett. 17:469,
// on ZDDP films), so below it the surfaces' asperities and those films carry load that the
// continuum Reynolds film does not describe, and its friction there (the shear of a
// nanometre film) is not physical. tehl models no asperity contact [m].
inline constexpr double kThinFilmNote = 10e-9;

// The converged steps whose h_min is below kThinFilmNote: how many, the thinnest and where
// (`where(k, step)` names step k), and the largest friction coefficient among them.
template <typename Step, typename Where>
void NoteThinFilms(const std::vector<Step>& steps, Where where) {
  size_t count = 0, thinnest = 0;
  double mu = 0;
  for (size_t k = 0; k < steps.size(); ++k) {
    if (!steps[k].summary.usable() || !(steps[k].h_min_m < kThinFilmNote)) continue;
    if (count++ == 0 || steps[k].h_min_m < steps[thinnest].h_min_m) thinnest = k;
    mu = std::max(mu, steps[k].friction_coefficient);
  }
  if (count == 0) return;
  std::printf(
      "note: in %zu of %zu films h_min is below %g nm (thinnest %.3g nm at %s): the surfaces "
      "are in asperity (mixed) contact, which tehl does not model; the continuum film there, "
      "and its friction (up to mu = %.3g), describe no real contact (rougher surfaces need "
      "a thicker film: lower load, higher speed or a more viscous oil)\n",
      count, UsableCount(steps), 1e9 * kThinFilmNote, 1e9 * steps[thinnest].h_min_m,
      where(thinnest, steps[thinnest]).c_str(), mu);
}

// The converged films whose pressure had not cavitated before the grid's last inner node
// (Summary::outlet_cut): the grid ends inside them and cuts them off.
template <typename Step, typename Where>
void NoteCutOutlets(const std::vector<Step>& steps, Where where) {
  size_t count = 0, first = 0;
  for (size_t k = 0; k < steps.size(); ++k)
    if (steps[k].summary.usable() && steps[k].summary.outlet_cut && count++ == 0) first = k;
  if (count == 0) return;
  std::printf(
      "note: in %zu of %zu films (the first at %s) the pressure is still positive next to the "
      "grid's outlet end: the grid cuts the film off before its Reynolds exit, so it is the "
      "film of a shorter contact; a larger [numerics] x_end_b (the outlet end in half-widths "
      "b of the largest contact) reaches it\n",
      count, UsableCount(steps), where(first, steps[first]).c_str());
}

// Above about 200 C mineral oils oxidize and their light ends evaporate (the flash points of
// gear and engine oils lie near 200-250 C), and the viscosity-temperature data the lubricant
// laws are fitted to span about 40-100 C (the reference temperatures of ISO 3448 and ASTM
// D2270): a film hotter than this is an extrapolation of its laws [K].
inline constexpr double kHotFilmNote = 473.15;

// The converged steps of a thermal run whose T_max is above kHotFilmNote: how many, the
// hottest and where (`where(k, step)` names step k); a Newtonian run is pointed at the
// Ree-Eyring film.
template <typename Step, typename Where>
void NoteHotFilms(const std::vector<Step>& steps, bool newtonian, Where where) {
  size_t count = 0, hottest = 0;
  for (size_t k = 0; k < steps.size(); ++k) {
    if (!steps[k].summary.usable() || !(steps[k].t_max_k > kHotFilmNote)) continue;
    if (count++ == 0 || steps[k].t_max_k > steps[hottest].t_max_k) hottest = k;
  }
  if (count == 0) return;
  std::printf(
      "note: in %zu of %zu films the oil is hotter than %.0f K (200 C; hottest %.4g K at %s): "
      "mineral oils oxidize and evaporate there, and the lubricant's laws, fitted to data of "
      "about 40-100 C, are far extrapolated%s\n",
      count, UsableCount(steps), kHotFilmNote, steps[hottest].t_max_k,
      where(hottest, steps[hottest]).c_str(),
      newtonian ? "; a Newtonian film in sliding overstates its heating ([effects] "
                  "non_newtonian = true bounds the shear stress)"
                : "");
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

}  // namespace tehl::cli
