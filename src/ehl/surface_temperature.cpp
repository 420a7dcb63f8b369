// Exact cell weights of the moving-heat-source integral (include/tehl/ehl/surface_temperature.hpp).
#include "tehl/ehl/surface_temperature.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "base/number_text.hpp"
#include "tehl/ehl/moving_line_source.hpp"
#include "tehl/error.hpp"

namespace tehl {

namespace {

// 2 [sqrt(a) - sqrt(b)] for a >= b >= 0, written as 2 (a - b) / (sqrt(a) + sqrt(b)) so that
// far cells (a ~ b) keep full relative precision.
double TwoRootDifference(double a, double b) {
  const double s = std::sqrt(a) + std::sqrt(b);
  return s > 0 ? 2.0 * (a - b) / s : 0.0;
}

}  // namespace

MovingHeatSource::MovingHeatSource(const UniformGrid& grid)
    : n_(grid.size()),
      dx_(grid.dx_m()),
      toeplitz_(2 * grid.size() - 1, 0.0),
      inlet_(grid.size()),
      outlet_(grid.size(), 0.0) {
  FillHighPeclet();
}

MovingHeatSource MovingHeatSource::Recent(const UniformGrid& grid, double reach_m) {
  if (!(reach_m > 0))
    throw InputError(InputProblem{"", 0, "reach_m", internal::FormatReal(reach_m), "must be > 0",
                                  "the travel of a time step u_s dt > 0 [m], or infinity"});
  MovingHeatSource s(grid);
  s.reach_ = reach_m;
  s.FillHighPeclet();
  return s;
}

void MovingHeatSource::FillHighPeclet() {
  // The part of a cell at distances [lo, hi] from x_i (upstream) within the reach.
  const double r = reach_;
  auto weight = [r](double lo, double hi) {
    return TwoRootDifference(std::min(hi, r), std::min(lo, r));
  };
  // Cell k >= 1 seen from node i = k + m: [x_i - (m + 1/2) dx, x_i - (m - 1/2) dx], clipped at
  // x_i for m = 0 (the integral stops at x_i).
  double* lag = toeplitz_.data() + (n_ - 1);
  lag[0] = weight(0.0, 0.5 * dx_);
  for (int m = 1; m < n_; ++m) lag[m] = weight((m - 0.5) * dx_, (m + 0.5) * dx_);
  // The inlet half cell [x_0, x_0 + dx/2] seen from node i: nothing at i = 0.
  inlet_[0] = 0.0;
  for (int i = 1; i < n_; ++i) inlet_[i] = weight((i - 0.5) * dx_, i * dx_);
  // The outlet half cell [x_(n-1) - dx/2, x_(n-1)] is seen from its own node only.
  outlet_[n_ - 1] = lag[0];
}

MovingHeatSource::MovingHeatSource(const UniformGrid& grid, double omega_1_m)
    : n_(grid.size()),
      dx_(grid.dx_m()),
      omega_(omega_1_m),
      toeplitz_(2 * grid.size() - 1),
      inlet_(grid.size()),
      outlet_(grid.size()) {
  if (!(std::isfinite(omega_1_m) && omega_1_m > 0))
    throw InputError(InputProblem{"", 0, "omega_1_m", internal::FormatReal(omega_1_m),
                                  "must be finite and > 0",
                                  "u_s / (2 kappa_s) > 0 [1/m] (MovingHeatSource::DecayRate)"});
  // Primitive of the kernel: P(X) = sqrt(2/(pi omega)) J(omega X), P(0) = 0; the weight of the
  // cell [a, b] seen from x_i is P(x_i - a) - P(x_i - b).
  const double scale = std::sqrt(2.0 / (M_PI * omega_));
  auto primitive = [&](double half_cells) {
    return scale * MovingLineSourceIntegral(omega_ * 0.5 * dx_ * half_cells);
  };
  // In half cells: an interior cell at lag l spans X in [(2l - 1), (2l + 1)] dx/2.
  std::vector<double> p(4 * n_ + 1);  // P at X = (j - 2n) dx/2, j = 0 ... 4n
  for (int j = 0; j <= 4 * n_; ++j) p[j] = primitive(j - 2.0 * n_);
  auto at = [&](int half_cells) { return p[half_cells + 2 * n_]; };
  for (int l = -(n_ - 1); l <= n_ - 1; ++l) toeplitz_[n_ - 1 + l] = at(2 * l + 1) - at(2 * l - 1);
  for (int i = 0; i < n_; ++i) {
    inlet_[i] = at(2 * i) - at(2 * i - 1);   // [x_0, x_0 + dx/2]
    const int l = i - (n_ - 1);              // <= 0
    outlet_[i] = at(2 * l + 1) - at(2 * l);  // [x_(n-1) - dx/2, x_(n-1)]
  }
}

double MovingHeatSource::Weight(int i, int k) const {
  if (i < 0 || k < 0 || i >= n_ || k >= n_) return 0.0;
  if (k == 0) return inlet_[i];
  if (k == n_ - 1) return outlet_[i];
  return toeplitz_[n_ - 1 + i - k];
}

double MovingHeatSource::CellLength(int k) const {
  return (k == 0 || k == n_ - 1) ? 0.5 * dx_ : dx_;
}

double MovingHeatSource::Factor(const SolidThermal& s, double speed_m_s) {
  ProblemList bad;
  auto rule = [&](double v, const char* key, const char* allowed) {
    if (!(std::isfinite(v) && v > 0))
      bad.Add({"", 0, key, internal::FormatReal(v), "must be finite and > 0", allowed});
  };
  rule(s.density_kg_m3, "SolidThermal::density_kg_m3", "a density > 0 [kg/m^3]");
  rule(s.heat_capacity_j_kgk, "SolidThermal::heat_capacity_j_kgk",
       "a heat capacity > 0 [J/(kg K)]");
  rule(s.conductivity_w_mk, "SolidThermal::conductivity_w_mk", "a conductivity > 0 [W/(m K)]");
  rule(speed_m_s, "surface speed",
       "a surface speed > 0 [m/s] in +x (the moving-heat-source integral needs the solid to "
       "move through the contact from the inlet)");
  bad.ThrowIfAny();
  return 1.0 / std::sqrt(M_PI * s.density_kg_m3 * s.heat_capacity_j_kgk * s.conductivity_w_mk *
                         speed_m_s);
}

double MovingHeatSource::DecayRate(const SolidThermal& s, double speed_m_s) {
  Factor(s, speed_m_s);  // the same checks
  return 0.5 * speed_m_s * s.density_kg_m3 * s.heat_capacity_j_kgk / s.conductivity_w_mk;
}

Eigen::VectorXd MovingHeatSource::History(double reach_m,
                                          double speed_m_s,
                                          const std::vector<FluxSpan>& spans) const {
  ProblemList bad;
  if (!high_peclet() || !(reach_m > 0))
    bad.Add({"", 0, "reach_m", internal::FormatReal(reach_m), "must be > 0",
             "a travel u_s dt > 0 [m] (the history is of the high-Peclet form)"});
  if (!(std::isfinite(speed_m_s) && speed_m_s > 0))
    bad.Add({"", 0, "speed_m_s", internal::FormatReal(speed_m_s), "must be finite and > 0",
             "the surface speed of the step [m/s]"});
  for (const FluxSpan& sp : spans) {
    if (!sp.q_w_m2 || sp.q_w_m2->size() != n_)
      bad.Add({"", 0, "FluxSpan::q_w_m2", sp.q_w_m2 ? std::to_string(sp.q_w_m2->size()) : "null",
               "must have one value per grid node", std::to_string(n_) + " values"});
    if (!(sp.travel_m >= 0))
      bad.Add({"", 0, "FluxSpan::travel_m", internal::FormatReal(sp.travel_m), "must be >= 0",
               "u_s dt [m], or infinity"});
    if (!(std::isfinite(sp.speed_m_s) && sp.speed_m_s >= 0))
      bad.Add({"", 0, "FluxSpan::speed_m_s", internal::FormatReal(sp.speed_m_s),
               "must be finite and >= 0", "the level's surface speed [m/s], 0 = the step's"});
  }
  bad.ThrowIfAny();
  Eigen::VectorXd h = Eigen::VectorXd::Zero(n_);
  if (spans.empty()) return h;
  // Span j covers the lags [edge[j], edge[j + 1]] (the last one has no upper edge). Its lag l
  // was travelled at the span's own speed u_j, (l - edge[j]) / u_j after the time lag start[j]
  // / u: measured in the step's speed u, at the lag start[j] + (l - edge[j]) u / u_j. The
  // kernel is 1/sqrt of that time lag (in units of u): Duhamel's integral in time.
  const int m = static_cast<int>(spans.size());
  constexpr double kInf = std::numeric_limits<double>::infinity();
  std::vector<double> edge(m + 1), start(m + 1), stretch(m);
  edge[0] = start[0] = reach_m;
  for (int j = 0; j < m; ++j) {
    stretch[j] = spans[j].speed_m_s > 0 ? speed_m_s / spans[j].speed_m_s : 1.0;
    const bool last = j + 1 == m;
    edge[j + 1] = last ? kInf : edge[j] + spans[j].travel_m;
    start[j + 1] = last ? kInf : start[j] + spans[j].travel_m * stretch[j];
  }
  // The pieces of the lags [lo, hi] in each span: (span, exact kernel integral) to `add`.
  auto pieces = [&](double lo, double hi, auto&& add) {
    lo = std::max(lo, reach_m);
    if (!(lo < hi)) return;
    int j = static_cast<int>(std::upper_bound(edge.begin() + 1, edge.end(), lo) - edge.begin()) - 1;
    while (lo < hi) {
      const double top = std::min(hi, edge[j + 1]);
      auto time_lag = [&](double l) { return start[j] + (l - edge[j]) * stretch[j]; };
      add(j, TwoRootDifference(time_lag(top), time_lag(lo)));
      lo = top;
      ++j;
    }
  };
  // The cells of the nodes k >= 1 at lag d = i - k: [(d - 1/2) dx, (d + 1/2) dx], clipped at
  // 0 for d = 0 (the outlet half cell too); computed once for every d.
  std::vector<int> first(n_ + 1, 0), span_of;
  std::vector<double> weight;
  for (int d = 0; d < n_; ++d) {
    first[d] = static_cast<int>(weight.size());
    pieces(d == 0 ? 0.0 : (d - 0.5) * dx_, (d + 0.5) * dx_, [&](int j, double w) {
      span_of.push_back(j);
      weight.push_back(w);
    });
  }
  first[n_] = static_cast<int>(weight.size());
  for (int i = 1; i < n_; ++i) {
    double sum = 0;
    for (int d = 0; d < i; ++d)
      for (int p = first[d]; p < first[d + 1]; ++p)
        sum += weight[p] * (*spans[span_of[p]].q_w_m2)[i - d];
    // The inlet half cell [x_0, x_0 + dx/2]: lags [(i - 1/2) dx, i dx].
    pieces((i - 0.5) * dx_, i * dx_, [&](int j, double w) { sum += w * (*spans[j].q_w_m2)[0]; });
    h[i] = sum;
  }
  return h;
}

Eigen::VectorXd MovingHeatSource::Rise(const SolidThermal& solid,
                                       double speed_m_s,
                                       const Eigen::VectorXd& q_w_m2) const {
  const double f = Factor(solid, speed_m_s);
  if (q_w_m2.size() != n_)
    throw InputError(InputProblem{"", 0, "q_w_m2", std::to_string(q_w_m2.size()) + " values",
                                  "must have one value per grid node",
                                  std::to_string(n_) + " values"});
  Eigen::VectorXd rise = Eigen::VectorXd::Zero(n_);
  const int last = n_ - 1;
  for (int i = 0; i < n_; ++i) {
    double sum = inlet_[i] * q_w_m2[0] + (last > 0 ? outlet_[i] * q_w_m2[last] : 0.0);
    const int k_end = high_peclet() ? std::min(i, last - 1) : last - 1;
    for (int k = 1; k <= k_end; ++k) sum += toeplitz_[last + i - k] * q_w_m2[k];
    rise[i] = f * sum;
  }
  return rise;
}

}  // namespace tehl
