#include "scene/mesh_cycle_plan.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "scene/automatic_grid.hpp"
#include "scene/dynamic_load.hpp"
#include "scene/profile_memory.hpp"
#include "tehl/gear/load_sharing.hpp"
#include "tehl/gear/operating_point.hpp"
#include "tehl/gear/tip_relief.hpp"
#include "tehl/scene/mesh_cycle_scene.hpp"
#include "tehl/units.hpp"

namespace tehl::internal {

CyclePath::CyclePath(const GearCase& c)
    : gear_(c),
      path_(*c.pair, c.operating.pinion_speed_rad_s),
      begin_m_(c.loaded_path.begin_m),
      end_m_(c.loaded_path.end_m),
      w_nominal_(NominalToothLoad(*c.pair, c.operating).load_per_width_n_per_m),
      normal_force_n_(NominalToothLoad(*c.pair, c.operating).normal_force_n) {}

PathState CyclePath::At(double s, bool left) const {
  const double nudge = 1e-9 * path_.length_m();
  double q = s;
  if (left && s > nudge)
    q = s - nudge;
  else if (!left && s < path_.length_m() - nudge)
    q = s + nudge;
  PathState st;
  st.contact = path_.At(s);
  st.contact.pairs_in_contact = path_.At(q).pairs_in_contact;
  double share = 0;
  if (gear_.load_sharing == LoadSharing::kLinear)
    share = LinearLoadShare(path_, q);
  else if (gear_.tip_relief.Active() || gear_.load_sharing == LoadSharing::kLoaded)
    share = RelievedLoadShare(path_, q, gear_.pair_stiffness, gear_.tip_relief, normal_force_n_,
                              gear_.corner_contact.get())
                .share;
  else
    share = StiffnessLoadShare(path_, q, gear_.pair_stiffness);
  st.static_load_n_per_m = share * w_nominal_;
  // [effects] dynamic_load: the tracked pair's load of the periodic torsional response.
  st.load_n_per_m = st.static_load_n_per_m *
                    (gear_.dynamic_load ? gear_.dynamic_load->LoadFactorAt(s, left) : 1.0);
  return st;
}

std::vector<double> SegmentEnds(double g, double sb, double sd, double begin, double end) {
  if (end < 0) end = g;
  std::vector<double> ends;
  for (double sw : {sb, sd})
    if (sw > begin + 1e-9 * g && sw < end - 1e-9 * g) ends.push_back(sw);
  std::sort(ends.begin(), ends.end());
  ends.push_back(end);
  return ends;
}

MeshCyclePlan PlanMeshCycle(Document& doc, const CyclePath& cycle, double e_prime_pa,
                            const FilmCase& film) {
  MeshCyclePlan plan;
  const PathOfContact& path = cycle.path();
  const double g = path.length_m();
  // The films are solved on the loaded part of the path (all of A..E without tip relief).
  const double begin = cycle.begin_m(), end = cycle.end_m();
  // A load so light that its film is not thin against R (Martin's film at the pitch point's
  // static load; film_case.hpp) is not a lubricated gear contact.
  if (film.lubricant) {
    const PathState st = cycle.At(std::clamp(path.s_c_m(), begin, end), false);
    const double r = st.contact.reduced_radius_m, w = st.static_load_n_per_m;
    const double eta0 =
        film.lubricant->viscosity().Evaluate(0.0, film.inlet_temperature_k).eta_pa_s;
    const double h_martin = kMartinFilm * eta0 * st.contact.um_m_s * r / w;
    if (!(h_martin <= kMaxFilmToRadius * r)) {
      const bool power = doc.Given("operating", "power_w");
      doc.Problem("operating", power ? "power_w" : "pinion_torque_nm",
                  "the tooth load " + FormatShort(w) +
                      " N/m at the pitch point carries a film "
                      "of about " +
                      FormatShort(h_martin) +
                      " m (Martin's rigid film 4.896 eta0 um "
                      "R / w) against R = " +
                      FormatShort(r) + " m: Reynolds' thin-film theory needs h << R",
                  std::string(power ? "a larger power_w" : "a larger pinion_torque_nm") +
                      " (tooth loads >= " +
                      FormatShort(kMartinFilm * eta0 * st.contact.um_m_s / kMaxFilmToRadius) +
                      " N/m at the pitch point), or check the lubricant's viscosity (eta0 = " +
                      FormatShort(eta0) +
                      " Pa s at the inlet: a value in mPa s is 1000 times "
                      "too large)");
      return plan;
    }
  }
  // b_max and the entrainment transits over a fine sampling of it (both sides of B, D).
  const int samples = 400;
  double transits = 0;
  GridUnits units;  // b_max, or the longest rigid inlet scale (GridUnitsFor)
  GridChoice choice(film, e_prime_pa);  // the node count (automatic_grid.hpp)
  // The films that size the automatic grid's inlet: those carrying at least
  // kInletSizingLoadFraction of the largest load (the single and double contact zones), not
  // the lightly loaded ends of a relieved path or a dip of the dynamic load.
  double w_max = 0;
  for (int i = 0; i <= samples; ++i)
    for (bool left : {true, false})
      w_max = std::max(w_max, cycle.At(begin + (end - begin) * i / samples, left).load_n_per_m);
  for (int i = 0; i <= samples; ++i) {
    const double s = begin + (end - begin) * i / samples;
    for (bool left : {true, false}) {
      const PathState st = cycle.At(s, left);
      const double b =
          LineContactHertz(st.load_n_per_m, st.contact.reduced_radius_m, e_prime_pa).half_width_m;
      plan.max_half_width_m = std::max(plan.max_half_width_m, b);
      // One grid serves the whole path: b_max here; the automatic grid stretches its inlet
      // for the loaded films only (GridChoice), and `tehl run` notes films whose inlet is
      // short (docs/results.md).
      units = units.Max(GridUnitsFor(film, b, st.contact.reduced_radius_m, st.contact.um_m_s,
                                     st.load_n_per_m, /*isoviscous_inlet=*/false));
      choice.Add(st.contact.reduced_radius_m, st.contact.um_m_s, st.load_n_per_m,
                 st.load_n_per_m >= kInletSizingLoadFraction * w_max);
      if (left && i > 0)
        transits += st.contact.um_m_s / b * (path.duration_s() * (end - begin) / g / samples);
    }
  }
  plan.grid = choice.Grid(units);
  plan.grid_rule = choice.Rule(units);
  plan.inlet_note = choice.InletNote(units);
  const UniformGrid& grid = plan.grid;
  CheckRoughnessResolution(doc, film, grid.dx_m());
  plan.input_notes = InputNotes(film, grid.dx_m(), grid.size());

  // Step count: the user's, or automatic; with roughness at least dt <= dx/um per segment.
  const long long user_steps = doc.Int("numerics", "steps");
  const int auto_steps = AutomaticMeshCycleSteps(transits);
  std::vector<int> min_seg;
  int rough_total = 0;
  if (film.effects.roughness) {
    double a = begin;
    for (double e : SegmentEnds(g, path.s_b_m(), path.s_d_m(), begin, end)) {
      double um_seg = 0;
      for (int i = 0; i <= 50; ++i) um_seg = std::max(um_seg, path.At(a + (e - a) * i / 50).um_m_s);
      const int need = static_cast<int>(
          std::ceil((e - a) / path.contact_speed_m_s() * um_seg / grid.dx_m() - 1e-9));
      min_seg.push_back(std::max(need, 1));
      rough_total += min_seg.back();
      a = e;
    }
  }
  int steps = user_steps > 0 ? static_cast<int>(user_steps) : auto_steps;
  if (user_steps > 0 && film.effects.roughness && user_steps < rough_total) {
    doc.Problem("numerics", "steps",
                "with moving roughness the cycle needs dt <= dx/um: at least " +
                    std::to_string(rough_total) + " steps on this grid",
                "0 (automatic) or >= " + std::to_string(rough_total));
  }
  plan.s_steps = MeshCycleStepPositions(g, path.s_b_m(), path.s_d_m(), steps, min_seg, begin, end);
  char rule[256];
  const long long planned = static_cast<long long>(plan.s_steps.size()) - 1;
  if (user_steps > 0 && planned != user_steps)
    std::snprintf(rule, sizeof rule,
                  "[numerics] steps = %lld, raised to %lld: each contact zone (A-B, B-D, D-E) "
                  "takes at least one",
                  user_steps, planned);
  else if (user_steps > 0)
    std::snprintf(rule, sizeof rule, "[numerics] steps = %lld", user_steps);
  else
    std::snprintf(rule, sizeof rule,
                  "automatic: 4 steps per entrainment transit of b (%.1f transits), "
                  "clamped to 100..200%s",
                  transits, film.effects.roughness ? "; raised to dt <= dx/um (roughness)" : "");
  plan.step_rule = rule;
  CheckProfileMemory(doc, film, grid.size(), static_cast<long long>(plan.s_steps.size()),
                     /*journal=*/true, "numerics", "steps", plan.input_notes);
  return plan;
}

}  // namespace tehl::internal
