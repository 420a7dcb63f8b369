// The notes `tehl run` prints beside a run's results (run_notes.hpp).
#include "cli/run_notes.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <string>
#include <vector>

#include "scene/automatic_grid.hpp"
#include "tehl/ehl/surface_temperature.hpp"
#include "tehl/units.hpp"

namespace tehl::cli {

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

// Blok's flash temperature along the converged steps, and in thermal runs the film's own
// hottest surfaces beside it (docs/thermal.md "Flash temperature").
void PrintCycleFlash(const MeshCycleResult& r) {
  if (UsableSteps(r) == 0 || !r.elastic) return;
  const std::vector<double> flash = r.BlokFlashRises();
  // A Newtonian mu above kNewtonianFrictionNote is not physical (the friction note says so),
  // and neither is the flash temperature from it: the maximum is taken over the other films.
  size_t at = r.steps.size(), left_out = 0;
  for (size_t k = 0; k < r.steps.size(); ++k) {
    if (!Usable(r, k)) continue;
    if (!r.non_newtonian && r.steps[k].friction_coefficient > kNewtonianFrictionNote) {
      ++left_out;
      continue;
    }
    if (at == r.steps.size() || flash[k] > flash[at]) at = k;
  }
  if (at == r.steps.size()) {
    std::printf(
        "flash temperature (Blok): not given: every film's Newtonian mu exceeds %.1f "
        "(note below)\n",
        kNewtonianFrictionNote);
    return;
  }
  std::printf("flash temperature (Blok%s, with each step's mu): max rise %.3g K at s = %.4g mm",
              r.finite_peclet ? ", finite Peclet" : "", flash[at], r.steps[at].s_m * 1e3);
  if (left_out > 0)
    std::printf(" (%zu films with a Newtonian mu above %.1f left out)", left_out,
                kNewtonianFrictionNote);
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

namespace {

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

}  // namespace

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

std::string Where(const char* format, size_t k, double value) {
  char buf[96];
  std::snprintf(buf, sizeof buf, format, k, value);
  return buf;
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

// The edge note: a film whose Hertzian edge spans fewer than kEdgeResolvedCells (include/tehl/
// ehl/hertz_edge.hpp; docs/results.md, "The edge note").
constexpr const char* kEdgeAdvice =
    "more [numerics] grid_points resolve it (the deficit falls as the square of the cells; "
    "docs/validation.md section 3.1)";

std::string EdgeDeficit(const HertzEdge& e) {
  if (e.film_deficit > 0.5) return "it is not resolved and may be far too thin";
  char buf[96];
  std::snprintf(buf, sizeof buf, "it is likely too thin by up to about %.2g %%",
                100 * e.film_deficit);
  return buf;
}

void NoteContactEdge(const HertzEdge& e) {
  if (!(e.width_m > 0) || e.resolved()) return;
  std::printf(
      "note: the film's Hertzian edge (where the dry gap outside the Hertz zone reaches h_c: "
      "%.3g um wide) spans %.2g cells, fewer than %.0f: %s; %s\n",
      e.width_m * 1e6, e.width_cells, kEdgeResolvedCells, EdgeDeficit(e).c_str(), kEdgeAdvice);
}

void NoteCycleEdges(const MeshCycleResult& r) {
  const std::vector<HertzEdge> edges = r.HertzEdges();
  int narrow = 0;
  size_t at = 0;
  for (size_t k = 0; k < r.steps.size() && k < edges.size(); ++k) {
    if (!Usable(r, k) || !(edges[k].width_m > 0) || edges[k].resolved()) continue;
    if (narrow++ == 0 || edges[k].width_cells < edges[at].width_cells) at = k;
  }
  if (narrow == 0) return;
  std::printf(
      "note: in %d of the %zu films along the path the Hertzian edge (where the dry gap outside "
      "the Hertz zone reaches h_c) spans fewer than %.0f cells (fewest %.2g cells at s = %.4g "
      "mm, where %s): %s\n",
      narrow, UsableSteps(r), kEdgeResolvedCells, edges[at].width_cells, r.steps[at].s_m * 1e3,
      EdgeDeficit(edges[at]).c_str(), kEdgeAdvice);
}

// The inlet note: a film thinned by more than kInletNoteDeficit by the truncated inlet
// (EstimateInletTruncation; docs/results.md, "The inlet note"), with the x_start_b that brings
// the deficit to kInletTargetDeficit (p_in ~ |x0|^-3).
// kInletNoteDeficit: scene/automatic_grid.hpp, where `case --check` estimates it before solving.
using internal::kInletNoteDeficit;
using internal::kInletTargetDeficit;  // the automatic grid's target: both say the same inlet
// The smallest [numerics] x_start_b the case schema allows [-].
constexpr double kMinStartB = -100.0;

// "[numerics] x_start_b = X with grid_points = N (the same spacing)": the grid of `g` with its
// inlet moved from x_start_b to new_b (UniformGrid::NodesFromStart).
std::string InletAdvice(double new_b, double x_start_b, const GridSpan& g) {
  char buf[160];
  const UniformGrid grid(g.x0_m, g.x_end_m, g.nodes);
  std::snprintf(buf, sizeof buf,
                "[numerics] x_start_b = %.3g with grid_points = %d (the same spacing)", new_b,
                grid.NodesFromStart(g.x0_m * new_b / x_start_b));
  return buf;
}

// A nearly isoviscous film (alpha p_max < kGrubinMinAlphaP) gets no Grubin estimate; its
// inlet is noted when it starts downstream of -l_iso (InletTruncation::short_isoviscous_inlet).
void PrintIsoviscousInletNote(const InletTruncation& t,
                              double x_start_b,
                              const GridSpan& g,
                              const std::string& where) {
  const double x0_m = g.x0_m;
  const double needed = x_start_b * t.isoviscous_inlet_m / -x0_m;
  char advice[320];
  if (needed >= kMinStartB)
    std::snprintf(advice, sizeof advice, "%s", InletAdvice(needed, x_start_b, g).c_str());
  else
    std::snprintf(advice, sizeof advice,
                  "that would be x_start_b = %.3g, beyond the %g allowed: such a film needs "
                  "a grid of its own (a [contact] case of its radius, speeds and load, whose "
                  "default inlet reaches it)",
                  needed, kMinStartB);
  std::printf(
      "note: %s is nearly isoviscous (alpha p_max = %.2g, below the %g at which the inlet's "
      "effect can be estimated) and such a film builds its pressure far upstream: its inlet at "
      "x_start_b = %.3g (%.3g mm) reaches %.2g %% of the %.3g mm over which a flooded "
      "isoviscous film does (Martin), so it is likely too thin; %s\n",
      where.c_str(), t.alpha_p_max, kGrubinMinAlphaP, x_start_b, -1e3 * x0_m,
      100 * -x0_m / t.isoviscous_inlet_m, 1e3 * t.isoviscous_inlet_m, advice);
}

// A nearly rigid film thick against R: its flooded inlet would reach beyond R/2, where the
// model's parabolic gap x^2/(2R) ends; the grid stops there (IsoviscousInletLength).
void PrintThickFilmNote(const InletTruncation& t, double x0_m, const std::string& where) {
  std::printf(
      "note: %s is thick against its radius: a flooded rigid film builds its pressure over "
      "tens of sqrt(2 R h), beyond R/2 where the gap of the model (the parabola x^2/2R) ends, "
      "and the grid's inlet at x = %.3g mm (R/2 at most) makes it about %.2g %% thinner than "
      "Martin's film with an unbounded inlet (the exact truncated rigid solution); a real "
      "film there depends on where the oil meets the gap\n",
      where.c_str(), 1e3 * x0_m, 100 * t.rigid_film_deficit);
}

void NoteContactInlet(const InletTruncation& t, double x_start_b, const GridSpan& g) {
  if (!t.estimated && t.short_isoviscous_inlet) {
    PrintIsoviscousInletNote(t, x_start_b, g, "the film");
    return;
  }
  if (!t.estimated && t.rigid_film_deficit > kInletNoteDeficit) {
    PrintThickFilmNote(t, g.x0_m, "the film");
    return;
  }
  if (!t.estimated || t.film_deficit <= kInletNoteDeficit) return;
  std::printf(
      "note: the inlet at x_start_b = %.3g cuts off %.3g MPa of inlet pressure: the film is "
      "about %.3g %% thinner than with an unbounded inlet (Grubin estimate, docs/results.md); "
      "%s brings that to about %.2g %%\n",
      x_start_b, t.missing_pressure_pa * 1e-6, 100 * t.film_deficit,
      InletAdvice(t.InletFor(x_start_b, kInletTargetDeficit), x_start_b, g).c_str(),
      100 * kInletTargetDeficit);
}

void NoteCycleInlet(const MeshCycleResult& r) {
  const std::vector<InletTruncation> inlet = r.InletTruncations();
  // The lightly loaded ends of a relieved path (down to 1 % of F_bt) are nearly isoviscous
  // whatever the case: only films carrying a tenth of the cycle's largest load count.
  double w_max = 0;
  for (size_t k = 0; k < r.steps.size(); ++k)
    if (Usable(r, k)) w_max = std::max(w_max, r.steps[k].load_n_per_m);
  size_t short_count = 0, shortest = inlet.size();
  for (size_t k = 0; k < r.steps.size() && k < inlet.size(); ++k) {
    if (!Usable(r, k) || inlet[k].estimated || !inlet[k].short_isoviscous_inlet ||
        r.steps[k].load_n_per_m < 0.1 * w_max)
      continue;
    ++short_count;
    if (shortest == inlet.size() ||
        inlet[k].isoviscous_inlet_m > inlet[shortest].isoviscous_inlet_m)
      shortest = k;
  }
  if (short_count > 0 && !r.x_m.empty()) {
    char where[128];
    std::snprintf(where, sizeof where,
                  "in %zu of the %zu films (the worst at s = %.4g mm) the film", short_count,
                  UsableSteps(r), r.steps[shortest].s_m * 1e3);
    PrintIsoviscousInletNote(inlet[shortest], r.x_start_b,
                             {r.x_m.front(), r.x_m.back(), static_cast<int>(r.x_m.size())}, where);
  }
  size_t thick = inlet.size();
  for (size_t k = 0; k < r.steps.size() && k < inlet.size(); ++k)
    if (Usable(r, k) && !inlet[k].estimated && r.steps[k].load_n_per_m >= 0.1 * w_max &&
        inlet[k].rigid_film_deficit > kInletNoteDeficit &&
        (thick == inlet.size() || inlet[k].rigid_film_deficit > inlet[thick].rigid_film_deficit))
      thick = k;
  if (thick < inlet.size() && short_count == 0 && !r.x_m.empty()) {
    char where[96];
    std::snprintf(where, sizeof where, "the film at s = %.4g mm (the worst)",
                  r.steps[thick].s_m * 1e3);
    PrintThickFilmNote(inlet[thick], r.x_m.front(), where);
  }
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
      "note: the inlet at x_start_b = %.3g thins the films by up to %.3g %% against an "
      "unbounded inlet (at s = %.4g mm%s; Grubin estimate, docs/results.md): %s brings that "
      "to about %.2g %%\n",
      r.x_start_b, 100 * inlet[worst].film_deficit, r.steps[worst].s_m * 1e3, at_pitch.c_str(),
      InletAdvice(inlet[worst].InletFor(r.x_start_b, kInletTargetDeficit), r.x_start_b,
                  {r.x_m.front(), r.x_m.back(), static_cast<int>(r.x_m.size())})
          .c_str(),
      100 * kInletTargetDeficit);
}

void PrintNewtonianFrictionNote(size_t count, size_t films, double mu, const std::string& where) {
  if (films > 1)
    std::printf(
        "note: in %zu of the %zu films the Newtonian friction coefficient exceeds %.1f, "
        "up to %.3g (%s)",
        count, films, kNewtonianFrictionNote, mu, where.c_str());
  else
    std::printf("note: the Newtonian film's friction coefficient is %.3g", mu);
  std::printf(
      ": a full film carries at most about 0.1 of its pressure as shear stress (the limiting "
      "shear stress of lubricants), so a Newtonian mu above %.1f, and the flash temperature "
      "from it, are not physical; [effects] non_newtonian = true bounds the shear stress "
      "(Ree-Eyring, docs/thermal.md)\n",
      kNewtonianFrictionNote);
}

}  // namespace tehl::cli
