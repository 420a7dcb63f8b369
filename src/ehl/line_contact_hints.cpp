// LineContactSolver::Impl: what a failed solve's message suggests: a roughness taller than
// the film, or a Hertzian edge the grid does not resolve.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "base/number_text.hpp"
#include "ehl/line_contact_impl.hpp"
#include "tehl/ehl/hertz_edge.hpp"
#include "tehl/ehl/surface_roughness.hpp"
#include "tehl/units.hpp"

namespace tehl {

std::string LineContactSolver::Impl::RoughnessHint(const ContactConditions& c,
                                                   const FilmState& s) const {
  if (!eff_.roughness || (!s1_ && !s2_)) return "";
  // The surfaces' combined height over the grid at the state's travel, peak to valley,
  // against the smooth film these conditions carry (EstimateCentralFilm).
  double lo = 0, hi = 0;
  for (int i = 0; i < grid_.size(); ++i) {
    const double z = (s1_ ? s1_->Height(grid_.x(i), s.travel1_m) : 0.0) +
                     (s2_ ? s2_->Height(grid_.x(i), s.travel2_m) : 0.0);
    lo = i ? std::min(lo, z) : z;
    hi = i ? std::max(hi, z) : z;
  }
  const double film = EstimateCentralFilm(c);
  if (!(hi - lo > film)) return "";
  return "; the roughness spans " + internal::FormatShort(hi - lo) +
         " m peak to valley on the grid, more than the smooth film these conditions carry "
         "(about " +
         internal::FormatShort(film) +
         " m): no full film may separate the surfaces, and asperity contact is not modelled";
}

std::string LineContactSolver::Impl::EdgeHint(const ContactConditions& c) const {
  if (!eff_.elastic) return "";
  const double b = LineContactHertz(c.load_n_per_m, c.reduced_radius_m, e_prime_).half_width_m;
  const HertzEdge e =
      EstimateHertzEdge(c.reduced_radius_m, b, EstimateCentralFilm(c), grid_.dx_m());
  if (!(e.width_m > 0) || e.resolved()) return "";
  const int nodes =
      NodesSpanningEdge(grid_.x_end_m() - grid_.x_start_m(), e.width_m, grid_.size(), 1 << 24);
  char buf[224];
  std::snprintf(buf, sizeof buf,
                "; the grid spans the Hertzian edge of the film (estimated from Moes' fit) with "
                "%.2g cells, where %.0f are needed: about %d nodes would span it "
                "(docs/results.md, \"The edge note\")",
                e.width_cells, kEdgeResolvedCells, nodes);
  return buf;
}

}  // namespace tehl
