#include "scene/automatic_grid.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "tehl/ehl/film_thickness_formulas.hpp"
#include "tehl/ehl/hertz_edge.hpp"
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

void GridChoice::Add(double r, double um, double w) {
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
}

int GridChoice::Nodes(const GridUnits& units) const {
  if (film_.grid_points > 0) return film_.grid_points;
  const double span = film_.x_end_b * units.outlet_m - film_.x_start_b * units.inlet_m;
  return NodesSpanningEdge(span, std::isfinite(edge_m_) ? edge_m_ : 0.0, kAutomaticGridMinNodes,
                           kAutomaticGridMaxNodes);
}

UniformGrid GridChoice::Grid(const GridUnits& units) const {
  return UniformGrid(film_.x_start_b * units.inlet_m, film_.x_end_b * units.outlet_m, Nodes(units));
}

std::string GridChoice::Rule(const GridUnits& units) const {
  char buf[320];
  if (film_.grid_points > 0) {
    std::snprintf(buf, sizeof buf, "[numerics] grid_points = %d", film_.grid_points);
    return buf;
  }
  if (!std::isfinite(edge_m_)) {
    std::snprintf(buf, sizeof buf, "automatic: %d, the smallest (no Hertzian edge: rigid films)",
                  kAutomaticGridMinNodes);
    return buf;
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
  return buf;
}

}  // namespace tehl::internal
