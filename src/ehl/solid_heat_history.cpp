// The solids' heat history of a transient energy step (src/ehl/solid_heat_history.hpp).
#include "ehl/solid_heat_history.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <vector>

namespace tehl::internal {

namespace {

double GridLength(const UniformGrid& g) { return (g.size() - 1) * g.dx_m(); }

// The spans of solid s (0 or 1) seen from a step from `previous`: its own level, then its
// earlier ones.
std::vector<FluxSpan> Spans(const FilmTemperature& previous, int s) {
  std::vector<FluxSpan> spans;
  spans.reserve(previous.earlier.size() + 1);
  spans.push_back(s == 0 ? FluxSpan{&previous.q1_w_m2, previous.travel1_m, previous.speed1_m_s}
                         : FluxSpan{&previous.q2_w_m2, previous.travel2_m, previous.speed2_m_s});
  for (const SolidFluxLevel& l : previous.earlier)
    spans.push_back(s == 0 ? FluxSpan{&l.q1_w_m2, l.travel1_m, l.speed1_m_s}
                           : FluxSpan{&l.q2_w_m2, l.travel2_m, l.speed2_m_s});
  return spans;
}

}  // namespace

StepHistory HistoryOfStep(const UniformGrid& grid,
                          const FilmTemperature& previous,
                          double dt_s,
                          double u1_m_s,
                          double u2_m_s) {
  StepHistory h;
  const double reach1_m = u1_m_s * dt_s, reach2_m = u2_m_s * dt_s;
  const double length = GridLength(grid);
  if (reach1_m >= length && reach2_m >= length) return h;
  h.active = true;
  h.reach1_m = reach1_m;
  h.reach2_m = reach2_m;
  const MovingHeatSource source(grid);
  h.history1 = source.History(reach1_m, u1_m_s, Spans(previous, 0));
  h.history2 = source.History(reach2_m, u2_m_s, Spans(previous, 1));
  return h;
}

void RememberLevels(const UniformGrid& grid,
                    const FilmTemperature& previous,
                    double dt_s,
                    double u1_m_s,
                    double u2_m_s,
                    FilmTemperature* t) {
  const double length = GridLength(grid);
  const double reach1_m = u1_m_s * dt_s, reach2_m = u2_m_s * dt_s;
  t->travel1_m = reach1_m;
  t->travel2_m = reach2_m;
  t->speed1_m_s = u1_m_s;
  t->speed2_m_s = u2_m_s;
  std::vector<SolidFluxLevel> kept;
  // Lags at which each candidate level starts, seen from the level after t (at least).
  double start1 = reach1_m, start2 = reach2_m;
  auto keep = [&](const SolidFluxLevel& l) {
    if (start1 >= length && start2 >= length) return false;
    kept.push_back(l);
    start1 += l.travel1_m;
    start2 += l.travel2_m;
    return true;
  };
  if (keep(SolidFluxLevel{previous.q1_w_m2, previous.q2_w_m2, previous.travel1_m,
                          previous.travel2_m, previous.speed1_m_s, previous.speed2_m_s}))
    for (const SolidFluxLevel& l : previous.earlier)
      if (!keep(l)) break;
  // Too many levels (very short steps): merge two neighbours of finite travel into one, each
  // flux weighted by its travel. The pair merged is the one whose span is shortest relative
  // to the square root of its lag, the kernel's scale there: old history is coarsened more
  // than recent history, geometrically (merging the oldest pair every time instead made the
  // first-order error of a 640-step march 40 times that of 320 steps). A steady level
  // (infinite travels, always the last) stays.
  while (static_cast<int>(kept.size()) > kMaxSolidFluxLevels) {
    size_t last = kept.size() - 1;
    if (std::isinf(kept[last].travel1_m)) --last;
    size_t best = 0;
    double best_score = std::numeric_limits<double>::infinity();
    double lag1 = reach1_m, lag2 = reach2_m;
    for (size_t j = 0; j < last; ++j) {
      const SolidFluxLevel &a = kept[j], &b = kept[j + 1];
      const double score = (a.travel1_m + b.travel1_m) / std::sqrt(lag1 + a.travel1_m) +
                           (a.travel2_m + b.travel2_m) / std::sqrt(lag2 + a.travel2_m);
      if (score < best_score) {
        best_score = score;
        best = j;
      }
      lag1 += a.travel1_m;
      lag2 += a.travel2_m;
    }
    SolidFluxLevel& a = kept[best];
    const SolidFluxLevel& b = kept[best + 1];
    // The merged level lasts both durations l/u (its speed their travel over their time).
    auto merge = [](Eigen::VectorXd* qa, double* la, double* ua, const Eigen::VectorXd& qb,
                    double lb, double ub) {
      if (*la + lb > 0) {
        *qa = (*qa * *la + qb * lb) / (*la + lb);
        if (*ua > 0 && ub > 0) *ua = (*la + lb) / (*la / *ua + lb / ub);
      }
      *la += lb;
    };
    merge(&a.q1_w_m2, &a.travel1_m, &a.speed1_m_s, b.q1_w_m2, b.travel1_m, b.speed1_m_s);
    merge(&a.q2_w_m2, &a.travel2_m, &a.speed2_m_s, b.q2_w_m2, b.travel2_m, b.speed2_m_s);
    kept.erase(kept.begin() + static_cast<std::ptrdiff_t>(best + 1));
  }
  t->earlier = std::move(kept);
}

void ForgetLevels(double u1_m_s, double u2_m_s, FilmTemperature* t) {
  t->travel1_m = t->travel2_m = std::numeric_limits<double>::infinity();
  t->speed1_m_s = u1_m_s;
  t->speed2_m_s = u2_m_s;
  t->earlier.clear();
}

}  // namespace tehl::internal
