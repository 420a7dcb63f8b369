#include "tehl/ehl/outlet_spike.hpp"

namespace tehl {

bool OutletSpike::resolved() const { return !found || width_cells >= kSpikeResolvedCells; }

OutletSpike FindOutletSpike(const Eigen::VectorXd& p,
                            double x_start_m,
                            double dx_m,
                            double min_relative_prominence) {
  OutletSpike s;
  const int n = static_cast<int>(p.size());
  // The outlet: the last node with a pressure above round-off. A linear solve can leave
  // pressures of order 1e-13 max p on cavitated nodes; a micro-peak among them used to stop
  // the walk below before it reached the spike (seed 004 cycle: 6 of 151 films).
  const double floor = 1e-6 * p.maxCoeff();
  int last = n - 1;
  while (last >= 0 && !(p[last] > floor)) --last;
  if (last < 2) return s;
  int peak = last;  // walk up from the outlet to the first maximum
  while (peak > 0 && p[peak - 1] >= p[peak]) --peak;
  int dip = peak;  // then down to the minimum before the hump
  while (dip > 0 && p[dip - 1] <= p[dip]) --dip;
  if (dip == 0 || dip == peak) return s;  // no hump upstream: the peak is the hump itself
  const double prominence = p[peak] - p[dip];
  if (!(prominence >= min_relative_prominence * p.maxCoeff())) return s;
  const double half = p[dip] + 0.5 * prominence;
  int a = peak;  // p[a] <= half < p[a + 1] on the upstream flank
  while (p[a] > half) --a;
  int c = peak;  // p[c - 1] > half >= p[c] on the downstream flank
  while (c < n - 1 && p[c] > half) ++c;
  const double left = a + (half - p[a]) / (p[a + 1] - p[a]);
  const double right = p[c] > half ? c : (c - 1) + (p[c - 1] - half) / (p[c - 1] - p[c]);
  s.found = true;
  s.node = peak;
  s.x_m = x_start_m + peak * dx_m;
  s.pressure_pa = p[peak];
  s.prominence_pa = prominence;
  s.width_cells = right - left;
  return s;
}

}  // namespace tehl
