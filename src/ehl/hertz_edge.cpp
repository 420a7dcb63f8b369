#include "tehl/ehl/hertz_edge.hpp"

#include <algorithm>
#include <cmath>

namespace tehl {

bool HertzEdge::resolved() const { return width_cells >= kEdgeResolvedCells; }

HertzEdge EstimateHertzEdge(double reduced_radius_m,
                            double half_width_m,
                            double central_film_m,
                            double dx_m) {
  HertzEdge e;
  const double r = reduced_radius_m, b = half_width_m, h = central_film_m;
  if (!(r > 0 && b > 0 && h > 0 && dx_m > 0)) return e;
  e.width_m = b * std::cbrt(std::pow(3.0 * r * h / (2.0 * std::sqrt(2.0) * b * b), 2.0));
  e.width_cells = e.width_m / dx_m;
  e.film_deficit = kEdgeDeficitConstant / (e.width_cells * e.width_cells);
  return e;
}

int NodesSpanningEdge(double span_m, double edge_width_m, int min_nodes, int max_nodes) {
  if (!(span_m > 0 && edge_width_m > 0)) return min_nodes;
  const double cells = kEdgeResolvedCells * span_m / edge_width_m;
  int n = 3;
  while (n < max_nodes && (n < min_nodes || n - 1 < cells)) n = 2 * n - 1;
  return std::min(std::max(n, min_nodes), max_nodes);
}

double HertzGap(double reduced_radius_m, double half_width_m, double xi) {
  const double a = std::abs(xi);
  if (a <= 1.0) return 0.0;
  const double s = std::sqrt(a * a - 1.0);
  return half_width_m * half_width_m / (2.0 * reduced_radius_m) * (a * s - std::log(a + s));
}

}  // namespace tehl
