#include "scene/automatic_grid.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "tehl/ehl/film_thickness_formulas.hpp"
#include "tehl/ehl/hertz_edge.hpp"
#include "tehl/ehl/inlet_truncation.hpp"
#include "tehl/lubricant/lubricant.hpp"
#include "tehl/units.hpp"

namespace tehl::internal {

GridChoice::GridChoice(const FilmCase& film, double e_prime_pa)
    : film_(film),
      e_prime_pa_(e_prime_pa),
      eta0_pa_s_(film.lubricant->viscosity().Evaluate(0.0, film.inlet_temperature_k).eta_pa_s),
      alpha_per_pa_(film.effects.piezoviscous
                        ? film.lubricant->viscosity().PressureViscosityCoefficient()
                        : 0.0) {}

namespace {

InletTruncationInputs InletInputs(
    double x0, double r, double b, double um, double eta0, double alpha, double w) {
  InletTruncationInputs in;
  in.x_start_m = x0;
  in.reduced_radius_m = r;
  in.half_width_m = b;
  in.um_m_s = um;
  in.inlet_viscosity_pa_s = eta0;
  in.pressure_viscosity_per_pa = alpha;
  in.load_n_per_m = w;
  return in;
}

}  // namespace

void GridChoice::Add(double r, double um, double w, bool sizes_inlet) {
  um = std::abs(um);  // the film forms the same way whichever way it is entrained
  if (!film_.effects.elastic || !(r > 0 && w > 0 && um > 0)) return;
  double h = EstimatedCentralFilmM(eta0_pa_s_, alpha_per_pa_, um, w, r, e_prime_pa_, true);
  if (alpha_per_pa_ > 0) {
    const DimensionlessGroups g =
        LineContactGroups(eta0_pa_s_, alpha_per_pa_, um, w, r, e_prime_pa_);
    h = std::min(h, PanHamrockCentralFilmM(g.U, g.G, g.W, r));
  }
  const double b = LineContactHertz(w, r, e_prime_pa_).half_width_m;
  const HertzEdge e = EstimateHertzEdge(r, b, h, 1.0);
  if (e.width_m > 0) edge_m_ = std::min(edge_m_, e.width_m);
  if (!sizes_inlet || !(b > 0)) return;
  inlet_films_.push_back({r, um, w, b, h});
  // The ends this film needs: a nearly isoviscous, nearly rigid film its isoviscous inlet and
  // the rigid film's outlet (GridUnitsFor); a piezoviscous one the inlet that brings Grubin's
  // deficit below the target (p_in ~ |x0|^-3, refined on the prediction itself), at most R/2.
  isoviscous_ = isoviscous_.Max(GridUnitsFor(film_, b, r, um, w, /*isoviscous_inlet=*/true));
  const double cap = kIsoviscousInletMaxRadii * r;
  double x0 = -std::max(-film_.x_start_b, 1.5) * b;
  for (int k = 0; k < 6; ++k) {
    const InletTruncation t =
        PredictInletTruncation(InletInputs(x0, r, b, um, eta0_pa_s_, alpha_per_pa_, w), h);
    if (!t.estimated) return;
    inlet_need_m_ = std::max(inlet_need_m_, -x0);
    if (t.film_deficit <= kInletTargetDeficit || -x0 >= cap) return;
    x0 = std::max(t.InletFor(x0, 0.9 * kInletTargetDeficit), -cap);
  }
  inlet_need_m_ = std::max(inlet_need_m_, -x0);
}

double GridChoice::WorstDeficit(double x0) const {
  double worst = -1;
  for (const InletFilm& f : inlet_films_) {
    if (!(-x0 > f.b_m)) continue;
    const InletTruncation t = PredictInletTruncation(
        InletInputs(x0, f.r_m, f.b_m, f.um_m_s, eta0_pa_s_, alpha_per_pa_, f.w_n_per_m), f.h_m);
    if (t.estimated) worst = std::max(worst, t.film_deficit);
  }
  return worst;
}

GridUnits GridChoice::Stretched(const GridUnits& units) const {
  if (film_.grid_points > 0 || !(film_.x_start_b < 0)) return units;
  GridUnits u = units.Max(isoviscous_);
  u.inlet_m = std::max(u.inlet_m, inlet_need_m_ / -film_.x_start_b);
  return u;
}

int GridChoice::Nodes(const GridUnits& given) const {
  if (film_.grid_points > 0) return film_.grid_points;
  const GridUnits units = Stretched(given);
  const double span = film_.x_end_b * units.outlet_m - film_.x_start_b * units.inlet_m;
  return NodesSpanningEdge(span, std::isfinite(edge_m_) ? edge_m_ : 0.0, kAutomaticGridMinNodes,
                           kAutomaticGridMaxNodes);
}

UniformGrid GridChoice::Grid(const GridUnits& given) const {
  const GridUnits units = Stretched(given);
  return UniformGrid(film_.x_start_b * units.inlet_m, film_.x_end_b * units.outlet_m, Nodes(units));
}

std::string GridChoice::Rule(const GridUnits& given) const {
  char buf[400];
  const GridUnits units = Stretched(given);
  const double x0 = film_.x_start_b * units.inlet_m;
  if (film_.grid_points > 0) {
    std::snprintf(buf, sizeof buf, "[numerics] grid_points = %d", film_.grid_points);
    return buf;
  }
  const double deficit = WorstDeficit(x0);
  std::string inlet;
  if (units.inlet_m > given.inlet_m || units.outlet_m > given.outlet_m) {
    char estimate[96] = "no Grubin estimate: nearly isoviscous films";
    if (deficit >= 0)
      std::snprintf(estimate, sizeof estimate, "inlet deficit at most %.2f %%, estimated",
                    100 * deficit);
    std::snprintf(buf, sizeof buf,
                  "; for the films' inlets and outlets it spans x = %.3g ... %.3g mm instead of "
                  "%.3g ... %.3g mm (%s)",
                  x0 * 1e3, film_.x_end_b * units.outlet_m * 1e3,
                  film_.x_start_b * given.inlet_m * 1e3, film_.x_end_b * given.outlet_m * 1e3,
                  estimate);
    inlet = buf;
  }
  if (!std::isfinite(edge_m_)) {
    std::snprintf(buf, sizeof buf, "automatic: %d, the smallest (no Hertzian edge: rigid films)",
                  kAutomaticGridMinNodes);
    return buf + inlet;
  }
  const int n = Nodes(units);
  const UniformGrid g = Grid(units);
  const double cells = edge_m_ / g.dx_m();
  std::snprintf(buf, sizeof buf,
                "automatic: the fewest from %d that span every film's Hertzian edge with %.0f "
                "cells; the narrowest, estimated %.3g um, spans %.1f cells%s",
                kAutomaticGridMinNodes, kEdgeResolvedCells, edge_m_ * 1e6, cells,
                n == kAutomaticGridMaxNodes && cells < kEdgeResolvedCells
                    ? " (capped at the largest automatic grid)"
                    : "");
  return buf + inlet;
}

std::string GridChoice::InletNote(const GridUnits& given) const {
  const GridUnits units = Stretched(given);
  const double x0 = film_.x_start_b * units.inlet_m;
  const double deficit = WorstDeficit(x0);
  if (!(deficit > kInletNoteDeficit) || !(inlet_need_m_ > -x0)) return "";
  const int nodes = Grid(given).NodesFromStart(-inlet_need_m_);
  char spacing[160];
  if (nodes <= kMaxGridPoints)
    std::snprintf(spacing, sizeof spacing, "with grid_points = %d keeps the spacing", nodes);
  else
    std::snprintf(spacing, sizeof spacing,
                  "keeps the spacing with %d nodes, more than grid_points allows (%d)", nodes,
                  kMaxGridPoints);
  char buf[480];
  std::snprintf(buf, sizeof buf,
                "the inlet at x = %.3g mm thins the films by up to %.1f %% (Grubin's estimate "
                "before solving); one at %.3g mm keeps it below %.1f %%: x_start_b = %.3g %s "
                "(the automatic grid, grid_points left out, reaches as far with fewer nodes, so "
                "a coarser spacing)",
                x0 * 1e3, 100 * deficit, -inlet_need_m_ * 1e3, 100 * kInletTargetDeficit,
                film_.x_start_b * inlet_need_m_ / -x0, spacing);
  return buf;
}

}  // namespace tehl::internal
